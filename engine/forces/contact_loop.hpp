// The force loop every kind of contact goes through, over fixed blocks of its list:
//
//   select   which listed contacts of the block touch (the springs of the others are cleared)
//   gather   their geometry, constants and springs into the lanes of simd::Wide values, eight at a time
//   law      contact_force() of contact/contact_law.hpp
//   add      each contact's force and torques added to its spheres, springs written back
//   finish   on threads, the kept terms summed into the wall's load, in list order
//
// A kind of contact (forces/pair_contacts.hpp; planes and shells: forces/wall_contacts.hpp) supplies
// them; `Isa` is the data-movement back end of simd/isa.hpp. On threads (core/parallel.hpp) each
// thread evaluates the contacts of its share of the spheres and makes their sums, each sphere's
// terms in list order as one thread makes them (forces/pair_contacts.hpp says how), so the
// result bits do not depend on the thread count, the lane count or the instruction set.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "contact/contact_law.hpp"
#include "core/parallel.hpp"
#include "simd/isa.hpp"

namespace softpack {

/// The lanes of one group of eight contacts, as gather() leaves them.
struct ContactLanes {
  ContactGeometry<simd::Wide> geometry;
  ContactConstants<simd::Wide> constants;
  V3<simd::Wide> spring;
  simd::Index i, j;      ///< the spheres (j: pairs only)
  simd::Wide ai, aj;     ///< branch lengths r - h/2 from the centres to the contact point
};

/// The value of lane m.
[[gnu::always_inline]] inline double lane(const simd::Wide& w, int m) { return w.v[m]; }
[[gnu::always_inline]] inline Vec3 lane(const V3<simd::Wide>& v, int m) { return {v.x.v[m], v.y.v[m], v.z.v[m]}; }

/// Contacts per block: what the scratch of closed indices holds.
inline constexpr std::size_t kBlock = 1024;

/// The contacts at positions [begin, end) of `contacts`: select, gather, law, add. `closed` has
/// room for end - begin + kLanes indices.
template <class NormalLaw, Effects Fx, class Isa, class Contacts>
[[gnu::always_inline]] inline void contact_block(Isa isa, Contacts& contacts, double dt, std::int32_t* closed, std::size_t begin,
                                                 std::size_t end) {
  const std::size_t touching = contacts.select(isa, closed, begin, end);
  if (touching == 0) return;
  // The last group is filled up with copies of the last contact; add() ignores them.
  std::fill(closed + touching, closed + touching + simd::kLanes, closed[touching - 1]);
  for (std::size_t m = 0; m < touching; m += simd::kLanes) {
    const simd::Index k = simd::load(closed + m);
    ContactLanes c = contacts.gather(isa, k, dt);
    if constexpr (BodyStateLaw<NormalLaw>) contacts.gather_body(isa, c);
    const ContactForce<simd::Wide> f = contact_force<NormalLaw, Fx>(c.geometry, c.constants, c.spring, dt);
    contacts.add(c, f, closed + m, static_cast<int>(std::min<std::size_t>(simd::kLanes, touching - m)));
  }
}

/// The per-body pass over positions [begin, end) of `contacts`, for a law with a body state
/// (contact/contact_law.hpp BodyStateLaw): select, then each closed contact's Law::body_term
/// added to its spheres' states (add_body_terms). Its select() does what the force pass's will
/// do again: the same springs cleared, the same flags.
template <class NormalLaw, class Isa, class Contacts>
[[gnu::always_inline]] inline void body_block(Isa isa, Contacts& contacts, std::int32_t* closed, std::size_t begin, std::size_t end) {
  const std::size_t touching = contacts.select(isa, closed, begin, end);
  if (touching == 0) return;
  std::fill(closed + touching, closed + touching + simd::kLanes, closed[touching - 1]);
  for (std::size_t m = 0; m < touching; m += simd::kLanes)
    contacts.template add_body_terms<NormalLaw>(isa, simd::load(closed + m), static_cast<int>(std::min<std::size_t>(simd::kLanes, touching - m)));
}

/// What the blocks of one thread need: kBlock closed indices and a group of lanes.
inline constexpr std::size_t kScratch = kBlock + simd::kLanes;

/// block(c, scratch, begin, end) over blocks of at most kBlock of c's positions [c.begin, c.end),
/// in order.
template <class Contacts, class Block>
void run_blocks(Contacts& c, std::int32_t* scratch, Block& block) {
  for (std::size_t b = c.begin; b < c.end; b += kBlock) block(c, scratch, b, std::min(c.end, b + kBlock));
}

/// Every contact of one kind on the calling thread: prepare(), its blocks in list order (add()
/// sums as it goes), finish(). The loops of a world on threads: forces/compile_loops.hpp.
template <class Contacts, class Block>
void contact_loop(Contacts& contacts, std::vector<std::int32_t>& closed, Block&& block) {
  contacts.prepare();
  closed.resize(kScratch);
  run_blocks(contacts, closed.data(), block);
  contacts.finish();
}

/// The constants the declared effects read, gathered for contacts k.
template <Effects Fx, class Isa, class Arrays>
[[gnu::always_inline]] inline ContactConstants<simd::Wide> gather_constants(Isa isa, const Arrays& a, simd::Index k) {
  ContactConstants<simd::Wide> c{0.0, 0.0, 0.0, 0.0, 0.0};
  c.kn = simd::gather(isa, a.kn.data(), k);
  if constexpr (Fx.damping) c.gamma0 = simd::gather(isa, a.gamma0.data(), k);
  if constexpr (Fx.friction) c.kt0 = simd::gather(isa, a.kt0.data(), k), c.mu = simd::gather(isa, a.mu.data(), k);
  if constexpr (Fx.friction && Fx.damping) c.gamma_t0 = simd::gather(isa, a.gamma_t0.data(), k);
  return c;
}

/// Component c of the vectors base[idx] (Vec3 is three doubles: component c of vector i is
/// double 3i + c).
template <class Isa>
[[gnu::always_inline]] inline V3<simd::Wide> gather_vec3(Isa isa, const Vec3* base, simd::Index idx) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  const double* const d = base->data();
  const simd::Index i3 = 3 * idx;
  return {simd::gather(isa, d, i3), simd::gather(isa, d + 1, i3), simd::gather(isa, d + 2, i3)};
}

}  // namespace softpack
