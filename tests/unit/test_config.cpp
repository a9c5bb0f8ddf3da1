// Scene files and profiles: every mistake gives one message naming the file, line, key and what
// is allowed, including every value beyond the ranges of scene/limits.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include "analysis/fit_options.hpp"
#include "profile/profile.hpp"
#include "core/error.hpp"
#include "core/integer_text.hpp"
#include "core/random.hpp"
#include "measure/settings.hpp"
#include "packing/packing_profile.hpp"
#include "scene/scene_yaml.hpp"
#include "scene/validate.hpp"
#include "sim/simulation.hpp"
#include "unit/config_text.hpp"

namespace softpack {
namespace {

using namespace config_test;

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

// The message that loading `text` produces ("" if it loads).
std::string error_of(const std::string& text) {
  try {
    parse_scene(ConfigNode::load_string(text, "scene.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

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

// particles[].rotation: locked holds a sphere's spin at zero; it needs effects.rotation and no w.
TEST(SceneFile, ALockedRotationIsReadAndItsConflictsAreNamed) {
  const std::string second = "{x: [0, 0, 0.0025], r: 1.0e-3, material: grain, body: 0}";
  const auto with = [&](const std::string& keys) { return replace(kValid, second, "{x: [0, 0, 0.0025], r: 1.0e-3, material: grain, body: 0, " + keys + "}"); };
  EXPECT_EQ(error_of(with("rotation: locked")), "");
  EXPECT_TRUE(parse_scene(ConfigNode::load_string(with("rotation: locked"), "scene.yaml")).scene.particles[1].spin_locked);
  EXPECT_FALSE(parse_scene(ConfigNode::load_string(with("rotation: free"), "scene.yaml")).scene.particles[1].spin_locked);
  EXPECT_CONTAINS(error_of(with("rotation: spinning")), "particles[1].rotation: 'spinning' is not allowed; allowed: free, locked");
  EXPECT_CONTAINS(error_of(replace(with("rotation: locked"), "  rotation: true\n", "")), "particles[1].rotation: locked needs effects.rotation");
  EXPECT_CONTAINS(error_of(with("rotation: locked, w: [0, 0, 1]")), "particles[1].w: a sphere whose rotation is locked cannot spin");
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

// --- Ranges (scene/limits.hpp) ------------------------------------------------------------------

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
                  "particles[0].body: '00': a number with a leading zero is not allowed");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: 9223372036854775808")),
                  "run.relaxation.stops: '9223372036854775808' is out of the range of integers");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: many")), "run.relaxation.stops: expected a number, got 'many'");
}

TEST(SceneFile, OverflowingMagnitudesAreRefusedWithKeyValueAndRange) {
  SCOPED_TRACE("random seed of this test: " + std::to_string(kRangeTestSeed));
  std::mt19937_64 rng(kRangeTestSeed);
  // (text to replace, its key, the template of the new value (%), the allowed range, the random exponents)
  struct Case {
    std::string from, key, to, allowed;
    double lo, hi;
  };
  const std::vector<Case> cases = {
      {"E: 5.0e5", "materials.grain.E", "E: %", "allowed: 1 <= E <= 1e13 Pa", 13.01, 308.2},
      {"density: 2500.0", "materials.grain.density", "density: %", "allowed: 0.001 <= density <= 1e9 kg/m^3", 9.01, 308.2},
      {"mu: 0.3", "materials.grain.mu", "mu: %", "allowed: 0 <= mu <= 100", 2.01, 308.2},
      {"r: 1.0e-3, material: grain, body: 0}\n  - {x: [0, 0, 0.0025]", "particles[0].r",
       "r: %, material: grain, body: 0}\n  - {x: [0, 0, 0.0025]", "allowed: 1e-9 <= r <= 1000 m", 3.01, 308.2},
      {"radius: 0.016", "shells[0].radius", "radius: %", "allowed: 1e-9 <= radius <= 1000 m", 3.01, 308.2},
      {"velocity: [0, 0, 1.0e-3]", "drivers[0].velocity", "velocity: [0, 0, %]", "allowed: 0 < |velocity| <= 10000 m/s", 4.01, 154},
      {"skin: 0.2", "neighbor.skin", "skin: %", "allowed: 0 < skin <= 100", 2.01, 308.2},
      {"level_ratio: 2.0", "neighbor.level_ratio", "level_ratio: %", "allowed: 1.1 <= level_ratio <= 1000", 3.01, 308.2},
      {"tangential_ratio: 1.0", "effects.damping.tangential_ratio", "tangential_ratio: %", "allowed: 0 <= tangential_ratio <= 100",
       2.01, 308.2},
  };
  for (const Case& c : cases)
    for (int k = 0; k < 4; ++k) {
      std::string value = k == 0 ? "1.0e308" : fmt::format("{:.6g}", random_magnitude(rng, c.lo, c.hi));
      std::string to = c.to;
      to.replace(to.find('%'), 1, value);
      const std::string msg = error_of(replace(kValid, c.from, to));
      EXPECT_CONTAINS(msg, "scene.yaml:");
      EXPECT_CONTAINS(msg, c.key + ": ");
      EXPECT_CONTAINS(msg, " is not allowed; " + c.allowed);
    }
  // The tiny ends, where the products underflow or the time step vanishes.
  EXPECT_CONTAINS(error_of(replace(kValid, "E: 5.0e5", "E: 1.0e-300")), "materials.grain.E: 1e-300 Pa is not allowed; allowed: 1 <= E <= 1e13 Pa");
  EXPECT_CONTAINS(error_of(replace(kValid, "density: 2500.0", "density: 1.0e-300")), "materials.grain.density: 1e-300 kg/m^3 is not allowed");
  EXPECT_CONTAINS(error_of(replace(kValid, "level_ratio: 2.0", "level_ratio: 1.0000001")),
                  "neighbor.level_ratio: 1.0000001 is not allowed; allowed: 1.1 <= level_ratio <= 1000");
  EXPECT_CONTAINS(error_of(replace(kValid, "centre: [0, 0, 0.001]", "centre: [0, 0, 1.0e300]")),
                  "shells[0].centre: 1e300 m (its z coordinate) is not allowed; allowed: -1e6 <= coordinate <= 1e6 m");
  EXPECT_CONTAINS(error_of(replace(kValid, "stops: 6", "stops: 2000000000")),
                  "run.relaxation.stops: 2e9 is not allowed; allowed: 0 <= stops <= 1e6");
}

TEST(SceneFile, SpheresBeyondTheContactGridAreRefused) {
  // Two spheres 10 km apart: 4.5e6 cells of 2.2 mm, beyond the grid's 21-bit coordinates. The
  // scene used to load and then fail inside the grid ("internal error").
  const std::string text = replace(replace(kValid, "  - {x: [0, 0, 0.0025], r: 1.0e-3, material: grain, body: 0}\n", "  - {x: [1.0e4, 0, 0], r: 1.0e-3, material: grain}\n"),
                                   "shells:\n  - {name: shell, body: 0, centre: [0, 0, 0.001], radius: 0.016, material: grain, contact_radius: concave}\n", "");
  EXPECT_CONTAINS(error_of(text), "scene.yaml:9:3: particles: the spheres span 10000.002 m along x, 4545455 cells");
  EXPECT_CONTAINS(error_of(text), "allowed: fewer than 2097151 cells (2^21 - 1)");
}

TEST(SceneFile, DurationsOfMoreThan1e12StepsAreRefused) {
  SCOPED_TRACE("random seed of this test: " + std::to_string(kRangeTestSeed));
  std::mt19937_64 rng(kRangeTestSeed);
  const SceneFile f = parse_scene(ConfigNode::load_string(kValid, "scene.yaml"));
  const Simulation sim(f.scene);
  const double dt = sim.dt();
  for (int k = 0; k < 5; ++k) {
    const double duration = dt * random_magnitude(rng, 12.01, 300);  // up to 1e300 steps: lround's range is 2^63
    try {
      validate_steps(duration, dt, "run.duration");
      ADD_FAILURE() << duration << " s accepted";
    } catch (const InputError& e) {
      EXPECT_CONTAINS(std::string(e.what()), "run.duration: ");
      EXPECT_CONTAINS(std::string(e.what()), " time steps of dt = ");
      EXPECT_CONTAINS(std::string(e.what()), "; allowed: at most 1e12 steps");
    }
    EXPECT_THROW(sim.steps_for(duration), InputError) << "the backstop of run_for";
  }
  EXPECT_NO_THROW(validate_steps(1e11 * dt, dt, "run.duration"));
  // The relaxation and the drivers, named by their keys.
  try {
    validate_steps(RelaxationDef{PaperRelaxationDef{6, 1e12 * dt, 0.3}}, dt, "run.relaxation");
    ADD_FAILURE() << "a wait of 6e12 steps accepted";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "run.relaxation.wait: the protocol (6 stops after");
  }
  SceneDef s = f.scene;
  std::get<MoveWallDef>(s.drivers[0]).velocity = Vec3(0, 0, 1e-100);
  try {
    const Simulation slow(s);
    ADD_FAILURE() << "a driver of 1e95 s accepted";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "drivers[0].distance: 1e-5 m at 1e-100 m/s is");
  }
}

TEST(SceneFile, ScenesWithOneOverflowingValueInTheLoadedFileAreLocated) {
  // The rules that need the time step are placed in the file by their key too.
  const SceneFile f = parse_scene(ConfigNode::load_string(replace(kValid, "wait: 0.3", "wait: 1.0e30"), "scene.yaml"));
  const Simulation sim(f.scene);
  try {
    validate_steps(*f.run.relaxation, sim.dt(), "run.relaxation");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(f.root.locate(e).what()), "scene.yaml:20:49: run.relaxation.wait: the protocol");
  }
}

}  // namespace
}  // namespace softpack
