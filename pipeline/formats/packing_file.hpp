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
//   /parameters/levels  (a packing of nested soft-particles, packing/nested.hpp; absent: 1) and
//   /sites/centres (M, 3), /sites/radius   the placed soft-particles of the level below, of
//                       radius Rs / Pi (absent when levels is 1); /stats/sites_drawn,
//                       /stats/sites_discarded; their contents are the level below's packings of
//                       seed nested_site_seed(seed, site), not stored here
//   /provenance/...     program, code_version, config_file, config (the YAML slice read),
//                       seed, seconds, cpu_seconds (wall-clock and CPU time of the generation),
//                       stamp (the packing stage's configuration stamp, profile/profile.hpp;
//                       files written before stamps were recorded have none)
//
// An imported packing (softpack-import, packing/import.hpp) has /centres, /radii, /shell, /stats
// (solid fraction, bulk fraction, depletion length, min shell gap, exponent, radial profile),
// /provenance (program softpack-import) and, instead of the generator's parameters,
//   /parameters/Rs      the shell radius [m]
//   /imported/...       source_file, source_sha256, format, shell (given|read|enclosing),
//                       shell_centre_in_file (3, the file's unit), length_unit [m per unit],
//                       overlap_tolerance, largest_overlap (over the smaller radius),
//                       density (the source's density column [kg/m^3]; absent: none or ignored),
//                       pressed_face (the source's face turned onto +x, the wall's side)
#pragma once
#include <cstdint>
#include <optional>
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
  std::string stamp;         ///< the packing stage's configuration stamp ("": a file from before stamps)
};

/// The soft-particles of the level below a packing of nested soft-particles holds (docs/nested.md).
struct PackingSites {
  int levels = 1;            ///< levels of the model from this packing's down; 1: grains only
  double radius = 0.0;       ///< their radius, Rs / Pi [m]
  std::vector<Vec3> centres; ///< about the shell's centre
  std::size_t drawn = 0, discarded = 0;
};

/// Writes the file atomically (no file is left behind on failure); `sites` when levels > 1.
void write_packing_file(const std::string& path, const PackingParameters& p, const Packing& packing,
                        const PackingStatistics& stats, const PackingProvenance& provenance, const PackingSites& sites = {});

/// What an imported packing records of its source (/imported).
struct ImportRecord {
  std::string source_file, source_sha256, format, shell;
  Vec3 shell_centre_in_file = Vec3::Zero();
  double length_unit = 1.0, overlap_tolerance = 0.0, largest_overlap = 0.0;
  /// The grains' density the source file gives [kg/m^3] (/imported/density; NaN, the dataset
  /// absent: the file has none, or the profile ignores it, or the file is from before 0.6.1).
  double density = kNaN;
  /// The face of the source's packing the wall presses, turned onto +x (/imported/pressed_face;
  /// "+x" for files from before it existed).
  std::string pressed_face = "+x";
  /// What the source holds that the import did not use, with what applied instead
  /// (/imported/not_used; "" for nothing, and for files from before it existed).
  std::string not_used;
};

/// Writes an imported packing atomically; `centres` about the shell's centre, SI.
void write_imported_packing_file(const std::string& path, const ImportRecord& record, const std::vector<Vec3>& centres,
                                 const std::vector<double>& radii, double Rs, const PackingStatistics& stats,
                                 const PackingProvenance& provenance);

struct PackingFile {
  std::vector<Vec3> centres;
  std::vector<double> radii;
  double Rs = 0.0;
  PackingParameters parameters;  ///< imported: Rs, and r_max the largest radius
  PackingProvenance provenance;
  std::optional<ImportRecord> imported;  ///< an imported packing's source
  PackingSites sites;                    ///< levels 1 and no site unless the file has /parameters/levels
  std::string path;                      ///< the file it was read from (empty: made in memory)
};

/// Reads a packing file; InputError names the file and what is missing or wrong.
PackingFile read_packing_file(const std::string& path);

/// The packing's identity by content: the SHA-256 of its shell radius and of its spheres (x, y, z,
/// r as IEEE doubles) sorted, then (levels > 1) of its levels and its sites sorted, so that the order they are listed in does not count. Two seeds whose packings have one identity are one packing
/// counted twice, whatever their names and seed numbers (analysis/average.hpp).
std::string packing_sha256(const PackingFile& p);

/// "a packing file (softpack-pack)" (or softpack-import) when `f` has the layout of one, else "" (formats/file_kind.hpp).
std::string describe_packing_file(const h5::File& f);

}  // namespace softpack
