// Verlet lists of potential contacts with their tangential history.
//
// Pairs (i < j) whose gap is below the skin are listed at each rebuild, sorted by (i, j), with
// the contact constants precomputed. When the friction effect is on, each entry carries its
// tangential spring xi; a rebuild carries constants and springs of surviving pairs over by a
// sorted merge, O(N). A pair whose gap opens keeps its entry until the next rebuild but its spring
// is cleared the moment the contact opens.
#pragma once
#include <cstdint>
#include <vector>

#include "contact/contact_force.hpp"
#include "core/types.hpp"

namespace softpack {

/// What the every-step overlap test reads, kept small: the list is streamed each step.
struct PairEntry {
  int i = 0, j = 0;
  double r_sum = 0.0;  ///< Ri + Rj
};

struct PairList {
  std::vector<PairEntry> pairs;
  std::vector<ContactCoefficients> k;  ///< constants per pair, read for touching pairs only
  std::vector<Vec3> spring;            ///< tangential spring per pair; empty without friction
  /// 1 where the spring may be non-zero (the pair touched at the last force evaluation).
  /// Kept by the force loop (sim/touching_pairs.hpp); empty means every spring may be.
  std::vector<std::uint8_t> spring_live;

  /// Replaces the list by `fresh` (sorted by (i, j)); pairs already listed keep their
  /// constants and spring. Returns the indices of the new pairs, whose constants are unset.
  std::vector<std::size_t> replace(std::vector<PairEntry>&& fresh, bool keep_springs);
};

/// Candidate contacts of one wall (plane or shell): sphere indices, sorted, with constants.
struct WallEntry {
  int i = 0;
  ContactCoefficients k;
};

struct WallList {
  std::vector<WallEntry> entries;
  std::vector<Vec3> spring;

  /// As PairList::replace, keyed by the sphere.
  std::vector<std::size_t> replace(std::vector<WallEntry>&& fresh, bool keep_springs);
};

}  // namespace softpack
