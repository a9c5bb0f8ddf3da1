// The normal and tangential sweeps (measure/): the chain measures Hertz's law, zero force at
// contact, balance of soft-soft, mirror symmetry of the shear, and bit-identical resumption.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/version.hpp"
#include "support/sweep_fixture.hpp"

namespace softpack {
namespace {

using testing::TempDir;
PackingFile packing(std::uint64_t seed) { return testing::sweep_packing(seed); }

// With the soft-particle replaced by one solid sphere of radius Rs, the whole chain (loading,
// relaxation, force measurement) must give Hertz's law for a sphere on a wall, Eq. 3:
// Fn = sqrt(Rs) hn^(3/2) / D, R12 = Rs.
TEST(NormalSweep, TheChainMeasuresHertz) {
  TempDir tmp("hertz");
  SweepContext c = testing::sweep_context(hertz_check_setup(0.016, parse_measurement(testing::sweep_profile()).simulation), tmp / "n");
  const auto points = run_normal_sweep(c);
  const Material& m = c.settings.simulation.material;
  const double D = 0.75 * 2.0 * (1 - m.nu * m.nu) / m.E;  // Eq. 4, wall of the same material
  ASSERT_EQ(points.size(), c.settings.normal.delta_n.size());
  for (const PointResult& p : points) {
    const double expected = std::sqrt(0.016) * std::pow(p.hn, 1.5) / D;
    EXPECT_NEAR(p.force.x(), expected, 1e-6 * expected + 1e-300) << "delta_n = " << p.delta_n;
    EXPECT_NEAR(p.force.y(), 0.0, 1e-12 * (expected + 1e-12));
    // The deepest overlap relative to the radius: the sphere's own on the wall, hn / Rs.
    EXPECT_NEAR(p.overlap_max, p.delta_n, 1e-9) << "delta_n = " << p.delta_n;
    EXPECT_EQ(p.overlap_q99, p.overlap_max) << "one contact: its percentile is its value";
  }
}

// A wall of another material (material.wall): Eq. 4 with both materials,
// D = 3/4 ((1 - nu^2) / E + (1 - nu'^2) / E').
TEST(NormalSweep, TheChainMeasuresHertzOnAWallOfAnotherMaterial) {
  TempDir tmp("hertz-wall");
  SimulationSettings s = parse_measurement(testing::sweep_profile()).simulation;
  s.wall_material.E = 20.0 * s.material.E;
  s.wall_material.nu = 0.45;
  SweepContext c = testing::sweep_context(hertz_check_setup(0.016, s), tmp / "n");
  c.settings.simulation = s;
  const auto points = run_normal_sweep(c);
  const Material &m = s.material, &w = s.wall_material;
  const double D = 0.75 * ((1 - m.nu * m.nu) / m.E + (1 - w.nu * w.nu) / w.E);
  for (const PointResult& p : points) {
    const double expected = std::sqrt(0.016) * std::pow(p.hn, 1.5) / D;
    EXPECT_NEAR(p.force.x(), expected, 1e-6 * expected + 1e-300) << "delta_n = " << p.delta_n;
  }
}

TEST(NormalSweep, NoForceAtContactAndSoftSoftIsBalanced) {
  TempDir tmp("balance");
  const PackingFile a = packing(1), b = packing(2);
  const auto settings = parse_measurement(testing::sweep_profile());
  for (const ContactSetup& setup : {soft_solid_setup(a, settings.simulation), soft_soft_setup(a, b, settings.simulation)}) {
    const auto points = run_normal_sweep(testing::sweep_context(setup, tmp / scene_name(setup.kind)));
    EXPECT_LT(points.front().force.norm(), 1e-15) << scene_name(setup.kind) << ": force at hn = 0";
    const PointResult& last = points.back();
    ASSERT_GT(last.force.x(), 0.0) << scene_name(setup.kind) << ": no repulsion at the deepest point";
    const auto& conv = std::get<ConvergedRelaxationDef>(settings.relaxation);
    ASSERT_LT(last.checks.back().residuals.force_ratio(), conv.force_tolerance) << "not relaxed: the balance is not tested";
    // In balance the first shell holds what the second body receives: equal and opposite.
    EXPECT_LT((last.force + last.force_first).norm(), 1e-3 * last.force.norm()) << scene_name(setup.kind);
    if (setup.kind == ContactScene::soft_soft) {
      EXPECT_LT((last.force_between - last.force).norm(), 1e-3 * last.force.norm());
    }
  }
}

// One grain in its shell pressed by the wall is symmetric under y -> -y: turning it by +alpha
// and -alpha about z must give opposite tangential forces, the +alpha one along +y.
TEST(TangentialSweep, OppositeAnglesGiveOppositeForcesOnAMirrorSymmetricScene) {
  TempDir tmp("mirror");
  PackingFile one;
  one.Rs = 0.016;
  one.centres = {Vec3::Zero()};
  one.radii = {0.9 * one.Rs};
  SweepContext c = testing::sweep_context(soft_solid_setup(one, parse_measurement(testing::sweep_profile()).simulation), tmp / "n");
  c.settings.normal.delta_n = {0.0, 0.15};
  c.settings.tangential.delta_n = {0.15};
  c.settings.tangential.alpha_deg = {-0.5, 0.0, 0.5};
  run_normal_sweep(c);
  SweepContext t = c;
  t.checkpoint_dir = tmp / "t";
  const auto points = run_tangential_sweep(t, tmp / "n");
  ASSERT_EQ(points.size(), 3u);
  const double minus = points[0].force.y(), zero = points[1].force.y(), plus = points[2].force.y();
  EXPECT_GT(plus, 0.0);
  EXPECT_NEAR(plus, -minus, 1e-9 * plus);
  EXPECT_NEAR(zero, 0.0, 1e-9 * plus);
  EXPECT_NEAR(points[0].ht, -std::numbers::pi * 0.016 * 0.5 / 180.0, 1e-18);
}

bool same_results(const std::vector<PointResult>& a, const std::vector<PointResult>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].force != b[k].force || a[k].force_first != b[k].force_first || a[k].force_between != b[k].force_between ||
        a[k].contacts != b[k].contacts || a[k].relax_steps != b[k].relax_steps || a[k].steps != b[k].steps ||
        a[k].checks.size() != b[k].checks.size())
      return false;
    for (std::size_t j = 0; j < a[k].checks.size(); ++j)
      if (a[k].checks[j].residuals.elastic_energy != b[k].checks[j].residuals.elastic_energy) return false;
  }
  return true;
}

// A sweep interrupted after any point and started again recomputes nothing finished and gives
// the same bits as one that never stopped (the wall-clock times aside).
TEST(Sweeps, ResumeAfterAnInterruptionGivesIdenticalResults) {
  TempDir tmp("resume");
  const PackingFile a = packing(1);
  const auto settings = parse_measurement(testing::sweep_profile());
  const ContactSetup setup = soft_solid_setup(a, settings.simulation);
  const auto straight = run_normal_sweep(testing::sweep_context(setup, tmp / "straight"));
  SweepContext ts = testing::sweep_context(setup, tmp / "straight-t");
  const auto straight_t = run_tangential_sweep(ts, tmp / "straight");
  for (std::size_t stop = 1; stop < settings.normal.delta_n.size(); ++stop) {
    const std::string dir = tmp / ("stop-" + std::to_string(stop));
    SweepContext c = testing::sweep_context(setup, dir);
    c.stop_after = stop;
    EXPECT_TRUE(run_normal_sweep(c).empty());
    c.stop_after = 0;
    std::size_t reused = 0;
    c.progress = [&](const std::string&, std::size_t, std::size_t, const PointResult&, bool r) { reused += r; };
    const auto resumed = run_normal_sweep(c);
    EXPECT_TRUE(same_results(resumed, straight)) << "stopped after " << stop << " points";
    EXPECT_EQ(reused, stop);
    // The timing of every point is kept through the resume: a reused point says so and carries
    // the time its computing run recorded in its point file.
    for (std::size_t k = 0; k < resumed.size(); ++k) {
      const PointResult& r = resumed[k];
      EXPECT_EQ(r.reused, k < stop) << k;
      EXPECT_GE(r.timing.loading.cpu, 0.0);
      EXPECT_GE(r.timing.relaxation.cpu, 0.0);
      EXPECT_GT(r.timing.output.wall, 0.0);  // the writer measured its own work
      const PointFile f = read_point_file(normal_point_path(dir, k), false);
      EXPECT_EQ(f.result.timing.relaxation.cpu, r.timing.relaxation.cpu) << k;
      EXPECT_EQ(f.result.timing.output.wall, r.timing.output.wall) << k;
    }
  }
  SweepContext t = testing::sweep_context(setup, tmp / "t");
  t.stop_after = 2;
  EXPECT_TRUE(run_tangential_sweep(t, tmp / "straight").empty());
  t.stop_after = 0;
  EXPECT_TRUE(same_results(run_tangential_sweep(t, tmp / "straight"), straight_t));
}

// A change of result bits bumps the release, so a checkpoint of another release is computed
// again (its configuration alone does not say the bits are this build's), and a tangential
// sweep refuses a normal state of another release rather than start from it.
TEST(Sweeps, ACheckpointOfAnotherReleaseIsComputedAgain) {
  TempDir tmp("release");
  const PackingFile a = packing(1);
  const auto settings = parse_measurement(testing::sweep_profile());
  const ContactSetup setup = soft_solid_setup(a, settings.simulation);
  SweepContext c = testing::sweep_context(setup, tmp / "normal");
  const auto straight = run_normal_sweep(c);
  const std::size_t old = 1;  // point 1 as if an earlier release had computed it
  const std::string path = normal_point_path(tmp / "normal", old);
  PointFile f = read_point_file(path, true);
  const std::string release = release_of(c.code_version);  // the fixture's "test"
  EXPECT_EQ(release_of(f.provenance.code_version), release);
  f.provenance.code_version = "0.0.1 (0000000)";
  write_point_file(path, f.result, f.state, f.provenance);
  std::vector<bool> reused;
  c.progress = [&](const std::string&, std::size_t, std::size_t, const PointResult&, bool r) { reused.push_back(r); };
  const auto again = run_normal_sweep(c);
  EXPECT_TRUE(same_results(again, straight));
  ASSERT_EQ(reused.size(), straight.size());
  for (std::size_t k = 0; k < reused.size(); ++k) EXPECT_EQ(reused[k], k < old) << k;  // from it on: computed again
  EXPECT_EQ(release_of(read_point_file(path, false).provenance.code_version), release);
  // the tangential sweep's normal state of another release
  for (std::size_t k = 0; k < straight.size(); ++k) {
    PointFile g = read_point_file(normal_point_path(tmp / "normal", k), true);
    g.provenance.code_version = "0.0.1 (0000000)";
    write_point_file(normal_point_path(tmp / "normal", k), g.result, g.state, g.provenance);
  }
  SweepContext t = testing::sweep_context(setup, tmp / "t");
  try {
    run_tangential_sweep(t, tmp / "normal");
    ADD_FAILURE() << "a normal state of another release was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("release 0.0.1, this build is " + release), std::string::npos) << e.what();
  }
  EXPECT_EQ(release_of("0.7.0 (7a9968e-dirty)"), "0.7.0");
  EXPECT_EQ(release_of(code_version()), release_version());
  EXPECT_EQ(release_of(""), "");
}

}  // namespace
}  // namespace softpack
