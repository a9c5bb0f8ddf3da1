// Contact detection of a world: the hierarchical grid (neighbor/hierarchical_grid.hpp), the
// Verlet lists with their springs (neighbor/contact_list.hpp), and when to rebuild them.
//
// A pair's gap shrinks by at most the sum of both spheres' displacements since the last build,
// at most the two largest of them; a wall gap by the sphere's plus the wall's. The lists are
// rebuilt before either can exceed the skin, so no contact is ever missed. The phases that
// move spheres (kick_drift, the drivers) report each displacement with moved().
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "neighbor/contact_list.hpp"
#include "neighbor/hierarchical_grid.hpp"
#include "scene/scene_def.hpp"
#include "state/world.hpp"

namespace softpack {

/// The entries a rebuild added to each list of one family (their constants are not set yet).
struct NewContacts {
  std::vector<std::size_t> pairs;
  std::vector<std::vector<std::size_t>> planes, shells;
};

class Neighbours {
 public:
  /// `constants[f]`: the number of per-contact constants of family f's contact model (none: the
  /// scene has no contact law and nothing is listed); `friction`: the lists carry springs.
  /// `shell_members[k]`: the spheres shell k confines. A contact goes to its spheres' family
  /// (neighbor/contact_list.hpp ContactLists).
  Neighbours(const NeighborDef& def, const World& world, const std::vector<std::size_t>& constants, bool friction,
             std::vector<std::vector<int>> shell_members);

  ContactLists& lists() { return lists_; }
  const ContactLists& lists() const { return lists_; }
  double skin() const { return skin_; }  ///< [m]
  long rebuilds() const { return rebuilds_; }

  /// Where the spheres were at the last build (kick_drift and the drivers measure displacements from it).
  const std::vector<Vec3>& x_at_build() const { return x_at_build_; }
  /// The two largest squared displacements since the last build (of different spheres).
  struct LargestTwo {
    double first = 0.0, second = 0.0;
    void add(double d2) {
      if (d2 > first) second = first, first = d2;
      else if (d2 > second) second = d2;
    }
  };
  /// Starts a new step's record (kick_drift calls it) and adds to it (kick_drift, the drivers).
  LargestTwo& moved() { return moved_; }
  void set_moved(const LargestTwo& m) { moved_ = m; }

  /// Whether the skin is used up (after the first rebuild, which the simulation makes at once).
  bool need_rebuild(const World& world) const;
  /// Rebuilds the lists at the world's positions; surviving entries keep their constants and
  /// springs. Returns each family's new entries. std::invalid_argument from the grid when
  /// positions are unusable.
  std::vector<NewContacts> rebuild(const World& world);

 private:
  HierarchicalGrid grid_;
  NeighborDef def_;
  double skin_ = 0.0;
  bool friction_ = false, listing_ = false;
  std::vector<std::vector<int>> shell_members_;
  ContactLists lists_;
  std::vector<Vec3> x_at_build_, plane_at_build_, shell_at_build_;
  LargestTwo moved_;
  long rebuilds_ = 0;
  std::vector<std::vector<std::pair<int, int>>> found_;  ///< scratch: pairs found, per part of the search
  std::vector<std::size_t> first_;                       ///< scratch: counting sort
  std::vector<std::vector<std::vector<std::int32_t>>> near_;  ///< scratch: [share][family] spheres near a plane
};

}  // namespace softpack
