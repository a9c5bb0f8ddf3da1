// The coarse-grain validation's pieces (studies/coarse/): the medium is one medium for both
// models, its files round-trip, the comparison reads curves as it says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include "coarse/medium_file.hpp"
#include "coarse/multi_contact.hpp"
#include "coarse/probe_settings.hpp"
#include "coarse/report.hpp"
#include "coarse/result_file.hpp"
#include "coarse/soft_census.hpp"
#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "support/coarse_tiny.hpp"

namespace softpack {
namespace {

const std::string kRoot = SOFTPACK_SOURCE_DIR;

const CoarseGrainSettings& tiny() { return testing::coarse_grain_tiny(); }

const Medium& medium() {
  static const Medium m = build_medium(tiny(), 901);
  return m;
}

SoftParticleLaws laws() { return soft_particle_laws(read_law_file(tiny().laws), tiny().laws); }

double ball(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

TEST(CoarseGrain, TheMediumRepeatsItsBitsAndNoBodyOverlapsAnother) {
  const Medium& m = medium();
  const Medium again = build_medium(tiny(), 901);
  ASSERT_EQ(m.grain_x.size(), 12u);
  ASSERT_GE(m.sites.size(), 1u);
  EXPECT_EQ(again.grain_x, m.grain_x);
  EXPECT_EQ(again.sites, m.sites);
  std::vector<std::pair<Vec3, double>> bodies;
  for (std::size_t k = 0; k < m.grain_x.size(); ++k) bodies.emplace_back(m.grain_x[k], m.grain_r[k]);
  for (const Vec3& x : m.sites) bodies.emplace_back(x, m.Rs);
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    const auto& [x, r] = bodies[a];
    for (int d = 0; d < 3; ++d) EXPECT_GE(x[d] - r, 0.0);
    EXPECT_LE(x.x() + r, m.L);
    EXPECT_LE(x.y() + r, m.L);
    EXPECT_LE(x.z() + r, m.H);
    for (std::size_t b = 0; b < a; ++b) EXPECT_GE((x - bodies[b].first).norm(), r + bodies[b].second) << a << " and " << b;
  }
}

// The packings stand for the second decade of the same power law: their solid volume is the
// nearest a whole number of packings comes to it, V2 = V1 (r2max^0.5 - r2min^0.5) / (r1max^0.5 - r1min^0.5).
TEST(CoarseGrain, ThePackingsHoldTheSecondDecadesSolidVolume) {
  const Medium& m = medium();
  const CoarseGrainSettings& s = tiny();
  const double r1 = s.r_min_over_Rs * m.Rs, r2max = s.packing.r_max, r2min = r2max / s.packing.polydispersity;
  double V1 = 0.0;
  for (double r : m.grain_r) V1 += ball(r);
  EXPECT_NEAR(m.grains_volume, V1, 1e-15);
  EXPECT_NEAR(m.target_volume, V1 * (std::sqrt(r2max) - std::sqrt(r2min)) / (std::sqrt(10 * r1) - std::sqrt(r1)), 1e-12 * V1);
  double largest = 0.0, V2 = 0.0;
  for (const Packing& p : m.packings) {
    double v = 0.0;
    for (double r : p.radii) v += ball(r);
    largest = std::max(largest, v), V2 += v;
  }
  EXPECT_NEAR(m.packings_volume, V2, 1e-15);
  EXPECT_LE(std::abs(V2 - m.target_volume), largest) << "a packing more or fewer would come nearer";
}

TEST(CoarseGrain, BothModelsHoldTheSameGrainsAndTheSiteMassesAgree) {
  const Medium& m = medium();
  const SceneDef a = medium_scene(tiny(), m, CoarseModel::resolved, laws());
  const SceneDef b = medium_scene(tiny(), m, CoarseModel::soft, laws());
  std::size_t packed = 0;
  for (const Packing& p : m.packings) packed += p.radii.size();
  ASSERT_EQ(a.particles.size(), m.grain_x.size() + packed);
  ASSERT_EQ(b.particles.size(), m.grain_x.size() + m.sites.size());
  for (std::size_t k = 0; k < m.grain_x.size(); ++k) {
    EXPECT_EQ(a.particles[k].x, b.particles[k].x);
    EXPECT_EQ(a.particles[k].r, b.particles[k].r);
  }
  const double rho = tiny().simulation.material.density;
  ASSERT_EQ(a.shells.size(), m.sites.size());
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const double grains = packing_mass(m.packings[k], rho);
    EXPECT_NEAR(*a.shells[k].mass, 0.05 * grains, 1e-15);
    const ParticleDef& soft = b.particles[m.grain_x.size() + k];
    EXPECT_TRUE(soft.soft);
    EXPECT_EQ(soft.x, m.sites[k]);
    EXPECT_NEAR(*soft.mass, 1.05 * grains, 1e-15);
  }
  EXPECT_TRUE(b.effects.soft_particles.has_value());
  EXPECT_FALSE(a.effects.soft_particles.has_value());
  // rotation: locked holds the soft-particles' spin, and only theirs; free (the default) none.
  for (const ParticleDef& p : b.particles) EXPECT_FALSE(p.spin_locked);
  CoarseGrainSettings locked = tiny();
  locked.spin_locked = true;
  const SceneDef c = medium_scene(locked, m, CoarseModel::soft, laws());
  for (const ParticleDef& p : c.particles) EXPECT_EQ(p.spin_locked, p.soft);
  for (const ParticleDef& p : medium_scene(locked, m, CoarseModel::resolved, laws()).particles) EXPECT_FALSE(p.spin_locked);
}

TEST(CoarseGrain, ACompressionOfEitherModelWritesAFileThatReadsBack) {
  const Medium& m = medium();
  const std::string dir = ::testing::TempDir() + "/coarse";
  std::filesystem::create_directories(dir);
  MediumFile mf{m, 901, tiny().medium_text, "test", {}};
  write_medium_file(dir + "/medium.h5", mf);
  const MediumFile back = read_medium_file(dir + "/medium.h5");
  EXPECT_EQ(back.medium.grain_x, m.grain_x);
  ASSERT_EQ(back.medium.packings.size(), m.packings.size());
  EXPECT_EQ(back.medium.packings.back().radii, m.packings.back().radii);
  for (const CoarseModel model : {CoarseModel::resolved, CoarseModel::soft}) {
    std::vector<SoftCensus> census;  // the soft model's contacts at each row (coarse/soft_census.hpp)
    std::function<void(const Simulation&, const CurveRow&)> observe;
    if (model == CoarseModel::soft)
      observe = [&](const Simulation& sim, const CurveRow& row) { census.push_back(soft_census(sim, back.medium, row, 0.4, 0.5)); };
    const CompressionRun run = run_compression(medium_scene(tiny(), back.medium, model, laws()), back.medium, model, tiny(), {}, observe);
    if (model == CoarseModel::soft) {
      ASSERT_EQ(census.size(), run.rows.size());
      for (const SoftCensus& c : census) {
        EXPECT_EQ(c.wall + c.grain + c.soft, c.contacts);
        EXPECT_EQ(c.soft % 2, 0u) << "a contact between two soft-particles is counted for each";
        EXPECT_EQ(c.soft / 2, static_cast<std::size_t>(run.rows[&c - census.data()].soft_soft)) << "as the curve counts its pairs";
        EXPECT_DOUBLE_EQ(c.n_mean, static_cast<double>(c.contacts) / static_cast<double>(back.medium.sites.size()));
        for (const double f : {c.beyond_dn, c.beyond_n, c.beyond_E}) EXPECT_TRUE(f >= 0.0 && f <= 1.0) << f;
        EXPECT_LE(c.dn_median, c.dn_p90);
        EXPECT_LE(c.dn_p90, c.dn_max);
      }
    }
    ASSERT_GE(run.rows.size(), 8u);  // 0, six loading rows, one unloading
    EXPECT_NEAR(run.rows[6].strain, 0.06, 1e-3);
    ASSERT_EQ(run.rows.size(), 10u);  // then two rows of shear
    EXPECT_EQ(run.rows[7].phase, -1);
    EXPECT_NEAR(run.rows[7].strain, 0.05, 1e-3);
    EXPECT_EQ(run.rows.back().phase, 2);
    EXPECT_NEAR(run.rows.back().shear, 0.02, 1e-3);
    EXPECT_NEAR(run.rows.back().strain, 0.05, 1e-3) << "the shear keeps the axial strain";
    // The soft model counts its contacts beyond the laws' range row by row, as the run's total at its end.
    for (std::size_t k = 0; k < run.rows.size(); ++k) {
      if (model == CoarseModel::resolved) {
        EXPECT_EQ(run.rows[k].beyond_range, -1);
        EXPECT_TRUE(std::isnan(run.rows[k].max_dn));
        continue;
      }
      EXPECT_GE(run.rows[k].beyond_range, k ? run.rows[k - 1].beyond_range : 0L);
      EXPECT_GE(run.rows[k].max_dn, k ? run.rows[k - 1].max_dn : 0.0);
    }
    if (model == CoarseModel::soft) {
      EXPECT_EQ(run.rows.back().beyond_range, run.soft.beyond_range);
      EXPECT_EQ(run.rows.back().max_dn, run.soft.max_dn);
    }
    const std::string path = dir + "/" + name(model) + ".h5";
    write_coarse_result(path, coarse_result(run, back.medium, model, 901, tiny()));
    const CoarseResult r = read_coarse_result(path);
    EXPECT_EQ(r.rows[5].beyond_range, run.rows[5].beyond_range) << "read back; -1 where not counted";
    EXPECT_EQ(std::isnan(r.rows[5].max_dn), model == CoarseModel::resolved);
    EXPECT_EQ(r.model, name(model));
    EXPECT_EQ(r.rows.size(), run.rows.size());
    EXPECT_EQ(r.rows.back().sigma_top, run.rows.back().sigma_top);
    EXPECT_EQ(r.rows.back().tau, run.rows.back().tau);
    EXPECT_EQ(r.spheres, static_cast<std::int64_t>(run.spheres));
  }
}

// The census of soft-particle contacts (coarse/soft_census.hpp) on a scene made by hand: two
// soft-particles on the bottom wall (Δn = 0.05 each), touching each other (Δn = 0.1), the first
// pressed by a grain of radius Rs / 2 (Δn = 0.2 with the wall rule's R = Rs).
TEST(CoarseGrain, TheSoftContactCensusCountsWhatTheSceneHolds) {
  const Medium& tiny_medium = medium();
  ASSERT_GE(tiny_medium.packings.size(), 1u);
  Medium m;
  const double R = tiny_medium.Rs;
  m.Rs = R, m.L = 10.0 * R, m.H = 10.0 * R;
  m.sites = {Vec3(5.0 * R, 5.0 * R, 0.95 * R), Vec3(6.9 * R, 5.0 * R, 0.95 * R)};
  m.packings = {tiny_medium.packings[0], tiny_medium.packings[0]};  // their masses only
  m.grain_x = {Vec3(5.0 * R, 5.0 * R, 2.25 * R)}, m.grain_r = {0.5 * R};
  const Simulation sim(medium_scene(tiny(), m, CoarseModel::soft, laws()));
  const SoftCensus c = soft_census(sim, m, CurveRow{}, 0.15, 1.0);
  EXPECT_EQ(c.contacts, 5u);
  EXPECT_EQ(c.wall, 2u);
  EXPECT_EQ(c.grain, 1u);
  EXPECT_EQ(c.soft, 2u);
  EXPECT_NEAR(c.dn_median, 0.1, 1e-9);
  EXPECT_NEAR(c.dn_max, 0.2, 1e-9);
  EXPECT_DOUBLE_EQ(c.beyond_dn, 0.2);
  EXPECT_DOUBLE_EQ(c.n_mean, 2.5);
  EXPECT_EQ(c.beyond_n, 0.0);
  EXPECT_EQ(c.beyond_E, 0.0);
  EXPECT_EQ(soft_census(sim, m, CurveRow{}, 0.15, 0.9 * (cap_volume(0.05) + cap_volume(0.1) + cap_volume(0.2))).beyond_E, 0.6)
      << "the first soft-particle's three contacts lie beyond an E just below its own";
  EXPECT_DOUBLE_EQ(c.grain_ratio_median, 0.5);
  EXPECT_GT(c.force_grain, 0.0);
}

}  // namespace
}  // namespace softpack

namespace softpack {
namespace {

// The many-body probe's plan (coarse/probe_settings.hpp): the committed one reads; a plan that
// fits and holds out one arrangement, names an unknown one, or lets Δn fall is refused, naming the key.
TEST(ManyBodyProbePlan, TheCommittedPlanReadsAndABadOneIsRefusedByName) {
  const ManyBodyProbe plan = read_many_body_probe(kRoot + "/experiments/many-body.yaml", kRoot);
  EXPECT_EQ(plan.radii.size(), 2u);
  EXPECT_GE(plan.seeds.size(), 4u);
  for (std::uint64_t seed : plan.seeds) EXPECT_GE(seed, 101u);  // never the paper's seeds 1-7
  EXPECT_EQ(plan.settings_at("half").packing.Rs, plan.radii.at("half"));
  EXPECT_THROW(plan.settings_at("double"), InputError);
  const std::string text = [&] {
    std::ifstream in(kRoot + "/experiments/many-body.yaml");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& says) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    const std::string bad_text = std::string(text).replace(at, from.size(), to);
    const std::string path = ::testing::TempDir() + "/many-body-bad.yaml";
    std::ofstream(path) << bad_text;
    try {
      read_many_body_probe(path, kRoot);
      ADD_FAILURE() << "taken: " << to;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused("held_out: [triangle", "held_out: [cube, triangle", "also fitted");
  refused("held_out: [triangle", "held_out: [hexagon", "allowed: one, opposite");
  refused("delta_n: [0.05, 0.1", "delta_n: [0.1, 0.05", "must increase");
  refused("  candidates:", "  colour: red\n  candidates:", "colour");
  refused("fit: [one, ", "fit: [", "'one'");
  refused("    grain-1: [one,", "    grain-y: [one,", "allowed: wall, soft, grain-X");
  refused("    grain-1: [one,", "    grain-1.0: [one,", "write it grain-1");
  refused("    soft: [one, opposite,", "    soft: [opposite,", "'one'");
  refused("v3_media_seeds: [315,", "v3_media_seeds: [311,", "also in media_seeds");
  refused("v4_media_seeds: [319,", "v4_media_seeds: [315,", "also in v3_media_seeds");
  EXPECT_EQ(plan.media_seeds_of(4).front(), 319u);
  EXPECT_EQ(plan.media_seeds_of(5).front(), 323u);
  EXPECT_EQ(plan.media_seeds_of(6).front(), 327u);
  EXPECT_THROW(plan.media_seeds_of(7), InputError);
  refused("v5_media_seeds: [323,", "v5_media_seeds: [319,", "also in v4_media_seeds");
  refused("    arrangements: [one, opposite, tetrahedral, cube]", "    arrangements: [opposite, tetrahedral, cube]", "'one'");
  refused("    soft: [one, opposite,", "    soft: [one, opposite:soft,", "without :BODY");
  const auto stamps_with = [&](const std::string& from, const std::string& to) {
    const std::string path = ::testing::TempDir() + "/many-body-edited.yaml";
    std::ofstream(path) << std::string(text).replace(text.find(from), from.size(), to);
    return read_many_body_probe(path, kRoot).runs_stamps("1.0");
  };
  const auto stamps = plan.runs_stamps("1.0");
  ASSERT_EQ(stamps.size(), 2 + plan.body_groups.size() + plan.confined_groups.size());  // seed, each bodies-KIND, shear
  EXPECT_EQ(stamps.front().first, "seed");
  EXPECT_EQ(stamps[1].first, "bodies-" + plan.body_groups.front().first);
  EXPECT_EQ(stamps_with("media_seeds: [", "media_seeds: [399, "), stamps) << "the validation decides no run";
  EXPECT_EQ(stamps_with("tie_factor:", "tie_factor: 1.2 #"), stamps) << "nor the selection rule";
  const auto dn = stamps_with("delta_n: [0.05, ", "delta_n: [0.04, ");
  EXPECT_NE(dn[0], stamps[0]);
  EXPECT_NE(dn[1], stamps[1]);
  EXPECT_EQ(dn.back(), stamps.back()) << "the shear has its own delta_n";
  const auto soft = stamps_with("soft: [one, opposite,", "soft: [one,");
  EXPECT_NE(soft[3], stamps[3]) << "the soft kind's arrangements";
  EXPECT_EQ(soft[1], stamps[1]) << "another kind's runs stay";
  EXPECT_EQ(soft[0], stamps[0]);
  EXPECT_NE(plan.runs_stamps("1.1"), stamps);
  EXPECT_EQ(plan.bodies("soft").front(), "one:soft");
  EXPECT_THROW(plan.bodies("grain-7"), InputError);
  // the fourth part's confined kinds run as bodies-KIND, not in body_groups (the second part's)
  ASSERT_FALSE(plan.confined_groups.empty());
  const std::string confined = plan.confined_groups.front().first;
  EXPECT_EQ(plan.bodies(confined).front(), plan.confined_groups.front().second.front() + ":" + confined);
  EXPECT_EQ(std::count_if(stamps.begin(), stamps.end(), [&](const auto& g) { return g.first == "bodies-" + confined; }), 1);
  for (const auto& [kind, arrangements] : plan.body_groups) EXPECT_NE(kind, confined);
  refused("    soft+walls-0.1: [opposite,", "    soft+walls-0.1: [one, opposite,", "no wall to confine it");
  refused("    soft+walls-0.1: [opposite,", "    soft: [opposite,", "BODY+walls-D");
  refused("    soft+walls-0.1: [opposite,", "    soft+walls-0.10: [opposite,", "write it soft+walls-0.1");
  refused("    grain-1: [one,", "    grain-1+walls-0.1: [one,", "goes in confined");
  // the fourth part's analysis: its arrangements run for every confined kind, fitted or held out
  ASSERT_TRUE(plan.fourth.has_value());
  EXPECT_EQ(plan.fourth->held_out, (std::vector<std::string>{"tetrahedral:soft+walls-0.1", "tetrahedral:soft+walls-0.2"}));
  ASSERT_TRUE(plan.fifth.has_value());
  EXPECT_EQ(plan.fifth->held_out, (std::vector<std::string>{"square:soft+walls-0.15", "pyramid:soft+walls-0.15"}));
  refused("    held_out: [tetrahedral]", "    held_out: [square]", "not run for confined kind");
  refused("    held_out: [tetrahedral]", "    held_out: [cube]", "also fitted");
  refused("    soft_forms: [volumetric-union, onset-shift]", "    soft_forms: [volumetric, onset-shift]", "soft_forms");
  refused("    held_out_kinds: [soft+walls-0.15]", "    held_out_kinds: [soft+walls-0.3]", "allowed: soft+walls-0.1, soft+walls-0.2, soft+walls-0.15");
  refused("    soft_forms: [volumetric-union, onset-shift]", "    soft_forms: [stress]", "soft_forms");
  refused("    held_out: [square, pyramid]", "    held_out: []", "an empty list is not allowed");
  // the sixth part's: its fit crosses names with its kinds or takes NAME:KIND as it is
  ASSERT_TRUE(plan.sixth.has_value());
  EXPECT_TRUE(plan.sixth->joint_beta_ss);
  EXPECT_EQ(plan.sixth->held_out,
            (std::vector<std::string>{"orthogonal:soft+walls-0.15", "triangle:soft+walls-0.15", "opposite-half:soft+walls-0.15"}));
  EXPECT_EQ(plan.sixth->fit.size(), 8u);
  EXPECT_NE(std::find(plan.sixth->fit.begin(), plan.sixth->fit.end(), "square:soft+walls-0.15"), plan.sixth->fit.end());
  EXPECT_NE(std::find(plan.sixth->fit.begin(), plan.sixth->fit.end(), "tetrahedral:soft+walls-0.2"), plan.sixth->fit.end());
  refused("square:soft+walls-0.15, pyramid", "square:soft+walls-0.3, pyramid", "not a confined kind");
  refused("square:soft+walls-0.15, pyramid", "orthogonal:soft+walls-0.1, pyramid", "not run for confined kind");
  refused("    soft_forms: [stress, stress-normal", "    soft_forms: [onset-shift, stress-normal", "soft_forms");
  refused("    joint_beta_ss: true", "    joint_beta_ss: yes please", "joint_beta_ss");
  refused("triangle, opposite-half]", "triangle, random-5]", "90 degrees");  // a confining plane would cut the pressing body
  // the seventh part's: confined kinds with a grid of their own, a grain or a wall at the first contact
  EXPECT_EQ(plan.delta_n_of("grain-0.4+walls-0.1").front(), 0.01);
  EXPECT_EQ(plan.delta_n_of("soft+walls-0.1"), plan.delta_n);
  EXPECT_EQ(plan.bodies("wall+walls-0.15").back(), "cube:wall+walls-0.15");
  ASSERT_TRUE(plan.seventh.has_value());
  EXPECT_EQ(plan.seventh->fit.size(), 18u);
  EXPECT_EQ(plan.seventh->held_out.size(), 8u);
  EXPECT_EQ(plan.seventh->held_out.front(), "opposite:grain-0.6+walls-0.15");
  EXPECT_EQ(stamps_with("delta_n: [0.05, ", "delta_n: [0.04, ")[stamps.size() - 3], stamps[stamps.size() - 3]) << "a kind with its own grid keeps it";
  refused("delta_n: &shallow [0.01, 0.02", "delta_n: &shallow [0.02, 0.01", "must increase");
  refused("grain-0.4+walls-0.1: {arrangements:", "grain-0.4+walls-0.1: {grid: 1, arrangements:", "grid");
  refused("    forms: [union-refit, stress, stress-joint]", "    forms: [union-refit, stress-normal]", "forms");
  refused("    held_out_kinds: [grain-0.6+walls-0.15, wall+walls-0.15]", "    held_out_kinds: [grain-0.6+walls-0.15]", "give a wall+walls-D kind");
  refused("    held_out_kinds: [grain-0.6+walls-0.15, wall+walls-0.15]", "    held_out_kinds: [grain-0.6+walls-0.15, soft+walls-0.15]",
          "a grain or a wall at the first contact");
  refused("    kinds: [soft+walls-0.1, soft+walls-0.2]\n    fit: [opposite, tetrahedral", "    kinds: [soft+walls-0.1, wall+walls-0.2]\n    fit: [opposite, tetrahedral",
          "a soft-particle at the first contact");
}

}  // namespace
}  // namespace softpack
