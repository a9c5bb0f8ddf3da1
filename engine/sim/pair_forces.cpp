#include "sim/pair_forces.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/cpu_features.hpp"
#include "sim/avx512_helpers.hpp"
#include "sim/contact_lanes.hpp"
#include "sim/touching_pairs.hpp"

namespace softpack {
namespace {

constexpr int kBatch = 64;  // contacts per batch: the SoA scratch stays in L1

/// One batch of touching contacts in structure-of-arrays form.
struct Batch {
  alignas(64) double dx[kBatch], dy[kBatch], dz[kBatch];     // x_i - x_j
  alignas(64) double vx[kBatch], vy[kBatch], vz[kBatch];     // v_i - v_j
  alignas(64) double wix[kBatch], wiy[kBatch], wiz[kBatch];  // spins
  alignas(64) double wjx[kBatch], wjy[kBatch], wjz[kBatch];
  alignas(64) double ri[kBatch], rj[kBatch], r_sum[kBatch];
  alignas(64) double kn[kBatch], kt0[kBatch], gamma0[kBatch], gamma_t0[kBatch], mu[kBatch];
  alignas(64) double sx[kBatch], sy[kBatch], sz[kBatch];     // springs before the step
  alignas(64) int i[kBatch], j[kBatch];                      // the spheres
  // results
  alignas(64) double Fx[kBatch], Fy[kBatch], Fz[kBatch];
  alignas(64) double nFx[kBatch], nFy[kBatch], nFz[kBatch];  // n x Ft
  alignas(64) double ai[kBatch], aj[kBatch];                 // branch lengths
  alignas(64) double new_sx[kBatch], new_sy[kBatch], new_sz[kBatch];  // springs after the step
  alignas(64) double slow[kBatch];  // lanes the common case does not cover (see compute)
  // The Coulomb limit, deferred by the common case (slide_group): the unscaled tangential force,
  // what scaling it needs, and whether the contact slides (1) or sticks (0).
  alignas(64) double Ftx[kBatch], Fty[kBatch], Ftz[kBatch], Ft2[kBatch], mu_Fn[kBatch], kt[kBatch];
  alignas(64) double F_normal[kBatch], nx[kBatch], ny[kBatch], nz[kBatch], slide[kBatch];
};

// Forces of one contact of a batch: geometry -> spring history -> Hertz normal (Eq. 3) ->
// damping -> Coulomb limit and tangential spring (Eq. 5), as contact_force() does for one contact.
//
// `Common` is the common case, written for speed: springs that lean out of the tangent plane by
// less than the series covers (the lanes it cannot do are marked `slow` and redone with Common =
// false from the same inputs), and the Coulomb limit left to slide_group(). It skips two square
// roots and two divisions per contact, and five more where no contact of a group slides. For
// every other lane both give the same bits: the operations they share are the same.
template <bool Friction, bool Damping, bool Rotation, bool Synchronized, bool Common>
[[gnu::always_inline]] inline void lane(Batch& b, int m, double dt) {
  const double half_dt = 0.5 * dt;
  double slow = 0.0;
  const double dist = std::sqrt(b.dx[m] * b.dx[m] + b.dy[m] * b.dy[m] + b.dz[m] * b.dz[m]);
  const double inv = 1.0 / dist;
  const double nx = b.dx[m] * inv, ny = b.dy[m] * inv, nz = b.dz[m] * inv;
  const double h = b.r_sum[m] - dist;
  // Contact-point velocity at the full step, vc = vij - (ai wi + aj wj) x n.
  double vcx = b.vx[m], vcy = b.vy[m], vcz = b.vz[m];
  double ai = 0.0, aj = 0.0;
  if constexpr (Rotation) {
    ai = b.ri[m] - 0.5 * h;
    aj = b.rj[m] - 0.5 * h;
    const double px = ai * b.wix[m] + aj * b.wjx[m], py = ai * b.wiy[m] + aj * b.wjy[m],
                 pz = ai * b.wiz[m] + aj * b.wjz[m];
    lanes::subtract_cross(vcx, vcy, vcz, px, py, pz, nx, ny, nz);
  }
  double sx = 0.0, sy = 0.0, sz = 0.0;
  if constexpr (Friction) {
    sx = b.sx[m], sy = b.sy[m], sz = b.sz[m];
    double fx = nx, fy = ny, fz = nz;  // frame of the spring update
    double ux = vcx, uy = vcy, uz = vcz;
    if constexpr (Synchronized) {
      const double hx = b.dx[m] - half_dt * b.vx[m], hy = b.dy[m] - half_dt * b.vy[m],
                   hz = b.dz[m] - half_dt * b.vz[m];
      const double dist_half = std::sqrt(hx * hx + hy * hy + hz * hz);
      const double inv_half = 1.0 / dist_half;
      fx = hx * inv_half, fy = hy * inv_half, fz = hz * inv_half;
      ux = b.vx[m], uy = b.vy[m], uz = b.vz[m];
      if constexpr (Rotation) {
        const double h_half = b.r_sum[m] - dist_half;
        const double ahi = b.ri[m] - 0.5 * h_half, ahj = b.rj[m] - 0.5 * h_half;
        const double px = ahi * b.wix[m] + ahj * b.wjx[m], py = ahi * b.wiy[m] + ahj * b.wjy[m],
                     pz = ahi * b.wiz[m] + ahj * b.wjz[m];
        lanes::subtract_cross(ux, uy, uz, px, py, pz, fx, fy, fz);
      }
    }
    lanes::advance_spring<Common>(sx, sy, sz, fx, fy, fz, ux, uy, uz, nx, ny, nz, dt, slow);
  }
  lanes::Force f = lanes::contact_force<Friction, Damping>(nx, ny, nz, h, vcx, vcy, vcz, sx, sy, sz, b.kn[m], b.kt0[m],
                                                           b.gamma0[m], b.gamma_t0[m], b.mu[m]);
  const double F_normal = f.F_normal;
  if constexpr (Friction) {
    if constexpr (Common) {  // sticking assumed here; slide_group() corrects the lanes that slide
      b.slide[m] = f.slide ? 1.0 : 0.0;
      b.Ftx[m] = f.Ftx, b.Fty[m] = f.Fty, b.Ftz[m] = f.Ftz, b.Ft2[m] = f.Ft2, b.mu_Fn[m] = f.mu_Fn, b.kt[m] = f.kt;
      b.F_normal[m] = F_normal, b.nx[m] = nx, b.ny[m] = ny, b.nz[m] = nz;
    } else {
      lanes::coulomb_limit(f.slide, f.mu_Fn, f.Ft2, f.kt, f.Ftx, f.Fty, f.Ftz, sx, sy, sz);
    }
    b.new_sx[m] = sx;
    b.new_sy[m] = sy;
    b.new_sz[m] = sz;
  }
  const double Ftx = f.Ftx, Fty = f.Fty, Ftz = f.Ftz;
  b.Fx[m] = F_normal * nx + Ftx;
  b.Fy[m] = F_normal * ny + Fty;
  b.Fz[m] = F_normal * nz + Ftz;
  if constexpr (Rotation) {
    b.nFx[m] = ny * Ftz - nz * Fty;
    b.nFy[m] = nz * Ftx - nx * Ftz;
    b.nFz[m] = nx * Fty - ny * Ftx;
    b.ai[m] = ai;
    b.aj[m] = aj;
  }
  if constexpr (Common) b.slow[m] = slow;
}

template <bool Friction, bool Damping, bool Rotation, bool Synchronized, bool Common>
[[gnu::always_inline]] inline void compute_all(Batch& b, int n, double dt) {
  for (int m = 0; m < n; ++m) lane<Friction, Damping, Rotation, Synchronized, Common>(b, m, dt);
}

// The Coulomb limit for lanes [begin, end) of a batch the common case went through: the
// operations lane<..., false> does after the spring, on what the common case stored. A lane that
// sticks gets the bits it has (its scale is 1).
template <bool Rotation>
[[gnu::always_inline]] inline void slide_group(Batch& b, int begin, int end) {
  for (int m = begin; m < end; ++m) {
    double Ftx = b.Ftx[m], Fty = b.Fty[m], Ftz = b.Ftz[m];
    lanes::coulomb_limit(b.slide[m] != 0.0, b.mu_Fn[m], b.Ft2[m], b.kt[m], Ftx, Fty, Ftz, b.new_sx[m], b.new_sy[m], b.new_sz[m]);
    const double nx = b.nx[m], ny = b.ny[m], nz = b.nz[m];
    b.Fx[m] = b.F_normal[m] * nx + Ftx;
    b.Fy[m] = b.F_normal[m] * ny + Fty;
    b.Fz[m] = b.F_normal[m] * nz + Ftz;
    if constexpr (Rotation) {
      b.nFx[m] = ny * Ftz - nz * Fty;
      b.nFy[m] = nz * Ftx - nx * Ftz;
      b.nFz[m] = nx * Fty - ny * Ftx;
    }
  }
}

// Forces of one batch. With friction, the common case first; then the Coulomb limit for each
// group of eight lanes (one AVX-512 vector) in which a contact slides; then the rare lanes whose
// spring leans out of the tangent plane, one by one, or, when they are many, the whole batch.
template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void compute(Batch& b, int n, double dt) {
  if constexpr (!Friction) {
    compute_all<Friction, Damping, Rotation, Synchronized, false>(b, n, dt);
  } else {
    compute_all<Friction, Damping, Rotation, Synchronized, true>(b, n, dt);
    constexpr int kGroup = 8;
    for (int begin = 0; begin < n; begin += kGroup) {
      const int end = std::min(begin + kGroup, n);
      bool any = false;
      for (int m = begin; m < end; ++m) any |= b.slide[m] != 0.0;
      if (!any) continue;
      if (end - begin == kGroup) slide_group<Rotation>(b, begin, begin + kGroup);  // a fixed count: one vector
      else slide_group<Rotation>(b, begin, end);
    }
    int nslow = 0;
    for (int m = 0; m < n; ++m) nslow += b.slow[m] != 0.0 ? 1 : 0;
    if (nslow == 0) return;
    if (4 * nslow > n) return compute_all<Friction, Damping, Rotation, Synchronized, false>(b, n, dt);
    for (int m = 0; m < n; ++m)
      if (b.slow[m] != 0.0) lane<Friction, Damping, Rotation, Synchronized, false>(b, m, dt);
  }
}

// Copies the contacts closed[0..n) into the batch, one by one: what the declared effects read.
template <bool Friction, bool Damping, bool Rotation>
[[gnu::always_inline]] inline void gather_portable(Batch& b, const int* closed, int n, const PairList& list,
                                                   const PairForceArrays& a) {
  for (int m = 0; m < n; ++m) {
    const int k = closed[m];
    const PairEntry& e = list.pairs[k];
    b.i[m] = e.i, b.j[m] = e.j;
    const Vec3 d = a.x[e.i] - a.x[e.j], v = a.v[e.i] - a.v[e.j];
    b.dx[m] = d.x(), b.dy[m] = d.y(), b.dz[m] = d.z();
    b.vx[m] = v.x(), b.vy[m] = v.y(), b.vz[m] = v.z();
    const ContactCoefficients& c = list.k[k];
    b.r_sum[m] = e.r_sum, b.kn[m] = c.kn;
    if constexpr (Damping) b.gamma0[m] = c.gamma0;
    if constexpr (Friction) b.kt0[m] = c.kt0, b.mu[m] = c.mu;
    if constexpr (Friction && Damping) b.gamma_t0[m] = c.gamma_t0;
    if constexpr (Rotation) {
      b.wix[m] = a.w[e.i].x(), b.wiy[m] = a.w[e.i].y(), b.wiz[m] = a.w[e.i].z();
      b.wjx[m] = a.w[e.j].x(), b.wjy[m] = a.w[e.j].y(), b.wjz[m] = a.w[e.j].z();
      b.ri[m] = a.r[e.i], b.rj[m] = a.r[e.j];
    }
    if constexpr (Friction) {
      const Vec3& s = list.spring[k];
      b.sx[m] = s.x(), b.sy[m] = s.y(), b.sz[m] = s.z();
    }
  }
}

// The same copy as gather_portable, eight contacts per instruction. Vec3 is three doubles, so
// component c of sphere i is at 3i + c; a pair's i and j are ints 4k and 4k + 1 of the list, its
// r_sum double 2k + 1; the constants of pair k are doubles 5k to 5k + 4, its spring 3k to 3k + 2.
template <bool Friction, bool Damping, bool Rotation>
SOFTPACK_TARGET_AVX512 void gather_avx512(Batch& b, const int* closed, int n, const PairList& list, const PairForceArrays& a) {
  static_assert(sizeof(ContactCoefficients) == 5 * sizeof(double) && sizeof(Vec3) == 3 * sizeof(double));
  const int* const pair_ints = reinterpret_cast<const int*>(list.pairs.data());
  const double* const pair_doubles = reinterpret_cast<const double*>(list.pairs.data());
  const double* const constants = reinterpret_cast<const double*>(list.k.data());
  const double* const x = a.x->data();
  const double* const v = a.v->data();
  const __m256i one = _mm256_set1_epi32(1);
  for (int m = 0; m < n; m += 8) {
    const __mmask8 live = n - m >= 8 ? __mmask8{0xff} : static_cast<__mmask8>((1u << (n - m)) - 1u);
    const __m256i k = _mm256_maskz_loadu_epi32(live, closed + m);
    const __m256i k2 = _mm256_add_epi32(k, k), k4 = _mm256_add_epi32(k2, k2);
    const __m256i i = _mm256_mmask_i32gather_epi32(_mm256_setzero_si256(), live, k4, pair_ints, 4);
    const __m256i j = _mm256_mmask_i32gather_epi32(_mm256_setzero_si256(), live, _mm256_add_epi32(k4, one), pair_ints, 4);
    _mm256_store_si256(reinterpret_cast<__m256i*>(b.i + m), i);
    _mm256_store_si256(reinterpret_cast<__m256i*>(b.j + m), j);
    const __m256i i3 = _mm256_add_epi32(i, _mm256_add_epi32(i, i)), j3 = _mm256_add_epi32(j, _mm256_add_epi32(j, j));
    _mm512_store_pd(b.dx + m, _mm512_sub_pd(avx512::gather8(x, i3, live), avx512::gather8(x, j3, live)));
    _mm512_store_pd(b.dy + m, _mm512_sub_pd(avx512::gather8(x + 1, i3, live), avx512::gather8(x + 1, j3, live)));
    _mm512_store_pd(b.dz + m, _mm512_sub_pd(avx512::gather8(x + 2, i3, live), avx512::gather8(x + 2, j3, live)));
    _mm512_store_pd(b.vx + m, _mm512_sub_pd(avx512::gather8(v, i3, live), avx512::gather8(v, j3, live)));
    _mm512_store_pd(b.vy + m, _mm512_sub_pd(avx512::gather8(v + 1, i3, live), avx512::gather8(v + 1, j3, live)));
    _mm512_store_pd(b.vz + m, _mm512_sub_pd(avx512::gather8(v + 2, i3, live), avx512::gather8(v + 2, j3, live)));
    _mm512_store_pd(b.r_sum + m, avx512::gather8(pair_doubles + 1, k2, live));
    const __m256i k5 = _mm256_add_epi32(k4, k);
    _mm512_store_pd(b.kn + m, avx512::gather8(constants, k5, live));
    if constexpr (Damping) _mm512_store_pd(b.gamma0 + m, avx512::gather8(constants + 2, k5, live));
    if constexpr (Friction) {
      _mm512_store_pd(b.kt0 + m, avx512::gather8(constants + 1, k5, live));
      _mm512_store_pd(b.mu + m, avx512::gather8(constants + 4, k5, live));
    }
    if constexpr (Friction && Damping) _mm512_store_pd(b.gamma_t0 + m, avx512::gather8(constants + 3, k5, live));
    if constexpr (Rotation) {
      const double* const w = a.w->data();
      _mm512_store_pd(b.wix + m, avx512::gather8(w, i3, live));
      _mm512_store_pd(b.wiy + m, avx512::gather8(w + 1, i3, live));
      _mm512_store_pd(b.wiz + m, avx512::gather8(w + 2, i3, live));
      _mm512_store_pd(b.wjx + m, avx512::gather8(w, j3, live));
      _mm512_store_pd(b.wjy + m, avx512::gather8(w + 1, j3, live));
      _mm512_store_pd(b.wjz + m, avx512::gather8(w + 2, j3, live));
      _mm512_store_pd(b.ri + m, avx512::gather8(a.r, i, live));
      _mm512_store_pd(b.rj + m, avx512::gather8(a.r, j, live));
    }
    if constexpr (Friction) {
      const double* const spring = list.spring.data()->data();
      const __m256i k3 = _mm256_add_epi32(k2, k);
      _mm512_store_pd(b.sx + m, avx512::gather8(spring, k3, live));
      _mm512_store_pd(b.sy + m, avx512::gather8(spring + 1, k3, live));
      _mm512_store_pd(b.sz + m, avx512::gather8(spring + 2, k3, live));
    }
  }
}

template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void run(PairList& list, const PairForceArrays& a, double dt, std::vector<int>& closed) {
  closed.resize(list.pairs.size());
  const std::size_t nclosed = select_touching_pairs(list, a.x, Friction, closed.data());
  const bool avx512 = cpu::avx512_in_use();
  Batch b;
  for (std::size_t base = 0; base < nclosed; base += kBatch) {
    const int n = static_cast<int>(std::min<std::size_t>(kBatch, nclosed - base));
    if (avx512) gather_avx512<Friction, Damping, Rotation>(b, closed.data() + base, n, list, a);
    else gather_portable<Friction, Damping, Rotation>(b, closed.data() + base, n, list, a);
    compute<Friction, Damping, Rotation, Synchronized>(b, n, dt);
    for (int m = 0; m < n; ++m) {
      const int i = b.i[m], j = b.j[m];
      const Vec3 F(b.Fx[m], b.Fy[m], b.Fz[m]);
      a.F[i] += F;
      a.F[j] -= F;
      if constexpr (Rotation) {
        const Vec3 nxFt(b.nFx[m], b.nFy[m], b.nFz[m]);
        a.T[i] -= b.ai[m] * nxFt;
        a.T[j] -= b.aj[m] * nxFt;
      }
      if constexpr (Friction) list.spring[closed[base + m]] = Vec3(b.new_sx[m], b.new_sy[m], b.new_sz[m]);
    }
  }
}

#define SOFTPACK_PAIR_VARIANT(NAME, FR, DA, RO, SY)                                             \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void NAME(     \
      PairList& list, const PairForceArrays& a, double dt, std::vector<int>& closed) {          \
    run<FR, DA, RO, SY>(list, a, dt, closed);                                                    \
  }
SOFTPACK_PAIR_VARIANT(pairs_hertz, false, false, false, false)
SOFTPACK_PAIR_VARIANT(pairs_hertz_damped, false, true, false, false)
SOFTPACK_PAIR_VARIANT(pairs_friction, true, false, false, false)
SOFTPACK_PAIR_VARIANT(pairs_friction_rot, true, false, true, false)
SOFTPACK_PAIR_VARIANT(pairs_friction_damped, true, true, false, false)
SOFTPACK_PAIR_VARIANT(pairs_friction_rot_damped, true, true, true, false)
SOFTPACK_PAIR_VARIANT(pairs_friction_sync, true, false, false, true)
SOFTPACK_PAIR_VARIANT(pairs_friction_rot_sync, true, false, true, true)
SOFTPACK_PAIR_VARIANT(pairs_friction_damped_sync, true, true, false, true)
SOFTPACK_PAIR_VARIANT(pairs_friction_rot_damped_sync, true, true, true, true)
#undef SOFTPACK_PAIR_VARIANT

}  // namespace

void accumulate_pair_forces(PairList& list, const PairForceArrays& a, const PairForceEffects& fx, double dt,
                            std::vector<int>& scratch) {
  if (!fx.friction) return fx.damping ? pairs_hertz_damped(list, a, dt, scratch) : pairs_hertz(list, a, dt, scratch);
  const int key = (fx.synchronized ? 4 : 0) | (fx.damping ? 2 : 0) | (fx.rotation ? 1 : 0);
  switch (key) {
    case 0: return pairs_friction(list, a, dt, scratch);
    case 1: return pairs_friction_rot(list, a, dt, scratch);
    case 2: return pairs_friction_damped(list, a, dt, scratch);
    case 3: return pairs_friction_rot_damped(list, a, dt, scratch);
    case 4: return pairs_friction_sync(list, a, dt, scratch);
    case 5: return pairs_friction_rot_sync(list, a, dt, scratch);
    case 6: return pairs_friction_damped_sync(list, a, dt, scratch);
    default: return pairs_friction_rot_damped_sync(list, a, dt, scratch);
  }
}

}  // namespace softpack
