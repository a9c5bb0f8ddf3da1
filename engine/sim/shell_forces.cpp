#include "sim/shell_forces.hpp"

#include "sim/contact_lanes.hpp"

#include <algorithm>
#include <cmath>

namespace softpack {
namespace {

constexpr int kBatch = 64;  // contacts per batch: the SoA scratch stays in L1

/// The shell, as every lane sees it.
struct ShellConstants {
  double cx, cy, cz, R;        // centre, radius
  double ux, uy, uz;           // velocity
  double ox, oy, oz;           // spin
};

/// One batch of touching sphere-shell contacts in structure-of-arrays form.
struct Batch {
  alignas(64) double dx[kBatch], dy[kBatch], dz[kBatch], dist[kBatch], h[kBatch];  // x - centre, |.|, overlap
  alignas(64) double x[kBatch], y[kBatch], z[kBatch], r[kBatch];
  alignas(64) double vx[kBatch], vy[kBatch], vz[kBatch];
  alignas(64) double wx[kBatch], wy[kBatch], wz[kBatch];
  alignas(64) double kn[kBatch], kt0[kBatch], gamma0[kBatch], gamma_t0[kBatch], mu[kBatch];
  alignas(64) double sx[kBatch], sy[kBatch], sz[kBatch];  // springs, advanced in place
  // results
  alignas(64) double Fx[kBatch], Fy[kBatch], Fz[kBatch];
  alignas(64) double Ftx[kBatch], Fty[kBatch], Ftz[kBatch];
  alignas(64) double nx[kBatch], ny[kBatch], nz[kBatch], ai[kBatch];
};

// One contact: the shell loop of Simulation::compute_forces_for and its wall_contact(), then
// advance_spring() and contact_force(), in their order of operations.
template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void lane(Batch& b, int m, const ShellConstants& s, double dt) {
  const double half_dt = 0.5 * dt;
  const double q = -1.0 / b.dist[m];  // the normal pushes inward
  const double nx = b.dx[m] * q, ny = b.dy[m] * q, nz = b.dz[m] * q;
  const double h = b.h[m];
  const double ai = b.r[m] - 0.5 * h;
  // Surface velocity at the contact point p = x - ai n: velocity + spin x (p - centre).
  double svx, svy, svz;
  {
    const double qx = (b.x[m] - ai * nx) - s.cx, qy = (b.y[m] - ai * ny) - s.cy, qz = (b.z[m] - ai * nz) - s.cz;
    svx = s.ux + (s.oy * qz - s.oz * qy);
    svy = s.uy + (s.oz * qx - s.ox * qz);
    svz = s.uz + (s.ox * qy - s.oy * qx);
  }
  double vcx = b.vx[m] - svx, vcy = b.vy[m] - svy, vcz = b.vz[m] - svz;
  if constexpr (Rotation) {
    const double tx = ai * b.wx[m], ty = ai * b.wy[m], tz = ai * b.wz[m];
    lanes::subtract_cross(vcx, vcy, vcz, tx, ty, tz, nx, ny, nz);
  }
  double sx = 0.0, sy = 0.0, sz = 0.0;
  if constexpr (Friction) {
    sx = b.sx[m], sy = b.sy[m], sz = b.sz[m];
    double fx = nx, fy = ny, fz = nz;  // frame of the spring update
    double ux = vcx, uy = vcy, uz = vcz;
    if constexpr (Synchronized) {
      const double hx = b.dx[m] - half_dt * (b.vx[m] - s.ux), hy = b.dy[m] - half_dt * (b.vy[m] - s.uy),
                   hz = b.dz[m] - half_dt * (b.vz[m] - s.uz);
      const double dist_half = std::sqrt(hx * hx + hy * hy + hz * hz);
      const double qh = -1.0 / dist_half;
      fx = hx * qh, fy = hy * qh, fz = hz * qh;
      const double h_half = dist_half + b.r[m] - s.R;
      const double ah = b.r[m] - 0.5 * h_half;
      const double px = ((s.cx + hx) - ah * fx) - s.cx, py = ((s.cy + hy) - ah * fy) - s.cy,
                   pz = ((s.cz + hz) - ah * fz) - s.cz;
      ux = b.vx[m] - (s.ux + (s.oy * pz - s.oz * py));
      uy = b.vy[m] - (s.uy + (s.oz * px - s.ox * pz));
      uz = b.vz[m] - (s.uz + (s.ox * py - s.oy * px));
      if constexpr (Rotation) {
        const double tx = ah * b.wx[m], ty = ah * b.wy[m], tz = ah * b.wz[m];
        lanes::subtract_cross(ux, uy, uz, tx, ty, tz, fx, fy, fz);
      }
    }
    double slow = 0.0;  // unused: no common-case shortcut here
    lanes::advance_spring<false>(sx, sy, sz, fx, fy, fz, ux, uy, uz, nx, ny, nz, dt, slow);
  }
  lanes::Force f = lanes::contact_force<Friction, Damping>(nx, ny, nz, h, vcx, vcy, vcz, sx, sy, sz, b.kn[m], b.kt0[m],
                                                           b.gamma0[m], b.gamma_t0[m], b.mu[m]);
  if constexpr (Friction) {
    lanes::coulomb_limit(f.slide, f.mu_Fn, f.Ft2, f.kt, f.Ftx, f.Fty, f.Ftz, sx, sy, sz);
    b.sx[m] = sx, b.sy[m] = sy, b.sz[m] = sz;
  }
  const double F_normal = f.F_normal, Ftx = f.Ftx, Fty = f.Fty, Ftz = f.Ftz;
  b.Fx[m] = F_normal * nx + Ftx;
  b.Fy[m] = F_normal * ny + Fty;
  b.Fz[m] = F_normal * nz + Ftz;
  b.Ftx[m] = Ftx, b.Fty[m] = Fty, b.Ftz[m] = Ftz;
  b.nx[m] = nx, b.ny[m] = ny, b.nz[m] = nz, b.ai[m] = ai;
}

template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
[[gnu::always_inline]] inline void run(WallList& list, const SphericalShell& shell, const PairForceArrays& a, double dt,
                                       Vec3& load_force, Vec3& load_torque) {
  const ShellConstants s{shell.centre.x(),   shell.centre.y(),   shell.centre.z(), shell.radius,
                         shell.velocity.x(), shell.velocity.y(), shell.velocity.z(), shell.spin.x(),
                         shell.spin.y(),     shell.spin.z()};
  Batch b;
  int k_of[kBatch], i_of[kBatch];
  const std::size_t entries = list.entries.size();
  std::size_t k = 0;
  while (k < entries) {
    // Gather the next touching entries; open ones have their spring cleared.
    int n = 0;
    for (; k < entries && n < kBatch; ++k) {
      const int i = list.entries[k].i;
      const Vec3 d = a.x[i] - shell.centre;
      const double dist = d.norm();
      const double h = dist + a.r[i] - shell.radius;
      if (h <= 0.0) {
        if constexpr (Friction) list.spring[k].setZero();
        continue;
      }
      k_of[n] = static_cast<int>(k), i_of[n] = i;
      b.dx[n] = d.x(), b.dy[n] = d.y(), b.dz[n] = d.z(), b.dist[n] = dist, b.h[n] = h;
      b.x[n] = a.x[i].x(), b.y[n] = a.x[i].y(), b.z[n] = a.x[i].z(), b.r[n] = a.r[i];
      b.vx[n] = a.v[i].x(), b.vy[n] = a.v[i].y(), b.vz[n] = a.v[i].z();
      if constexpr (Rotation) b.wx[n] = a.w[i].x(), b.wy[n] = a.w[i].y(), b.wz[n] = a.w[i].z();
      const ContactCoefficients& c = list.entries[k].k;
      b.kn[n] = c.kn, b.kt0[n] = c.kt0, b.gamma0[n] = c.gamma0, b.gamma_t0[n] = c.gamma_t0, b.mu[n] = c.mu;
      if constexpr (Friction) b.sx[n] = list.spring[k].x(), b.sy[n] = list.spring[k].y(), b.sz[n] = list.spring[k].z();
      ++n;
    }
    for (int m = 0; m < n; ++m) lane<Friction, Damping, Rotation, Synchronized>(b, m, s, dt);
    // Accumulate in list order, as the per-contact loop did.
    for (int m = 0; m < n; ++m) {
      const int i = i_of[m];
      const Vec3 F(b.Fx[m], b.Fy[m], b.Fz[m]), nrm(b.nx[m], b.ny[m], b.nz[m]);
      const double ai = b.ai[m];
      a.F[i] += F;
      if constexpr (Rotation) a.T[i] -= ai * nrm.cross(Vec3(b.Ftx[m], b.Fty[m], b.Ftz[m]));
      load_force -= F;
      load_torque += (a.x[i] - ai * nrm - shell.centre).cross(-F);
      if constexpr (Friction) list.spring[k_of[m]] = Vec3(b.sx[m], b.sy[m], b.sz[m]);
    }
  }
}

#define SOFTPACK_SHELL_VARIANT(NAME, FR, DA, RO, SY)                                                        \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void NAME(                 \
      WallList& list, const SphericalShell& shell, const PairForceArrays& a, double dt, Vec3& force, Vec3& torque) { \
    run<FR, DA, RO, SY>(list, shell, a, dt, force, torque);                                                  \
  }
SOFTPACK_SHELL_VARIANT(shell_hertz, false, false, false, false)
SOFTPACK_SHELL_VARIANT(shell_hertz_damped, false, true, false, false)
SOFTPACK_SHELL_VARIANT(shell_friction, true, false, false, false)
SOFTPACK_SHELL_VARIANT(shell_friction_rot, true, false, true, false)
SOFTPACK_SHELL_VARIANT(shell_friction_damped, true, true, false, false)
SOFTPACK_SHELL_VARIANT(shell_friction_rot_damped, true, true, true, false)
SOFTPACK_SHELL_VARIANT(shell_friction_sync, true, false, false, true)
SOFTPACK_SHELL_VARIANT(shell_friction_rot_sync, true, false, true, true)
SOFTPACK_SHELL_VARIANT(shell_friction_damped_sync, true, true, false, true)
SOFTPACK_SHELL_VARIANT(shell_friction_rot_damped_sync, true, true, true, true)
#undef SOFTPACK_SHELL_VARIANT

}  // namespace

void accumulate_shell_forces(WallList& list, const SphericalShell& shell, const PairForceArrays& a,
                             const PairForceEffects& fx, double spring_dt, Vec3& load_force, Vec3& load_torque) {
  if (!fx.friction)
    return fx.damping ? shell_hertz_damped(list, shell, a, spring_dt, load_force, load_torque)
                      : shell_hertz(list, shell, a, spring_dt, load_force, load_torque);
  const int key = (fx.synchronized ? 4 : 0) | (fx.damping ? 2 : 0) | (fx.rotation ? 1 : 0);
  switch (key) {
    case 0: return shell_friction(list, shell, a, spring_dt, load_force, load_torque);
    case 1: return shell_friction_rot(list, shell, a, spring_dt, load_force, load_torque);
    case 2: return shell_friction_damped(list, shell, a, spring_dt, load_force, load_torque);
    case 3: return shell_friction_rot_damped(list, shell, a, spring_dt, load_force, load_torque);
    case 4: return shell_friction_sync(list, shell, a, spring_dt, load_force, load_torque);
    case 5: return shell_friction_rot_sync(list, shell, a, spring_dt, load_force, load_torque);
    case 6: return shell_friction_damped_sync(list, shell, a, spring_dt, load_force, load_torque);
    default: return shell_friction_rot_damped_sync(list, shell, a, spring_dt, load_force, load_torque);
  }
}

}  // namespace softpack
