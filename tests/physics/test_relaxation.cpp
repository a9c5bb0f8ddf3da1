// Relaxation protocols reach force balance and report what they did.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "relax/relaxation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

// 500 frictional spheres (polydispersity 5) placed at random in a shell and grown until they
// jam at a solid fraction of 0.62, then grown by 3% more: a compressed packing out of balance.
SceneDef compressed_packing() {
  static const SceneDef scene = [] {
    SceneDef s = testing::basic_scene();
    s.effects.friction = true;
    s.effects.rotation = true;
    s.effects.restitution = 0.3;
    const double Rs = 0.016;
    testing::Random rng(5);
    s.particles = testing::random_spheres_in_shell(rng, 500, Rs, 3.0e-4, 1.5e-3, 3.5, 2000, 0);
    s.shells = {ShellDef{"shell", 0, Vec3::Zero(), Rs, 0, ShellContactRadius::concave, std::nullopt}};
    testing::compress(s, Rs, 0.62, 0.03);
    for (auto& p : s.particles) p.r *= 1.03;
    return s;
  }();
  return scene;
}

TEST(Relaxation, CompressedFrictionalPackingInAShellReachesForceBalance) {
  const SceneDef s = compressed_packing();
  ASSERT_EQ(s.particles.size(), 500u);
  Simulation sim(s);
  const Measurement before = sim.residuals();
  ASSERT_GT(before.force_ratio(), 1.0);  // far from balance to begin with
  ConvergedRelaxationDef def;
  def.force_tolerance = 1e-3;
  def.energy_tolerance = 1e-8;
  def.check_interval = 0.02;
  def.max_time = 5.0;
  def.zero_velocities_at_checks = true;
  const RelaxationReport rep = relax(sim, def);
  ASSERT_TRUE(rep.converged.has_value());
  EXPECT_TRUE(*rep.converged) << "force ratio " << rep.checks.back().residuals.force_ratio()
                              << " energy ratio " << rep.checks.back().residuals.energy_ratio();
  const Measurement after = sim.residuals();
  EXPECT_LT(after.force_ratio(), def.force_tolerance);
  EXPECT_LT(after.energy_ratio(), def.energy_tolerance);
  EXPECT_GT(after.contacts, 500u);
  EXPECT_EQ(rep.steps, sim.step_count());
  EXPECT_NEAR(rep.simulated_time, sim.time(), 1e-12);
  // In balance the shell carries the pressure of the packing but no net force.
  EXPECT_LT(sim.shell_loads()[0].force.norm(), 1e-2 * after.mean_contact_force * after.contacts);
}

TEST(Relaxation, PaperProtocolReportsEveryStop) {
  Simulation sim(compressed_packing());
  const double initial_ratio = sim.residuals().force_ratio();
  PaperRelaxationDef def{6, 0.05, 0.05};
  int seen = 0;
  const RelaxationReport rep = relax(sim, def, [&](const RelaxationCheck&) { ++seen; });
  EXPECT_FALSE(rep.converged.has_value());
  ASSERT_EQ(rep.checks.size(), 7u);  // six stops and the final wait
  EXPECT_EQ(seen, 7);
  EXPECT_EQ(rep.steps, 7 * sim.steps_for(0.05));
  for (int k = 0; k < 6; ++k) EXPECT_EQ(rep.checks[k].residuals.kinetic_energy, 0.0);  // just stopped
  // The stops drain the energy: the residual force falls by orders of magnitude.
  EXPECT_LT(rep.checks.back().residuals.force_ratio(), 1e-2 * initial_ratio);
}

TEST(Relaxation, RejectsBadDefinitions) {
  Simulation sim(compressed_packing());
  EXPECT_THROW(relax(sim, PaperRelaxationDef{-1, 0.3, 0.3}), InputError);
  EXPECT_THROW(relax(sim, ConvergedRelaxationDef{0.0, 1e-6, 0.1, 1.0, false}), InputError);
}

}  // namespace
}  // namespace softpack
