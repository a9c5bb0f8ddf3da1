// The measurement scenes of a packing of nested soft-particles (measure/contact_scenes.hpp,
// the profile's `content`, docs/nested.md): each site one soft-particle of its content's mass
// (soft), or its content down to the last level in free shells inside the enclosing one
// (resolved); the same packing gives the same grains of its own level in both, and a scene is
// built only with a `content` that says how to hold its sites.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"
#include "measure/contact_scenes.hpp"
#include "measure/settings.hpp"
#include "packing/nested.hpp"
#include "sim/simulation.hpp"
#include "support/sweep_fixture.hpp"
#include "support/temp_dir.hpp"
#include "support/written_out_laws.hpp"

namespace softpack {
namespace {

// Two levels at Π = √10 whose sites (Rs / Π = 16 mm) are the radius study's soft-particle, so
// that its law file holds them.
PackingFile level_packing(std::uint64_t seed) {
  PackingParameters p;
  p.Rs = 0.016 * std::sqrt(10.0);
  p.r_max = 0.3 * p.Rs;
  p.polydispersity = std::sqrt(10.0);
  p.exponent = 3.5;
  p.beta = 1.0;
  p.trials = 300;
  p.level_ratio = 2.0;
  const LevelPacking l = generate_level(p, 1, seed);
  PackingFile f;
  f.centres = l.grains.centres, f.radii = l.grains.radii, f.Rs = p.Rs, f.parameters = p;
  f.provenance.seed = seed;
  f.sites = PackingSites{2, l.site_radius, l.sites, l.sites_drawn, l.sites_discarded};
  return f;
}

SimulationSettings settings(ContentForm form) {
  SimulationSettings s = parse_measurement(testing::sweep_profile()).simulation;
  ContentSettings c;
  c.form = form;
  c.shell_mass_fraction = 0.05;
  if (form == ContentForm::soft) c.laws = testing::kPairwiseLaws;
  s.content = c;
  return s;
}

double ball(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

TEST(NestedContent, SoftSitesAreSoftParticlesOfTheirContentsMass) {
  const PackingFile f = level_packing(71);
  ASSERT_FALSE(f.sites.centres.empty());
  const SimulationSettings s = settings(ContentForm::soft);
  const ContactSetup c = soft_solid_setup(f, s);
  const auto contents = generate_contents(f.parameters, 1, 71, f.sites.centres.size());
  ASSERT_EQ(c.scene.particles.size(), f.radii.size() + f.sites.centres.size());
  for (std::size_t k = 0; k < f.sites.centres.size(); ++k) {
    const ParticleDef& p = c.scene.particles[f.radii.size() + k];
    EXPECT_TRUE(p.soft);
    EXPECT_EQ(p.body, 0);
    EXPECT_EQ(p.r, f.sites.radius);
    double grains = 0.0;  // the content's grains, written out; the last level has no shells below
    for (double r : contents[k].level.grains.radii) grains += s.material.density * ball(r);
    ASSERT_TRUE(contents[k].sites.empty());
    EXPECT_NEAR(*p.mass, 1.05 * grains, 1e-12 * grains);
  }
  ASSERT_TRUE(c.scene.effects.soft_particles.has_value());
  EXPECT_NO_THROW(Simulation sim(c.scene));
}

TEST(NestedContent, ResolvedSitesAreTheirPackingsInFreeShellsInsideTheSoftParticle) {
  const PackingFile first = level_packing(71), second = level_packing(72);
  const SimulationSettings s = settings(ContentForm::resolved);
  const ContactSetup c = soft_soft_setup(first, second, s);
  const auto a = generate_contents(first.parameters, 1, 71, first.sites.centres.size());
  const auto b = generate_contents(second.parameters, 1, 72, second.sites.centres.size());
  std::size_t grains = first.radii.size() + second.radii.size();
  for (const auto& x : a) grains += x.grains();
  for (const auto& x : b) grains += x.grains();
  EXPECT_EQ(c.scene.particles.size(), grains);
  ASSERT_EQ(c.scene.shells.size(), 2 + a.size() + b.size());
  EXPECT_FALSE(c.scene.effects.soft_particles.has_value());
  // The first soft-particle's sites are bodies 2.., inside body 0; the second's inside body 1.
  for (std::size_t k = 0; k < a.size() + b.size(); ++k) {
    const ShellDef& sh = c.scene.shells[k < a.size() ? 1 + k : 2 + k];
    EXPECT_EQ(sh.parent, k < a.size() ? 0 : 1) << sh.name;
    EXPECT_EQ(sh.body, static_cast<int>(2 + k));
    EXPECT_NEAR(sh.radius, first.sites.radius, 1e-15);
    ASSERT_TRUE(sh.mass.has_value());
  }
  // A first-level site's shell weighs 5 % of its content's grains.
  double m = 0.0;
  for (double r : a.at(0).level.grains.radii) m += s.material.density * ball(r);
  EXPECT_NEAR(*c.scene.shells[1].mass, 0.05 * m, 1e-12 * m);
  EXPECT_NO_THROW(Simulation sim(c.scene));
  // The second soft-particle scaled by k: its sites' shells weigh k^3 as much, as its grains do.
  const ContactSetup half = soft_soft_setup(first, second, s, 0.5);
  double mb = 0.0;
  for (double r : b.at(0).level.grains.radii) mb += s.material.density * ball(r);
  EXPECT_NEAR(*half.scene.shells[2 + a.size()].mass, 0.125 * 0.05 * mb, 1e-12 * mb);
}

TEST(NestedContent, BothFormsHoldTheSameGrainsOfTheSoftParticlesOwnLevel) {
  const PackingFile f = level_packing(73);
  const ContactSetup soft = soft_solid_setup(f, settings(ContentForm::soft));
  const ContactSetup resolved = soft_solid_setup(f, settings(ContentForm::resolved));
  for (std::size_t i = 0; i < f.radii.size(); ++i) {
    EXPECT_EQ(soft.scene.particles[i].x, resolved.scene.particles[i].x);
    EXPECT_EQ(soft.scene.particles[i].r, resolved.scene.particles[i].r);
  }
}

// content.many_body: the sites follow the level below's pairwise laws and another file's
// many-body law (a diagnosis of level 1's gap, experiments/nested.yaml); a file without one is
// refused naming the key, and without the key the sites are pairwise.
TEST(NestedContent, TheSitesTakeTheManyBodyLawOfTheFileContentManyBodyNames) {
  const PackingFile f = level_packing(75);
  SimulationSettings s = settings(ContentForm::soft);
  EXPECT_FALSE(soft_solid_setup(f, s).scene.effects.soft_particles->laws.many_body);
  const testing::TempDir dir("nested-content-many-body");
  LawFile with = read_law_file(testing::kPairwiseLaws);
  with.version = kLawFileVersion;  // a many-body law needs version 2 or later
  with.many_body = ManyBodyFit{"volumetric", {0.75, 0.01}, "a test"};
  write_law_file(dir / "many-body.json", with);
  s.content->many_body = dir / "many-body.json";
  const ContactSetup c = soft_solid_setup(f, s);
  const SoftParticleLaws& laws = c.scene.effects.soft_particles->laws;
  ASSERT_TRUE(laws.many_body);
  EXPECT_EQ(laws.many_body->beta, 0.75);
  // The pairwise laws stay the level below's.
  const SoftParticleLaws pairwise = soft_particle_laws(read_law_file(testing::kPairwiseLaws), testing::kPairwiseLaws);
  EXPECT_EQ(laws.soft_solid->normal.a, pairwise.soft_solid->normal.a);
  EXPECT_EQ(laws.R0, pairwise.R0);
  s.content->many_body = testing::kPairwiseLaws;  // version 1: no many-body law
  try {
    soft_solid_setup(f, s);
    FAIL() << "a many-body law file without a many-body law was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("content.many_body"), std::string::npos) << e.what();
  }
}

TEST(NestedContent, APackingOfLevelsNeedsTheContentSectionAndItsLawFile) {
  const PackingFile f = level_packing(74);
  SimulationSettings s = settings(ContentForm::soft);
  s.content->laws = "/nonexistent/laws.json";  // read when the scene is built: the level below may run later
  try {
    soft_solid_setup(f, s);
    FAIL() << "a law file that does not exist was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("content.laws"), std::string::npos) << e.what();
  }
  s.content.reset();
  try {
    soft_solid_setup(f, s);
    FAIL() << "sites measured without a content section";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("content"), std::string::npos) << e.what();
  }
}

// A resolved content's free shells are part of a point's state: saved with it and restored, so
// that the tangential stage starts from the normal stage's state (it used to refuse it).
TEST(NestedContent, APointFileKeepsTheFreeShellsMotion) {
  testing::TempDir dir("nested-point");
  const ContactSetup c = soft_solid_setup(level_packing(75), settings(ContentForm::resolved));
  Simulation sim(c.scene);
  for (int k = 0; k < 20; ++k) sim.step();
  const SimulationState state = sim.state();
  ASSERT_FALSE(state.shell_velocities.empty());
  PointResult r;
  PointProvenance prov;
  prov.stage = "normal", prov.scene = "soft-solid";
  write_point_file(dir / "point.h5", r, state, prov);
  const PointFile back = read_point_file(dir / "point.h5", true);
  EXPECT_EQ(back.state.shell_velocities, state.shell_velocities);
  EXPECT_EQ(back.state.shell_spins, state.shell_spins);
  EXPECT_EQ(back.state.shell_forces, state.shell_forces);
  EXPECT_EQ(back.state.shell_torques, state.shell_torques);
  Simulation again(c.scene);
  EXPECT_NO_THROW(again.restore(back.state));
}

// The profile's `content`: required with packing.levels > 1, refused without, its keys checked.
TEST(NestedContent, TheProfilesContentSectionNamesTheKey) {
  std::string base;
  {
    std::ifstream in(SOFTPACK_SOURCE_DIR "/tests/data/sweep-profile.yaml");
    base.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::string levels = base;
  const std::size_t at = levels.find("\n  level_ratio:");
  ASSERT_NE(at, std::string::npos);
  levels.insert(at, "\n  levels: 2");
  const auto refused = [](const std::string& text, const std::string& key) {
    try {
      parse_measurement(ConfigNode::load_string(text, "profile.yaml"));
      ADD_FAILURE() << "accepted; expected a refusal naming " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused(levels, "packing.levels");
  refused(base + "content: {form: resolved, shell_mass_fraction: 0.05}\n", "content");
  refused(levels + "content: {form: coarse, shell_mass_fraction: 0.05}\n", "content.form");
  refused(levels + "content: {form: soft, shell_mass_fraction: 0.05, grain_contact: wall}\n", "'laws'");
  refused(levels + "content: {form: resolved, shell_mass_fraction: -1}\n", "content.shell_mass_fraction");
  const MeasurementSettings m =
      parse_measurement(ConfigNode::load_string(levels + "content: {form: resolved, shell_mass_fraction: 0.05}\n", "p.yaml"));
  ASSERT_TRUE(m.simulation.content.has_value());
  EXPECT_EQ(m.simulation.content->form, ContentForm::resolved);
}

}  // namespace
}  // namespace softpack
