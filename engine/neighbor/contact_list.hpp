// Verlet lists of potential contacts with their tangential history, one array per field
// (structure of arrays): the force loops stream the indices and gather the rest by contact.
//
// Pairs (i < j) whose gap is below the skin are listed at each rebuild, sorted by (i, j), with
// the contact constants precomputed. When the friction effect is on, each entry carries its
// tangential spring xi; a rebuild carries constants and springs of surviving pairs over by a
// sorted merge, O(N). A pair whose gap opens keeps its entry until the next rebuild but its spring
// is cleared the moment the contact opens (forces/contact_loop.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace softpack {

/// The per-contact constants of a list's contacts, one array per constant (the contact model's,
/// contact/contact_model.hpp each_constant, in its order; forces/contact_loop.hpp reads and writes them).
struct ConstantArrays {
  std::vector<std::vector<double>> field;

  std::size_t size() const { return field.empty() ? 0 : field[0].size(); }
  /// `fields` arrays of n contacts each.
  void resize(std::size_t fields, std::size_t n) {
    field.resize(fields);
    for (auto& f : field) f.resize(n);
  }
  /// Contact a of `from` becomes contact b of this.
  void copy(const ConstantArrays& from, std::size_t a, std::size_t b) {
    for (std::size_t f = 0; f < field.size(); ++f) field[f][b] = from.field[f][a];
  }
};

/// What the force loop leaves for each contact of a wall's list on threads (forces/wall_contacts.hpp),
/// for the wall's load to be summed afterwards in list order: scratch, written anew at every step.
struct WallResults {
  std::vector<std::uint8_t> touched;  ///< 1: evaluated and closed at this step
  std::vector<Vec3> F;                ///< the force on the sphere
  std::vector<Vec3> torque;           ///< the wall's torque
  void resize(std::size_t n) { touched.resize(n), F.resize(n), torque.resize(n); }
};

/// A pair list cut for T threads (forces/pair_contacts.hpp): thread t evaluates the pairs whose
/// sphere i is in its share of the spheres, [sphere[t], sphere[t + 1]) (core/parallel.hpp), list
/// positions [first[t], first[t + 1]), and makes the sums of its spheres. Its `ghosts` are the
/// pairs of lower shares whose sphere j is its own, ascending: it evaluates them again, before
/// its own, for sphere j's sum. Made for one generation of the list, one count and one size.
struct PairShares {
  std::vector<std::size_t> sphere, first;
  std::vector<std::vector<std::int32_t>> ghosts;
  std::uint64_t generation = ~std::uint64_t{0};
  std::size_t parts = 0, spheres = 0;
};

/// A pair found by a neighbour search.
struct PairEntry {
  std::int32_t i = 0, j = 0;
  double r_sum = 0.0;  ///< Ri + Rj
};

struct PairList {
  std::vector<std::int32_t> i, j;  ///< the spheres, i < j, sorted by (i, j)
  std::vector<double> r_sum;       ///< Ri + Rj: what the every-step overlap test reads
  ConstantArrays k;                ///< the model's constants, read for touching pairs only
  std::vector<Vec3> spring;        ///< tangential spring per pair; empty without friction
  /// 1 where the spring may be non-zero (the pair touched at the last force evaluation).
  /// Kept by the force loop (forces/pair_contacts.hpp); empty means every spring may be.
  std::vector<std::uint8_t> spring_live;
  /// With an active set (sim/active_set.hpp), `masked`: the force loop evaluates only the pairs
  /// listed in `live` (ascending: those with an awake sphere); the forces of the others, two
  /// sleeping spheres, are kept by the active set. A rebuild unmasks the list.
  bool masked = false;
  std::vector<std::int32_t> live;
  PairShares shares;  ///< the force loop's cut for threads
  /// Counts the replacements: the force loop's cut for threads (forces/pair_contacts.hpp) is
  /// made again when it changes.
  std::uint64_t generation = 0;

  std::size_t size() const { return i.size(); }
  /// Replaces the list by `fresh` (sorted by (i, j)); pairs already listed keep their
  /// constants and spring. Returns the indices of the new pairs, whose constants are unset.
  std::vector<std::size_t> replace(const std::vector<PairEntry>& fresh, bool keep_springs);
};

/// Candidate contacts of one wall (plane or shell): sphere indices, sorted, with constants.
struct WallList {
  std::vector<std::int32_t> i;
  ConstantArrays k;
  std::vector<Vec3> spring;  ///< empty without friction
  WallResults results;       ///< the force loop's scratch

  std::size_t size() const { return i.size(); }
  /// As PairList::replace, keyed by the sphere.
  std::vector<std::size_t> replace(const std::vector<std::int32_t>& fresh, bool keep_springs);
};

/// One sphere's closed contacts' caps of the last per-body pass (contact/contact_model.hpp
/// BodyCapsModel): the direction from its centre towards each contact, and the cap's depth.
struct BodyCaps {
  std::vector<Vec3> u;
  std::vector<double> depth;
};

/// The lists of one contact model (a family): sphere pairs, and the candidates of each plane and
/// each shell, whose contacts that model evaluates.
struct ContactFamily {
  PairList pairs;
  std::vector<WallList> planes, shells;
  /// Each sphere's state from the per-body pass of the last force evaluation, when the model
  /// declares one (contact/contact_model.hpp BodyStateModel); empty otherwise.
  std::vector<double> body_state;
  /// Each sphere's caps, when the model's state is made from them (BodyCapsModel); empty otherwise.
  std::vector<BodyCaps> body_caps;
  /// Each sphere's stress tensor from the stress pass of the last force evaluation, Σ Fn n ⊗ n over
  /// its closed contacts [N], when the model's law has a stress term (BodyStressModel); empty otherwise.
  std::vector<SymmetricTensor> body_stress;
};

/// Every list of a scene, one family per contact model: family 0 the scene's model
/// (effects.normal), family 1 the soft-particle model when the scene has soft-particles. A pair
/// belongs to the higher family of its two spheres (Particles::family), a wall contact to its
/// sphere's.
struct ContactLists {
  std::vector<ContactFamily> family;
};

}  // namespace softpack
