// An effect the scene does not declare leaves its state untouched and unallocated.
#include <gtest/gtest.h>

#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

SceneDef pile(bool friction, bool rotation, bool damping) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = friction;
  s.effects.rotation = rotation;
  if (damping) s.effects.restitution = 0.5;
  testing::Random rng(7);
  // Non-overlapping spheres in a ball, moving at random: a gas of colliding grains.
  s.particles = testing::random_spheres_in_shell(rng, 300, 0.016, 5e-4, 2e-3, 3.5, 1000, kNoBody);
  for (auto& p : s.particles) p.v = rng.in_box(0.2);
  return s;
}

TEST(Effects, FrictionlessSceneHasNoTangentialHistoryNoSpinNoDrivers) {
  Simulation sim(pile(false, false, false));
  sim.run_steps(50);
  ASSERT_GT(sim.pair_list().size(), 0u);
  EXPECT_EQ(sim.pair_list().spring.capacity(), 0u);
  EXPECT_EQ(sim.particles().w.capacity(), 0u);
  EXPECT_EQ(sim.particles().T.capacity(), 0u);
  EXPECT_EQ(sim.particles().inv_I.capacity(), 0u);
  EXPECT_EQ(sim.particles().driven.capacity(), 0u);
  EXPECT_TRUE(sim.plane_lists().empty());
  EXPECT_TRUE(sim.shell_lists().empty());
}

TEST(Effects, FrictionWithoutRotationHasSpringsButNoSpin) {
  Simulation sim(pile(true, false, false));
  sim.run_steps(50);
  EXPECT_EQ(sim.pair_list().spring.size(), sim.pair_list().size());
  EXPECT_EQ(sim.particles().w.capacity(), 0u);
}

TEST(Effects, UndampedFrictionlessCollisionsKeepTheirEnergyDampedOnesLoseIt) {
  // Same cloud, damping declared or not: only the damped one dissipates.
  for (bool damping : {false, true}) {
    SceneDef s = pile(false, false, damping);
    s.integration.safety = 0.05;
    Simulation sim(s);
    const Measurement m0 = sim.residuals();
    const double e0 = m0.kinetic_energy + m0.elastic_energy;
    sim.run_steps(5000);
    const Measurement m1 = sim.residuals();
    const double e1 = m1.kinetic_energy + m1.elastic_energy;
    if (damping) EXPECT_LT(e1, 0.99 * e0);
    else EXPECT_NEAR(e1, e0, 1e-4 * e0);
  }
}

TEST(Effects, GravityOnlyWhenDeclared) {
  SceneDef s = testing::basic_scene();
  ParticleDef p;
  p.r = 1e-3;
  s.particles = {p};
  Simulation still(s);
  still.run_steps(10);
  EXPECT_EQ(still.particles().v[0], Vec3::Zero());
  s.effects.gravity = Vec3(0, 0, -9.81);
  Simulation falling(s);
  falling.run_steps(10);
  // Free fall: velocity Verlet is exact for constant acceleration.
  EXPECT_NEAR(falling.particles().v[0].z(), -9.81 * falling.time(), 1e-12);
  EXPECT_NEAR(falling.particles().x[0].z(), -0.5 * 9.81 * falling.time() * falling.time(), 1e-15);
}

}  // namespace
}  // namespace softpack
