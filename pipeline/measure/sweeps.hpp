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
// Each is a stage of the one sweep skeleton (measure/sweep.hpp), which reuses finished points,
// restores, relaxes, records, checkpoints every point (atomically) and reports progress: an
// interrupted sweep recomputes nothing finished and gives the same bits as an uninterrupted one.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "measure/sweep.hpp"

namespace softpack {

std::vector<PointResult> run_normal_sweep(const SweepContext& c);

/// `normal_dir` holds the normal stage's point files of the same scene and seed.
std::vector<PointResult> run_tangential_sweep(const SweepContext& c, const std::string& normal_dir);

/// `normal_dir` as for the tangential sweep.
std::vector<PointResult> run_sliding_sweep(const SweepContext& c, const std::string& normal_dir);

std::string normal_point_path(const std::string& dir, std::size_t k);
std::string sliding_point_path(const std::string& dir, std::size_t hn_index, std::size_t ht_index);
std::string tangential_point_path(const std::string& dir, std::size_t hn_index, std::size_t alpha_index);

}  // namespace softpack
