// Bodies inside bodies (scene/bodies.hpp, docs/nested.md): a soft-particle of a body lies in
// its body's shell, which pushes it by the soft-solid law (Eq. 7 at Δn = h / R, written out
// from the law file's numbers); a shell's `parent` encloses it, so the grains of the inner body
// meet the outer shell by Hertz's law (Eq. 3 with the concave R12, written out), a driver of the
// outer body moves them, and the force between two bodies counts them. Scenes without a parent
// are unchanged (their bits: ResultBits.*).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "formats/scene_laws.hpp"
#include "scene/bodies.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"
#include "support/written_out_laws.hpp"

namespace softpack {
namespace {

constexpr double kRs = 0.05;  // the outer shell's radius [m]

ShellDef shell(const std::string& name, int body, const Vec3& c, double radius, int parent = kNoBody) {
  ShellDef s;
  s.name = name, s.body = body, s.centre = c, s.radius = radius, s.parent = parent;
  return s;
}

ParticleDef grain(const Vec3& x, double r, int body) {
  ParticleDef p;
  p.x = x, p.r = r, p.body = body;
  return p;
}

// Eq. 3 with Eq. 4 written out: Fn = sqrt(R12) h^(3/2) / D, D = 3/4 * 2 (1 - nu^2) / E.
double hertz(double R12, double h) {
  const Material m = testing::paper_grain();
  const double D = 0.75 * 2.0 * (1.0 - m.nu * m.nu) / m.E;
  return std::sqrt(R12) * std::pow(h, 1.5) / D;
}

TEST(NestedBodies, ASoftParticleOfABodyIsPushedByItsShellByTheSoftSolidLaw) {
  const LawFile& file = testing::pairwise_law_file();
  const double R = file.reference_radius;
  for (const double dn : {0.15, 0.3, 0.45}) {
    SceneDef s = testing::basic_scene();
    s.effects.soft_particles = SoftParticlesDef{soft_particle_laws(file, testing::kPairwiseLaws), GrainContactRule::wall,
                                                SoftParticlesDef::BeyondRange::report};
    ParticleDef p = testing::soft_particle(Vec3(kRs - R + dn * R, 0, 0), R);
    p.body = 0;
    s.particles = {p};
    s.shells = {shell("outer", 0, Vec3::Zero(), kRs)};
    s.drivers = {HoldGroupDef{GroupDef{}}};
    Simulation sim(s);
    const double expected = testing::eq7("soft-solid", dn);
    ASSERT_GT(expected, 0.0);
    EXPECT_NEAR(-sim.particles().F[0].x(), expected, 1e-9 * expected) << "dn = " << dn;
    EXPECT_NEAR(sim.shell_loads()[0].force.x(), expected, 1e-9 * expected);
    EXPECT_EQ(sim.particles().F[0].y(), 0.0);
  }
}

// Outer shell (body 0) and an inner free shell (body 1, parent 0) that pokes out of it: a grain
// of body 1 pressed into the outer shell by h meets it by Hertz's law; the inner shell, which
// it does not touch, carries nothing.
SceneDef nested_scene(double h, double r) {
  SceneDef s = testing::basic_scene();
  s.shells = {shell("outer", 0, Vec3::Zero(), kRs), shell("inner", 1, Vec3(0.045, 0, 0), 0.01, 0)};
  s.shells[1].mass = 1e-3;
  s.particles = {grain(Vec3(kRs - r + h, 0, 0), r, 1), grain(Vec3(-0.02, 0, 0), 0.004, 0)};
  return s;
}

TEST(NestedBodies, TheGrainsOfAnInnerBodyMeetTheEnclosingShell) {
  const double h = 1e-4, r = 0.002;
  SceneDef s = nested_scene(h, r);
  s.drivers = {HoldGroupDef{GroupDef{}}};
  Simulation sim(s);
  const double expected = hertz(r * kRs / (kRs - r), h);
  EXPECT_NEAR(-sim.particles().F[0].x(), expected, 1e-12 * expected);
  EXPECT_NEAR(sim.shell_loads()[0].force.x(), expected, 1e-12 * expected);
  EXPECT_EQ(sim.shell_loads()[1].force, Vec3::Zero());
  // Without the parent the outer shell ignores the inner body's grain.
  s.shells[1].parent = kNoBody;
  Simulation flat(s);
  EXPECT_EQ(flat.particles().F[0], Vec3::Zero());
  EXPECT_EQ(flat.shell_loads()[0].force, Vec3::Zero());
}

TEST(NestedBodies, ADriverOfTheOuterBodyMovesTheInnerBodysGrains) {
  SceneDef s = nested_scene(-1e-3, 0.002);  // nothing touches
  const Vec3 v(0.0, 0.01, 0.0);
  s.drivers = {TranslateGroupDef{GroupDef{GroupDef::Kind::body, 0}, v, std::nullopt, 1.0, AfterDrive::release}};
  Simulation sim(s);
  const Vec3 x0 = sim.particles().x[0], x1 = sim.particles().x[1];
  for (int k = 0; k < 10; ++k) sim.step();
  const Vec3 moved = v * sim.time();
  EXPECT_NEAR((sim.particles().x[0] - x0 - moved).norm(), 0.0, 1e-15) << "the inner body's grain";
  EXPECT_NEAR((sim.particles().x[1] - x1 - moved).norm(), 0.0, 1e-15) << "the outer body's grain";
}

TEST(NestedBodies, TheForceBetweenTwoBodiesCountsTheBodiesInsideThem) {
  // Body 1 inside body 0; body 2 beside body 0; a grain of body 1 presses a grain of body 2.
  SceneDef s = testing::basic_scene();
  const double r = 0.002, h = 1e-4;
  s.shells = {shell("a", 0, Vec3::Zero(), kRs), shell("a-inner", 1, Vec3(0.04, 0, 0), 0.01, 0),
              shell("b", 2, Vec3(0.09, 0, 0), kRs)};
  s.particles = {grain(Vec3(0.044, 0, 0), r, 1), grain(Vec3(0.044 + 2 * r - h, 0, 0), r, 2)};
  s.drivers = {HoldGroupDef{GroupDef{}}};
  Simulation sim(s);
  const double expected = hertz(0.5 * r, h);
  EXPECT_NEAR(sim.force_between(0, 2).x(), expected, 1e-12 * expected);
  EXPECT_NEAR(sim.force_between(1, 2).x(), expected, 1e-12 * expected);
  EXPECT_NEAR(sim.force_between(2, 0).x(), -expected, 1e-12 * expected);
}

TEST(NestedBodies, TheTreeAndTheMembersFollowTheParents) {
  const std::vector<ShellDef> shells = {shell("a", 0, Vec3::Zero(), kRs), shell("b", 1, Vec3::Zero(), 0.01, 0),
                                        shell("c", 2, Vec3::Zero(), 0.005, 1), shell("d", 3, Vec3(1, 0, 0), kRs)};
  const BodyTree tree(shells);
  EXPECT_EQ(tree.root(2), 0);
  EXPECT_EQ(tree.parent(2), 1);
  EXPECT_TRUE(tree.within(2, 0));
  EXPECT_FALSE(tree.within(0, 2));
  EXPECT_FALSE(tree.within(3, 0));
  const auto members = shell_members(shells, {2, 0, kNoBody, 3, 1});
  EXPECT_EQ(members[0], (std::vector<int>{0, 1, 4}));
  EXPECT_EQ(members[1], (std::vector<int>{0, 4}));
  EXPECT_EQ(members[2], (std::vector<int>{0}));
  EXPECT_EQ(members[3], (std::vector<int>{3}));
}

void expect_refused(const SceneDef& s, const std::string& key) {
  try {
    Simulation sim(s);
    FAIL() << "accepted; expected a refusal naming " << key;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(NestedBodies, TheRulesNameTheKey) {
  SceneDef s = nested_scene(-1e-3, 0.002);
  s.shells[1].parent = 1;
  expect_refused(s, "shells[1].parent");
  s.shells[1].parent = 7;  // no shell of body 7
  expect_refused(s, "shells[1].parent");
  s = nested_scene(-1e-3, 0.002);
  s.shells[0].parent = 1;  // 0 in 1 in 0
  expect_refused(s, "encloses itself");
  s = nested_scene(-1e-3, 0.002);
  s.shells[1].centre = Vec3(0.06, 0, 0);
  s.particles[0].x = Vec3(0.062, 0, 0);
  expect_refused(s, "shells[1].centre");
  s = nested_scene(-1e-3, 0.002);
  s.shells[1].radius = 0.02;
  s.particles[0].x = Vec3(0.055, 0, 0);  // in its own shell, outside the enclosing one
  expect_refused(s, "particles[0]");
  // A soft-particle of a body without a shell.
  SceneDef soft = testing::basic_scene();
  const LawFile& file = testing::pairwise_law_file();
  soft.effects.soft_particles = SoftParticlesDef{soft_particle_laws(file, testing::kPairwiseLaws), GrainContactRule::wall,
                                                 SoftParticlesDef::BeyondRange::report};
  ParticleDef p = testing::soft_particle(Vec3::Zero(), file.reference_radius);
  p.body = 4;
  soft.particles = {p};
  expect_refused(soft, "particles[0].body");
}

}  // namespace
}  // namespace softpack
