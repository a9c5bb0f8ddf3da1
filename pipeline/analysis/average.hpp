// Averages over seeds of the sweep results of one scene (paper §5: "averaging over seven
// different simulations"): mean and standard error of the mean (seed_statistics.hpp) at every
// Delta_n (normal) and every (Delta_n, alpha) (tangential), and the tangential spring constant
// kt: the slope of the parallel force against ht over the alpha grid, one per seed, then
// averaged. On the results in memory (formats/sweep_file.hpp reads them); the average file:
// formats/average_file.hpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/seed_statistics.hpp"  // MeanError, mean_error

namespace softpack {

/// The columns of one seed's sweep results that the averages read.
struct SweepColumns {
  std::string path;  ///< the file they come from (for messages)
  std::vector<double> delta_n, alpha_deg, ht, Fn, Ft_parallel, Ft_perpendicular;
};

/// One file of an average: the seed, the configuration and the packing it records.
struct SeedFile {
  std::string path;
  std::uint64_t seed = 0;
  std::string config;          ///< the canonical text of the stage's sections it was computed with
  std::string stamp;           ///< the stage's configuration stamp ("": a file from before stamps)
  std::string packing_sha256;  ///< the identity of its own packing by content ("": not recorded)
};
/// InputError unless every file is another file, of another seed and of another packing: the same
/// packing counted twice would enter the mean twice and shrink its standard error (to 0 for
/// [1, 1]), whatever its files are called and whatever seed numbers they carry (identity by
/// content). The message names `option` and both files ("--normal: a.h5 and b.h5 are the same file").
void check_distinct_seeds(const std::vector<SeedFile>& files, const std::string& option);
/// One configuration per average (docs/measurement.md): InputError unless every file records the
/// configuration of the first (text and stamp) and, when `expected_config` is given (the profile's
/// text of `stage`, with `expected_stamp`, from `profile_path`), that one. The message names both
/// files or the file and the profile, and the first line that differs.
void check_one_configuration(const std::vector<SeedFile>& files, const std::string& option, const std::string& stage,
                             const std::string& expected_config = "", const std::string& expected_stamp = "",
                             const std::string& profile_path = "");
/// InputError unless the normal and the tangential results are of the same seeds: the two
/// laws of one table would otherwise describe different soft-particles.
void check_same_seeds(const std::vector<SeedFile>& normal, const std::vector<SeedFile>& tangential);

struct NormalAverage {
  std::vector<double> delta_n;
  std::vector<MeanError> Fn, Ft_parallel, Ft_perpendicular;
  std::vector<std::vector<double>> Fn_per_seed;  ///< [Δn][seed]: what the jackknife of the fits re-averages
  std::size_t seeds = 0;
};
/// All files must share the Delta_n grid (InputError names the file that differs).
NormalAverage average_normal(const std::vector<SweepColumns>& seeds);

struct TangentialAverage {
  std::vector<double> delta_n, alpha_deg, ht;  ///< one row per (Delta_n, alpha)
  std::vector<MeanError> Ft_parallel, Ft_perpendicular, Fn;
  std::vector<double> kt_delta_n;  ///< one row per Delta_n
  std::vector<MeanError> kt;       ///< [N/m]
  std::vector<std::vector<double>> kt_per_seed;  ///< [Δn][seed]
  std::size_t seeds = 0;
};
TangentialAverage average_tangential(const std::vector<SweepColumns>& seeds);

/// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace softpack
