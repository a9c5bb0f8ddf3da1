// The Tsuji tangential spring (Eq. 5-6) with Coulomb limit and its history rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kFormulaTolerance = 1e-9;  // relative; only rounding separates code and formula

// A sphere held at a fixed overlap h on a plane that is dragged tangentially along x by the
// path `moves` (signed distances). Returns (wall displacement, tangential force on the wall).
std::vector<std::pair<double, double>> drag(const std::vector<double>& moves, double speed) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  const double r = 1e-3, h = 2e-5;
  s.planes = {PlaneDef{"plane", Vec3::Zero(), Vec3::UnitZ(), 0}};
  ParticleDef p;
  p.r = r;
  p.body = 0;
  p.x = Vec3(0, 0, r - h);
  s.particles = {p};
  s.drivers = {HoldGroupDef{GroupDef{GroupDef::Kind::body, 0}}};
  Simulation sim(s);
  std::vector<std::pair<double, double>> out;
  for (double d : moves) {
    sim.add_driver(MoveWallDef{"plane", Vec3(d > 0 ? speed : -speed, 0, 0), std::abs(d), std::nullopt});
    while (sim.drivers_moving()) {
      sim.step();
      out.emplace_back(sim.planes()[0].point.x(), sim.plane_loads()[0].force.x());
    }
  }
  return out;
}

TEST(TangentialSpring, DragFollowsEquation5ThenSlidesAtCoulombAndUnloadsElastically) {
  const Material m = testing::paper_grain();
  const double r = 1e-3, h = 2e-5;
  const double D = 0.75 * 2 * (1 - m.nu * m.nu) / m.E;
  const double Fn = std::sqrt(r) * std::pow(h, 1.5) / D;                             // Eq. 3, R12 = r
  const double kt = std::sqrt(r * h) * 2 * m.E / ((2 - m.nu) * (1 + m.nu));         // Eq. 5-6
  const double slip = m.mu * Fn / kt;  // spring length at which Ft reaches mu Fn
  // Out to 2 slip lengths, back by 4, out again by 4: a full hysteresis loop.
  const auto path = drag({2 * slip, -4 * slip, 4 * slip}, 1e-3);
  ASSERT_GT(path.size(), 300u);
  // Expected force on the wall, replaying Eq. 5 with its Coulomb rule along the path: the
  // spring follows the wall's displacement and is shortened to mu Fn / kt when it slides.
  int sliding = 0, sticking = 0;
  double previous_x = 0.0;
  double spring = 0.0;  // spring length of Eq. 5
  for (const auto& [x, Ft] : path) {
    spring += x - previous_x;
    previous_x = x;
    if (std::abs(kt * spring) > m.mu * Fn) {
      spring = std::copysign(m.mu * Fn / kt, spring);
      ++sliding;
    } else {
      ++sticking;
    }
    const double expected = -kt * spring;
    EXPECT_NEAR(Ft, expected, kFormulaTolerance * m.mu * Fn) << "wall at x = " << x;
    EXPECT_LE(std::abs(Ft), m.mu * Fn * (1 + 1e-12));
  }
  EXPECT_GT(sliding, 50);
  EXPECT_GT(sticking, 50);
}

// Equal spheres too: their pair may be found from either sphere by the grid as they move
// (a spring keyed by the finder was once dropped when that flipped).
class RigidRotation : public ::testing::TestWithParam<double> {};  // param: R2 / R1

TEST_P(RigidRotation, OfALoadedContactKeepsItsForce) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  const double R1 = 1e-3, R2 = GetParam() * R1, h = 3e-5;
  ParticleDef a, b;
  a.r = R1;
  a.body = 0;
  b.r = R2;
  b.body = 1;
  b.x = Vec3(R1 + R2 - h, 0, 0);
  s.particles = {a, b};
  s.drivers = {HoldGroupDef{GroupDef{GroupDef::Kind::body, 0}}};
  Simulation sim(s);
  // Load the spring: shear sphere b along y by ~40% of its slip length, then hold it.
  TranslateGroupDef shear;
  shear.group = GroupDef{GroupDef::Kind::body, 1};
  shear.velocity = Vec3(0, 1e-4, 0);
  shear.distance = 3e-6;
  shear.after = AfterDrive::hold;
  sim.add_driver(shear);
  while (sim.drivers_moving()) sim.step();
  sim.step();
  const auto normal_and_tangential = [&] {
    const Vec3 n = (sim.particles().x[1] - sim.particles().x[0]).normalized();
    const Vec3 F = sim.particles().F[1];
    return std::pair{F.dot(n), (F - F.dot(n) * n).norm()};
  };
  const auto [Fn0, Ft0] = normal_and_tangential();
  ASSERT_GT(Ft0, 0.1 * 0.3 * Fn0);  // loaded well inside the Coulomb cone (mu = 0.3)
  // Rotate the pair rigidly by 90 degrees about the contact point, four times about z (a
  // full turn: the spheres swap sides) and once about a skew axis.
  const Vec3 contact = Vec3(R1 - 0.5 * h, 0, 0);
  const Vec3 z = Vec3::UnitZ();
  for (const Vec3& axis : {z, z, z, z, Vec3(0, 1, 1).normalized()}) {
    sim.release_drivers();
    RotateGroupDef rot;
    rot.group = GroupDef{};  // all spheres
    rot.centre = contact;
    rot.axis = axis;
    rot.rate = 2.0;
    rot.angle = std::numbers::pi / 2;
    rot.after = AfterDrive::hold;
    sim.add_driver(rot);
    while (sim.drivers_moving()) sim.step();
    sim.step();
    const auto [Fn, Ft] = normal_and_tangential();
    EXPECT_NEAR(Fn, Fn0, kFormulaTolerance * Fn0);
    EXPECT_NEAR(Ft, Ft0, kFormulaTolerance * Ft0) << "axis " << axis.transpose();
  }
}

INSTANTIATE_TEST_SUITE_P(SizeRatios, RigidRotation, ::testing::Values(1.0, 1.5));

// A sphere on a plane dragged at speed u along x (gravity presses it, friction drags it): a free
// solid sphere ends rolling with v = 2/7 u (angular momentum about the contact point is conserved,
// m v r + I w = 0 with v - w r = u and I = 2/5 m r^2); one whose rotation is locked
// (particles[].rotation: locked) cannot roll and ends moving with the plane, its spin exactly 0.
double belt_speed(bool locked, double& max_spin) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = 0.5;
  s.effects.gravity = Vec3(0, 0, -9.81);
  const double r = 1e-3;
  s.planes = {PlaneDef{"plane", Vec3::Zero(), Vec3::UnitZ(), 0}};
  ParticleDef p;
  p.r = r;
  p.x = Vec3(0, 0, r);
  p.spin_locked = locked;
  s.particles = {p};
  Simulation sim(s);
  sim.run_for(0.05);  // settles on the plane
  const double u = 2e-3;
  sim.add_driver(MoveWallDef{"plane", Vec3(u, 0, 0), 0.05 * r, std::nullopt});
  max_spin = 0.0;
  while (sim.drivers_moving()) {
    sim.step();
    max_spin = std::max(max_spin, sim.particles().w[0].norm());
  }
  return sim.particles().v[0].x() / u;
}

TEST(LockedRotation, AFreeSphereRollsAtTwoSeventhsOfTheBeltAndALockedOneMovesWithIt) {
  double spin_free = 0.0, spin_locked = 1.0;
  EXPECT_NEAR(belt_speed(false, spin_free), 2.0 / 7.0, 0.02);
  EXPECT_GT(spin_free, 0.5);  // [rad/s]: it rolls, at 5/7 u / r = 1.4 rad/s in the end
  EXPECT_NEAR(belt_speed(true, spin_locked), 1.0, 0.02);
  EXPECT_EQ(spin_locked, 0.0);
}

}  // namespace
}  // namespace softpack
