// The soft-soft law on the probe's confined runs (coarse/probe_soft_soft.hpp, paper/many-body.md):
// the fourth and fifth parts' analyses finding the law that made a synthetic probe, and a confined
// file's walls read where they stand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "coarse/probe_soft_soft.hpp"
#include "core/error.hpp"
#include "support/power_law.hpp"

namespace softpack {
namespace {

// A synthetic probe of the soft-soft forms (coarse/probe_soft_soft.hpp): soft arrangements `one`,
// `opposite`, `cube` and confined kinds at walls 0.1 and 0.2 (opposite, tetrahedral, cube) and 0.15
// (square, pyramid), both radii; the walls press by the walls' union law, every soft-soft contact
// by `truth` (its stress term on the row's other forces, solved by iteration), a 2 % seed scatter.
struct SyntheticSoftProbe {
  ManyBodyProbe plan;
  std::vector<ProbeWallForce> soft, confined;
};
SyntheticSoftProbe synthetic_soft_probe(ProbeLaw truth) {
  SyntheticSoftProbe s;
  ManyBodyProbe& plan = s.plan;
  plan.seeds = {1, 2, 3, 4};
  plan.radii = {{"r", 0.016}, {"s", 0.008}};
  plan.delta_n = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  plan.force_floor = 0.01;
  plan.body_groups = {{"soft", {"one", "opposite", "cube"}}};
  plan.confined_groups = {{"soft+walls-0.1", {"opposite", "tetrahedral", "cube"}},
                          {"soft+walls-0.2", {"opposite", "tetrahedral", "cube"}},
                          {"soft+walls-0.15", {"square", "pyramid", "orthogonal", "triangle", "opposite-half"}}};
  const fit::PowerLawFit X = testing::eq7_fit(40.0 / 3.0, 2.5, -0.05 / 3.0), W = testing::eq7_fit(40.0, 2.5, -0.05);
  truth.F1 = {{"r", X}, {"s", X}};
  const ProbeLaw walls{"volumetric-union", 0.3, {{"r", W}, {"s", W}}};
  for (const std::uint64_t seed : plan.seeds)
    for (const auto& [radius, Rs] : plan.radii)
      for (const auto* groups : {&plan.body_groups, &plan.confined_groups})
        for (const auto& [kind, names] : *groups)
          for (const std::string& name : names) {
            const ProbeArrangement a = builtin_arrangement(name + ":" + kind, seed);
            for (const double dn : plan.delta_n) {
              std::vector<double> d;
              for (std::size_t k = 0; k < a.walls.size(); ++k) d.push_back(k == 0 || a.body.walls_at == 0.0 ? dn : a.body.walls_at);
              std::vector<ProbeWallForce> row;
              for (std::size_t k = 0; k < d.size(); ++k) row.push_back(probe_point(a, radius, seed, d, k, 0.0));
              for (int sweep = 0; sweep < 60; ++sweep) {
                set_other_contacts(row.data(), row.size(), a);
                for (ProbeWallForce& p : row) p.Fn = (a.body.kind_at(p.wall) == PressingBody::Kind::soft ? truth : walls).predict(p);
              }
              // each point's force is its law's on the others it was given (where the sweeps have not
              // settled, the last sweep's), the scatter on the force only
              for (ProbeWallForce& p : row) {
                p.Fn *= 1.0 + 0.02 * (static_cast<double>(seed) - 2.5) / 1.5;
                (groups == &plan.body_groups ? s.soft : s.confined).push_back(p);
              }
            }
          }
  return s;
}

SoftSoftVersion::Form baseline(const std::string& name, double beta_ss) {
  SoftSoftVersion::Form f;
  f.name = name, f.base = "volumetric-union", f.parameter = {beta_ss, 0.01};
  return f;
}

// The fourth part's analysis on a probe made by onset-shift at γ = 3 (the engine's; the probe's
// centre carries all the others, the mean rule half of them): it finds γ, chooses onset-shift over
// volumetric-union and lets it in, the third version's β_ss missing the force below the onset.
TEST(ManyBodyProbeLaws, TheFourthPartFindsTheConfinedSoftLawThatMadeTheProbe) {
  SyntheticSoftProbe s = synthetic_soft_probe({"onset-shift", 1.5, {}});
  const ManyBodyProbe::SoftSoftPlan part{{"volumetric-union", "onset-shift"},
                                         {"opposite:soft+walls-0.1", "cube:soft+walls-0.1", "opposite:soft+walls-0.2", "cube:soft+walls-0.2"},
                                         {"tetrahedral:soft+walls-0.1", "tetrahedral:soft+walls-0.2"}};
  const SoftSoftVersion f = analyse_soft_soft(s.plan, part, s.soft, s.confined, baseline("third", 0.3));
  ASSERT_EQ(f.forms.size(), 3u);
  EXPECT_EQ(f.forms[0].name, "third");
  EXPECT_EQ(f.chosen, "onset-shift");
  EXPECT_TRUE(f.enters_engine);
  EXPECT_NEAR(f.form("onset-shift").parameter.value, 3.0, 0.1);
  EXPECT_LT(f.form("onset-shift").held_out.rms_log, 0.03);
  EXPECT_GT(f.forms[0].held_out.rms_log, 0.3);  // the third version has no force below its onset
  for (const auto& [radius, e] : f.form("onset-shift").held_out_by_radius) EXPECT_GT(e.points, 0u) << radius;
  EXPECT_THROW(f.form("stress"), InputError);
}

// The fifth part's on a probe made by the stress term at κ = 4 on volumetric-union at β_ss = 0.5:
// it finds κ on its baseline's β_ss and lets it in on the held-out kind, which no fit has seen.
TEST(ManyBodyProbeLaws, TheFifthPartFindsTheStressTermThatMadeTheProbe) {
  ProbeLaw truth{"volumetric-union", 0.25, {}};
  truth.stress = 2.0;
  SyntheticSoftProbe s = synthetic_soft_probe(truth);
  const ManyBodyProbe::SoftSoftPlan part{{"stress"},
                                         {"opposite:soft+walls-0.1", "cube:soft+walls-0.1", "opposite:soft+walls-0.2", "cube:soft+walls-0.2"},
                                         {"square:soft+walls-0.15", "pyramid:soft+walls-0.15"}};
  SoftSoftVersion::Form base = baseline("fourth", 0.5);
  base.by_arrangement["tetrahedral:soft+walls-0.1"] = {};  // an earlier part's run, not this part's
  const SoftSoftVersion f = analyse_soft_soft(s.plan, part, s.soft, s.confined, base);
  EXPECT_EQ(f.form("fourth").by_arrangement.size(), f.form("stress").by_arrangement.size());
  ASSERT_EQ(f.forms.size(), 2u);
  EXPECT_EQ(f.chosen, "stress");
  EXPECT_TRUE(f.enters_engine);
  EXPECT_NEAR(f.form("stress").parameter.value, 4.0, 0.2);
  EXPECT_DOUBLE_EQ(f.form("stress").beta_ss.value, 0.5);
  EXPECT_DOUBLE_EQ(f.form("stress").beta_ss.se, 0.01);  // the baseline's, with its error
  EXPECT_LT(f.form("stress").held_out.rms_log, 0.03);
  EXPECT_GT(f.form("fourth").held_out.rms_log, 0.3);
}

// The sixth part's on a probe made by the stress along the contact (κ = 4 on β_ss = 0.8): with
// β_ss fitted with κ it finds both, chooses stress-normal over the mean and the lateral stress, and
// lets it in against the fifth version's term (κ 1 on β_ss 0.3) on held-out arrangements.
TEST(ManyBodyProbeLaws, TheSixthPartFindsTheDirectionalStressThatMadeTheProbe) {
  ProbeLaw truth{"volumetric-union", 0.4, {}};
  truth.stress = 2.0, truth.stress_form = ProbeLaw::StressForm::normal;
  SyntheticSoftProbe s = synthetic_soft_probe(truth);
  ManyBodyProbe::SoftSoftPlan part{{"stress", "stress-normal", "stress-lateral"},
                                   {"opposite:soft+walls-0.1", "tetrahedral:soft+walls-0.1", "cube:soft+walls-0.1", "opposite:soft+walls-0.2",
                                    "tetrahedral:soft+walls-0.2", "cube:soft+walls-0.2", "square:soft+walls-0.15", "pyramid:soft+walls-0.15"},
                                   {"orthogonal:soft+walls-0.15", "triangle:soft+walls-0.15", "opposite-half:soft+walls-0.15"}};
  part.joint_beta_ss = true;
  SoftSoftVersion::Form base = baseline("fifth", 1.0);
  base.stress = "stress", base.beta_ss = {0.3, 0.01};
  const SoftSoftVersion f = analyse_soft_soft(s.plan, part, s.soft, s.confined, base);
  ASSERT_EQ(f.forms.size(), 4u);
  EXPECT_EQ(f.chosen, "stress-normal");
  EXPECT_TRUE(f.enters_engine);
  EXPECT_NEAR(f.form("stress-normal").parameter.value, 4.0, 0.2);
  EXPECT_NEAR(f.form("stress-normal").beta_ss.value, 0.8, 0.05);
  EXPECT_GT(f.form("stress-normal").beta_ss.se, 0.0);
  EXPECT_LT(f.form("stress-normal").held_out.rms_log, 0.03);
  EXPECT_GT(f.form("stress-lateral").held_out.rms_log, 2.0 * f.form("stress-normal").held_out.rms_log);
}

// The stress along and across the contact written out: in `cube` the walls beside the contact
// count across it only, the opposite one along it only.
TEST(ManyBodyProbeLaws, TheDirectionalStressTakesTheWallsByTheirDirection) {
  ProbeLaw law{"volumetric-union", 0.25, {{"r", testing::eq7_fit(40.0, 2.5, -0.05)}}};
  const ProbeArrangement a = builtin_arrangement("cube:soft+walls-0.2", 1);
  std::vector<ProbeWallForce> row;
  for (std::size_t k = 0; k < 6; ++k) row.push_back(probe_point(a, "r", 1, {0.1, 0.2, 0.2, 0.2, 0.2, 0.2}, k, 1.0 + static_cast<double>(k)));
  set_other_contacts(row.data(), row.size(), a);
  const ProbeWallForce& p = row[0];  // +z; -z is wall 1 (force 2), the four beside it 3 + 4 + 5 + 6
  EXPECT_NEAR(p.others_Fn, 20.0, 1e-12);
  EXPECT_NEAR(p.others_along, 2.0, 1e-12);
  const double alone = law.predict(p), kappa = 0.8, a01 = 2.0 * 0.1 - 0.1 * 0.1;
  law.stress = kappa / 2.0, law.stress_form = ProbeLaw::StressForm::normal;
  EXPECT_NEAR(law.predict(p), alone + kappa / 2.0 * 3.0 * 2.0 / 4.0 * a01, 1e-12);
  law.stress_form = ProbeLaw::StressForm::lateral;
  EXPECT_NEAR(law.predict(p), alone + kappa / 2.0 * 3.0 * 18.0 / 8.0 * a01, 1e-12);
  EXPECT_EQ(ProbeLaw::stress_form_of("stress-lateral"), ProbeLaw::StressForm::lateral);
  EXPECT_THROW(ProbeLaw::stress_form_of("stress-radial"), InputError);
}

// The stress term written out: κ p̄ π Rs² a(Δn) with p̄ half the centre's p = others_Fn / (4π Rs²)
// (ProbeLaw::stress is κ / 2, as the mean rule halves it), on the law alone.
TEST(ManyBodyProbeLaws, TheStressTermIsTheNeighboursStressOverTheContactsBase) {
  ProbeLaw law{"volumetric-union", 0.25, {{"r", testing::eq7_fit(40.0, 2.5, -0.05)}}};
  const ProbeArrangement a = builtin_arrangement("cube:soft+walls-0.2", 1);
  ProbeWallForce p = probe_point(a, "r", 1, {0.1, 0.2, 0.2, 0.2, 0.2, 0.2}, 0, 0.0);
  p.others_Fn = 3.0;
  const double alone = law.predict(p), kappa = 0.8, Rs = 0.016, pi = std::acos(-1.0);
  law.stress = kappa / 2.0;
  const double pbar = 0.5 * p.others_Fn / (4.0 * pi * Rs * Rs), base = pi * Rs * Rs * (2.0 * 0.1 - 0.1 * 0.1);
  EXPECT_NEAR(law.predict(p), alone + kappa * pbar * base, 1e-12);
  EXPECT_DOUBLE_EQ(law.predict_alone(p), alone);
}

// A confined kind's file: the first contact at the row's Δn, the others' walls at D.
TEST(ManyBodyProbeLaws, AConfinedFileHasItsWallsAtD) {
  const std::string path = (std::filesystem::temp_directory_path() / "softpack-confined-probe.dat").string();
  std::ofstream(path) << "# arrangement opposite:soft+walls-0.2: u=(0 0 1) w=1 u=(0 0 -1) w=1\n2 0.0500 1.0e-3 2.0e-2\n2 0.3000 4.0e-2 5.0e-2\n";
  const std::vector<ProbeWallForce> p = read_probe_file(path, "r", 501);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].delta_n, (std::vector<double>{0.05, 0.2}));
  EXPECT_EQ(p[3].delta_n, (std::vector<double>{0.3, 0.2}));
  EXPECT_EQ(p[3].wall, 1u);
  EXPECT_DOUBLE_EQ(p[3].Fn, 5.0e-2);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace softpack
