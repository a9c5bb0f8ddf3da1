#include "sim/pair_forces.hpp"

#include <algorithm>
#include <cmath>

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
  alignas(64) double sx[kBatch], sy[kBatch], sz[kBatch];     // springs
  // results
  alignas(64) double Fx[kBatch], Fy[kBatch], Fz[kBatch];
  alignas(64) double nFx[kBatch], nFy[kBatch], nFz[kBatch];  // n x Ft
  alignas(64) double ai[kBatch], aj[kBatch];                 // branch lengths
};

// tsuji::rotate_into_tangent_plane for one lane, without branches.
[[gnu::always_inline]] inline void rotate_lane(double& x, double& y, double& z, double nx, double ny, double nz) {
  const double len2 = x * x + y * y + z * z;
  const double c = x * nx + y * ny + z * nz;
  const double s = len2 > 0.0 ? c * c / len2 : 0.0;
  const double restore = s < 1e-6 ? 1.0 + s * (0.5 + 0.375 * s) : 1.0 / std::sqrt(1.0 - s);
  const bool keep = s < 1.0;
  x = keep ? (x - c * nx) * restore : 0.0;
  y = keep ? (y - c * ny) * restore : 0.0;
  z = keep ? (z - c * nz) * restore : 0.0;
}

// Forces of one batch: geometry -> spring history -> Hertz normal (Eq. 3) -> damping ->
// Coulomb limit and tangential spring (Eq. 5), as contact_force() does for one contact.
template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void compute(Batch& b, int n, double dt) {
  const double half_dt = 0.5 * dt;
  for (int m = 0; m < n; ++m) {
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
      vcx -= py * nz - pz * ny;
      vcy -= pz * nx - px * nz;
      vcz -= px * ny - py * nx;
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
          ux -= py * fz - pz * fy;
          uy -= pz * fx - px * fz;
          uz -= px * fy - py * fx;
        }
      }
      // advance_spring: into the update frame, add the tangential displacement, into n.
      rotate_lane(sx, sy, sz, fx, fy, fz);
      const double un = ux * fx + uy * fy + uz * fz;
      sx += (ux - un * fx) * dt;
      sy += (uy - un * fy) * dt;
      sz += (uz - un * fz) * dt;
      rotate_lane(sx, sy, sz, nx, ny, nz);
    }
    // contact_force
    const double sqrt_h = std::sqrt(h);
    const double Fn = b.kn[m] * h * sqrt_h;  // Eq. 3
    const double vn = vcx * nx + vcy * ny + vcz * nz;
    double h_quarter = 0.0;
    double F_normal = Fn;
    if constexpr (Damping) {
      h_quarter = std::sqrt(sqrt_h);
      F_normal -= b.gamma0[m] * h_quarter * vn;
    }
    double Ftx = 0.0, Fty = 0.0, Ftz = 0.0;
    if constexpr (Friction) {
      const double vtx = vcx - vn * nx, vty = vcy - vn * ny, vtz = vcz - vn * nz;
      const double kt = b.kt0[m] * sqrt_h;  // Eq. 5
      const double gamma_t = Damping ? b.gamma_t0[m] * h_quarter : 0.0;
      Ftx = -kt * sx - gamma_t * vtx;
      Fty = -kt * sy - gamma_t * vty;
      Ftz = -kt * sz - gamma_t * vtz;
      const double Ft2 = Ftx * Ftx + Fty * Fty + Ftz * Ftz;
      const double mu_Fn = b.mu[m] * Fn;
      const bool slide = Ft2 > mu_Fn * mu_Fn;  // Coulomb limit: slide at mu Fn
      const double scale = slide ? mu_Fn / std::sqrt(Ft2) : 1.0;
      Ftx *= scale;
      Fty *= scale;
      Ftz *= scale;
      b.sx[m] = slide ? -Ftx / kt : sx;
      b.sy[m] = slide ? -Fty / kt : sy;
      b.sz[m] = slide ? -Ftz / kt : sz;
    }
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
  }
}

template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void run(PairList& list, const PairForceArrays& a, double dt, std::vector<int>& closed) {
  // Pick out the touching pairs without a branch (about half of a Verlet list touches, at
  // random); open pairs have their spring cleared.
  const std::size_t npairs = list.pairs.size();
  closed.resize(npairs);
  std::size_t nclosed = 0;
  for (std::size_t k = 0; k < npairs; ++k) {
    const PairEntry& e = list.pairs[k];
    const bool touching = (a.x[e.i] - a.x[e.j]).squaredNorm() < e.r_sum * e.r_sum;
    closed[nclosed] = static_cast<int>(k);
    nclosed += touching ? 1 : 0;
    if constexpr (Friction) list.spring[k] *= touching ? 1.0 : 0.0;  // open: spring cleared
  }
  Batch b;
  for (std::size_t base = 0; base < nclosed; base += kBatch) {
    const int n = static_cast<int>(std::min<std::size_t>(kBatch, nclosed - base));
    for (int m = 0; m < n; ++m) {
      const int k = closed[base + m];
      const PairEntry& e = list.pairs[k];
      const Vec3 d = a.x[e.i] - a.x[e.j], v = a.v[e.i] - a.v[e.j];
      b.dx[m] = d.x(), b.dy[m] = d.y(), b.dz[m] = d.z();
      b.vx[m] = v.x(), b.vy[m] = v.y(), b.vz[m] = v.z();
      const ContactCoefficients& c = list.k[k];
      b.r_sum[m] = e.r_sum, b.kn[m] = c.kn, b.kt0[m] = c.kt0;
      b.gamma0[m] = c.gamma0, b.gamma_t0[m] = c.gamma_t0, b.mu[m] = c.mu;
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
    compute<Friction, Damping, Rotation, Synchronized>(b, n, dt);
    for (int m = 0; m < n; ++m) {
      const int k = closed[base + m];
      const PairEntry& e = list.pairs[k];
      const Vec3 F(b.Fx[m], b.Fy[m], b.Fz[m]);
      a.F[e.i] += F;
      a.F[e.j] -= F;
      if constexpr (Rotation) {
        const Vec3 nxFt(b.nFx[m], b.nFy[m], b.nFz[m]);
        a.T[e.i] -= b.ai[m] * nxFt;
        a.T[e.j] -= b.aj[m] * nxFt;
      }
      if constexpr (Friction) list.spring[k] = Vec3(b.sx[m], b.sy[m], b.sz[m]);
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
