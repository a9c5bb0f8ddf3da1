// The resolved model's cost estimate of a medium of nested soft-particles and its plan a few
// levels deeper (coarse/resolved_estimate.hpp, docs/nested.md "The three-decade medium"), by hand
// on the tiny nested medium (its sites at two levels, every content made). The estimate of a
// sampled medium: test_nested_medium.cpp, NestedMedium.ASampledMediumWeighsItsSitesSitesByTheMean.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "coarse/medium.hpp"
#include "coarse/resolved_estimate.hpp"
#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "sim/simulation.hpp"
#include "support/coarse_tiny.hpp"

namespace softpack {
namespace resolved_estimate_test {

const CoarseGrainSettings& nested() { return testing::coarse_grain_nested_tiny(); }

const Medium& medium() {
  static const Medium m = build_medium(nested(), 901);
  return m;
}

SoftParticleLaws laws() { return soft_particle_laws(read_law_file(nested().laws), nested().laws); }

// The resolved model's cost estimate (coarse/resolved_estimate.hpp): N spheres, the engine's own
// step for the resolved scene, the soft run's simulated time over it, the measured runs' mean CPU
// time per sphere-step; a run of another medium or of the wrong model refused.
TEST(NestedMedium, TheResolvedEstimateIsSpheresTimesStepsTimesTheMeasuredCost) {
  const Medium& m = medium();
  const SceneDef resolved = medium_scene(nested(), m, CoarseModel::resolved, laws());
  CoarseResult soft;
  soft.path = "soft.h5", soft.model = "soft", soft.steps = 1000, soft.dt = 1e-6, soft.cpu_seconds = 2.0;
  soft.grains = static_cast<std::int64_t>(m.grain_x.size()), soft.sites = static_cast<std::int64_t>(m.sites.size());
  CoarseResult a, b;
  a.path = "a.h5", b.path = "b.h5", a.model = b.model = "resolved";
  a.spheres = b.spheres = 100, a.steps = b.steps = 1000, a.cpu_seconds = 10.0, b.cpu_seconds = 30.0;  // 1e-4 and 3e-4 s
  const ResolvedEstimate e = estimate_resolved(nested(), m, soft, {a, b});
  EXPECT_EQ(e.spheres, static_cast<double>(resolved.particles.size()));
  EXPECT_EQ(e.spheres_error, 0.0) << "every content made: counted";
  EXPECT_NEAR(e.dt, Simulation(resolved).dt(), 1e-12 * e.dt) << "the engine's step for the whole resolved scene";
  EXPECT_NEAR(e.steps, 1000 * 1e-6 / e.dt, 1e-9 * e.steps);
  EXPECT_NEAR(e.cpu_per_sphere_step, 2e-4, 1e-15);
  EXPECT_NEAR(e.cpu_per_sphere_step_error, 1e-4, 1e-15);
  EXPECT_NEAR(e.cpu, static_cast<double>(e.spheres) * e.steps * 2e-4, 1e-9 * e.cpu);
  EXPECT_NEAR(e.speed_up(), e.cpu / 2.0, 1e-9 * e.speed_up());
  // The file names the soft run's contacts beyond the laws' range, as the run counted them.
  CoarseResult pressed = soft;
  pressed.beyond_range = 7, pressed.max_dn = 1.25;
  const auto j = nlohmann::json::parse(resolved_estimate_json(e, "c.yaml", "m.h5", pressed, {a, b}));
  EXPECT_EQ(j.at("soft_beyond_range").get<long>(), 7);
  EXPECT_EQ(j.at("soft_max_dn").get<double>(), 1.25);
  EXPECT_TRUE(j.at("soft_within_laws").at("strain").is_null()) << "rows that do not count them";
  // Rows that count them: beyond from the third loading row on, so within the laws up to the second.
  for (int k = 0; k < 4; ++k) {
    CurveRow row;
    row.strain = 0.01 * k, row.sigma_top = 100.0 * k, row.beyond_range = k >= 2 ? 7 : 0, row.max_dn = 0.3 * k;
    pressed.rows.push_back(row);
  }
  const auto w = nlohmann::json::parse(resolved_estimate_json(e, "c.yaml", "m.h5", pressed, {a, b})).at("soft_within_laws");
  EXPECT_EQ(w.at("strain").get<double>(), 0.01);
  EXPECT_EQ(w.at("sigma_zz").at("value").get<double>(), 100.0);
  EXPECT_FALSE(j.contains("plan")) << "no plan without plan.levels_added";
  CoarseResult other = soft;
  other.sites += 1;
  EXPECT_THROW(estimate_resolved(nested(), m, other, {a}), InputError);
  EXPECT_THROW(estimate_resolved(nested(), m, soft, {soft}), InputError);
  EXPECT_THROW(estimate_resolved(nested(), m, soft, {}), InputError);
}

// The plan (coarse/resolved_estimate.hpp, settings plan.levels_added): the same medium a levels
// deeper, by hand. At two levels (D = 1) the sites' sites are grains-only packings, and one and two
// levels more make each of them hold n + 1 and n² + n + 1 packings' worth of grains; the step is
// the engine's for a grain Π^a smaller, the Rayleigh time's proportion to the radius.
TEST(NestedMedium, ThePlanDeeperCountsTheContentsLevelsByTheirSitesAndShortensTheStep) {
  const Medium& m = medium();
  double own = static_cast<double>(m.grain_r.size()), inside = 0.0, sites = 0.0;
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    own += static_cast<double>(m.packings[k].radii.size());
    inside += site_inside(m, k).grains;
    sites += static_cast<double>(m.inner_sites[k].size());
  }
  ASSERT_GT(inside, 0.0);
  const double n = sites / static_cast<double>(m.sites.size());
  CoarseResult soft;
  soft.path = "soft.h5", soft.model = "soft", soft.steps = 1000, soft.dt = 1e-6, soft.cpu_seconds = 2.0;
  soft.grains = static_cast<std::int64_t>(m.grain_x.size()), soft.sites = static_cast<std::int64_t>(m.sites.size());
  CoarseResult a;
  a.path = "a.h5", a.model = "resolved", a.spheres = 100, a.steps = 1000, a.cpu_seconds = 10.0;
  EXPECT_EQ(estimate_resolved(nested(), m, soft, {a}).deeper.levels_added, 0) << "no plan without plan.levels_added";
  const double Pi = nested().packing.polydispersity;
  for (const int added : {1, 2}) {
    CoarseGrainSettings s = nested();
    s.plan_levels_added = added;
    const ResolvedEstimate e = estimate_resolved(s, m, soft, {a});
    const DeeperPlan& d = e.deeper;
    EXPECT_EQ(d.levels_added, added);
    EXPECT_NEAR(d.sites_per_packing, n, 1e-12);
    const double ratio = added == 1 ? n + 1.0 : n * n + n + 1.0;
    EXPECT_NEAR(d.depth_ratio, ratio, 1e-12 * ratio);
    EXPECT_NEAR(d.spheres, own + ratio * inside, 1e-9 * d.spheres);
    EXPECT_NEAR(e.spheres, own + inside, 1e-9 * e.spheres) << "the estimate itself unchanged";
    EXPECT_NEAR(d.smallest_radius, e.smallest_radius / std::pow(Pi, added), 1e-15);
    EXPECT_NEAR(d.dt, e.dt / std::pow(Pi, added), 1e-9 * d.dt);
    EXPECT_NEAR(d.steps, 1000 * 1e-6 / d.dt, 1e-9 * d.steps);
    EXPECT_NEAR(d.cpu, d.spheres * d.steps * 1e-4, 1e-9 * d.cpu);
    EXPECT_EQ(d.cpu_error, 0.0) << "every content made, c measured once";
  }
}

}  // namespace resolved_estimate_test
}  // namespace softpack
