// The average files of one scene (softpack-average; read by softpack-fit and the figures): the
// mean and standard error over the seeds of its sweep results (analysis/average.hpp), in HDF5
// for softpack-fit and as text columns for gnuplot. In the output folder:
//
//   <scene>.h5  /normal/{delta_n, Fn_mean, Fn_stderr, Ft_parallel_mean, Ft_parallel_stderr,
//                        Ft_perpendicular_mean, Ft_perpendicular_stderr, seeds}
//               /tangential/{delta_n, alpha_deg, ht, the same pairs for Ft_parallel,
//                            Ft_perpendicular and Fn}        one row per (delta_n, alpha)
//               /kt/{delta_n, mean, stderr}                  spring constant [N/m] per delta_n
//               /normal/Fn_per_seed, /kt/per_seed            every seed's value (since 0.6.0): row-major
//                            [point][seed], points x seeds values, seeds in the order of /provenance/inputs
//               /provenance/{scene, profile, code_version, inputs, seconds, cpu_seconds, stamp}
//                            (stamp: the average stage's configuration stamp, profile/profile.hpp,
//                            with --config; empty without, absent in files from before stamps)
//   normal-<scene>.dat, tangential-<scene>.dat (one block per delta_n, gnuplot's index) and
//   kt-<scene>.dat: the same numbers as columns, under a header that names them.
// A normal-only profile's averages have no /tangential and /kt, and no tangential and kt .dat.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/average.hpp"
#include "core/stopwatch.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {

struct AverageProvenance {
  std::string scene, profile, code_version;
  std::vector<std::string> normal_inputs, tangential_inputs;  ///< the results files averaged
  double seconds = 0.0;      ///< wall-clock time [s]
  double cpu_seconds = 0.0;  ///< CPU time of the process [s]
  std::string stamp;         ///< the average stage's stamp of the profile (--config; "" without)
};

/// Writes the four files into `dir`, each atomically (two without `tangential`: normal only).
void write_average_files(const std::string& dir, const NormalAverage& normal, const TangentialAverage* tangential,
                         const AverageProvenance& provenance);

/// What softpack-fit reads from an average file.
struct AverageFile {
  std::string path;
  std::string scene;  ///< soft-solid or soft-soft
  std::string profile, code_version;
  std::string stamp;  ///< the average stage's configuration stamp ("": none recorded)
  std::int64_t seeds = 0;
  std::vector<double> delta_n, Fn, Fn_stderr;  ///< /normal
  bool has_kt = false;                         ///< the /kt group is there
  std::vector<double> kt_delta_n, kt, kt_stderr;
  /// Every seed's Fn and kt, [point][seed] (empty in files from before 0.6.0): the jackknife of the fits.
  std::vector<std::vector<double>> Fn_per_seed, kt_per_seed;
  std::optional<Elapsed> time;  ///< of softpack-average (provenance/seconds, cpu_seconds), when the file says
};
/// Reads and checks an average file; InputError names the file and the dataset (an unknown
/// scene, columns of different lengths, values that are not finite).
AverageFile read_average_file(const std::string& path);

/// "an average file (softpack-average)" when `f` has the layout of one, else ""
/// (formats/file_kind.hpp).
std::string describe_average_file(const h5::File& f);

}  // namespace softpack
