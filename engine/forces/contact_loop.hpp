// The force loop every kind of contact goes through, over fixed blocks of its list:
//
//   select   which listed contacts of the block touch (the springs of the others are cleared)
//   gather   their geometry, constants and springs into the lanes of simd::Wide values, eight at a time
//   law      the contact model's force() (contact/contact_model.hpp), lane by lane for a model
//            written for one contact at a time
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
#include <array>
#include <cstdint>
#include <vector>

#include "contact/contact_model.hpp"
#include "core/parallel.hpp"
#include "neighbor/contact_list.hpp"
#include "simd/isa.hpp"

namespace softpack {

/// The lanes of one group of eight contacts, as gather() leaves them, with the constants of
/// their model (Model::Constants<simd::Wide>).
template <class Constants>
struct ContactLanes {
  ContactGeometry<simd::Wide> geometry;
  Constants constants;
  V3<simd::Wide> spring;
  simd::Index i, j;      ///< the spheres (j: pairs only)
  simd::Wide ai, aj;     ///< branch lengths r - h/2 from the centres to the contact point
};

/// The value of lane m.
[[gnu::always_inline]] inline double lane(const simd::Wide& w, int m) { return w.v[m]; }
[[gnu::always_inline]] inline Vec3 lane(const V3<simd::Wide>& v, int m) { return {v.x.v[m], v.y.v[m], v.z.v[m]}; }
[[gnu::always_inline]] inline void set_lane(V3<simd::Wide>& v, int m, const V3<double>& x) { v.x.v[m] = x.x, v.y.v[m] = x.y, v.z.v[m] = x.z; }

/// Contacts per block: what the scratch of closed indices holds.
inline constexpr std::size_t kBlock = 1024;

/// The force of each lane of `c`: eight at once, or for a model written for one contact at a
/// time (ScalarOnlyModel) one lane after the other (the live ones; the others are copies).
template <class Model, Effects Fx, class Lanes, class Contacts>
[[gnu::always_inline]] inline ContactForce<simd::Wide> lanes_force(const typename Model::Params& params, Lanes& c, double dt, int live,
                                                                  const Contacts& contacts) {
  if constexpr (!ScalarOnlyModel<Model>) {
    return Model::template force<Fx>(params, c.geometry, c.constants, c.spring, dt);
  } else {
    ContactForce<simd::Wide> f{};
    for (int m = 0; m < live; ++m) {
      const auto at = [m](const V3<simd::Wide>& w) { return v3(lane(w, m)); };
      const ContactGeometry<simd::Wide>& G = c.geometry;
      ContactGeometry<double> g{at(G.n), G.h.v[m], at(G.vc), {}, {}, 0.0, 0.0};
      if constexpr (Fx.friction) g.n_frame = at(G.n_frame), g.vc_frame = at(G.vc_frame);
      if constexpr (BodyStateModel<Model>) g.body1 = G.body1.v[m], g.body2 = G.body2.v[m];
      if constexpr (BodyStressModel<Model>) contacts.lane_stress(c, m, g);
      typename Model::template Constants<double> k{};
      std::array<double*, Model::constant_count()> field{};
      std::size_t n = 0;
      Model::each_constant(k, [&](double& x, Need) { field[n++] = &x; });
      n = 0;
      Model::each_constant(c.constants, [&](const simd::Wide& x, Need) { *field[n++] = x.v[m]; });
      V3<double> xi = Fx.friction ? at(c.spring) : V3<double>{0.0, 0.0, 0.0};
      const ContactForce<double> one = Model::template force<Fx>(params, g, k, xi, dt);
      set_lane(f.F, m, one.F), set_lane(f.Ft, m, one.Ft), f.Fn.v[m] = one.Fn;
      if constexpr (Fx.friction) set_lane(c.spring, m, xi);
    }
    return f;
  }
}

/// What select() is told comes after it when no gather() does (the per-body pass): it then
/// prefetches nothing for a gather (forces/pair_contacts.hpp).
struct SelectOnly {};

/// The contacts at positions [begin, end) of `contacts`: select, gather, law, add. `closed` has
/// room for end - begin + kLanes indices.
template <class Model, Effects Fx, class Isa, class Contacts>
[[gnu::always_inline]] inline void contact_block(Isa isa, Contacts& contacts, const typename Model::Params& params, double dt,
                                                 std::int32_t* closed, std::size_t begin, std::size_t end) {
  const std::size_t touching = contacts.template select<Model>(isa, closed, begin, end);
  if (touching == 0) return;
  // The last group is filled up with copies of the last contact; add() ignores them.
  std::fill(closed + touching, closed + touching + simd::kLanes, closed[touching - 1]);
  for (std::size_t m = 0; m < touching; m += simd::kLanes) {
    const simd::Index k = simd::load(closed + m);
    const int live = static_cast<int>(std::min<std::size_t>(simd::kLanes, touching - m));
    auto c = contacts.template gather<Model>(isa, k, dt);
    if constexpr (BodyStateModel<Model>) contacts.gather_body(isa, c);
    const ContactForce<simd::Wide> f = lanes_force<Model, Fx>(params, c, dt, live, contacts);
    contacts.add(c, f, closed + m, live);
  }
}

/// The per-body pass over positions [begin, end) of `contacts`, for a model with a body state
/// (contact/contact_model.hpp BodyStateModel): select, then each closed contact's body_term
/// added to its spheres' states (add_body_terms). Its select() does what the force pass's will
/// do again: the same springs cleared, the same flags.
template <class Model, class Isa, class Contacts>
[[gnu::always_inline]] inline void body_block(Isa isa, Contacts& contacts, std::int32_t* closed, std::size_t begin, std::size_t end) {
  const std::size_t touching = contacts.template select<SelectOnly>(isa, closed, begin, end);
  if (touching == 0) return;
  std::fill(closed + touching, closed + touching + simd::kLanes, closed[touching - 1]);
  for (std::size_t m = 0; m < touching; m += simd::kLanes)
    contacts.template add_body_terms<Model>(isa, simd::load(closed + m), static_cast<int>(std::min<std::size_t>(simd::kLanes, touching - m)));
}

/// The stress pass over positions [begin, end) of `contacts`, for a model whose law has a stress
/// term (contact/contact_model.hpp BodyStressModel), once the body states are final: select, then
/// each closed contact's base force times n ⊗ n added to its spheres' tensors (add_stress_terms),
/// in the order of the per-body pass.
template <class Model, class Isa, class Contacts>
[[gnu::always_inline]] inline void stress_block(Isa isa, Contacts& contacts, const typename Model::Params& params, std::int32_t* closed,
                                                std::size_t begin, std::size_t end) {
  const std::size_t touching = contacts.template select<SelectOnly>(isa, closed, begin, end);
  if (touching == 0) return;
  std::fill(closed + touching, closed + touching + simd::kLanes, closed[touching - 1]);
  for (std::size_t m = 0; m < touching; m += simd::kLanes)
    contacts.template add_stress_terms<Model>(isa, params, simd::load(closed + m),
                                              static_cast<int>(std::min<std::size_t>(simd::kLanes, touching - m)));
}

/// The normal law's force of lane m of `G` with the normal constants `c`, without the bodies'
/// tensors (the base force the stress pass sums): the force pass's evaluate(), the same bits.
template <class Model>
[[gnu::always_inline]] inline double base_normal_force(const typename Model::Params& params,
                                                       const typename Model::Normal::template Constants<simd::Wide>& c,
                                                       const ContactGeometry<simd::Wide>& G, int m) {
  ContactGeometry<double> g{};
  g.n = v3(lane(G.n, m)), g.h = G.h.v[m], g.body1 = G.body1.v[m], g.body2 = G.body2.v[m];
  typename Model::Normal::template Constants<double> k{};
  std::array<double*, Model::constant_count()> field{};
  std::size_t n = 0;
  Model::Normal::each_constant(k, [&](double& x, Need) { field[n++] = &x; });
  n = 0;
  Model::Normal::each_constant(c, [&](const simd::Wide& x, Need) { *field[n++] = x.v[m]; });
  return Model::Normal::evaluate(params.normal, k, g).Fn;
}

/// S += Fn n ⊗ n.
[[gnu::always_inline]] inline void add_stress(SymmetricTensor& S, double Fn, const Vec3& n) {
  S[0] += Fn * n.x() * n.x(), S[1] += Fn * n.y() * n.y(), S[2] += Fn * n.z() * n.z();
  S[3] += Fn * n.x() * n.y(), S[4] += Fn * n.x() * n.z(), S[5] += Fn * n.y() * n.z();
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

/// The constants of `Model` the declared effects read (contact/contact_model.hpp Need), gathered
/// for contacts k from their arrays; the others stay 0.
template <class Model, Effects Fx, class Isa>
[[gnu::always_inline]] inline typename Model::template Constants<simd::Wide> gather_constants(Isa isa, const ConstantArrays& a,
                                                                                              simd::Index k) {
  typename Model::template Constants<simd::Wide> c{};
  std::size_t field = 0;
  Model::each_constant(c, [&](simd::Wide& x, Need need) {
    if (needed<Fx>(need)) x = simd::gather(isa, a.field[field].data(), k);
    else x = simd::Wide(0.0);
    ++field;
  });
  return c;
}

/// Every constant of `Model`'s normal sub-law for contacts k (the per-body pass's body_term reads them).
template <class Model, class Isa>
[[gnu::always_inline]] inline typename Model::Normal::template Constants<simd::Wide> gather_normal_constants(Isa isa, const ConstantArrays& a,
                                                                                                           simd::Index k) {
  typename Model::Normal::template Constants<simd::Wide> c{};
  std::size_t field = 0;
  Model::Normal::each_constant(c, [&](simd::Wide& x, Need) { x = simd::gather(isa, a.field[field++].data(), k); });
  return c;
}

/// Asks the memory for the constants of `Model` the declared effects read, of the contacts at
/// k, ..., k + kLanes - 1 (one cache line of each array, or the start of a second): a hint, no
/// result depends on it.
template <class Model, Effects Fx>
[[gnu::always_inline]] inline void prefetch_constants(const ConstantArrays& a, std::size_t k) {
  typename Model::template Constants<double> c{};
  std::size_t field = 0;
  Model::each_constant(c, [&](double&, Need need) {
    if (needed<Fx>(need)) __builtin_prefetch(a.field[field].data() + k);
    ++field;
  });
}

/// The constants of `Model` of contact k, and their setting.
template <class Model>
typename Model::template Constants<double> constants_at(const ConstantArrays& a, std::size_t k) {
  typename Model::template Constants<double> c{};
  std::size_t field = 0;
  Model::each_constant(c, [&](double& x, Need) { x = a.field[field++][k]; });
  return c;
}
template <class Model>
void set_constants_at(ConstantArrays& a, std::size_t k, const typename Model::template Constants<double>& c) {
  auto copy = c;
  std::size_t field = 0;
  Model::each_constant(copy, [&](double& x, Need) { a.field[field++][k] = x; });
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
