// Sphere-sphere contacts for the force loop (forces/contact_loop.hpp): body 1 is sphere i, body 2
// sphere j (i < j), the normal points from j to i.
//
//   d = xi - xj,  h = Ri + Rj - |d|,  n = d / |d|,
//   vc = vi - vj - (ai wi + aj wj) x n,   ai = Ri - h/2, aj = Rj - h/2 (rotation)
//
// With the synchronized history update the spring's frame is the half-step one: d - dt/2 (vi - vj)
// and its contact-point velocity.
#pragma once
#include <bit>
#include <cstdint>

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

  std::size_t size() const { return list.size(); }

  // Clearing a spring is `spring *= 0.0`, not setZero(): it keeps the sign of each zero, as it
  // always has for pairs (the archived results depend on these bits).
  static void clear(Vec3& spring) { spring *= 0.0; }

  /// The indices of the touching pairs, in list order (|d|^2 < (Ri + Rj)^2); with friction the
  /// springs of the others are cleared where PairList::spring_live says they may be loaded.
  /// A masked list (an active set) offers only its live pairs.
  template <class Isa>
  [[gnu::always_inline]] std::size_t select(Isa isa, std::int32_t* closed) {
    using simd::Wide;
    const std::size_t n_pairs = list.size();
    if constexpr (Fx.friction)
      if (list.spring_live.size() != n_pairs) list.spring_live.assign(n_pairs, 1);  // a fresh list: any may be
    if (list.masked) return select_live(isa, closed);
    std::size_t n = 0, k = 0;
    for (; k + simd::kLanes <= n_pairs; k += simd::kLanes) {
      const simd::Index i = simd::load(list.i.data() + k), j = simd::load(list.j.data() + k);
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
    for (; k < n_pairs; ++k) touch_test(k, closed, n);
    return n;
  }

  /// select() over the live pairs of a masked list, eight at a time by their indices.
  template <class Isa>
  [[gnu::always_inline]] std::size_t select_live(Isa isa, std::int32_t* closed) {
    using simd::Wide;
    const std::int32_t* const live = list.live.data();
    const std::size_t n_live = list.live.size();
    std::size_t n = 0, m = 0;
    for (; m + simd::kLanes <= n_live; m += simd::kLanes) {
      const simd::Index k = simd::load(live + m);
      const simd::Index i = simd::gather(isa, list.i.data(), k), j = simd::gather(isa, list.j.data(), k);
      const V3<Wide> d = gather_vec3(isa, s.x, i) - gather_vec3(isa, s.x, j);
      const Wide r_sum = simd::gather(isa, list.r_sum.data(), k);
      const simd::Mask touch = dot(d, d) < r_sum * r_sum;
      n += static_cast<std::size_t>(simd::compress(isa, closed + n, touch, k));
      if constexpr (Fx.friction) {
        const unsigned t = simd::bits(touch);
        for (int l = 0; l < simd::kLanes; ++l) {
          const auto kk = static_cast<std::size_t>(live[m + static_cast<std::size_t>(l)]);
          const bool touching = (t >> l) & 1u;
          if (list.spring_live[kk] && !touching) clear(list.spring[kk]);
          list.spring_live[kk] = touching ? 1 : 0;
        }
      }
    }
    for (; m < n_live; ++m) touch_test(static_cast<std::size_t>(live[m]), closed, n);
    return n;
  }

  /// The scalar form of the touch test and spring bookkeeping, for pair k.
  void touch_test(std::size_t k, std::int32_t* closed, std::size_t& n) {
    const bool t = (s.x[list.i[k]] - s.x[list.j[k]]).squaredNorm() < list.r_sum[k] * list.r_sum[k];
    closed[n] = static_cast<std::int32_t>(k);
    n += t ? 1 : 0;
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

  /// F_i += F, F_j -= F, T_i -= ai n x Ft, T_j -= aj n x Ft, and the springs back, for the
  /// first `live` lanes in order.
  [[gnu::always_inline]] void add(const ContactLanes& c, const ContactForce<simd::Wide>& f, const std::int32_t* k, int live) {
    V3<simd::Wide> nxFt{};
    if constexpr (Fx.rotation) nxFt = cross(c.geometry.n, f.Ft);
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
      if constexpr (Fx.friction) list.spring[k[m]] = lane(c.spring, m);
    }
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

  template <class Isa>
  std::size_t select(Isa, std::int32_t* closed) const {
    const PairList& l = this->list;
    std::size_t n = 0;
    for (std::size_t k = 0; k < l.size(); ++k) {
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
