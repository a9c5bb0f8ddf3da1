// Linear and angular momentum are conserved in a free polydisperse cloud with every contact
// effect on: contact forces are equal and opposite and act at one common contact point, and
// velocity Verlet preserves both momenta of such forces exactly (up to rounding).
#include <gtest/gtest.h>

#include "sim/simulation.hpp"
#include "support/momenta.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kConservedTolerance = 1e-12;  // relative to the sum of the magnitudes

using testing::momenta;
using testing::Momenta;

TEST(Conservation, MomentaOfA1000SpherePolydisperseCloud) {
  for (const HistoryUpdate hu : {HistoryUpdate::synchronized, HistoryUpdate::standard}) {
    SceneDef s = testing::basic_scene();
    s.effects.friction = true;
    s.effects.rotation = true;
    s.effects.restitution = 0.6;
    s.integration.history_update = hu;
    testing::Random rng(11);
    // Polydispersity 10: 1000 spheres placed without overlap in a ball, then swollen by 8% so
    // that hundreds of contacts are closed from the start; random velocities and spins make
    // contacts open, close and slide.
    s.particles = testing::random_spheres_in_shell(rng, 1000, 0.02, 5e-4, 5e-3, 3.0, 500, kNoBody);
    ASSERT_EQ(s.particles.size(), 1000u);
    for (auto& p : s.particles) {
      p.r *= 1.08;
      p.x += Vec3(0.03, -0.01, 0.02);  // away from the origin: L has an orbital part
      p.v = rng.in_box(0.05);
      p.w = rng.in_box(20.0);
    }
    Simulation sim(s);
    const std::size_t contacts0 = sim.residuals().contacts;
    EXPECT_GT(contacts0, 300u);
    const Momenta m0 = momenta(sim);
    double P_scale = m0.P_scale, L_scale = m0.L_scale;
    for (int chunk = 0; chunk < 30; ++chunk) {
      sim.run_steps(100);
      const Momenta m = momenta(sim);
      P_scale = std::max(P_scale, m.P_scale);  // rounding follows the largest terms summed
      L_scale = std::max(L_scale, m.L_scale);
      EXPECT_LT((m.P - m0.P).norm(), kConservedTolerance * P_scale);
      EXPECT_LT((m.L - m0.L).norm(), kConservedTolerance * L_scale);
    }
    EXPECT_LT(sim.residuals().contacts, contacts0 / 2);  // the swollen cloud has burst open
  }
}

}  // namespace
}  // namespace softpack
