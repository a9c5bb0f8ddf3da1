// The packing file (HDF5), written by softpack-pack and read by the sweeps and the figures.
// Layout (SI units; readable with h5dump or h5py without project code):
//
//   /centres            (N, 3)  sphere centres [m], shell centre at the origin
//   /radii              (N)     radii after growth [m]
//   /radii_inserted     (N)     radii before growth [m]
//   /shell/radius, /shell/centre (3)
//   /parameters/...     the generator's parameters (Rs, r_max, polydispersity, exponent,
//                       beta, trials, shell_is_neighbour, level_ratio)
//   /stats/...          sampled, inserted, discarded, grown, solid_fraction, bulk_fraction,
//                       depletion_length, min_shell_gap, exponent, exponent_error,
//                       exponent_r_min, exponent_r_max, radial_profile/{r_inner,r_outer,solid_fraction}
//   /provenance/...     program, code_version, config_file, config (the YAML slice read),
//                       seed, seconds, cpu_seconds (wall-clock and CPU time of the generation)
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/hdf5_file.hpp"
#include "packing/generator.hpp"
#include "packing/statistics.hpp"

namespace softpack {

struct PackingProvenance {
  std::string program;
  std::string code_version;
  std::string config_file;
  std::string config;  ///< the configuration slice the packing depends on
  std::uint64_t seed = 0;
  double seconds = 0.0;      ///< wall-clock time [s]
  double cpu_seconds = 0.0;  ///< CPU time of the process [s]
};

/// Writes the file atomically (no file is left behind on failure).
void write_packing_file(const std::string& path, const PackingParameters& p, const Packing& packing,
                        const PackingStatistics& stats, const PackingProvenance& provenance);

struct PackingFile {
  std::vector<Vec3> centres;
  std::vector<double> radii;
  double Rs = 0.0;
  PackingParameters parameters;
  PackingProvenance provenance;
};

/// Reads a packing file; InputError names the file and what is missing or wrong.
PackingFile read_packing_file(const std::string& path);

/// "a packing file (softpack-pack)" when `f` has the layout of one, else "" (formats/file_kind.hpp).
std::string describe_packing_file(const h5::File& f);

}  // namespace softpack
