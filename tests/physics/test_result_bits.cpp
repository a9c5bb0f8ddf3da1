// Results are versioned, not frozen: these digests are the bits of three runs, recorded with the
// engine of release 0.1.0 (be4482f) and reproduced since. A change that alters them must bump
// the release version and re-archive (README); then record the new digests here.
//
// About 300 grains inflated into contact, confined in a shell, a plane wall pressed into them,
// gravity, 400 steps: pairs, shell and plane contacts that open, close and slide. Variants:
//   0  friction, rotation, damping, synchronized spring history (the paper profile's effects)
//   1  friction, rotation, no damping, standard history
//   2  no friction, damping
// The digest covers positions, velocities, spins, forces, torques, springs and wall loads, and is
// the same on every processor (the AVX-512 and portable loops give the same bits, IsaPaths.*).
#include <gtest/gtest.h>

#include <cstdint>

#include "core/parallel.hpp"
#include "forces/contact_loop.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

std::uint64_t digest_of(const SimulationState& s, const std::vector<WallLoad>& planes, const std::vector<WallLoad>& shells) {
  Fnv1a h;
  add_bits(h, s);
  for (const auto* loads : {&planes, &shells})
    for (const auto& l : *loads) h.add(&l.force, sizeof l.force), h.add(&l.torque, sizeof l.torque);
  return h.value;
}

SceneDef scene(int variant, int grains = 300) {
  SceneDef s = testing::basic_scene();
  testing::Random rng(101);
  s.particles = testing::random_spheres_in_shell(rng, grains, 0.016, grains == 300 ? 8e-4 : 4e-4, 3e-3, 3.5, 200, 0);
  std::vector<ParticleDef> kept;  // inflated into contact; the ones beyond the wall dropped
  for (auto p : s.particles) {
    p.r *= 1.15, p.v = rng.in_box(0.02), p.material = 0;
    if (p.x.x() + p.r < 0.0105 && p.x.norm() + p.r < 0.016) kept.push_back(p);
  }
  s.particles = kept;
  s.shells.push_back(ShellDef{"shell", 0, Vec3::Zero(), 0.016, 0, ShellContactRadius::concave, std::nullopt});
  s.planes.push_back(PlaneDef{"wall", Vec3(0.0105, 0, 0), Vec3(-1, 0, 0), 0});
  s.drivers = {MoveWallDef{"wall", Vec3(-0.1, 0, 0), 0.002, std::nullopt}};
  s.effects.gravity = Vec3(0, 0, -9.81);
  s.effects.friction = variant < 2;
  s.effects.rotation = variant < 2;
  if (variant != 1) s.effects.restitution = 0.5;
  s.integration.history_update = variant == 1 ? HistoryUpdate::standard : HistoryUpdate::synchronized;
  return s;
}

TEST(ResultBits, ThreeRunsKeepTheDigestsOfTheirRelease) {
  const std::uint64_t recorded[] = {0x417f6f7259abc408ull, 0x7e08532cde4b04aeull, 0x600235d049d47709ull};
  for (int variant = 0; variant < 3; ++variant) {
    Simulation sim(scene(variant));
    sim.run_steps(400);
    ASSERT_GT(sim.residuals().contacts, 80u);
    EXPECT_GT(sim.plane_loads()[0].force.norm(), 0.0) << "variant " << variant << ": the wall must touch the grains";
    EXPECT_EQ(digest_of(sim.state(), sim.plane_loads(), sim.shell_loads()), recorded[variant])
        << "variant " << variant << ": the result bits changed (bump the release and re-archive, then record the digest)";
  }
}

// On threads (core/parallel.hpp) each sphere's sum is made by one thread in list order
// (forces/pair_contacts.hpp): the bits are the same for 1, 2, 3 and 8 threads -- the recorded
// ones, and on a scene large enough for every thread to have pairs, ghost pairs (the spheres are
// in generation order: many) and wall contacts, those of one thread.
TEST(ResultBits, TheSameBitsForAnyThreadCount) {
  const std::uint64_t recorded[] = {0x417f6f7259abc408ull, 0x7e08532cde4b04aeull, 0x600235d049d47709ull};
  const int before = parallel::threads();
  std::uint64_t one_thread[3] = {0, 0, 0};
  for (const int threads : {1, 2, 3, 8}) {
    parallel::set_threads(threads);
    for (int variant = 0; variant < 3; ++variant) {
      Simulation sim(scene(variant));
      sim.run_steps(100);
      SceneDef many = scene(variant, 3000);
      many.drivers.clear();  // state() is taken after 40 steps, when the wall would still be moving
      Simulation big(many);
      big.run_steps(40);
      ASSERT_GT(big.residuals().contacts, 2 * kBlock) << "the scene must give every thread thousands of contacts";
      const std::uint64_t d = digest_of(big.state(), big.plane_loads(), big.shell_loads());
      if (threads == 1) one_thread[variant] = d;
      EXPECT_EQ(d, one_thread[variant]) << threads << " threads, variant " << variant << ": not the bits of one thread";
      sim.run_steps(300);
      EXPECT_EQ(digest_of(sim.state(), sim.plane_loads(), sim.shell_loads()), recorded[variant])
          << threads << " threads, variant " << variant << ": not the recorded bits";
    }
  }
  parallel::set_threads(before);
}

}  // namespace
}  // namespace softpack
