// The linear and angular momenta of a world about the origin, spheres and free shells (a shell's
// spin momentum 2/3 m Rs² ω), with the sums of their magnitudes as the scale a conservation test
// compares a drift with.
#pragma once
#include "sim/simulation.hpp"

namespace softpack::testing {

struct Momenta {
  Vec3 P = Vec3::Zero(), L = Vec3::Zero();
  double P_scale = 0.0, L_scale = 0.0;
};

inline Momenta momenta(const Simulation& sim) {
  Momenta m;
  const auto add = [&](const Vec3& x, double mass, const Vec3& v, const Vec3& spin_momentum) {
    const Vec3 p = mass * v, l = x.cross(p);
    m.P += p, m.L += l + spin_momentum;
    m.P_scale += p.norm(), m.L_scale += l.norm() + spin_momentum.norm();
  };
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) add(p.x[i], p.m[i], p.v[i], p.w[i] / p.inv_I[i]);
  for (const SphericalShell& s : sim.shells()) add(s.centre, s.mass, s.velocity, 2.0 / 3.0 * s.mass * s.radius * s.radius * s.spin);
  return m;
}

}  // namespace softpack::testing
