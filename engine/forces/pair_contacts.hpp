// Sphere-sphere contacts for the force loop (forces/contact_loop.hpp): body 1 is sphere i, body 2
// sphere j (i < j), the normal points from j to i.
//
//   d = xi - xj,  h = Ri + Rj - |d|,  n = d / |d|,
//   vc = vi - vj - (ai wi + aj wj) x n,   ai = Ri - h/2, aj = Rj - h/2 (rotation)
//
// With the synchronized history update the spring's frame is the half-step one: d - dt/2 (vi - vj)
// and its contact-point velocity.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>

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
};

template <Effects Fx>
struct PairContacts {
  PairList& list;
  SphereArrays s;
  std::size_t spheres = 0;  ///< the length of the sphere arrays
  /// One thread runs the blocks in order (parallel::serial): add() sums into the spheres as it
  /// goes, in list order, and finish() has nothing left to do; the same bits either way.
  bool direct = true;

  static constexpr bool kThreaded = true;

  /// What the blocks cut: the list, or the live pairs of a masked one.
  std::size_t positions() const { return list.masked ? list.live.size() : list.size(); }

  /// Before the blocks: on threads, the scratch sized and a masked list's pairs that are not live
  /// marked open (one thread keeps no results).
  void prepare() {
    if constexpr (Fx.friction)
      if (list.spring_live.size() != list.size()) list.spring_live.assign(list.size(), 1);  // a fresh list: any may be
    direct = parallel::serial((positions() + kBlock - 1) / kBlock);
    if (direct) return;
    list.results.resize(list.size());
    if (list.masked) std::fill(list.results.touched.begin(), list.results.touched.end(), std::uint8_t{0});
  }

  // Clearing a spring is `spring *= 0.0`, not setZero(): it keeps the sign of each zero, as it
  // always has for pairs (the archived results depend on these bits).
  static void clear(Vec3& spring) { spring *= 0.0; }

  /// The indices of the touching pairs among positions [begin, end), in list order
  /// (|d|^2 < (Ri + Rj)^2), each pair's `touched` set on threads; with friction the springs of the others
  /// are cleared where PairList::spring_live says they may be loaded. A masked list offers only
  /// its live pairs.
  template <class Isa>
  [[gnu::always_inline]] std::size_t select(Isa isa, std::int32_t* closed, std::size_t begin, std::size_t end) {
    using simd::Wide;
    if (list.masked) return select_live(isa, closed, begin, end);
    std::size_t n = 0, k = begin;
    for (; k + simd::kLanes <= end; k += simd::kLanes) {
      const simd::Index i = simd::load(list.i.data() + k), j = simd::load(list.j.data() + k);
      const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
      const Wide r_sum = simd::load(list.r_sum.data() + k);
      const simd::Mask touch = dot(d, d) < r_sum * r_sum;
      n += static_cast<std::size_t>(simd::compress(isa, closed + n, touch, simd::iota(static_cast<std::int32_t>(k))));
      const unsigned t = simd::bits(touch);
      if (!direct) simd::store_bits_as_bytes(isa, list.results.touched.data() + k, t);
      if constexpr (Fx.friction) {
        for (unsigned opened = simd::nonzero_bytes(isa, list.spring_live.data() + k) & ~t & 0xffu; opened != 0; opened &= opened - 1)
          clear(list.spring[k + static_cast<std::size_t>(std::countr_zero(opened))]);
        simd::store_bits_as_bytes(isa, list.spring_live.data() + k, t);
      }
    }
    for (; k < end; ++k) touch_test(k, closed, n);
    return n;
  }

  /// select() over the live pairs at positions [begin, end) of a masked list, eight at a time by their indices.
  template <class Isa>
  [[gnu::always_inline]] std::size_t select_live(Isa isa, std::int32_t* closed, std::size_t begin, std::size_t end) {
    using simd::Wide;
    const std::int32_t* const live = list.live.data();
    std::size_t n = 0, m = begin;
    for (; m + simd::kLanes <= end; m += simd::kLanes) {
      const simd::Index k = simd::load(live + m);
      const simd::Index i = simd::gather(isa, list.i.data(), k), j = simd::gather(isa, list.j.data(), k);
      const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
      const Wide r_sum = simd::gather(isa, list.r_sum.data(), k);
      const simd::Mask touch = dot(d, d) < r_sum * r_sum;
      n += static_cast<std::size_t>(simd::compress(isa, closed + n, touch, k));
      const unsigned t = simd::bits(touch);
      for (int l = 0; l < simd::kLanes; ++l) {
        const auto kk = static_cast<std::size_t>(live[m + static_cast<std::size_t>(l)]);
        const bool touching = (t >> l) & 1u;
        if (!direct) list.results.touched[kk] = touching ? 1 : 0;
        if constexpr (Fx.friction) {
          if (list.spring_live[kk] && !touching) clear(list.spring[kk]);
          list.spring_live[kk] = touching ? 1 : 0;
        }
      }
    }
    for (; m < end; ++m) touch_test(static_cast<std::size_t>(live[m]), closed, n);
    return n;
  }

  /// The scalar form of the touch test and spring bookkeeping, for pair k.
  void touch_test(std::size_t k, std::int32_t* closed, std::size_t& n) {
    const bool t = (s.x[list.i[k]] - s.x[list.j[k]]).squaredNorm() < list.r_sum[k] * list.r_sum[k];
    closed[n] = static_cast<std::int32_t>(k);
    n += t ? 1 : 0;
    if (!direct) list.results.touched[k] = t ? 1 : 0;
    if constexpr (Fx.friction) {
      if (list.spring_live[k] && !t) clear(list.spring[k]);
      list.spring_live[k] = t ? 1 : 0;
    }
  }

  template <class Isa>
  [[gnu::always_inline]] ContactLanes gather(Isa isa, simd::Index k, double dt) const {
    using simd::Wide;
    ContactLanes c;
    c.i = simd::gather(isa, list.i.data(), k);
    c.j = simd::gather(isa, list.j.data(), k);
    const V3<Wide> d = gather_vec3(isa, s.x, c.i) - gather_vec3(isa, s.x, c.j);
    const V3<Wide> vij = gather_vec3(isa, s.v, c.i) - gather_vec3(isa, s.v, c.j);
    const Wide r_sum = simd::gather(isa, list.r_sum.data(), k);
    c.constants = gather_constants<Fx>(isa, list.k, k);
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

  /// Each contact's force and torque terms kept (F, ai n x Ft, aj n x Ft), and the springs back,
  /// for the first `live` lanes.
  [[gnu::always_inline]] void add(const ContactLanes& c, const ContactForce<simd::Wide>& f, const std::int32_t* k, int live) {
    V3<simd::Wide> nxFt{};
    if constexpr (Fx.rotation) nxFt = cross(c.geometry.n, f.Ft);
    if (direct) return add_to_spheres(c, f, nxFt, k, live);
    ContactResults& r = list.results;
    for (int m = 0; m < live; ++m) {
      const auto kk = static_cast<std::size_t>(k[m]);
      r.F[kk] = lane(f.F, m);
      if constexpr (Fx.rotation) {
        const Vec3 t = lane(nxFt, m);
        r.T1[kk] = lane(c.ai, m) * t;
        r.T2[kk] = lane(c.aj, m) * t;
      }
      if constexpr (Fx.friction) list.spring[kk] = lane(c.spring, m);
    }
  }

  /// F_i += F, F_j -= F, T_i -= ai n x Ft, T_j -= aj n x Ft of every touching pair, sphere by
  /// sphere (on the threads), each sphere's terms in list order: as body 2 (pairs (i', s), i' < s)
  /// then as body 1 (pairs (s, j')), the order of the list sorted by (i, j).
  void finish() {
    if (direct) return;
    index_by_sphere();
    const PairsBySphere& b = list.by_sphere;
    const ContactResults& r = list.results;
    const std::size_t blocks = (spheres + kBlock - 1) / kBlock;
    parallel::for_each_block(blocks, [&](std::size_t block) {
      const std::size_t end = std::min(spheres, (block + 1) * kBlock);
      for (std::size_t sphere = block * kBlock; sphere < end; ++sphere) {
        for (auto m = b.first_j[sphere]; m < b.first_j[sphere + 1]; ++m) {
          const auto k = static_cast<std::size_t>(b.as_j[static_cast<std::size_t>(m)]);
          if (!r.touched[k]) continue;
          s.F[sphere] -= r.F[k];
          if constexpr (Fx.rotation) s.T[sphere] -= r.T2[k];
        }
        for (auto k = static_cast<std::size_t>(b.first_i[sphere]); k < static_cast<std::size_t>(b.first_i[sphere + 1]); ++k) {
          if (!r.touched[k]) continue;
          s.F[sphere] += r.F[k];
          if constexpr (Fx.rotation) s.T[sphere] -= r.T1[k];
        }
      }
    });
  }

 private:
  /// F_i += F, F_j -= F, T_i -= ai n x Ft, T_j -= aj n x Ft, and the springs back, for the
  /// first `live` lanes in order (one thread).
  [[gnu::always_inline]] void add_to_spheres(const ContactLanes& c, const ContactForce<simd::Wide>& f, const V3<simd::Wide>& nxFt,
                                             const std::int32_t* k, int live) {
    for (int m = 0; m < live; ++m) {
      const int i = c.i.v[m], j = c.j.v[m];
      const Vec3 F = lane(f.F, m);
      s.F[i] += F;
      s.F[j] -= F;
      if constexpr (Fx.rotation) {
        const Vec3 t = lane(nxFt, m);
        s.T[i] -= lane(c.ai, m) * t;
        s.T[j] -= lane(c.aj, m) * t;
      }
      if constexpr (Fx.friction) list.spring[static_cast<std::size_t>(k[m])] = lane(c.spring, m);
    }
  }

  /// The list's pairs by sphere (PairsBySphere), made again when the list or the spheres changed.
  void index_by_sphere() {
    PairsBySphere& b = list.by_sphere;
    if (b.generation == list.generation && b.spheres == spheres) return;
    const std::size_t n = list.size();
    b.first_i.assign(spheres + 1, 0);
    b.first_j.assign(spheres + 1, 0);
    for (std::size_t k = 0; k < n; ++k) ++b.first_i[static_cast<std::size_t>(list.i[k]) + 1], ++b.first_j[static_cast<std::size_t>(list.j[k]) + 1];
    for (std::size_t q = 0; q < spheres; ++q) b.first_i[q + 1] += b.first_i[q], b.first_j[q + 1] += b.first_j[q];
    b.as_j.resize(n);
    std::vector<std::int32_t> next(b.first_j.begin(), b.first_j.end() - 1);
    for (std::size_t k = 0; k < n; ++k) b.as_j[static_cast<std::size_t>(next[static_cast<std::size_t>(list.j[k])]++)] = static_cast<std::int32_t>(k);
    b.generation = list.generation;
    b.spheres = spheres;
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

  static constexpr bool kThreaded = false;  // add() sums as it goes, in list order

  std::size_t positions() const { return this->list.size(); }
  void prepare() {}
  void finish() {}

  template <class Isa>
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

  void add(const ContactLanes& c, const ContactForce<simd::Wide>& f, const std::int32_t*, int live) const {
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
