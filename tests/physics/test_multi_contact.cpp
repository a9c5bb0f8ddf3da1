// The multi-contact probe (coarse/multi_contact.hpp) on the tiny settings: the arrangements are
// what their names say, each contact reports its push, the walls' path keeps its numbers, other
// bodies press like walls, a body presses a soft-particle that walls already confine, and the
// confined shear leaves no trace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "coarse/multi_contact.hpp"
#include "coarse/settings.hpp"
#include "core/error.hpp"
#include "support/coarse_tiny.hpp"

namespace softpack {
namespace {

using testing::coarse_grain_tiny;

// The many-body probe's arrangements (coarse/multi_contact.hpp): unit directions, the first +z at
// its full Δn, the angles each names, random-N's directions apart by 60 degrees and the same for a seed.
TEST(MultiContactProbe, TheArrangementsAreWhatTheirNamesSay) {
  const auto angle = [](const ProbeWall& a, const ProbeWall& b) { return std::acos(std::clamp(a.u.dot(b.u), -1.0, 1.0)) * 180.0 / std::numbers::pi; };
  const std::pair<const char*, std::size_t> walls[] = {{"one", 1},     {"opposite", 2}, {"orthogonal", 2},    {"triangle", 3},
                                                       {"tetrahedral", 4}, {"square", 4},   {"pyramid", 5},       {"cube", 6},
                                                       {"opposite-half", 2}, {"orthogonal-half", 2}, {"random-2", 2}, {"random-6", 6}};
  for (const auto& [name, n] : walls) {
    const ProbeArrangement a = builtin_arrangement(name, 7);
    ASSERT_EQ(a.walls.size(), n) << name;
    EXPECT_EQ(a.walls[0].u, Vec3::UnitZ()) << name;
    EXPECT_EQ(a.walls[0].w, 1.0) << name;
    for (const ProbeWall& w : a.walls) EXPECT_NEAR(w.u.norm(), 1.0, 1e-12) << name;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) EXPECT_GE(angle(a.walls[i], a.walls[j]), 60.0 - 1e-9) << name << " walls " << i << ", " << j;
  }
  const ProbeArrangement t = builtin_arrangement("tetrahedral", 0);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) EXPECT_NEAR(t.walls[i].u.dot(t.walls[j].u), -1.0 / 3.0, 1e-12);
  const ProbeArrangement tri = builtin_arrangement("triangle", 0);
  EXPECT_NEAR(angle(tri.walls[1], tri.walls[2]), 120.0, 1e-9);
  EXPECT_NEAR(angle(builtin_arrangement("orthogonal-half", 0).walls[0], builtin_arrangement("orthogonal-half", 0).walls[1]), 90.0, 1e-9);
  EXPECT_EQ(builtin_arrangement("opposite-half", 0).walls[1].w, 0.5);
  const ProbeArrangement r1 = builtin_arrangement("random-5", 11), r2 = builtin_arrangement("random-5", 11), r3 = builtin_arrangement("random-5", 12);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(r1.walls[k].u, r2.walls[k].u);
  EXPECT_NE(r1.walls[1].u, r3.walls[1].u);
  const ProbeArrangement g = builtin_arrangement("cube:grain-0.4", 0), soft = builtin_arrangement("one:soft", 0);
  EXPECT_EQ(g.walls.size(), 6u);
  EXPECT_EQ(g.body.kind, PressingBody::Kind::grain);
  EXPECT_EQ(g.body.radius_ratio, 0.4);
  EXPECT_EQ(g.body.name(), "grain-0.4");
  EXPECT_EQ(soft.body.kind, PressingBody::Kind::soft);
  EXPECT_EQ(builtin_arrangement("one:wall", 0).body.kind, PressingBody::Kind::wall);
  // a confining plane must not cut the body pressing at the first contact: random-N (walls 60
  // degrees apart) is refused with +walls-D, every fixed arrangement's walls stand 90 degrees or more away
  for (const char* name : {"orthogonal", "triangle", "tetrahedral", "square", "pyramid", "cube", "opposite-half", "orthogonal-half"})
    EXPECT_NO_THROW(builtin_arrangement(std::string(name) + ":soft+walls-0.15", 0)) << name;
  try {
    builtin_arrangement("random-5:soft+walls-0.15", 501);
    ADD_FAILURE() << "random-5 taken with +walls-D";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("90 degrees"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(builtin_arrangement("random-5:soft", 501));
  for (const char* bad : {"one:rock", "one:grain-0", "one:grain-x", "one:grain-0.4x", "one:"}) {
    try {
      builtin_arrangement(bad, 0);
      ADD_FAILURE() << bad << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("allowed: wall, soft, grain-X"), std::string::npos) << e.what();
    }
  }
  const ProbeArrangement r12 = builtin_arrangement("random-12", 5);
  ASSERT_EQ(r12.walls.size(), 12u);
  for (std::size_t k = 0; k < 12; ++k)
    for (std::size_t l = 0; l < k; ++l) EXPECT_GE(angle(r12.walls[k], r12.walls[l]), 40.0 - 1e-9);
  for (const char* bad : {"two", "random-1", "random-13", "random-07", "random-", "random-6x", "Cube"}) {
    try {
      builtin_arrangement(bad, 0);
      ADD_FAILURE() << bad << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("allowed: one, opposite"), std::string::npos) << e.what();
    }
  }
}

// On the tiny settings: one force per wall and point, each a push (>= 0), and Δn out of order refused.
TEST(MultiContactProbe, EachWallOfAnArrangementReportsItsPush) {
  const std::vector<ProbeArrangement> a{builtin_arrangement("orthogonal-half", 3)};
  const auto points = measure_multi_contact(coarse_grain_tiny(), 3, a, {0.3, 0.5});
  ASSERT_EQ(points.size(), 2u);
  for (const MultiContactPoint& p : points) {
    ASSERT_EQ(p.Fn.size(), 2u);
    for (const double F : p.Fn) EXPECT_TRUE(std::isfinite(F) && F >= 0.0) << F;
  }
  EXPECT_GT(points[1].Fn[0], 0.0);
  EXPECT_GT(points[1].Fn[1], 0.0);
  EXPECT_THROW(measure_multi_contact(coarse_grain_tiny(), 3, a, {0.2, 0.1}), InputError);
  EXPECT_THROW(measure_multi_contact(coarse_grain_tiny(), 3, a, {1.0}), InputError);
}

// The walls-only probe keeps its numbers (the committed data/many-body/probe/*/seed-S.dat were
// made by it): the tiny settings' forces, recorded when the pressing bodies came in beside the
// walls (to 1e-9: a change of the walls' path moves them by far more).
TEST(MultiContactProbe, TheWallsKeepTheirForces) {
  const auto points = measure_multi_contact(coarse_grain_tiny(), 3, {builtin_arrangement("opposite", 3)}, {0.3, 0.5});
  ASSERT_EQ(points.size(), 2u);
  const double expected[2][2] = {{0.13262936025659181, 0.16089455636791539}, {5.7228875962771593, 5.208651712451676}};
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t w = 0; w < 2; ++w) EXPECT_NEAR(points[k].Fn[w], expected[k][w], 1e-9 * std::abs(expected[k][w])) << k << " " << w;
}

// Other pressing bodies: a held grain and a resolved soft-particle push back on every contact.
TEST(MultiContactProbe, GrainsAndSoftParticlesPressLikeWalls) {
  const std::vector<ProbeArrangement> a{builtin_arrangement("opposite:grain-1", 3), builtin_arrangement("opposite:soft", 3)};
  const auto points = measure_multi_contact(coarse_grain_tiny(), 3, a, {0.2, 0.4});
  ASSERT_EQ(points.size(), 4u);
  for (const MultiContactPoint& p : points) {
    ASSERT_TRUE(p.failed.empty()) << p.failed;
    ASSERT_EQ(p.Fn.size(), 2u);
    for (const double F : p.Fn) EXPECT_TRUE(std::isfinite(F) && F >= 0.0) << p.arrangement << " " << F;
  }
  for (const std::size_t k : {1u, 3u}) EXPECT_GT(points[k].Fn[0] + points[k].Fn[1], 0.0) << points[k].arrangement;
}

// The confined shear: Δn's unsheared point, then each slide; the next Δn starts again from the
// unsheared state, so its ht = 0 point is the plain probe's at that Δn; bad input refused.
TEST(MultiContactProbe, TheConfinedShearSlidesTheFirstWallAndLeavesNoTrace) {
  const std::vector<ProbeArrangement> a{builtin_arrangement("opposite", 3)};
  const auto sheared = measure_confined_shear(coarse_grain_tiny(), 3, a, {0.3, 0.5}, {0.01, 0.05});
  ASSERT_EQ(sheared.size(), 6u);
  for (const ShearPoint& p : sheared) ASSERT_TRUE(p.failed.empty()) << p.failed;
  EXPECT_EQ(sheared[1].ht, 0.01);
  EXPECT_EQ(sheared[3].ht, 0.0);
  EXPECT_EQ(sheared[3].delta_n, 0.5);
  const auto plain = measure_multi_contact(coarse_grain_tiny(), 3, a, {0.3, 0.5});
  EXPECT_EQ(sheared[0].Fn, plain[0].Fn[0]);
  EXPECT_NEAR(sheared[3].Fn, plain[1].Fn[0], 1e-9 * std::abs(plain[1].Fn[0]));
  EXPECT_NE(sheared[2].Ft, sheared[0].Ft) << "the slide loads the wall tangentially";
  EXPECT_THROW(measure_confined_shear(coarse_grain_tiny(), 3, a, {0.3}, {0.05, 0.01}), InputError);
  EXPECT_THROW(measure_confined_shear(coarse_grain_tiny(), 3, {builtin_arrangement("one:soft", 3)}, {0.3}, {0.01}), InputError);
}

// BODY+walls-D: the first contact is the body, the others walls moved in to D first and held:
// the name reads back, D out of (0, 0.5] or a single contact is refused; the wall pushes as the
// body arrives, the body pushes as it comes in — a grain, or a wall (the seventh part's).
TEST(MultiContactProbe, ABodyPressesASoftParticleTheWallsConfine) {
  const ProbeArrangement a = builtin_arrangement("opposite:grain-1+walls-0.45", 3);
  EXPECT_EQ(a.body.kind, PressingBody::Kind::grain);
  EXPECT_EQ(a.body.walls_at, 0.45);
  EXPECT_EQ(a.body.name(), "grain-1+walls-0.45");
  EXPECT_EQ(a.body.kind_at(0), PressingBody::Kind::grain);
  EXPECT_EQ(a.body.kind_at(1), PressingBody::Kind::wall);
  EXPECT_EQ(parse_pressing_body("soft+walls-0.1").name(), "soft+walls-0.1");
  EXPECT_EQ(parse_pressing_body("wall+walls-0.2").name(), "wall+walls-0.2");
  for (const char* bad : {"opposite:wall+walls-0", "opposite:soft+walls-0", "opposite:soft+walls-0.6", "opposite:soft+walls-x", "one:soft+walls-0.2"})
    EXPECT_THROW(builtin_arrangement(bad, 3), InputError) << bad;
  const auto points = measure_multi_contact(coarse_grain_tiny(), 3, {a}, {0.02, 0.5});
  ASSERT_EQ(points.size(), 2u);
  for (const MultiContactPoint& p : points) ASSERT_TRUE(p.failed.empty()) << p.failed;
  EXPECT_GT(points[0].Fn[1], 0.0) << "the confining wall pushes as the grain barely arrives";
  EXPECT_GT(points[1].Fn[0], points[0].Fn[0]) << "the grain pushes as it comes in";
  EXPECT_GT(points[1].Fn[1], 0.0);
  const auto walls = measure_multi_contact(coarse_grain_tiny(), 3, {builtin_arrangement("opposite:wall+walls-0.45", 3)}, {0.02, 0.5});
  ASSERT_EQ(walls.size(), 2u);
  for (const MultiContactPoint& p : walls) ASSERT_TRUE(p.failed.empty()) << p.failed;
  EXPECT_GT(walls[0].Fn[1], 0.0) << "the confining wall pushes as the first wall barely arrives";
  EXPECT_GT(walls[1].Fn[0], walls[0].Fn[0]) << "the first wall pushes as it comes in";
}

}  // namespace
}  // namespace softpack

