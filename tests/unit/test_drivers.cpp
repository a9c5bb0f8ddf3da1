// Kinematic drivers land exactly on their targets and move their groups rigidly.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
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
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), 0.016, 0, ShellContactRadius::concave, std::nullopt}};
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

namespace softpack {
namespace {

// A run stopped, saved and continued in a fresh simulation gives the same bits as one that
// never stopped: the checkpoints of the sweeps rely on it.
TEST(State, RestoredRunContinuesBitForBit) {
  SceneDef s = body_in_shell();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = 0.5;
  s.effects.gravity = Vec3(0, 0, -9.81);
  for (auto& p : s.particles) p.r *= 1.25;  // overlapping: springs load from the first steps
  Simulation straight(s);
  straight.run_steps(400);
  const SimulationState mid = straight.state();
  ASSERT_FALSE(mid.pair_springs.empty());
  straight.run_steps(400);

  Simulation resumed(s);
  resumed.run_steps(17);  // a different history, overwritten by the restore
  resumed.restore(mid);
  resumed.run_steps(400);
  const auto same = [](const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
  };
  EXPECT_TRUE(same(straight.particles().x, resumed.particles().x));
  EXPECT_TRUE(same(straight.particles().v, resumed.particles().v));
  EXPECT_TRUE(same(straight.particles().w, resumed.particles().w));
  // Springs compared through state(): the Verlet lists themselves may differ (rebuilt at
  // other steps), the contacts and their springs may not.
  const SimulationState a = straight.state(), b = resumed.state();
  ASSERT_EQ(a.pair_springs.size(), b.pair_springs.size());
  for (std::size_t k = 0; k < a.pair_springs.size(); ++k) {
    EXPECT_EQ(a.pair_springs[k].i, b.pair_springs[k].i);
    EXPECT_EQ(a.pair_springs[k].j, b.pair_springs[k].j);
    EXPECT_EQ(a.pair_springs[k].xi, b.pair_springs[k].xi);
  }
  ASSERT_EQ(a.shell_springs[0].size(), b.shell_springs[0].size());
  for (std::size_t k = 0; k < a.shell_springs[0].size(); ++k) EXPECT_EQ(a.shell_springs[0][k].xi, b.shell_springs[0][k].xi);
  EXPECT_EQ(straight.time(), resumed.time());
}

TEST(State, RestoreRefusesAStateOfAnotherScene) {
  SceneDef s = body_in_shell();
  Simulation a(s);
  SimulationState st = a.state();
  st.x.pop_back();
  EXPECT_THROW(a.restore(st), InputError);
}

// Turning a soft-particle rigidly with its shell leaves its shell springs unloaded.
TEST(Drivers, RotationWithTheShellDoesNotSlideAlongIt) {
  SceneDef s = body_in_shell();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.gravity = Vec3(0, 0, -9.81);
  for (auto& p : s.particles) p.r *= 1.25;  // press the spheres on the shell
  Simulation sim(s);
  RotateGroupDef r;
  r.group = GroupDef{GroupDef::Kind::body, 0};
  r.centre = Vec3::Zero();
  r.axis = Vec3::UnitZ();
  r.rate = 1.0;
  r.angle = 0.1;
  r.after = AfterDrive::hold;
  for (const bool with_shell : {true, false}) {
    Simulation run(s);
    r.with_shell = with_shell;
    run.add_driver(r);
    while (run.drivers_moving()) run.step();
    double spring = 0.0;
    for (const Vec3& xi : run.shell_lists()[0].spring) spring = std::max(spring, xi.norm());
    ASSERT_GT(run.residuals().contacts, 0u);
    if (with_shell) EXPECT_LT(spring, 1e-9);  // (rounding only)
    else EXPECT_GT(spring, 1e-6);
  }
}

// About a point other than its centre (the sliding stage's orbit) the shell is carried on the
// arc with its spheres: the motion stays rigid (no shell spring loaded) and the centre ends at
// R(angle) applied about that point.
TEST(Drivers, AnOrbitCarriesTheShellOnTheArc) {
  SceneDef s = body_in_shell();
  s.effects.friction = true;
  s.effects.rotation = true;
  for (auto& p : s.particles) p.r *= 1.25;  // press the spheres on the shell
  const Vec3 c0 = s.shells[0].centre, pivot = c0 - Vec3(2.0 * s.shells[0].radius, 0, 0);
  Simulation run(s);
  RotateGroupDef r;
  r.group = GroupDef{GroupDef::Kind::body, 0};
  r.centre = pivot;
  r.axis = Vec3::UnitZ();
  r.rate = 1.0;
  r.angle = 0.1;
  r.after = AfterDrive::hold;
  r.with_shell = true;
  run.add_driver(r);
  while (run.drivers_moving()) run.step();
  double spring = 0.0;
  for (const Vec3& xi : run.shell_lists()[0].spring) spring = std::max(spring, xi.norm());
  ASSERT_GT(run.residuals().contacts, 0u);
  EXPECT_LT(spring, 1e-9);  // (rounding only)
  const Vec3 expected = pivot + Eigen::AngleAxisd(0.1, Vec3::UnitZ()).toRotationMatrix() * (c0 - pivot);
  EXPECT_LT((run.state().shell_centres[0] - expected).norm(), 1e-10 * s.shells[0].radius);  // rounding over the steps
}

}  // namespace
}  // namespace softpack
