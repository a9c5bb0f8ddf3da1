// Scene files and profiles: every mistake gives one message naming the file, line, key and what
// is allowed; integers and seeds are read exactly.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "config/profile.hpp"
#include "core/error.hpp"
#include "core/integer_text.hpp"
#include "core/random.hpp"
#include "measure/settings.hpp"
#include "packing/packing_profile.hpp"
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

// --- Integers and seeds, read exactly ----------------------------------------------------------

// Random draws of these tests: a fixed seed, printed, so that a failure reproduces.
constexpr std::uint64_t kRangeTestSeed = 20240611;

// The message of loading `text` as a profile with every section read ("" if it loads).
std::string profile_error(const std::string& text) {
  try {
    const ConfigNode root = ConfigNode::load_string(text, "profile.yaml");
    parse_seeds(root);
    parse_packing(root);
    parse_measurement(root);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string quick_profile() {
  std::ifstream in(SOFTPACK_SOURCE_DIR "/experiments/quick.yaml");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Integers, AreReadExactlyAsDecimalDigits) {
  EXPECT_EQ(parse_integer("0").value, 0);
  EXPECT_EQ(parse_integer("-42").value, -42);
  EXPECT_EQ(parse_integer("9223372036854775807").value, INT64_MAX);
  EXPECT_EQ(parse_integer("-9223372036854775808").value, INT64_MIN);
  EXPECT_EQ(parse_integer("9223372036854775808").status, IntegerText::Status::out_of_range);
  EXPECT_EQ(parse_integer("-9223372036854775809").status, IntegerText::Status::out_of_range);
  EXPECT_EQ(parse_integer("99999999999999999999999").status, IntegerText::Status::out_of_range);
  for (const char* bad : {"", "-", "+3", " 3", "3 ", "1.5", "2.0", "1e3", "0x10", "0o7", "007", "-0", "1_000", "3a"})
    EXPECT_EQ(parse_integer(bad).status, IntegerText::Status::not_integer) << "'" << bad << "'";
}

TEST(SceneFile, IntegerKeysAreReadExactly) {
  // Through a double, 6.0 and 6e0 were 6 and 2^63 was clamped; now only decimal digits are.
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: 6.0")),
                  "run.relaxation.stops: expected an integer, got '6.0' (decimal digits");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: 6e0")), "run.relaxation.stops: expected an integer, got '6e0'");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: +6")), "run.relaxation.stops: expected an integer, got '+6'");
  EXPECT_CONTAINS(error_of(replace(kValid, "body: 0}\n  - {x: [0, 0, 0.0025]", "body: 00}\n  - {x: [0, 0, 0.0025]")),
                  "particles[0].body: expected an integer, got '00'");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: 9223372036854775808")),
                  "run.relaxation.stops: '9223372036854775808' is out of the range of integers");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: many")), "run.relaxation.stops: expected a number, got 'many'");
}

TEST(Profile, SeedsAtOrBeyond2To63AreRefusedNotClamped) {
  SCOPED_TRACE("random seed of this test: " + std::to_string(kRangeTestSeed));
  std::mt19937_64 rng(kRangeTestSeed);
  const std::string text = quick_profile();
  ASSERT_NE(text.find("seeds: [1, 2]"), std::string::npos);
  std::vector<std::string> seeds{"9223372036854775808", "18446744073709551615", "18446744073709551616",
                                 "99999999999999999999999999"};
  for (int k = 0; k < 5; ++k)  // random seeds in [2^63, 2^64)
    seeds.push_back(std::to_string(std::uniform_int_distribution<std::uint64_t>(std::uint64_t{1} << 63, UINT64_MAX)(rng)));
  for (const std::string& seed : seeds) {
    const std::string msg = profile_error(replace(text, "seeds: [1, 2]", "seeds: [1, " + seed + "]"));
    EXPECT_CONTAINS(msg, "profile.yaml:6:12: seeds[1]: '" + seed + "' is not allowed; allowed: a seed, an integer 0 <= seed "
                         "<= 9223372036854775807 (2^63 - 1)");
  }
  // The largest seed is read exactly (a double would make it 2^63).
  const ConfigNode root = ConfigNode::load_string(replace(text, "seeds: [1, 2]", "seeds: [0, 9223372036854775807]"), "p.yaml");
  EXPECT_EQ(parse_seeds(root), (std::vector<std::uint64_t>{0, 9223372036854775807ull}));
}

TEST(Profile, SeedsThatAreNotPlainDecimalIntegersAreRefused) {
  const std::string text = quick_profile();
  for (const char* seed : {"1.5", "1e3", "2.0", "+3", "-1", "007", "0x10", "'3 '", "three"}) {
    const std::string msg = profile_error(replace(text, "seeds: [1, 2]", std::string("seeds: [1, ") + seed + "]"));
    EXPECT_CONTAINS(msg, "seeds[1]: '");
    EXPECT_CONTAINS(msg, "' is not allowed; allowed: a seed, an integer 0 <= seed <= 9223372036854775807");
  }
  std::string error;
  EXPECT_FALSE(parse_seed("1\n2", error));
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
}

TEST(Profile, RepeatedSeedsAreRefusedNamingKeyAndValue) {
  const std::string text = quick_profile();
  EXPECT_CONTAINS(profile_error(replace(text, "seeds: [1, 2]", "seeds: [1, 1]")),
                  "profile.yaml:6:12: seeds[1]: seed 1 is listed twice (first as seeds[0])");
  EXPECT_CONTAINS(profile_error(replace(text, "seeds: [1, 2]", "seeds: [5, 9, 7, 9]")), "seeds[3]: seed 9 is listed twice (first as seeds[1])");
}

}  // namespace
}  // namespace softpack
