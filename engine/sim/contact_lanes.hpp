// The arithmetic of one contact, written for the vectorised force loops (sim/pair_forces.cpp,
// sim/shell_forces.cpp): plain doubles and selects instead of Eigen vectors and branches, so that
// the compiler evaluates several contacts per instruction. Operation for operation it is that of
// the per-contact routines of contact/contact_force.hpp and contact/tsuji_tangential.hpp, which
// stay the reference; the loops' tests check the values agree.
#pragma once
#include <cmath>

namespace softpack::lanes {

/// v -= p x n, component by component as Eigen's cross product: the rotation part of a contact
/// point's relative velocity, p being (branch length) x (spin).
[[gnu::always_inline]] inline void subtract_cross(double& vx, double& vy, double& vz, double px, double py, double pz,
                                                  double nx, double ny, double nz) {
  vx -= py * nz - pz * ny;
  vy -= pz * nx - px * nz;
  vz -= px * ny - py * nx;
}

/// tsuji::rotate_into_tangent_plane with its exact cases: a zero spring stays as it is, one along
/// n (s >= 1) is cleared. The exact restoring factor 1/sqrt(1 - s) is only needed when the
/// spring leans out of the plane by more than the series covers (s >= 1e-6). `Common` computes
/// the series alone and adds 1 to `slow` for such lanes (arithmetic, not a bool: the loop must
/// stay branch-free); the caller redoes them with Common = false.
template <bool Common>
[[gnu::always_inline]] inline void rotate_into_tangent_plane(double& x, double& y, double& z, double nx, double ny, double nz,
                                                             double& slow) {
  const double len2 = x * x + y * y + z * z;
  const double c = x * nx + y * ny + z * nz;
  const double s = len2 != 0.0 ? c * c / len2 : 0.0;
  const double series = 1.0 + s * (0.5 + 0.375 * s);
  double factor = series;
  if constexpr (Common) {
    slow += s < 1e-6 ? 0.0 : 1.0;
  } else {
    factor = s < 1e-6 ? series : 1.0 / std::sqrt(1.0 - s);
  }
  const bool keep = len2 == 0.0, clear = s >= 1.0;
  x = keep ? x : (clear ? 0.0 : (x - c * nx) * factor);
  y = keep ? y : (clear ? 0.0 : (y - c * ny) * factor);
  z = keep ? z : (clear ? 0.0 : (z - c * nz) * factor);
}

/// advance_spring: the spring (sx, sy, sz) into the update frame f, plus the tangential part of
/// the velocity u over dt, then into the contact plane of n.
template <bool Common>
[[gnu::always_inline]] inline void advance_spring(double& sx, double& sy, double& sz, double fx, double fy, double fz,
                                                  double ux, double uy, double uz, double nx, double ny, double nz,
                                                  double dt, double& slow) {
  rotate_into_tangent_plane<Common>(sx, sy, sz, fx, fy, fz, slow);
  const double un = ux * fx + uy * fy + uz * fz;
  sx += (ux - un * fx) * dt;
  sy += (uy - un * fy) * dt;
  sz += (uz - un * fz) * dt;
  rotate_into_tangent_plane<Common>(sx, sy, sz, nx, ny, nz, slow);
}

/// contact_force up to the Coulomb test: Hertz normal force (Eq. 3) with its damping, and the
/// spring's tangential force (Eq. 5) before the limit.
struct Force {
  double F_normal = 0.0;  ///< Fn minus normal damping [N]
  double Fn = 0.0;        ///< Hertz force, Eq. 3, the Coulomb limit's Fn [N]
  double Ftx = 0.0, Fty = 0.0, Ftz = 0.0;  ///< tangential force before the limit [N]
  double Ft2 = 0.0, mu_Fn = 0.0, kt = 0.0;
  bool slide = false;  ///< |Ft| > mu Fn
};

template <bool Friction, bool Damping>
[[gnu::always_inline]] inline Force contact_force(double nx, double ny, double nz, double h, double vcx, double vcy, double vcz,
                                                  double sx, double sy, double sz, double kn, double kt0, double gamma0,
                                                  double gamma_t0, double mu) {
  Force f;
  const double sqrt_h = std::sqrt(h);
  f.Fn = kn * h * sqrt_h;  // Eq. 3
  const double vn = vcx * nx + vcy * ny + vcz * nz;
  double h_quarter = 0.0;
  f.F_normal = f.Fn;
  if constexpr (Damping) {
    h_quarter = std::sqrt(sqrt_h);
    f.F_normal -= gamma0 * h_quarter * vn;
  }
  if constexpr (Friction) {
    const double vtx = vcx - vn * nx, vty = vcy - vn * ny, vtz = vcz - vn * nz;
    f.kt = kt0 * sqrt_h;  // Eq. 5
    const double gamma_t = Damping ? gamma_t0 * h_quarter : 0.0;
    f.Ftx = -f.kt * sx - gamma_t * vtx;
    f.Fty = -f.kt * sy - gamma_t * vty;
    f.Ftz = -f.kt * sz - gamma_t * vtz;
    f.Ft2 = f.Ftx * f.Ftx + f.Fty * f.Fty + f.Ftz * f.Ftz;
    f.mu_Fn = mu * f.Fn;
    f.slide = f.Ft2 > f.mu_Fn * f.mu_Fn;
  }
  return f;
}

/// The Coulomb limit of tsuji::force: a sliding contact's tangential force scaled to mu Fn and
/// its spring shortened to match; a sticking one keeps both (its scale is 1).
[[gnu::always_inline]] inline void coulomb_limit(bool slide, double mu_Fn, double Ft2, double kt, double& Ftx, double& Fty,
                                                 double& Ftz, double& sx, double& sy, double& sz) {
  const double scale = slide ? mu_Fn / std::sqrt(Ft2) : 1.0;
  Ftx *= scale;
  Fty *= scale;
  Ftz *= scale;
  sx = slide ? -Ftx / kt : sx;
  sy = slide ? -Fty / kt : sy;
  sz = slide ? -Ftz / kt : sz;
}

}  // namespace softpack::lanes
