// The results file of one coarse-grain run (softpack-coarse run; read by softpack-coarse
// report): the compression curve of one model and one seed, HDF5,
//
//   /curve/{strain, phase, sigma_top, sigma_bottom, sigma_lateral, fraction, grain_grain,
//           grain_soft, soft_soft, Z, kinetic, elastic, shear, tau} one row per increment
//   /curve/{beyond_range, max_dn}  soft model: the contacts beyond the laws' range so far, each row
//                                  (absent in a run from before the count, and in resolved runs)
//   /medium/{L, H, Rs, grains, sites, spheres, bodies, grains_volume, packings_volume,
//            target_volume, packing_seeds}
//   /soft/{beyond_range, max_dn}                                  (soft model)
//   /provenance/{model, seed, settings, laws, code_version, steps, dt, seconds, cpu_seconds, threads}
//
// `settings` is the coarse_grain section as read, `laws` the law file's path. A run of LAMMPS
// (/provenance/engine "lammps", coarse/lammps_export.hpp) has no Z, grain_grain, grain_soft, soft_soft nor elastic: read as NaN
// (Z, elastic) and 0; nor /soft (the contacts beyond the laws' range are not counted there):
// beyond_range -1, max_dn NaN.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "coarse/compression.hpp"

namespace softpack {

struct CoarseResult {
  std::string path, model, settings, laws, code_version;
  /// What ran it: "softpack" (the engine) or "lammps" (softpack-coarse lammps-curve); only a LAMMPS
  /// run may lack the columns it does not record (/provenance/engine; absent: softpack).
  std::string engine = "softpack";
  std::uint64_t seed = 0;
  double L = 0.0, H = 0.0, Rs = 0.0;
  std::int64_t grains = 0, sites = 0, spheres = 0, bodies = 0, steps = 0;
  double grains_volume = 0.0, packings_volume = 0.0, target_volume = 0.0;
  std::vector<std::int64_t> packing_seeds;
  double dt = 0.0, seconds = 0.0, cpu_seconds = 0.0;
  std::int64_t threads = 0;  ///< the engine's threads (provenance/threads; 0: a file from before they were recorded)
  std::int64_t beyond_range = 0;
  double max_dn = 0.0;
  std::vector<CurveRow> rows;
};

/// The result of a run, ready to write.
CoarseResult coarse_result(const CompressionRun& run, const Medium& m, CoarseModel model, std::uint64_t seed,
                           const CoarseGrainSettings& s);
/// Writes atomically.
void write_coarse_result(const std::string& path, const CoarseResult& r);
/// Reads and checks; InputError names the file and the dataset.
CoarseResult read_coarse_result(const std::string& path);

}  // namespace softpack
