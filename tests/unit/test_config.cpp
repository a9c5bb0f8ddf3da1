// Scene files: every mistake gives one message naming the file, line, key and what is allowed.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "scene/scene_yaml.hpp"

namespace softpack {
namespace {

const std::string kValid = R"(materials:
  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}
effects:
  normal: hertz
  friction: tsuji
  rotation: true
  damping: {restitution: 0.5, tangential_ratio: 1.0}
particles:
  - {x: [0, 0, 0], r: 1.0e-3, material: grain, body: 0}
  - {x: [0, 0, 0.0025], r: 1.0e-3, material: grain, body: 0}
shells:
  - {name: shell, body: 0, centre: [0, 0, 0.001], radius: 0.016, material: grain, contact_radius: concave}
planes:
  - {name: floor, point: [0, 0, -0.001], normal: [0, 0, 1], material: grain}
drivers:
  - {type: move_wall, wall: floor, velocity: [0, 0, 1.0e-3], distance: 1.0e-5}
integration: {safety: 0.2, tangential_history: synchronized}
neighbor: {skin: 0.2, level_ratio: 2.0}
run:
  relaxation: {protocol: paper, stops: 6, wait: 0.3, final_wait: 0.3}
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The message that loading `text` produces ("" if it loads).
std::string error_of(const std::string& text) {
  try {
    parse_scene(ConfigNode::load_string(text, "scene.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_CONTAINS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

TEST(SceneFile, ValidSceneLoads) {
  const SceneFile f = parse_scene(ConfigNode::load_string(kValid, "scene.yaml"));
  EXPECT_EQ(f.scene.particles.size(), 2u);
  EXPECT_TRUE(f.scene.effects.friction);
  EXPECT_DOUBLE_EQ(*f.scene.effects.restitution, 0.5);
  EXPECT_EQ(f.scene.shells.at(0).contact_radius, ShellContactRadius::concave);
  ASSERT_TRUE(f.run.relaxation.has_value());
  EXPECT_EQ(std::get<PaperRelaxationDef>(*f.run.relaxation).stops, 6);
}

TEST(SceneFile, MalformedYamlGivesLineAndColumn) {
  const std::string msg = error_of("materials:\n  grain: {E: 5.0e5, nu: 0.3\neffects: [\n");
  EXPECT_CONTAINS(msg, "scene.yaml:");
  EXPECT_CONTAINS(msg, "malformed YAML");
}

TEST(SceneFile, UnknownEffectIsRejectedWithASuggestion) {
  const std::string msg = error_of(replace(kValid, "  friction: tsuji", "  frcition: tsuji"));
  EXPECT_CONTAINS(msg, "scene.yaml:5:3: effects.frcition: unknown key");
  EXPECT_CONTAINS(msg, "did you mean 'friction'?");
  EXPECT_CONTAINS(msg, "allowed: normal, friction, rotation, damping, gravity");
}

TEST(SceneFile, UnknownTopLevelKeyIsRejected) {
  EXPECT_CONTAINS(error_of(kValid + "neighbour: {skin: 0.1}\n"), "did you mean 'neighbor'?");
}

TEST(SceneFile, ValueOutOfRangeNamesKeyAndRange) {
  const std::string msg = error_of(replace(kValid, "nu: 0.3", "nu: 0.7"));
  // validate() owns the range; the reader places its message at the key.
  EXPECT_CONTAINS(msg, "scene.yaml:2:25: materials.grain.nu: 0.7 is not allowed; allowed: -1 < nu < 0.5");
}

TEST(SceneFile, NonNumberIsRejected) {
  EXPECT_CONTAINS(error_of(replace(kValid, "r: 1.0e-3, material: grain, body: 0}\n  - {x: [0, 0, 0.0025]",
                                   "r: big, material: grain, body: 0}\n  - {x: [0, 0, 0.0025]")),
                  "particles[0].r: expected a number, got 'big'");
}

TEST(SceneFile, MissingKeyIsNamed) {
  EXPECT_CONTAINS(error_of(replace(kValid, "density: 2500.0", "rho: 2500.0")),
                  "materials.grain.rho: unknown key; allowed: E, nu, mu, density");
  EXPECT_CONTAINS(error_of(replace(kValid, ", density: 2500.0", "")), "materials.grain: missing required key 'density'");
}

TEST(SceneFile, UnknownMaterialIsNamed) {
  EXPECT_CONTAINS(error_of(replace(kValid, "material: grain, body: 0}\n  - {x: [0, 0, 0.0025]",
                                   "material: grian, body: 0}\n  - {x: [0, 0, 0.0025]")),
                  "'grian' is not allowed; did you mean 'grain'?");
}

TEST(SceneFile, DriverOnMissingBodyIsRejected) {
  const std::string text = replace(kValid, "  - {type: move_wall, wall: floor, velocity: [0, 0, 1.0e-3], distance: 1.0e-5}",
                                   "  - {type: hold, group: {body: 7}}");
  EXPECT_CONTAINS(error_of(text), "drivers[0].group.body: body 7 does not exist (bodies present: 0)");
}

TEST(SceneFile, DriverOnMissingWallIsRejected) {
  EXPECT_CONTAINS(error_of(replace(kValid, "wall: floor", "wall: roof")), "drivers[0].wall: no plane or shell is named 'roof'");
}

TEST(SceneFile, ContradictorySettingsAreRejected) {
  EXPECT_CONTAINS(error_of(replace(kValid, "  friction: tsuji\n", "")), "effects.rotation: rotation without friction");
  EXPECT_CONTAINS(error_of(replace(kValid, "{safety: 0.2,", "{safety: 0.2, dt: 1.0e-6,")), "give 'dt' or 'safety', not both");
  EXPECT_CONTAINS(error_of(replace(kValid, "distance: 1.0e-5", "distance: 1.0e-5, duration: 1.0")), "give 'distance' or 'duration', not both");
  EXPECT_CONTAINS(error_of(replace(kValid, "mu: 0.3", "mu: 0.0")), "friction declared but every material has mu = 0");
  EXPECT_CONTAINS(error_of(replace(kValid, "  normal: hertz\n", "")), "friction needs the normal law");
}

TEST(SceneFile, SphereOutsideItsShellIsRejected) {
  EXPECT_CONTAINS(error_of(replace(kValid, "radius: 0.016", "radius: 0.0014")), "particles[1]: its centre lies outside shell 'shell'");
}

TEST(SceneFile, TwoDriversOnTheSameSpheresAreRejected) {
  const std::string text = replace(kValid, "  - {type: move_wall, wall: floor, velocity: [0, 0, 1.0e-3], distance: 1.0e-5}",
                                   "  - {type: hold, group: {body: 0}}\n  - {type: hold, group: all}");
  EXPECT_CONTAINS(error_of(text), "drivers[1].group: these spheres are already moved by an earlier driver");
}

TEST(SceneFile, MissingFileIsReported) {
  try {
    load_scene_file("/nonexistent/scene.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "/nonexistent/scene.yaml: cannot open the file");
  }
}

TEST(ClosestMatch, SuggestsOnlyCloseWords) {
  EXPECT_EQ(closest_match("frcition", {"normal", "friction"}), "friction");
  EXPECT_EQ(closest_match("zzzzzzzz", {"normal", "friction"}), "");
}

}  // namespace
}  // namespace softpack
