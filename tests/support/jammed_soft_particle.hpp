// The four-grain soft-particle with a single state of rest, and what the relaxation tests
// compare on it (tests/physics/test_relaxation_knobs.cpp, test_active_set.cpp).
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/sweep_fixture.hpp"

namespace softpack::testing {

inline ConvergedRelaxationDef converged(double force_tolerance) {
  ConvergedRelaxationDef c;
  c.force_tolerance = force_tolerance;
  c.energy_tolerance = 1e-10;
  c.check_interval = 0.02;
  c.max_time = 50.0;
  c.zero_velocities_at_checks = true;
  return c;
}

inline void frictionless(MeasurementSettings& s) {
  s.simulation.effects.friction = false;
  s.simulation.effects.rotation = false;
}

// A soft-particle with one state of rest: four grains of radius 0.46 Rs at the corners of a
// tetrahedron, one on the +x axis, each pressed against the other three and the shell (overlaps
// of 0.01-0.02 Rs), frictionless, pressed by the wall at Delta_n = 0, 0.03 and 0.06. No grain
// is a rattler and every contact stays closed, so a relaxation that reaches rest reaches that
// state, whatever its path. (The random test packing is no such scene: its rattlers and marginal
// contacts rearrange differently for every path; two protocols that both reach a force ratio
// of 1e-5 there give wall forces 1-4% apart.)
inline PackingFile jammed_packing() {
  const double Rs = 0.016, r = 0.46 * Rs, d = 0.5505 * Rs;  // d: centres touching at r = 0.4495 Rs
  PackingFile p;
  p.Rs = Rs;
  const double s2 = std::sqrt(2.0), s23 = std::sqrt(2.0 / 3.0);
  for (const Vec3& u : {Vec3(1, 0, 0), Vec3(-1.0 / 3, 2 * s2 / 3, 0), Vec3(-1.0 / 3, -s2 / 3, s23), Vec3(-1.0 / 3, -s2 / 3, -s23)})
    p.centres.push_back(d * u), p.radii.push_back(r);
  return p;
}

template <class Edit>
std::vector<PointResult> jammed_sweep(const std::string& dir, Edit&& edit) {
  SweepContext c = sweep_context({}, dir);
  frictionless(c.settings);
  c.settings.normal.delta_n = {0.0, 0.03, 0.06};
  edit(c.settings);
  c.setup = soft_solid_setup(jammed_packing(), c.settings.simulation);
  return run_normal_sweep(c);
}

// Two sweeps whose every point relaxed to rest (force ratio below `ratio`) give the same force on
// the wall within `tolerance` of the largest. The tolerance each test states is ten times the
// force ratio its relaxations reach: the wall force is the sum of a few contact forces, each
// balanced to that ratio of the mean.
inline void expect_same_rest(const std::vector<PointResult>& a, const std::vector<PointResult>& b, double ratio, double tolerance) {
  ASSERT_EQ(a.size(), b.size());
  const double scale = a.back().force.x();
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_LT(a[k].checks.back().residuals.force_ratio(), ratio) << "point " << k << ": not at rest";
    EXPECT_LT(b[k].checks.back().residuals.force_ratio(), ratio) << "point " << k << ": not at rest";
    EXPECT_NEAR(a[k].force.x(), b[k].force.x(), tolerance * scale) << "point " << k;
  }
}

}  // namespace softpack::testing
