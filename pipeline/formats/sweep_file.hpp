// The two files of a sweep (measure/sweeps.hpp), both HDF5.
//
// The point file: one measured point with the simulation state it ended in; the checkpoint
// that lets an interrupted sweep resume, and the normal states the tangential stage shears.
//   /result/...      PointResult: delta_n, hn, alpha_deg, ht, force, force_first, force_between
//                    (3), contacts, overlap_max, overlap_q99, relax_steps, relax_time, steps, and per relaxation
//                    check checks/{time, force_ratio, energy_ratio, kinetic_energy,
//                    elastic_energy, max_unbalanced_force, mean_contact_force, contacts};
//                    last, timing/{loading, relaxation, output}/{wall, cpu}
//   /state/...       SimulationState: time, steps, x, v, w, F, T, plane_points, shell_centres
//                    (N, 3), pair_springs/{i, j, xi}, plane_springs/<w>/{i, xi},
//                    shell_springs/<w>/{i, xi}
//   /provenance/...  stage, scene, config, code_version, stamp (the stage's configuration stamp,
//                    profile/profile.hpp; none in files written before stamps were recorded)
//
// The results file: the points of one sweep (one stage, scene and seed) as columns, read by
// softpack-average and the checks of the archive (tests/stability/test_archive.cpp); one value
// per point unless said:
//   /delta_n, /hn [m], /alpha_deg, /ht [m]        the deformation (ht: tangential stage, pi Rs alpha / 180;
//                                                 sliding stage, the second body's move along +y, alpha 0)
//   /Fn, /Ft_parallel, /Ft_perpendicular [N]      the force on the second body along x, y, z
//   /force, /force_first, /force_between (N, 3)   [N], as in PointResult
//   /contacts, /steps, /relaxation/{steps, time, final_force_ratio, final_energy_ratio}
//   /overlap_max, /overlap_q99                    largest overlap / smaller radius at the end, and its
//                                                 99th percentile over the contacts (0.5.0 on)
//   /relaxation/checks/{point, time, force_ratio, energy_ratio}   one value per relaxation check
//   /seconds                                      wall-clock time of each point's loading and relaxation
//   /timing/{loading, relaxation, output}/{wall, cpu} [s]   where each point's time went (PointTiming)
//   /timing/reused                                1: the point was taken from its checkpoint
//   /provenance/...  stage, scene, config, code_version, packings, seed, seconds and cpu_seconds
//                    (wall-clock and CPU time of the stage's process), stamp, packing_sha256 (the
//                    identity of the seed's own packing, formats/packing_file.hpp; the last two
//                    absent in files written before stamps were recorded)
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/average.hpp"
#include "io/hdf5_file.hpp"
#include "formats/point_result.hpp"
#include "state/simulation_state.hpp"

namespace softpack {

struct PointProvenance {
  std::string stage;   ///< "normal", "tangential" or "sliding"
  std::string scene;   ///< "soft-solid" or "soft-soft"
  std::string config;  ///< the configuration the point depends on (YAML)
  std::string code_version;
  std::string stamp;  ///< the stage's configuration stamp ("": a file from before stamps)
  /// The engine's threads in the run that wrote the file (core/parallel.hpp; no result bit depends
  /// on them; 0: a file from before they were recorded).
  int threads = 0;
};


// --- The point file ---------------------------------------------------------------------------

/// Writes a point file atomically; r.timing.output is set to the time this took (up to the
/// timing datasets, which are written last).
void write_point_file(const std::string& path, PointResult& r, const SimulationState& state,
                      const PointProvenance& prov);

/// Reads a point file, with the simulation state when `with_state`. InputError, naming the file
/// and the dataset, when it is missing, unreadable, not a point file, or inconsistent (columns of
/// different lengths, values that are not finite, spring ids outside the state).
struct PointFile {
  PointResult result;
  SimulationState state;
  PointProvenance provenance;
};
PointFile read_point_file(const std::string& path, bool with_state);

/// "a sweep point file (a checkpoint of softpack-normal)" when `f` has the layout of one, else
/// "" (formats/file_kind.hpp).
std::string describe_point_file(const h5::File& f);

// --- The results file -------------------------------------------------------------------------

/// Every column of a results file: those the averages read (analysis/average.hpp), and the rest.
struct SweepResults : SweepColumns {
  std::vector<double> hn;
  std::vector<Vec3> force, force_first, force_between;
  std::vector<std::int64_t> contacts, steps, relax_steps;
  std::vector<double> relax_time;
  std::vector<double> final_force_ratio, final_energy_ratio;  ///< may be infinite (sim/residuals.hpp)
  std::vector<std::int64_t> check_point;                      ///< per relaxation check: its point
  std::vector<double> check_time, check_force_ratio, check_energy_ratio;
  std::vector<double> seconds;
  std::array<std::vector<double>, 3> phase_wall, phase_cpu;  ///< [s] per point: loading, relaxation, output
  std::vector<std::int64_t> reused;                          ///< per point: 1 = taken from its checkpoint
  bool has_timing = false;  ///< the file has the timings (release 0.4.0 on; else the four above are empty)
  std::vector<double> overlap_max;  ///< per point: largest overlap / smaller radius [-] (PointResult)
  std::vector<double> overlap_q99;  ///< per point: its 99th percentile over the contacts [-]
  bool has_overlap = false;         ///< the file has overlap_max (release 0.5.0 on; else it is empty)
  PointProvenance provenance;
  std::string packings;
  std::string packing_sha256;  ///< of the seed's own packing (the first); "" for the Hertz check and older files
  std::uint64_t seed = 0;
  double total_seconds = 0.0;      ///< wall-clock time of the whole stage
  double total_cpu_seconds = 0.0;  ///< CPU time of the stage's process
};

/// Writes the results of a whole sweep atomically: arrays over the points, the relaxation
/// checks flattened.
void write_sweep_results_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                              const std::string& packings, const std::string& packing_sha256, std::uint64_t seed,
                              const Elapsed& stage_time);

/// Reads a sweep results file. With `stage` or `scene` given, the file must have been made by
/// that stage (normal, tangential) for that scene. Files of releases before 0.4.0, which have no
/// timings, are read with has_timing false. InputError names the file and the dataset:
/// not a results file, another stage or scene, no points, columns of different lengths, values
/// that are not finite (but the ratios).
SweepResults read_sweep_results_file(const std::string& path, const std::string& stage = "", const std::string& scene = "");

/// "a normal sweep results file (softpack-normal)" when `f` has the layout of one, else ""
/// (formats/file_kind.hpp).
std::string describe_sweep_results_file(const h5::File& f);

}  // namespace softpack
