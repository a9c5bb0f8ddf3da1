// Kinematic drivers land exactly on their targets and move their groups rigidly.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

SceneDef body_in_shell() {
  SceneDef s = testing::basic_scene();
  testing::Random rng(3);
  s.particles = testing::random_spheres_in_shell(rng, 60, 0.016, 0.0008, 0.003, 3.5, 200, 0);
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), 0.016, 0, ShellContactRadius::concave}};
  s.planes = {PlaneDef{"wall", Vec3(0, 0, -0.0161), Vec3::UnitZ(), 0}};
  return s;
}

TEST(Drivers, MoveWallLandsExactlyOnItsDistanceThenStops) {
  SceneDef s = body_in_shell();
  s.drivers = {MoveWallDef{"wall", Vec3(0, 0, 2e-3), 1.2345e-4, std::nullopt}};
  Simulation sim(s);
  while (sim.drivers_moving()) sim.step();
  EXPECT_NEAR(sim.planes()[0].point.z(), -0.0161 + 1.2345e-4, 1e-15);
  EXPECT_EQ(sim.planes()[0].velocity, Vec3::Zero());
  const long expected_steps = static_cast<long>(std::ceil(1.2345e-4 / (2e-3 * sim.dt()) - 1e-9));
  EXPECT_EQ(sim.step_count(), expected_steps);
}

TEST(Drivers, RotationIsRigidAndLandsOnItsAngle) {
  SceneDef s = body_in_shell();
  s.effects.friction = true;
  s.effects.rotation = true;
  const double angle = 2.0 * std::numbers::pi / 180.0;
  RotateGroupDef r;
  r.group = GroupDef{GroupDef::Kind::body, 0};
  r.centre = Vec3::Zero();
  r.axis = Vec3(0, 1, 0);
  r.rate = -0.5;
  r.angle = angle;
  r.after = AfterDrive::hold;
  s.drivers = {r};
  Simulation sim(s);
  const std::vector<Vec3> x0 = sim.particles().x;
  while (sim.drivers_moving()) sim.step();
  // Every sphere is where an exact rotation by -angle about y puts it.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(-angle, Vec3::UnitY()).toRotationMatrix();
  for (std::size_t i = 0; i < x0.size(); ++i) EXPECT_LT((sim.particles().x[i] - R * x0[i]).norm(), 1e-15);
  // Held afterwards: at rest and kinematic.
  sim.run_steps(10);
  for (std::size_t i = 0; i < x0.size(); ++i) {
    EXPECT_LT((sim.particles().x[i] - R * x0[i]).norm(), 1e-15);
    EXPECT_EQ(sim.particles().v[i], Vec3::Zero());
    EXPECT_TRUE(sim.particles().is_driven(i));
  }
}

TEST(Drivers, ReleasedSpheresBecomeFree) {
  SceneDef s = body_in_shell();
  TranslateGroupDef t;
  t.group = GroupDef{GroupDef::Kind::body, 0};
  t.velocity = Vec3(1e-3, 0, 0);
  t.distance = 1e-5;
  t.after = AfterDrive::release;
  s.drivers = {t};
  Simulation sim(s);
  while (sim.drivers_moving()) sim.step();
  for (std::size_t i = 0; i < sim.particles().size(); ++i) EXPECT_FALSE(sim.particles().is_driven(i));
}

TEST(Drivers, AddingADriverOnBusySpheresIsRefused) {
  SceneDef s = body_in_shell();
  s.drivers = {HoldGroupDef{GroupDef{GroupDef::Kind::body, 0}}};
  Simulation sim(s);
  EXPECT_THROW(sim.add_driver(HoldGroupDef{GroupDef{}}), InputError);
  sim.release_drivers();
  EXPECT_NO_THROW(sim.add_driver(HoldGroupDef{GroupDef{}}));
}

}  // namespace
}  // namespace softpack
