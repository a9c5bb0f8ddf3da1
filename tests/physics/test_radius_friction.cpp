// Issue 16's measurements, checked where the answer is known: the sliding stage measures
// Coulomb's limit for a solid sphere on a wall; the chain scales a solid sphere's force with the
// square of its radius at fixed delta_n (Hertz's law, dimensional analysis); the second
// soft-particle orbits the first at a fixed distance while it slides; a mixed soft-soft scene
// scales its second packing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/sweep_file.hpp"
#include "support/sweep_fixture.hpp"

namespace softpack {
namespace {

using testing::TempDir;

// A solid sphere of radius Rs held at the origin, pressed into the wall to delta_n = 0.02, the
// wall then moved along +y: the Tsuji spring grows until it reaches mu Fn (Eq. 5's cap) and the
// contact slides there: Ft / Fn = mu = 0.3 (the profile's material) once it slides, below before.
TEST(SlidingSweep, ASolidSphereOnAWallSlidesAtTheCoulombLimit) {
  TempDir tmp("coulomb");
  SweepContext c = testing::sweep_context(hertz_check_setup(0.016, parse_measurement(testing::sweep_profile()).simulation), tmp / "n");
  c.settings.normal.delta_n = {0.0, 0.01, 0.02};
  ASSERT_EQ(run_normal_sweep(c).size(), 3u);
  SweepContext s = c;
  s.checkpoint_dir = tmp / "s";
  s.settings.has_sliding = true;
  s.settings.sliding = SlidingSettings{{0.02}, {0.0005, 0.001, 0.004, 0.008, 0.016}, 0.01};
  const auto points = run_sliding_sweep(s, tmp / "n");
  ASSERT_EQ(points.size(), 5u);
  const double mu = c.settings.simulation.material.mu;
  EXPECT_LT(-points[0].force.y() / points[0].force.x(), 0.5 * mu) << "sticks at the first, small move";
  for (std::size_t k = 3; k < points.size(); ++k) {
    const PointResult& p = points[k];
    EXPECT_NEAR(p.ht, 0.016 * s.settings.sliding.ht_over_Rs[k], 1e-15);
    EXPECT_NEAR(-p.force.y() / p.force.x(), mu, 1e-6 * mu) << "ht/Rs = " << s.settings.sliding.ht_over_Rs[k];
    EXPECT_EQ(p.alpha_deg, 0.0) << "the wall translates: the contact's frame does not turn";
  }
  // A rerun reuses every point, bit for bit.
  const auto again = run_sliding_sweep(s, tmp / "n");
  ASSERT_EQ(again.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_TRUE(again[k].reused);
    EXPECT_EQ(again[k].force, points[k].force);
  }
}

// Hertz's law, Fn = sqrt(R) h^(3/2) / D with h = delta_n R, makes a solid sphere's force at fixed
// delta_n scale as R^2: the chain (scene, loading, relaxation, measurement) at Rs and 2 Rs gives
// a ratio of 4, as the self-similar soft-particles of the radius study must in the quasi-static
// limit (docs/radius.md).
TEST(NormalSweep, AtFixedDeltaNTheChainScalesASolidSphereAsRSquared) {
  TempDir tmp("scaling");
  const SimulationSettings sim = parse_measurement(testing::sweep_profile()).simulation;
  SweepContext small = testing::sweep_context(hertz_check_setup(0.016, sim), tmp / "small");
  SweepContext large = testing::sweep_context(hertz_check_setup(0.032, sim), tmp / "large");
  const auto f1 = run_normal_sweep(small), f2 = run_normal_sweep(large);
  ASSERT_EQ(f1.size(), f2.size());
  for (std::size_t k = 0; k < f1.size(); ++k) {
    if (f1[k].delta_n == 0.0) continue;
    EXPECT_NEAR(f2[k].force.x() / f1[k].force.x(), 4.0, 4e-6) << "delta_n = " << f1[k].delta_n;
    EXPECT_NEAR(f2[k].hn, 2.0 * f1[k].hn, 1e-15);
  }
}

// The second soft-particle slides by orbiting the first's centre: its shell's centre keeps the
// distance 2 Rs - hn (the contact its depth), turned by the recorded angle ht / Rs.
TEST(SlidingSweep, TheSecondSoftParticleOrbitsAtAFixedDistance) {
  TempDir tmp("orbit");
  const SimulationSettings sim = parse_measurement(testing::sweep_profile()).simulation;
  SweepContext c = testing::sweep_context(soft_soft_setup(testing::sweep_packing(1), testing::sweep_packing(2), sim), tmp / "n");
  c.settings.normal.delta_n = {0.0, 0.5};
  ASSERT_EQ(run_normal_sweep(c).size(), 2u);
  SweepContext s = c;
  s.checkpoint_dir = tmp / "s";
  s.settings.has_sliding = true;
  s.settings.sliding = SlidingSettings{{0.5}, {0.02, 0.1}, 0.02};
  const auto points = run_sliding_sweep(s, tmp / "n");
  ASSERT_EQ(points.size(), 2u);
  const double Rs = 0.016;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double theta = s.settings.sliding.ht_over_Rs[k];  // [rad]
    EXPECT_NEAR(points[k].alpha_deg, theta * 180.0 / std::numbers::pi, 1e-12);
    const SimulationState state = read_point_file(sliding_point_path(tmp / "s", 0, k), true).state;
    ASSERT_EQ(state.shell_centres.size(), 2u);
    const Vec3 c2 = state.shell_centres[1];
    EXPECT_NEAR(c2.norm(), (2.0 - 0.5) * Rs, 1e-12 * Rs) << "ht/Rs = " << theta;
    EXPECT_NEAR(std::atan2(c2.y(), c2.x()), theta, 1e-9);
    EXPECT_NEAR(state.shell_centres[0].norm(), 0.0, 1e-15) << "the first shell stays";
  }
}

// normal.second_radius_ratio: the second packing scaled by k, its shell touching the first.
TEST(ContactScenes, AMixedSoftSoftSceneScalesTheSecondPacking) {
  const SimulationSettings sim = parse_measurement(testing::sweep_profile()).simulation;
  const PackingFile a = testing::sweep_packing(1), b = testing::sweep_packing(2);
  const ContactSetup s = soft_soft_setup(a, b, sim, 0.5);
  ASSERT_EQ(s.scene.shells.size(), 2u);
  EXPECT_DOUBLE_EQ(s.scene.shells[1].radius, 0.5 * b.Rs);
  EXPECT_DOUBLE_EQ(s.scene.shells[1].centre.x(), a.Rs + 0.5 * b.Rs);
  ASSERT_EQ(s.scene.particles.size(), a.radii.size() + b.radii.size());
  for (std::size_t i = 0; i < b.radii.size(); ++i) {
    const ParticleDef& p = s.scene.particles[a.radii.size() + i];
    EXPECT_DOUBLE_EQ(p.r, 0.5 * b.radii[i]);
    EXPECT_LT((p.x - s.scene.shells[1].centre - 0.5 * b.centres[i]).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace softpack
