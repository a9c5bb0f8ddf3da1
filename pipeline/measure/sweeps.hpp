// The normal and tangential sweeps of paper §4, point by point, each point checkpointed.
//
// Normal: the second body approaches along -x at `normal.speed` to each hn = delta_n Rs of the
// grid, in increasing order, from the previous point (incremental) or from the undeformed
// state (direct); then the scene relaxes with the profile's protocol and the force on the
// second body is recorded with the state reached.
//
// Tangential: from the saved normal state at each of `tangential.delta_n`, the first
// soft-particle (its spheres and its shell) is turned rigidly about +z through its centre by
// each alpha of the grid at `tangential.rate`, then released (or held) and relaxed; ht =
// pi Rs alpha / 180 and the force on the second body is split into parallel (+y) and
// perpendicular (z) parts.
//
// Sliding (issue 16): from the saved normal state at each of `sliding.delta_n`, the second body
// is moved parallel to the contact to each ht = ht_over_Rs Rs of the grid in turn, each point
// from the previous one, at `sliding.speed`, then released and relaxed; the grains are dragged
// until the contact slides. The wall is moved along +y; the second soft-particle (its shell and
// spheres, rigidly) orbits the first's centre about +z by the angle ht / Rs, recorded as
// alpha_deg: the contact keeps its depth hn and its normal turns by that angle.
//
// Every point is written to its own file in the checkpoint directory as soon as it is done
// (atomically). A sweep started again reuses every point whose file holds the same
// configuration and continues from the last state: an interrupted sweep recomputes nothing
// finished and gives the same bits as an uninterrupted one.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "formats/sweep_file.hpp"
#include "measure/contact_scenes.hpp"
#include "measure/settings.hpp"

namespace softpack {

struct SweepContext {
  ContactSetup setup;
  MeasurementSettings settings;
  std::string config;          ///< configuration text recorded with (and checked against) each point
  std::string stamp;           ///< the stage's configuration stamp, recorded with each point
  /// Tangential and sliding sweeps: the configuration the normal states they start from must
  /// record (the normal stage's `config`); a state filed under another point, stage, seed or
  /// configuration is refused.
  std::string normal_config;
  std::string checkpoint_dir;  ///< point files of this stage
  std::string code_version;
  /// Progress: the stage of the point ("normal", "tangential"), its index, the number of points,
  /// the point just finished (or reused).
  std::function<void(const std::string& stage, std::size_t, std::size_t, const PointResult&, bool reused)> progress;
  std::size_t stop_after = 0;  ///< for tests: stop after computing this many new points (0: never)
};

std::vector<PointResult> run_normal_sweep(const SweepContext& c);

/// `normal_dir` holds the normal stage's point files of the same scene and seed.
std::vector<PointResult> run_tangential_sweep(const SweepContext& c, const std::string& normal_dir);

/// `normal_dir` as for the tangential sweep.
std::vector<PointResult> run_sliding_sweep(const SweepContext& c, const std::string& normal_dir);

std::string normal_point_path(const std::string& dir, std::size_t k);
std::string sliding_point_path(const std::string& dir, std::size_t hn_index, std::size_t ht_index);
std::string tangential_point_path(const std::string& dir, std::size_t hn_index, std::size_t alpha_index);

}  // namespace softpack
