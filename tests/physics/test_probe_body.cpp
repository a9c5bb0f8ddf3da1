// The seventh part of the probe (coarse/probe_body.hpp, paper/many-body.md, "Next: a grain or a
// wall pressing a confined soft-particle"): its analysis finding the law that made a synthetic
// probe — the grains' and the wall's β and κ each on their own runs — and choosing by the plan's
// rule; the fifth version's share of a shallow contact.
#include <gtest/gtest.h>

#include <cmath>

#include "coarse/probe_body.hpp"
#include "core/error.hpp"
#include "support/power_law.hpp"

namespace softpack {
namespace {

const std::vector<double> kShallow{0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4};

// A synthetic seventh part: the single wall `one` by Eq. 7 (X1), confined kinds with a grain
// (0.4, 1; 0.6 held out) or a wall at the first contact under walls at 0.1, 0.2 (0.15 held out),
// both radii; the confining walls press by the walls' union law at β_w, the first body by the
// union law at its β plus κ g p π R² a(Δn) on the walls' forces; a 2 % seed scatter.
struct SyntheticBodyProbe {
  ManyBodyProbe plan;
  std::vector<ProbeWallForce> walls, confined;
};
SyntheticBodyProbe synthetic_body_probe(double beta_grain, double kappa_grain, double beta_wall, double kappa_wall, double p) {
  SyntheticBodyProbe s;
  ManyBodyProbe& plan = s.plan;
  plan.seeds = {1, 2, 3, 4};
  plan.radii = {{"r", 0.016}, {"s", 0.008}};
  plan.delta_n = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  plan.force_floor = 0.01;
  plan.fit = {"one", "opposite"};
  const std::vector<std::string> fit{"opposite", "tetrahedral", "cube"}, held{"orthogonal", "cube"};
  plan.confined_groups = {{"grain-0.4+walls-0.1", fit}, {"grain-1+walls-0.2", fit}, {"wall+walls-0.1", fit},
                          {"wall+walls-0.2", fit},      {"grain-0.6+walls-0.15", held}, {"wall+walls-0.15", held}};
  for (const auto& [kind, names] : plan.confined_groups) plan.kind_delta_n[kind] = kShallow;
  const fit::PowerLawFit W = testing::eq7_fit(40.0, 2.5, -0.05);
  const std::map<std::string, fit::PowerLawFit> X1{{"r", W}, {"s", W}};
  const ProbeLaw confining{"volumetric-union", beta_wall, X1};
  for (const std::uint64_t seed : plan.seeds)
    for (const auto& [radius, Rs] : plan.radii) {
      const double scatter = 1.0 + 0.02 * (static_cast<double>(seed) - 2.5) / 1.5;
      for (const double dn : plan.delta_n) {
        ProbeWallForce one = probe_point(builtin_arrangement("one", seed), radius, seed, {dn}, 0, 0.0);
        one.Fn = scatter * fit::evaluate(W, dn);
        s.walls.push_back(one);
        for (std::size_t k = 0; k < 2; ++k) {  // the first part's opposite walls, moving at once
          ProbeWallForce w = probe_point(builtin_arrangement("opposite", seed), radius, seed, {dn, dn}, k, 0.0);
          w.Fn = scatter * confining.predict(w);
          s.walls.push_back(w);
        }
      }
      for (const auto& [kind, names] : plan.confined_groups)
        for (const std::string& name : names) {
          const ProbeArrangement a = builtin_arrangement(name + ":" + kind, seed);
          const bool grain = a.body.kind == PressingBody::Kind::grain;
          ProbeLaw first{"volumetric-union", grain ? beta_grain : beta_wall, X1, p};
          const double kappa = grain ? kappa_grain : kappa_wall, x = a.body.radius_ratio;
          const double g = grain ? std::pow(x / (1.0 + x), p) : 1.0;
          for (const double dn : kShallow) {
            std::vector<double> d;
            for (std::size_t k = 0; k < a.walls.size(); ++k) d.push_back(k == 0 ? dn : a.body.walls_at);
            std::vector<ProbeWallForce> row;
            for (std::size_t k = 0; k < d.size(); ++k) row.push_back(probe_point(a, radius, seed, d, k, 0.0));
            for (std::size_t k = 1; k < row.size(); ++k) row[k].Fn = confining.predict(row[k]);
            set_other_contacts(row.data(), row.size(), a);
            row[0].Fn = first.predict_alone(row[0]) + kappa * g * row[0].others_Fn / 4.0 * cap_area(dn);
            for (ProbeWallForce& w : row) w.Fn *= scatter, s.confined.push_back(w);
          }
        }
    }
  return s;
}

ManyBodyProbe::SoftSoftPlan seventh(const ManyBodyProbe& plan, std::vector<std::string> forms) {
  ManyBodyProbe::SoftSoftPlan part;
  part.forms = std::move(forms);
  for (const auto& [kind, names] : plan.confined_groups)
    for (const std::string& name : names) (kind.find("0.15") == std::string::npos ? part.fit : part.held_out).push_back(name + ":" + kind);
  return part;
}

// Made by the stress term (κ 2 for grains, 1 for the wall) on the fifth version's β: the stress
// form finds each κ on its own runs, is chosen and enters; the fifth version misses the force the
// term adds, most at shallow Δn; union-refit, with no term, cannot make it up.
TEST(ManyBodyProbeLaws, TheSeventhPartFindsTheGrainsAndTheWallsStressTerms) {
  const SyntheticBodyProbe s = synthetic_body_probe(0.7, 2.0, 0.5, 1.0, 1.3);
  const FifthBodyLaw fifth{"volumetric-union", 0.5, 0.7, 1.3};
  const BodyVersion b = analyse_body_version(s.plan, seventh(s.plan, {"union-refit", "stress", "stress-joint"}), s.walls, s.confined, fifth);
  ASSERT_EQ(b.forms.size(), 4u);
  EXPECT_EQ(b.forms.front().name, "fifth");
  EXPECT_DOUBLE_EQ(b.form("fifth").body.at("grain").beta.value, 0.7);
  EXPECT_EQ(b.form("fifth").body.at("wall").kappa.value, 0.0);
  const BodyVersion::Form& stress = b.form("stress");
  EXPECT_NEAR(stress.body.at("grain").kappa.value, 2.0, 0.1);
  EXPECT_NEAR(stress.body.at("wall").kappa.value, 1.0, 0.05);
  EXPECT_DOUBLE_EQ(stress.body.at("wall").beta.value, 0.5);  // kept: the fifth's
  EXPECT_GT(stress.body.at("grain").kappa.se, 0.0);
  EXPECT_NEAR(b.form("stress-joint").body.at("grain").beta.value, 0.7, 0.1);
  EXPECT_NEAR(b.form("stress-joint").body.at("wall").kappa.value, 1.0, 0.1);
  EXPECT_EQ(b.form("union-refit").body.at("grain").kappa.value, 0.0);
  EXPECT_TRUE(b.chosen == "stress" || b.chosen == "stress-joint") << b.chosen;
  EXPECT_TRUE(b.enters_engine);
  EXPECT_LT(stress.held_out.rms_log, 0.03);
  EXPECT_GT(b.form("fifth").held_out.rms_log, 5.0 * stress.held_out.rms_log);
  EXPECT_GT(b.form("union-refit").held_out.rms_log, 2.0 * stress.held_out.rms_log);
  for (const auto& [radius, e] : stress.held_out_by_radius) EXPECT_GT(e.points, 0u) << radius;
  EXPECT_THROW(b.form("stress-normal"), InputError);
  // reported: the first part's walls moving at once, made by the fifth's β, which the stress form keeps
  ASSERT_EQ(b.earlier.count("walls"), 1u);
  EXPECT_GT(b.earlier.at("walls").first.points, 0u);
  EXPECT_LT(b.earlier.at("walls").first.rms_log, 0.03);
  EXPECT_LT(b.earlier.at("walls").second.rms_log, 0.03);
  // the shallow table: every kind, both radii, Δn below 0.1; the fifth gives less than measured
  EXPECT_EQ(b.shallow.size(), 2u * 6u * 5u);
  for (const BodyVersion::Shallow& sh : b.shallow) {
    EXPECT_LT(sh.delta_n, 0.1 - 1e-12);
    if (sh.measured > 0.0) {
      EXPECT_LT(sh.fifth, sh.measured) << sh.kind << " " << sh.delta_n;
    }
  }
}

// Made by the fifth version itself: the fitted terms vanish and the stress form's error is the fifth's.
TEST(ManyBodyProbeLaws, TheSeventhPartKeepsTheFifthVersionWhereItMadeTheProbe) {
  const SyntheticBodyProbe s = synthetic_body_probe(0.7, 0.0, 0.5, 0.0, 1.3);
  const BodyVersion b = analyse_body_version(s.plan, seventh(s.plan, {"stress"}), s.walls, s.confined, {"volumetric-union", 0.5, 0.7, 1.3});
  EXPECT_NEAR(b.form("stress").body.at("grain").kappa.value, 0.0, 0.05);
  EXPECT_NEAR(b.form("stress").body.at("wall").kappa.value, 0.0, 0.05);
  EXPECT_EQ(b.chosen, "stress");
  EXPECT_LT(b.form("fifth").held_out.rms_log, 0.03);
  EXPECT_NEAR(b.form("stress").held_out.rms_log, b.form("fifth").held_out.rms_log, 0.005);
}

}  // namespace
}  // namespace softpack
