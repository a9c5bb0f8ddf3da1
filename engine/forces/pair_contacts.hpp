// Sphere-sphere contacts for the force loop (forces/contact_loop.hpp): body 1 is sphere i, body 2
// sphere j (i < j), the normal points from j to i.
//
//   d = xi - xj,  h = Ri + Rj - |d|,  n = d / |d|,
//   vc = vi - vj - (ai wi + aj wj) x n,   ai = Ri - h/2, aj = Rj - h/2 (rotation)
//
// With the synchronized history update the spring's frame is the half-step one: d - dt/2 (vi - vj)
// and its contact-point velocity.
//
// Sums. One thread adds each pair's terms to spheres i and j as it goes, in list order (sorted by
// (i, j)): sphere s receives its terms as body 2 (pairs (i', s), ascending i'), then as body 1.
// T threads make the same sums in the same order: thread t owns a share of the spheres and the
// pairs whose sphere i is its own; it first evaluates again, for their sphere j only, the pairs
// of lower shares that reach into its own (its ghosts, which come first in list order), then its
// own pairs in list order, adding to sphere j only when j is its own. A pair is computed by the
// same arithmetic on either thread, so both get the same bits; the spheres in spatial order
// (neighbor/spatial_order.hpp) keep the ghosts few.
//
// Memory. Beyond the caches (kPrefetchSpheres), a pair's constants, spring and sphere j are
// misses the hardware does not foresee (gathers, and spheres j far from i), so select() asks for
// them (a prefetch) as it tests the pairs, before gather() and add() read them: a sphere-step of
// the bench's 10^6-sphere lattice took about two thirds of the time and 10^4 spheres about as
// long (151-159 ns against 152-171), but the bench's 5 000-sphere packing 4-5 % more and a
// 3 000-sphere lattice 3 % more (both in the caches), hence the threshold.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <type_traits>

#include "core/parallel.hpp"
#include "forces/contact_loop.hpp"
#include "neighbor/contact_list.hpp"

namespace softpack {

/// The sphere arrays the force loops read and accumulate into (w and T only with rotation).
struct SphereArrays {
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;  ///< half-step velocities of velocity Verlet
  const Vec3* w = nullptr;
  const double* r = nullptr;
  Vec3* F = nullptr;
  Vec3* T = nullptr;
  double* body = nullptr;  ///< the per-body pass's state (a model with one: contact/contact_model.hpp BodyStateModel)
  BodyCaps* caps = nullptr;  ///< the per-body pass's caps (a model whose state is made from them: BodyCapsModel)
  SymmetricTensor* stress = nullptr;  ///< the stress pass's tensors (a law with a stress term: BodyStressModel)
};

template <Effects Fx>
struct PairContacts {
  PairList& list;
  SphereArrays s;
  std::size_t spheres = 0;  ///< the length of the sphere arrays
  /// One thread evaluates every pair in list order and makes every sum: F_i += F, F_j -= F as
  /// it goes. On T threads (a copy per thread and phase, part()): first each thread evaluates
  /// its ghosts for their sphere j only, then its own pairs, with the sums of sphere j only when
  /// j is its own (j < j_end): each sphere's terms come in list order either way, so the bits
  /// are the same.
  bool direct = true;
  const std::int32_t* index = nullptr;  ///< positions -> pairs; null: position k is pair k
  std::size_t begin = 0, end = 0;       ///< the positions evaluated
  std::size_t j_end = 0;                ///< sphere j's sums are made here when j < j_end
  bool ghost = false;                   ///< only sphere j's sums; nothing of the pair written
  bool prefetch = false;                ///< select() prefetches (a hint: no bit depends on it)

  /// From this many spheres on, select() prefetches.
  static constexpr std::size_t kPrefetchSpheres = 10000;
  /// How far ahead of the pairs it tests select() prefetches their spheres j's positions.
  static constexpr std::size_t kAhead = 4 * simd::kLanes;

  /// Before the evaluation: the springs' bookkeeping, the positions (a masked list offers only
  /// its live pairs and runs on one thread) and on threads the cut (PairShares).
  void prepare() {
    if constexpr (Fx.friction)
      if (list.spring_live.size() != list.size()) list.spring_live.assign(list.size(), 1);  // a fresh list: any may be
    index = list.masked ? list.live.data() : nullptr;
    begin = 0, end = list.masked ? list.live.size() : list.size(), j_end = spheres;
    direct = parallel::threads_for(spheres) == 1 || list.masked;
    prefetch = spheres >= kPrefetchSpheres;
    if (!direct) cut(static_cast<std::size_t>(parallel::threads_for(spheres)));
  }

  /// The copy that thread t of `parts` runs in `phase` (0: its ghosts, 1: its own pairs).
  PairContacts part(std::size_t phase, std::size_t t, std::size_t) const {
    PairContacts c = *this;
    const PairShares& sh = list.shares;
    c.j_end = sh.sphere[t + 1];
    c.ghost = phase == 0;
    if (c.ghost) c.index = sh.ghosts[t].data(), c.begin = 0, c.end = sh.ghosts[t].size();
    else c.index = nullptr, c.begin = sh.first[t], c.end = sh.first[t + 1];
    return c;
  }
  void finish() {}

  // Clearing a spring is `spring *= 0.0`, not setZero(): it keeps the sign of each zero, as it
  // always has for pairs (the archived results depend on these bits).
  static void clear(Vec3& spring) { spring *= 0.0; }

  /// The indices of the touching pairs among positions [begin, end), in list order
  /// (|d|^2 < (Ri + Rj)^2); with friction the springs of the others are cleared where
  /// PairList::spring_live says they may be loaded (not by a ghost: the pair's own thread does).
  /// `Gather`: the model whose gather() follows (its constants prefetched), or SelectOnly.
  template <class Gather, class Isa>
  [[gnu::always_inline]] std::size_t select(Isa isa, std::int32_t* closed, std::size_t from, std::size_t to) {
    using simd::Wide;
    if (index) return select_indexed(isa, closed, from, to);
    std::size_t n = 0, k = from;
    for (; k + simd::kLanes <= to; k += simd::kLanes) {
      const simd::Index i = simd::load(list.i.data() + k), j = simd::load(list.j.data() + k);
      if (prefetch) prefetch_group<Gather>(k, j);
      const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
      const Wide r_sum = simd::load(list.r_sum.data() + k);
      const simd::Mask touch = dot(d, d) < r_sum * r_sum;
      n += static_cast<std::size_t>(simd::compress(isa, closed + n, touch, simd::iota(static_cast<std::int32_t>(k))));
      if constexpr (Fx.friction) {
        const unsigned t = simd::bits(touch);
        for (unsigned opened = simd::nonzero_bytes(isa, list.spring_live.data() + k) & ~t & 0xffu; opened != 0; opened &= opened - 1)
          clear(list.spring[k + static_cast<std::size_t>(std::countr_zero(opened))]);
        simd::store_bits_as_bytes(isa, list.spring_live.data() + k, t);
      }
    }
    for (; k < to; ++k) touch_test(k, closed, n);
    return n;
  }

  /// The prefetches of select() at the group of pairs k, ..., k + kLanes - 1 (spheres j): the positions of
  /// the spheres j of the group kAhead further on, which select() itself reads; for a `Gather`
  /// model what gather() and add() read of this group: its constants, its springs (to be
  /// written), and sphere j's velocities, spins, radius, force and torque (sphere i's are read in
  /// order, which the hardware foresees).
  template <class Gather>
  [[gnu::always_inline]] void prefetch_group(std::size_t k, const simd::Index& j_group) const {
    if (k + kAhead + simd::kLanes <= list.size())
      for (std::size_t l = 0; l < simd::kLanes; ++l) __builtin_prefetch(s.x + list.j[k + kAhead + l]);
    if constexpr (!std::is_same_v<Gather, SelectOnly>) {
      prefetch_constants<Gather, Fx>(list.k, k);
      if constexpr (Fx.friction) {
        const char* const spring = reinterpret_cast<const char*>(list.spring.data() + k);
        constexpr std::size_t bytes = simd::kLanes * sizeof(Vec3);
        for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(spring + b, 1);
        __builtin_prefetch(spring + bytes - 1, 1);
      }
      for (std::size_t l = 0; l < simd::kLanes; ++l) {
        const std::int32_t j = j_group.v[l];
        __builtin_prefetch(s.v + j);
        if constexpr (Fx.rotation) __builtin_prefetch(s.w + j), __builtin_prefetch(s.r + j);
        if (static_cast<std::size_t>(j) >= j_end) continue;  // another thread's sphere: its lines stay in its cache
        __builtin_prefetch(s.F + j, 1);
        if constexpr (Fx.rotation) __builtin_prefetch(s.T + j, 1);
      }
    }
  }

  /// select() over the pairs `index` lists at positions [from, to) (a masked list's live pairs, a
  /// thread's ghosts), eight at a time.
  template <class Isa>
  [[gnu::always_inline]] std::size_t select_indexed(Isa isa, std::int32_t* closed, std::size_t from, std::size_t to) {
    using simd::Wide;
    std::size_t n = 0, m = from;
    for (; m + simd::kLanes <= to; m += simd::kLanes) {
      const simd::Index k = simd::load(index + m);
      const simd::Index i = simd::gather(isa, list.i.data(), k), j = simd::gather(isa, list.j.data(), k);
      const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
      const Wide r_sum = simd::gather(isa, list.r_sum.data(), k);
      const simd::Mask touch = dot(d, d) < r_sum * r_sum;
      n += static_cast<std::size_t>(simd::compress(isa, closed + n, touch, k));
      if constexpr (Fx.friction) {
        if (ghost) continue;
        const unsigned t = simd::bits(touch);
        for (int l = 0; l < simd::kLanes; ++l) {
          const auto kk = static_cast<std::size_t>(index[m + static_cast<std::size_t>(l)]);
          const bool touching = (t >> l) & 1u;
          if (list.spring_live[kk] && !touching) clear(list.spring[kk]);
          list.spring_live[kk] = touching ? 1 : 0;
        }
      }
    }
    for (; m < to; ++m) touch_test(static_cast<std::size_t>(index[m]), closed, n);
    return n;
  }

  /// The scalar form of the touch test and spring bookkeeping, for pair k.
  void touch_test(std::size_t k, std::int32_t* closed, std::size_t& n) {
    const bool t = (s.x[list.i[k]] - s.x[list.j[k]]).squaredNorm() < list.r_sum[k] * list.r_sum[k];
    closed[n] = static_cast<std::int32_t>(k);
    n += t ? 1 : 0;
    if constexpr (Fx.friction) {
      if (ghost) return;
      if (list.spring_live[k] && !t) clear(list.spring[k]);
      list.spring_live[k] = t ? 1 : 0;
    }
  }

  template <class Model, class Isa>
  [[gnu::always_inline]] auto gather(Isa isa, simd::Index k, double dt) const {
    using simd::Wide;
    ContactLanes<typename Model::template Constants<Wide>> c;
    c.i = simd::gather(isa, list.i.data(), k);
    c.j = simd::gather(isa, list.j.data(), k);
    const V3<Wide> d = gather_vec3(isa, s.x, c.i) - gather_vec3(isa, s.x, c.j);
    const V3<Wide> vij = gather_vec3(isa, s.v, c.i) - gather_vec3(isa, s.v, c.j);
    const Wide r_sum = simd::gather(isa, list.r_sum.data(), k);
    c.constants = gather_constants<Model, Fx>(isa, list.k, k);
    ContactGeometry<Wide>& g = c.geometry;
    const Wide dist = simd::sqrt(dot(d, d));
    g.n = d * (Wide(1.0) / dist);
    g.h = r_sum - dist;
    g.vc = vij;
    V3<Wide> wi{}, wj{};
    Wide ri{}, rj{};
    if constexpr (Fx.rotation) {
      wi = gather_vec3(isa, s.w, c.i), wj = gather_vec3(isa, s.w, c.j);
      ri = simd::gather(isa, s.r, c.i), rj = simd::gather(isa, s.r, c.j);
      c.ai = ri - Wide(0.5) * g.h;
      c.aj = rj - Wide(0.5) * g.h;
      g.vc = g.vc - cross(c.ai * wi + c.aj * wj, g.n);
    }
    if constexpr (Fx.friction) {
      c.spring = gather_vec3(isa, list.spring.data(), k);
      g.n_frame = g.n, g.vc_frame = g.vc;
      if constexpr (Fx.synchronized) {
        const V3<Wide> d_half = d - Wide(0.5 * dt) * vij;
        const Wide dist_half = simd::sqrt(dot(d_half, d_half));
        g.n_frame = d_half * (Wide(1.0) / dist_half);
        g.vc_frame = vij;
        if constexpr (Fx.rotation) {
          const Wide h_half = r_sum - dist_half;
          const Wide ai = ri - Wide(0.5) * h_half, aj = rj - Wide(0.5) * h_half;
          g.vc_frame = g.vc_frame - cross(ai * wi + aj * wj, g.n_frame);
        }
      }
    }
    return c;
  }

  /// The per-body pass: Model::Normal::body_term(h, normal constants) of pairs k added to the states of spheres i and j, for
  /// the first `live` lanes in order, as add() adds forces (the same spheres, the same order).
  template <class Model, class Isa>
  [[gnu::always_inline]] void add_body_terms(Isa isa, simd::Index k, int live) {
    using simd::Wide;
    const simd::Index i = simd::gather(isa, list.i.data(), k), j = simd::gather(isa, list.j.data(), k);
    const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
    const auto constants = gather_normal_constants<Model>(isa, list.k, k);
    const Wide h = simd::gather(isa, list.r_sum.data(), k) - simd::sqrt(dot(d, d));
    const Wide term = Model::Normal::body_term(h, constants);
    for (int m = 0; m < live; ++m) {
      if (!ghost) s.body[i.v[m]] += lane(term, m);
      if (static_cast<std::size_t>(j.v[m]) < j_end) s.body[j.v[m]] += lane(term, m);
    }
    if constexpr (BodyCapsModel<Model>)
      if (s.caps) {
        const Wide depth = Model::Normal::cap_depth_of(h, constants);
        for (int m = 0; m < live; ++m) {
          const Vec3 u = lane(d, m).normalized();  // from j towards i: sphere j's cap, sphere i's the other way
          if (!ghost && Model::Normal::keeps_cap(constants, m, 1)) s.caps[i.v[m]].u.push_back(-u), s.caps[i.v[m]].depth.push_back(lane(depth, m));
          if (static_cast<std::size_t>(j.v[m]) < j_end && Model::Normal::keeps_cap(constants, m, 2))
            s.caps[j.v[m]].u.push_back(u), s.caps[j.v[m]].depth.push_back(lane(depth, m));
        }
      }
  }

  /// The stress pass: each of pairs k's base force (evaluate() at the final states) times n ⊗ n
  /// added to the tensors of spheres i and j, for the first `live` lanes in order, as add_body_terms.
  template <class Model, class Isa>
  [[gnu::always_inline]] void add_stress_terms(Isa isa, const typename Model::Params& params, simd::Index k, int live) {
    using simd::Wide;
    const simd::Index i = simd::gather(isa, list.i.data(), k), j = simd::gather(isa, list.j.data(), k);
    const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
    const Wide dist = simd::sqrt(dot(d, d));
    ContactGeometry<Wide> g{};  // as gather() makes it
    g.n = d * (Wide(1.0) / dist), g.h = simd::gather(isa, list.r_sum.data(), k) - dist;
    g.body1 = simd::gather(isa, s.body, i), g.body2 = simd::gather(isa, s.body, j);
    const auto constants = gather_normal_constants<Model>(isa, list.k, k);
    for (int m = 0; m < live; ++m) {
      const double Fn = base_normal_force<Model>(params, constants, g, m);
      if (!ghost) add_stress(s.stress[i.v[m]], Fn, lane(g.n, m));
      if (static_cast<std::size_t>(j.v[m]) < j_end) add_stress(s.stress[j.v[m]], Fn, lane(g.n, m));
    }
  }
  /// Lane m's tensors and radii of spheres i and j, for a law with a stress term (none without the pass).
  template <class Lanes>
  [[gnu::always_inline]] void lane_stress(const Lanes& c, int m, ContactGeometry<double>& g) const {
    if (!s.stress) return;
    g.stress1 = {&s.stress[c.i.v[m]], s.r[c.i.v[m]]}, g.stress2 = {&s.stress[c.j.v[m]], s.r[c.j.v[m]]};
  }

  /// The bodies' states of the lanes' pairs, for a law that reads them.
  template <class Isa, class Lanes>
  [[gnu::always_inline]] void gather_body(Isa isa, Lanes& c) const {
    c.geometry.body1 = simd::gather(isa, s.body, c.i);
    c.geometry.body2 = simd::gather(isa, s.body, c.j);
  }

  /// F_i += F, F_j -= F, T_i -= ai n x Ft, T_j -= aj n x Ft for the first `live` lanes in order
  /// (sphere j's only when j < j_end; a ghost: sphere j's only), and the springs back.
  template <class Lanes>
  [[gnu::always_inline]] void add(const Lanes& c, const ContactForce<simd::Wide>& f, const std::int32_t* k, int live) {
    V3<simd::Wide> nxFt{};
    if constexpr (Fx.rotation) nxFt = cross(c.geometry.n, f.Ft);
    for (int m = 0; m < live; ++m) {
      const int i = c.i.v[m], j = c.j.v[m];
      const Vec3 F = lane(f.F, m);
      if (!ghost) {
        s.F[i] += F;
        if constexpr (Fx.rotation) s.T[i] -= lane(c.ai, m) * lane(nxFt, m);
        if constexpr (Fx.friction) list.spring[static_cast<std::size_t>(k[m])] = lane(c.spring, m);
      }
      if (static_cast<std::size_t>(j) < j_end) {
        s.F[j] -= F;
        if constexpr (Fx.rotation) s.T[j] -= lane(c.aj, m) * lane(nxFt, m);
      }
    }
  }

 private:
  /// The list's cut for `parts` threads (PairShares), made again when the list, the count or
  /// the spheres changed.
  void cut(std::size_t parts) {
    PairShares& sh = list.shares;
    if (sh.generation == list.generation && sh.parts == parts && sh.spheres == spheres) return;
    sh.sphere.resize(parts + 1), sh.first.resize(parts + 1);
    for (std::size_t t = 0; t <= parts; ++t) {
      sh.sphere[t] = parallel::share_begin(spheres, t, parts);
      sh.first[t] = static_cast<std::size_t>(std::lower_bound(list.i.begin(), list.i.end(), static_cast<std::int32_t>(sh.sphere[t])) - list.i.begin());
    }
    sh.ghosts.assign(parts, {});
    for (std::size_t t = 0, k = 0; t < parts; ++t)
      for (; k < sh.first[t + 1]; ++k) {  // pair k is thread t's: a ghost of the share of j if that is another
        const auto j = static_cast<std::size_t>(list.j[k]);
        if (j < sh.sphere[t + 1]) continue;
        const auto owner = static_cast<std::size_t>(std::upper_bound(sh.sphere.begin(), sh.sphere.end(), j) - sh.sphere.begin()) - 1;
        sh.ghosts[owner].push_back(static_cast<std::int32_t>(k));
      }
    sh.generation = list.generation, sh.parts = parts, sh.spheres = spheres;
  }
};

/// The pairs marked in `mask` (one byte per pair of the list) that touch, for the active set's
/// sums of frozen forces (sim/active_set.hpp): their forces times `sign` go to the arrays of
/// `s` (the frozen sums, not the spheres' F and T), and the springs stay as they are. Run with
/// dt = 0 on spheres at rest, it gives each contact's force as the force loop would give it on
/// the next step.
template <Effects Fx>
struct MaskedPairContacts : PairContacts<Fx> {
  const std::uint8_t* mask = nullptr;
  double sign = 1.0;

  void prepare() { this->begin = 0, this->end = this->list.size(); }
  void finish() {}

  template <class Gather, class Isa>
  std::size_t select(Isa, std::int32_t* closed, std::size_t begin, std::size_t end) const {
    const PairList& l = this->list;
    std::size_t n = 0;
    for (std::size_t k = begin; k < end; ++k) {
      if (!mask[k]) continue;
      closed[n] = static_cast<std::int32_t>(k);
      n += (this->s.x[l.i[k]] - this->s.x[l.j[k]]).squaredNorm() < l.r_sum[k] * l.r_sum[k] ? 1 : 0;
    }
    return n;
  }

  template <class Lanes>
  void add(const Lanes& c, const ContactForce<simd::Wide>& f, const std::int32_t*, int live) const {
    V3<simd::Wide> nxFt{};
    if constexpr (Fx.rotation) nxFt = cross(c.geometry.n, f.Ft);
    for (int m = 0; m < live; ++m) {
      const int i = c.i.v[m], j = c.j.v[m];
      const Vec3 F = sign * lane(f.F, m);
      this->s.F[i] += F;
      this->s.F[j] -= F;
      if constexpr (Fx.rotation) {
        const Vec3 t = sign * lane(nxFt, m);
        this->s.T[i] -= lane(c.ai, m) * t;
        this->s.T[j] -= lane(c.aj, m) * t;
      }
    }
  }
};

}  // namespace softpack
