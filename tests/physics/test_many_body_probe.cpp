// The many-body probe's analysis (coarse/probe_fit.hpp, paper/many-body.md): the candidates'
// geometry, each reducing to the pairwise law for one contact, the probe file's reader, and the
// rule finding the law that made a synthetic probe.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "coarse/probe_fit.hpp"
#include "core/error.hpp"
#include "coarse/probe_second.hpp"
#include "coarse/probe_third.hpp"
#include "coarse/validation.hpp"
#include "coarse/kinematics.hpp"
#include "formats/law_file.hpp"
#include "core/error.hpp"
#include "support/power_law.hpp"

namespace softpack {
namespace {

TEST(ManyBodyProbeLaws, CapDepthInvertsCapVolume) {
  EXPECT_EQ(cap_volume(1.0), 0.5);  // a hemisphere
  EXPECT_EQ(cap_volume(2.0), 1.0);
  EXPECT_EQ(cap_area(1.0), 1.0);
  for (double d = 0.001; d < 2.0; d += 0.0137) EXPECT_NEAR(cap_depth(cap_volume(d)), d, 1e-14) << d;
  EXPECT_EQ(cap_depth(0.0), 0.0);
  EXPECT_EQ(cap_depth(1.5), 2.0);
}

// The pressure acts on the cap's base up to the hemisphere and on the equator's area past it
// (cap_area): the many-body force X(δ*) a(Δn) / a(δ*) stays finite as the caps fill the
// soft-particle (δ* → 2), where 2δ* − δ*² would vanish, and meets X(2) a(Δn) where they fill it.
TEST(ManyBodyProbeLaws, TheManyBodyForceHasNoPoleAsTheCapsFillTheSoftParticle) {
  EXPECT_EQ(cap_area(0.5), 0.75);
  EXPECT_EQ(cap_area(1.5), 1.0);
  EXPECT_EQ(cap_area(2.0), 1.0);
  const auto X = [](double d) { return 40.0 * std::pow(d, 2.5); };
  const double dn = 0.3, v = cap_volume(dn), beta = 1.4;
  // below the hemisphere: the formula as written, 2δ − δ²
  const double low = 0.2;  // others' volume: v(δ*) = v + β 0.2 < 1/2
  const double star_low = cap_depth(v + beta * low);
  ASSERT_LT(star_low, 1.0);
  EXPECT_NEAR(many_body_force(X, 1.0, dn, low, beta), X(star_low) * (2 * dn - dn * dn) / (2 * star_low - star_low * star_low), 1e-12 * X(star_low));
  // past it: X(δ*) a(Δn), the equator's area under the pressure
  const double high = 0.5, star_high = cap_depth(v + beta * high);
  ASSERT_GT(star_high, 1.0);
  EXPECT_NEAR(many_body_force(X, 1.0, dn, high, beta), X(star_high) * (2 * dn - dn * dn), 1e-12 * X(star_high));
  // up to and past the caps filling it: bounded by X(2) a(Δn), and continuous there
  const double full = X(2.0) * (2 * dn - dn * dn);
  double before = 0.0;  // rising with the others' caps, never past the filled ball's force
  for (double eps = 1.0 - 1e-2; eps < 1.0; eps = 1.0 - (1.0 - eps) / 10.0) {
    const double F = many_body_force(X, 1.0, dn, (eps - v) / beta, beta);
    EXPECT_LE(F, full * (1.0 + 1e-12)) << eps;
    EXPECT_GE(F, before) << eps;
    before = F;
  }
  EXPECT_NEAR(many_body_force(X, 1.0, dn, (1.0 - 1e-12 - v) / beta, beta), full, 1e-5 * full);
  EXPECT_DOUBLE_EQ(many_body_force(X, 1.0, dn, (1.0 - v) / beta, beta), full);
  EXPECT_DOUBLE_EQ(many_body_force(X, 1.0, dn, 2.0, beta), full);
}

TEST(ManyBodyProbeLaws, EveryCandidateIsThePairwiseLawForOneContactAndForNoParameter) {
  ProbeLaw law{"pairwise", 0.0, {{"r", testing::eq7_fit(40.0, 2.5, -0.05)}}};
  const ProbeWallForce one{"r", "one", 1, {0.3}, 0, 0.0};
  const ProbeWallForce two{"r", "opposite", 1, {0.3, 0.2}, 0, 0.0};
  const double F1 = 40.0 * std::pow(0.3, 2.5) - 0.05;
  EXPECT_DOUBLE_EQ(law.predict(one), F1);
  EXPECT_DOUBLE_EQ(law.predict(two), F1);
  for (const char* name : {"volumetric", "ratio"}) {
    law.name = name, law.parameter = 0.8;
    EXPECT_NEAR(law.predict(one), F1, 1e-12 * F1) << name;
    EXPECT_GT(law.predict(two), 1.05 * F1) << name;  // another wall stiffens
    law.parameter = 0.0;
    EXPECT_NEAR(law.predict(two), F1, 1e-12 * F1) << name;
  }
  // volumetric with β = 1: wall k feels the sum of the caps, as one cap of that volume
  law.name = "volumetric", law.parameter = 1.0;
  const double star = cap_depth(cap_volume(0.3) + cap_volume(0.2));
  EXPECT_NEAR(law.predict(two), (40.0 * std::pow(star, 2.5) - 0.05) / cap_area(star) * cap_area(0.3), 1e-12);
}

TEST(ManyBodyProbeLaws, TheProbeFileReadsWallByWallAndSkipsAFailedPoint) {
  const std::string path = ::testing::TempDir() + "/probe.dat";
  std::ofstream(path) << "# softpack-coarse multi-contact: ...\n# walls delta_n Fn_1 ... Fn_walls [N]\n\n"
                         "# arrangement opposite-half: u=(0 0 1) w=1 u=(0 0 -1) w=0.5\n2 0.2000 1.5e+00 4.0e-01\n"
                         "# delta_n 0.3000 not measured (nor the larger): overlap\n\n# arrangement one: u=(0 0 1) w=1\n1 0.1000 2.0e-02\n";
  const auto w = read_probe_file(path, "r", 7);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[1].arrangement, "opposite-half");
  EXPECT_EQ(w[1].wall, 1u);
  EXPECT_DOUBLE_EQ(w[1].delta_n[1], 0.1);
  EXPECT_EQ(w[1].Fn, 0.4);
  EXPECT_EQ(w[2].seed, 7u);
  std::ofstream(path) << "# arrangement one: u=(0 0 1) w=1\n2 0.1000 2.0e-02 1.0\n";
  EXPECT_THROW(read_probe_file(path, "r", 7), InputError);
}

// A synthetic probe made by the volumetric law at β = 0.6 (and a 2 % seed-to-seed scatter): the
// analysis recovers β, chooses it, and lets it into the engine.
TEST(ManyBodyProbeLaws, TheRuleFindsTheLawThatMadeTheProbe) {
  ManyBodyProbe plan;
  plan.seeds = {1, 2, 3, 4};
  plan.radii = {{"r", 0.016}};
  plan.delta_n = {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  plan.fit = {"one", "opposite", "cube"};
  plan.held_out = {"orthogonal-half", "triangle"};
  plan.candidates = {"pairwise", "volumetric", "ratio"};
  plan.force_floor = 0.01, plan.tie_factor = 1.1;
  const ProbeLaw truth{"volumetric", 0.6, {{"r", testing::eq7_fit(40.0, 2.5, -0.05)}}};
  const std::map<std::string, std::vector<double>> w{{"one", {1.0}}, {"opposite", {1.0, 1.0}}, {"cube", {1, 1, 1, 1, 1, 1}},
                                                     {"orthogonal-half", {1.0, 0.5}}, {"triangle", {1.0, 1.0, 1.0}}};
  std::vector<ProbeWallForce> walls;
  for (const std::uint64_t seed : plan.seeds)
    for (const auto& [name, weights] : w)
      for (const double dn : plan.delta_n) {
        std::vector<double> d;
        for (const double x : weights) d.push_back(x * dn);
        for (std::size_t k = 0; k < d.size(); ++k) {
          ProbeWallForce p{"r", name, seed, d, k, 0.0};
          p.Fn = truth.predict(p) * (1.0 + 0.02 * (static_cast<double>(seed) - 2.5) / 1.5);
          walls.push_back(p);
        }
      }
  const ProbeAnalysis a = analyse_probe(plan, walls);
  ASSERT_EQ(a.candidates.size(), 3u);
  EXPECT_EQ(a.chosen, "volumetric");
  EXPECT_TRUE(a.enters_engine);
  EXPECT_NEAR(a.candidates[1].law.parameter, 0.6, 0.02);
  EXPECT_LT(a.candidates[1].held_out.rms_log, 0.03);
  EXPECT_GT(a.candidates[0].held_out.rms_log, 0.1);  // pairwise misses the stiffening
}

// The second part's analysis (coarse/probe_second.hpp) on a synthetic probe: grains of half the
// wall's single-contact force, stiffened by the volumetric law at β = 0.6; a cube whose confined
// kt is twice the single contact's and whose sliding ratio is the same.
TEST(ManyBodyProbeLaws, TheSecondPartReadsRatiosErrorsAndTheShearAsMade) {
  ManyBodyProbe plan;
  plan.seeds = {1, 2, 3, 4};
  plan.radii = {{"r", 0.016}};
  plan.delta_n = {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  plan.force_floor = 0.01;
  plan.body_groups = {{"grain-1", {"one", "opposite", "cube"}}};
  plan.shear_arrangements = {"one", "cube"}, plan.shear_delta_n = {0.2}, plan.shear_ht = {0.0025, 0.005, 0.1};
  const fit::PowerLawFit wall = testing::eq7_fit(40.0, 2.5, -0.05), grain = testing::eq7_fit(20.0, 2.5, -0.025);
  const ProbeLaw truth{"volumetric", 0.6, {{"r", grain}}};
  const std::map<std::string, std::vector<double>> w{{"one", {1.0}}, {"opposite", {1.0, 1.0}}, {"cube", {1, 1, 1, 1, 1, 1}}};
  std::vector<ProbeWallForce> walls, bodies;
  for (const std::uint64_t seed : plan.seeds) {
    const double scatter = 1.0 + 0.02 * (static_cast<double>(seed) - 2.5) / 1.5;
    for (const double dn : plan.delta_n) walls.push_back({"r", "one", seed, {dn}, 0, fit::evaluate(wall, dn) * scatter});
    for (const auto& [name, weights] : w)
      for (const double dn : plan.delta_n) {
        std::vector<double> d;
        for (const double x : weights) d.push_back(x * dn);
        for (std::size_t k = 0; k < d.size(); ++k) {
          ProbeWallForce p{"r", name + ":grain-1", seed, d, k, 0.0};
          p.Fn = truth.predict(p) * scatter;
          bodies.push_back(p);
        }
      }
  }
  std::vector<ShearRow> shear;
  const double k1 = 50.0, Rs = 0.016;
  for (const std::uint64_t seed : plan.seeds)
    for (const auto& [name, kt, Fn] : {std::tuple{"one", k1, 1.0}, std::tuple{"cube", 2.0 * k1, 3.0}}) {
      const double s = 1.0 + 0.01 * static_cast<double>(seed);
      shear.push_back({"r", name, seed, 0.2, 0.0, Fn * s, -0.01});
      for (const double ht : {0.0025, 0.005}) shear.push_back({"r", name, seed, 0.2, ht, Fn * s, -0.01 + kt * s * ht * Rs});
      shear.push_back({"r", name, seed, 0.2, 0.1, Fn * s, 0.3 * Fn * s});
    }
  const SecondPart a = analyse_second_part(plan, walls, bodies, shear, 0.6);
  EXPECT_NEAR(std::exp(a.single.at("grain-1").at("r").at(0.2).mean), 0.5, 1e-3);
  EXPECT_TRUE(a.notes.empty());
  const auto& k = a.kinds.at("grain-1");
  EXPECT_TRUE(k.carries_over);
  EXPECT_NEAR(k.beta, 0.6, 0.02);
  EXPECT_LT(k.volumetric.at("cube:grain-1").rms_log, 0.03);
  EXPECT_GT(k.pairwise.at("cube:grain-1").rms_log, 0.1);
  const auto& cube = a.shear.at("r").at("cube").at(0.2);
  EXPECT_NEAR(std::exp(cube.kt.mean), 2.0, 1e-9);
  EXPECT_FALSE(cube.kt.within());
  EXPECT_NEAR(std::exp(cube.mu.mean), 1.0, 1e-9);
  EXPECT_NEAR(std::exp(cube.Fn.mean), 3.0, 1e-9);
  EXPECT_NEAR(cube.mu_mean, 0.3, 1e-12);
}

// The media criterion (coarse/validation.hpp): every loading and unloading point of the range
// within 2 sqrt(se^2 + se^2), and τ at the shear's end; a point outside the range does not count.
TEST(ManyBodyValidation, ThePreregisteredCriterionJudgesEveryPointOfItsRangeAndTheShear) {
  ManyBodyProbe plan;
  plan.strain_lo = 0.02, plan.strain_hi = 0.35, plan.bound_in_standard_errors = 2.0;
  const auto point = [](double strain, int phase, double res, double soft, double se) {
    CoarsePoint p;
    p.strain = strain, p.phase = phase;
    p.sigma[0] = {res, se}, p.sigma[1] = {soft, se};
    p.tau[0] = {res / 2, se}, p.tau[1] = {soft / 2, se};
    return p;
  };
  CoarseComparison c;
  c.points = {point(0.01, 1, 10.0, 100.0, 1.0), point(0.1, 1, 100.0, 102.0, 1.0), point(0.3, -1, 200.0, 197.5, 1.0), point(0.3, 2, 200.0, 201.0, 1.0)};
  ValidationVerdict v = judge_validation(c, plan, "s");
  EXPECT_EQ(v.points, 2u);  // 0.01 is outside the range
  EXPECT_EQ(v.agreeing, 2u);
  EXPECT_NEAR(v.worst_excess, 2.5 / (2.0 * std::sqrt(2.0)), 1e-12);
  EXPECT_EQ(v.worst_phase, -1);
  EXPECT_TRUE(v.tau_measured);
  EXPECT_TRUE(v.accepted);
  c.points[1].sigma[1].mean = 103.0;  // 3 > 2 sqrt(2)
  v = judge_validation(c, plan, "s");
  EXPECT_EQ(v.agreeing, 1u);
  EXPECT_FALSE(v.accepted);
  c.points[1].sigma[1].mean = 102.0, c.points[3].tau[1].mean = 104.0;  // τ 100 against 104
  EXPECT_FALSE(judge_validation(c, plan, "s").accepted);
  c.points.pop_back();  // no shear: not accepted (the criterion asks for τ)
  EXPECT_FALSE(judge_validation(c, plan, "s").accepted);
}

// A soft setting read against another on the same resolved runs (validation --against): only the
// loading points of the range count; above and below by more than 2 sqrt(se^2 + se^2); the gap's
// share is the mean of (σ − σ_base) / (σ_resolved − σ_base); points of other strains are refused.
TEST(ManyBodyValidation, ASettingAgainstAnotherCountsItsLoadingPointsBeyondTheBoundAndTheGapItCloses) {
  ManyBodyProbe plan;
  plan.strain_lo = 0.02, plan.strain_hi = 0.35, plan.bound_in_standard_errors = 2.0;
  const auto point = [](double strain, int phase, double res, double soft) {
    CoarsePoint p;
    p.strain = strain, p.phase = phase;
    p.sigma[0] = {res, 1.0}, p.sigma[1] = {soft, 1.0};
    return p;
  };
  CoarseComparison base, c;
  base.points = {point(0.01, 1, 10, 1), point(0.1, 1, 100, 50), point(0.2, 1, 200, 100), point(0.3, 1, 300, 100), point(0.3, -1, 250, 80)};
  c.points = {point(0.01, 1, 10, 9), point(0.1, 1, 100, 75), point(0.2, 1, 200, 102), point(0.3, 1, 300, 96), point(0.3, -1, 250, 250)};
  const SettingShift s = shift_against(base, c, plan, "v6", "locked");
  EXPECT_EQ(s.points, 3u);  // 0.01 outside the range, the unloading point not a loading one
  EXPECT_EQ(s.above, 1u);   // 25 > 2 sqrt(2); 2 is within it
  EXPECT_EQ(s.below, 1u);   // -4
  EXPECT_FALSE(s.moves_up());
  EXPECT_NEAR(s.gap_share, (25.0 / 50 + 2.0 / 100 - 4.0 / 200) / 3, 1e-12);
  c.points[2].sigma[1].mean = 110;  // 10 above as well: two of three
  EXPECT_TRUE(shift_against(base, c, plan, "v6", "locked").moves_up());
  c.points[1].sigma[0].mean = 101;  // another resolved run
  EXPECT_THROW(shift_against(base, c, plan, "v6", "locked"), InputError);
  c.points[1].sigma[0].mean = 100, c.points[3].strain = 0.31;
  EXPECT_THROW(shift_against(base, c, plan, "v6", "locked"), InputError);
}

// The third version's analysis (coarse/probe_third.hpp) on a synthetic probe made by its own law:
// walls by the union form at β = 0.6, grains by g(X) = (X / (1 + X))^1.3 and β = 0.7, soft-particles
// of a third of the wall's force by the mean rule at β_ss = 0.3; it chooses the union and finds them.
TEST(ManyBodyProbeLaws, TheThirdVersionFindsTheLawThatMadeTheProbe) {
  ManyBodyProbe plan;
  plan.seeds = {1, 2, 3, 4};
  plan.radii = {{"r", 0.016}};
  plan.delta_n = {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  plan.fit = {"one", "opposite", "cube"}, plan.held_out = {"orthogonal-half", "triangle"};
  plan.force_floor = 0.01, plan.tie_factor = 1.1;
  plan.body_groups = {{"wall", {"random-8", "random-7"}}, {"grain-0.5", {"one", "opposite", "cube"}}, {"grain-2", {"one", "tetrahedral"}},
                      {"soft", {"one", "opposite", "tetrahedral"}}};
  plan.third = ManyBodyProbe::ThirdVersionPlan{{"volumetric", "volumetric-union"}, {"random-8"}, {"random-7"}, {"grain-0.5"}, {"grain-2"}};
  const fit::PowerLawFit wall = testing::eq7_fit(40.0, 2.5, -0.05), soft = testing::eq7_fit(40.0 / 3.0, 2.5, -0.05 / 3.0);
  std::vector<ProbeWallForce> walls, bodies;
  for (const std::uint64_t seed : plan.seeds) {
    const auto add = [&](const std::string& name, std::vector<ProbeWallForce>& to) {
      const ProbeArrangement a = builtin_arrangement(name, seed);
      const bool is_soft = a.body.kind == PressingBody::Kind::soft, is_grain = a.body.kind == PressingBody::Kind::grain;
      const ProbeLaw truth{"volumetric-union", is_soft ? 0.15 : is_grain ? 0.7 : 0.6, {{"r", is_soft ? soft : wall}}, is_grain ? 1.3 : 0.0};
      for (const double dn : plan.delta_n) {
        std::vector<double> d;
        for (const ProbeWall& w : a.walls) d.push_back(w.w * dn);
        for (std::size_t k = 0; k < d.size(); ++k) {
          ProbeWallForce p = probe_point(a, "r", seed, d, k, 0.0);
          p.Fn = truth.predict(p) * (1.0 + 0.02 * (static_cast<double>(seed) - 2.5) / 1.5);
          to.push_back(p);
        }
      }
    };
    for (const std::string& name : plan.arrangements()) add(name, walls);
    for (const auto& [kind, names] : plan.body_groups)
      for (const std::string& name : names) add(name + ":" + kind, bodies);
  }
  const ThirdVersion t = analyse_third_version(plan, walls, bodies, SecondPart{}, 0.9);
  ASSERT_EQ(t.count.size(), 2u);
  EXPECT_EQ(t.count_chosen, "volumetric-union");
  EXPECT_NEAR(t.count[1].beta.value, 0.6, 0.02);
  EXPECT_LT(t.count[1].held_out.rms_log, 0.03);
  EXPECT_GT(t.count[0].held_out.rms_log, t.count[1].held_out.rms_log);
  EXPECT_NEAR(t.grain_p.value, 1.3, 0.05);
  EXPECT_NEAR(t.grain_beta.value, 0.7, 0.05);
  EXPECT_LT(t.grain_held_out.rms_log, 0.03);
  EXPECT_NEAR(t.soft_beta.value, 0.3, 0.03);
}

// The soft medium's geometry against the resolved one's (coarse/kinematics.hpp) on rows written
// here: two seeds of two sites each at strain 0.05 (a row at 0.07 is not tabled), one soft-soft
// contact on the soft side only, the law files named in the headers checked; the soft Fn are
// set to multiples of the law alone (Eq. 7 of the file, a grain's times (X / (1 + X))^1.3), so each
// contact's confinement is known, and one contact of each model is below the onset (δ = 0.105).
TEST(ManyBodyKinematics, TheReportSetsTheSoftContactsAgainstTheResolvedOnes) {
  const std::string laws_path = std::string(SOFTPACK_SOURCE_DIR) + "/data/radius/report/laws.json";
  LawFile f = read_law_file(laws_path);
  f.version = 3, f.many_body = ManyBodyFit{"volumetric-union", {0.6, 0.0}, "test", "pairwise"};
  f.many_body->grain = ManyBodyGrainFit{{1.3, 0.0}, {0.7, 0.0}};
  f.many_body->soft_beta = LawValue{0.3, 0.0};
  const SoftParticleLaws laws = soft_particle_laws(f, laws_path);
  const double R = f.reference_radius;
  const LawFit& n = f.scenes.at("soft-solid").normal;
  const auto X = [&](double dn) { return n.a.value * std::pow(dn, n.b.value) + n.c.value; };
  const double g = std::pow(0.5 / 1.5, 1.3);
  const std::string dir = ::testing::TempDir() + "/kinematics";
  std::filesystem::create_directories(dir);
  {
    std::ofstream rows(dir + "/contact-rows.dat");
    rows << fmt::format("# soft-particle contacts (softpack-coarse soft-contacts): settings with the laws {}\n# seed 1: 2 soft-particles, Rs {} m\n", laws_path, R);
    rows << fmt::format("1 0.0500 0 0 0.300000 0.0000 1 {:.17g}\n1 0.0500 1 0 0.001000 0.0000 2 0\n", 2.0 * X(0.3));
    rows << fmt::format("1 0.0500 1 1 0.200000 0.5000 2 {:.17g}\n1 0.0700 1 1 0.250000 0.5000 2 1.0\n", 1.5 * g * X(0.2));
    rows << fmt::format("# seed 2: 2 soft-particles, Rs {} m\n2 0.0500 0 0 0.150000 0.0000 1 {:.17g}\n", R, X(0.15));
    rows << "2 0.0500 1 2 0.150000 0.0000 1 0\n";  // two soft-particles below the soft-soft onset (0.21)
    std::ofstream one(dir + "/seed-1.dat");
    one << fmt::format("# the law in place (softpack-coarse in-place): resolved medium, laws {}\n0.0500 0 0 0.200000 0.0000 2 0.8 {:.17g} 0\n0.0500 0 1 0.250000 0.5000 2 0.5 {:.17g} 0\n", laws_path, 3.0 * X(0.2),
                       1.2 * g * X(0.25));
    std::ofstream two(dir + "/seed-2.dat");
    two << "# the law in place (softpack-coarse in-place): resolved medium, laws " << laws_path << "\n0.0500 1 0 0.050000 0.0000 1 0.1 0 0\n0.0700 1 0 0.090000 0.0000 1 0.3 0 0\n";
  }
  ManyBodyProbe plan;
  plan.media_seeds[3] = {1, 2};
  write_kinematics_report(plan, "plan.yaml", laws, laws_path, dir + "/contact-rows.dat", dir, dir, 3);
  std::ifstream in(dir + "/kinematics.md");
  std::stringstream md;
  md << in.rdbuf();
  // walls: soft 3 on 4 sites (Δn 0.001, 0.15, 0.3; confinements 2 and 1, one below the onset),
  // resolved 2 (Δn 0.05, 0.2; confinement 3, one below the onset)
  EXPECT_NE(md.str().find(fmt::format("| 0.05 | wall | 0.75 / 0.50 | 0.150 / 0.200 | 0.300 / 0.200 | {:.3g} / 0.225 / {:.3g} | 2.00 / 3.00 | 0.33 / 0.50 |",
                                      (2.0 * X(0.3) + X(0.15)) / 4.0, 3.0 * X(0.2) / 4.0)),
            std::string::npos)
      << md.str();
  EXPECT_NE(md.str().find(fmt::format("| 0.05 | grain | 0.25 / 0.25 | 0.200 / 0.250 | 0.200 / 0.250 | {:.3g} / 0.125 / {:.3g} | 1.50 / 1.20 | 0.00 / 0.00 |",
                                      1.5 * g * X(0.2) / 4.0, 1.2 * g * X(0.25) / 4.0)),
            std::string::npos)
      << md.str();
  EXPECT_EQ(md.str().find("| 0.07 |"), std::string::npos);
  // soft-particles: one soft contact below the onset, none resolved ("–" where there is nothing to take)
  EXPECT_NE(md.str().find("| 0.05 | soft-particle | 0.25 / 0.00 | 0.150 / – | 0.150 / – | 0 / 0 / 0 | – / – | 1.00 / – |"), std::string::npos) << md.str();
  EXPECT_THROW(write_kinematics_report(plan, "plan.yaml", laws, "other-laws.json", dir + "/contact-rows.dat", dir, dir, 3), InputError);
  std::ofstream(dir + "/seed-2.dat") << "# laws " << laws_path << "\n0.0500 1 0 0.05\n";
  EXPECT_THROW(write_kinematics_report(plan, "plan.yaml", laws, laws_path, dir + "/contact-rows.dat", dir, dir, 3), InputError);
}

}  // namespace
}  // namespace softpack
