// Free shells (walls/spherical_shell.hpp, ShellDef::mass): a soft-particle's shell that moves as a
// rigid body under its grains' load, so that a medium of soft-particles can be resolved grain by
// grain. Conserved quantities and the saved state.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/momenta.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

// Three soft-particles (a shell of 8 mm with about 60 grains each) thrown at each other, every
// contact effect on, the shells free.
SceneDef three_soft_particles() {
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = 0.6;
  testing::Random rng(5);
  const double Rs = 0.008;
  const Vec3 centres[] = {Vec3(0, 0, 0), Vec3(2.05 * Rs, 0.3 * Rs, 0), Vec3(0.9 * Rs, 2.0 * Rs, 0.4 * Rs)};
  for (int b = 0; b < 3; ++b) {
    const Vec3 v = rng.in_box(0.1) - 0.1 * centres[b] / Rs;  // towards the middle
    for (ParticleDef p : testing::random_spheres_in_shell(rng, 60, Rs, 6e-4, 2.4e-3, 3.5, 300, b)) {
      p.r *= 1.05;  // into contact with each other and the shell
      p.x += centres[b];
      p.v = v + rng.in_box(0.02);
      p.w = rng.in_box(10.0);
      s.particles.push_back(p);
    }
    s.shells.push_back(ShellDef{"shell" + std::to_string(b), b, centres[b], Rs, 0, ShellContactRadius::concave, 1e-4});
  }
  return s;
}

using testing::momenta;
using testing::Momenta;

TEST(FreeShells, MomentaOfSoftParticlesResolvedGrainByGrainAreConserved) {
  Simulation sim(three_soft_particles());
  const Momenta m0 = momenta(sim);
  const Vec3 c0 = sim.shells()[0].centre;
  for (int chunk = 0; chunk < 20; ++chunk) sim.run_steps(100);
  const Momenta m1 = momenta(sim);
  EXPECT_GT((sim.shells()[0].centre - c0).norm(), 1e-4) << "the shell must move with its grains";
  EXPECT_GT(sim.shell_loads()[0].force.norm(), 0.0);
  EXPECT_LT((m1.P - m0.P).norm(), 1e-12 * m0.P_scale);
  EXPECT_LT((m1.L - m0.L).norm(), 1e-12 * m0.L_scale);
}

TEST(FreeShells, ARunContinuesBitForBitFromItsState) {
  Simulation first(three_soft_particles());
  first.run_steps(500);
  const SimulationState st = first.state();
  ASSERT_EQ(st.shell_velocities.size(), 3u);
  Simulation second(three_soft_particles());
  second.restore(st);
  first.run_steps(300);
  second.run_steps(300);
  EXPECT_EQ(state_digest(first.state()), state_digest(second.state()));
}

TEST(FreeShells, AFreeShellIsNotDriven) {
  SceneDef s = three_soft_particles();
  s.drivers = {MoveWallDef{"shell1", Vec3(0.01, 0, 0), 0.001, std::nullopt}};
  try {
    Simulation sim(s);
    FAIL() << "a driver on a free shell must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("drivers[0].wall: shell 'shell1' is free"), std::string::npos) << e.what();
  }
  s = three_soft_particles();
  s.shells[2].mass = -1.0;
  EXPECT_THROW(Simulation{s}, InputError);
}

}  // namespace
}  // namespace softpack
