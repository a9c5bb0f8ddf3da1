// The sweep results file: the points of one sweep (softpack-normal or softpack-tangential, one
// scene, one seed) as columns, read by softpack-average and by the checks of the archived
// results (tests/stability/test_archive.cpp). HDF5 layout, one value per point unless said:
//
//   /delta_n, /hn [m], /alpha_deg, /ht [m]        the deformation (ht: tangential stage)
//   /Fn, /Ft_parallel, /Ft_perpendicular [N]      the force on the second body along x, y, z
//   /force, /force_first, /force_between (N, 3)   [N], as PointResult (measure/point_result.hpp)
//   /contacts, /steps, /relaxation/{steps, time, final_force_ratio, final_energy_ratio}
//   /relaxation/checks/{point, time, force_ratio, energy_ratio}   one value per relaxation check
//   /seconds                                      wall-clock time of each point
//   /provenance/...  stage, scene, config, code_version (formats/sweep_provenance.hpp),
//                    packings, seed, seconds (of the whole stage)
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "formats/sweep_provenance.hpp"
#include "io/hdf5_file.hpp"
#include "measure/point_result.hpp"

namespace softpack {

struct SweepResults {
  std::string path;  ///< the file read (for messages)
  std::vector<double> delta_n, hn, alpha_deg, ht, Fn, Ft_parallel, Ft_perpendicular;
  std::vector<Vec3> force, force_first, force_between;
  std::vector<std::int64_t> contacts, steps, relax_steps;
  std::vector<double> relax_time;
  std::vector<double> final_force_ratio, final_energy_ratio;  ///< may be infinite (sim/residuals.hpp)
  std::vector<std::int64_t> check_point;                      ///< per relaxation check: its point
  std::vector<double> check_time, check_force_ratio, check_energy_ratio;
  std::vector<double> seconds;
  PointProvenance provenance;
  std::string packings;
  std::uint64_t seed = 0;
  double total_seconds = 0.0;  ///< of the whole stage
};

/// Writes the results of a whole sweep atomically: arrays over the points, the relaxation
/// checks flattened.
void write_sweep_results_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                              const std::string& packings, std::uint64_t seed, double seconds);

/// Reads a sweep results file. With `stage` or `scene` given, the file must have been made by
/// that stage (normal, tangential) for that scene. InputError names the file and the dataset:
/// not a results file, another stage or scene, no points, columns of different lengths, values
/// that are not finite (but the ratios).
SweepResults read_sweep_results_file(const std::string& path, const std::string& stage = "", const std::string& scene = "");

/// "a normal sweep results file (softpack-normal)" when `f` has the layout of one, else ""
/// (formats/file_kind.hpp).
std::string describe_sweep_results_file(const h5::File& f);

}  // namespace softpack
