// The watchdog (sim/watchdog.hpp): a run that leaves the physical regime stops with a
// NumericalError naming step, time, spheres, overlap, dt and the stable limit; a sound run never
// trips it; its thresholds come from the scene's `watchdog` block or the profile's section.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "measure/settings.hpp"
#include "scene/scene_yaml.hpp"
#include "sim/simulation.hpp"
#include "state/world.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kOff = std::numeric_limits<double>::infinity();
constexpr double r = 1e-3;

// What `statement` throws as a NumericalError (fails the test if it throws nothing).
template <class F>
std::string numerical_error(F&& statement) {
  try {
    statement();
  } catch (const NumericalError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no NumericalError";
  return "";
}

SceneDef two_spheres(double overlap_fraction) {
  SceneDef s = testing::basic_scene();
  ParticleDef a, b;
  a.r = b.r = r;
  b.x = Vec3(2.0 * r - overlap_fraction * r, 0, 0);
  s.particles = {a, b};
  return s;
}

// One sphere squeezed between two planes, 0.35 r into the floor and 0.25 r into the ceiling,
// at the largest step the scene allows (dt = t_R). The Hertz stiffness at such overlaps puts
// omega dt well above 2 (docs/physics.md §13): the explicit integration blows up.
SceneDef squeezed_sphere() {
  SceneDef s = testing::basic_scene();
  s.integration.safety = 1.0;
  ParticleDef p;
  p.r = r;
  p.x = Vec3(0, 0, 0.65 * r);
  s.particles = {p};
  s.planes = {PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0}, PlaneDef{"ceiling", Vec3(0, 0, 1.4 * r), -Vec3::UnitZ(), 0}};
  return s;
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

TEST(Watchdog, HugeOverlapStopsTheRunWithIdsOverlapAndTimeStep) {
  SceneDef s = two_spheres(0.8);
  s.watchdog.max_overlap_fraction = 0.5;
  const std::string msg = numerical_error([&] { Simulation sim(s); });
  expect_contains(msg, "step 0, t = 0 s");
  expect_contains(msg, "spheres 0 and 1 (r = 0.001 m and 0.001 m) overlap by 0.0008 m, 0.8 of the smaller radius");
  expect_contains(msg, "watchdog.max_overlap_fraction = 0.5");
  expect_contains(msg, "; dt = 7.74e-05 s, stable limit 0.000387 s (Rayleigh time of sphere 0)");
  // The same pair within the limit runs.
  s.watchdog.max_overlap_fraction = 0.9;
  Simulation sim(s);
  EXPECT_NO_THROW(sim.run_steps(10));
}

TEST(Watchdog, SphereDrivenThroughAWallStopsMidRun) {
  // A held-in-place kinematic push: the driver forces the overlap, the default limit catches it.
  SceneDef s = testing::basic_scene();
  ParticleDef p;
  p.r = r;
  p.x = Vec3(0, 0, 1.1 * r);
  s.particles = {p};
  s.planes = {PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0}};
  s.drivers = {TranslateGroupDef{GroupDef{}, Vec3(0, 0, -0.1), 3.0 * r, std::nullopt, AfterDrive::hold}};
  Simulation sim(s);
  const std::string msg = numerical_error([&] { sim.run_for(0.1); });
  expect_contains(msg, "sphere 0 (r = 0.001 m) overlaps plane 'floor' by");
  expect_contains(msg, "of its radius, above watchdog.max_overlap_fraction = 1");
  // Caught within one check interval of crossing the limit (1.1 r of travel to reach h = r).
  const long crossing = std::lround(1.1 * r / 0.1 / sim.dt());
  EXPECT_GE(sim.step_count(), crossing);
  EXPECT_LE(sim.step_count(), crossing + s.watchdog.check_interval);
}

TEST(Watchdog, TimeStepAboveTheStabilityOfTheContactIsAnEnergyBlowUp) {
  SceneDef s = squeezed_sphere();
  s.watchdog.max_overlap_fraction = kOff;  // the energy criterion alone
  s.watchdog.check_interval = 1;
  Simulation sim(s);
  const std::string msg = numerical_error([&] { sim.run_steps(1000); });
  expect_contains(msg, "energy blow-up: kinetic + normal elastic energy");
  expect_contains(msg, "exceeds watchdog.energy_growth = 10 times its budget");
  expect_contains(msg, "most energetic sphere 0");
  expect_contains(msg, "dt = 0.000387 s, stable limit 0.000387 s");
  EXPECT_LT(sim.step_count(), 20);  // a blow-up: orders of magnitude within a few steps
}

TEST(Watchdog, BlowUpPastEveryOtherCriterionEndsAsNonFinite) {
  SceneDef s = squeezed_sphere();
  s.watchdog.max_overlap_fraction = kOff;
  s.watchdog.energy_growth = kOff;
  Simulation sim(s);
  const std::string msg = numerical_error([&] { sim.run_steps(100000); });
  expect_contains(msg, "sphere 0 (r = 0.001 m) has a non-finite");
  expect_contains(msg, "1 of 1 spheres are not finite");
}

TEST(Watchdog, NaNInARestoredStateIsCaught) {
  // Validation refuses a NaN velocity in a scene, so inject it through a saved state.
  SceneDef s = two_spheres(0.1);
  Simulation sim(s);
  sim.run_steps(5);
  SimulationState state = sim.state();
  state.v[1].y() = std::numeric_limits<double>::quiet_NaN();
  const std::string msg = numerical_error([&] { sim.restore(state); });
  expect_contains(msg, "step 5, t = ");
  expect_contains(msg, "sphere 1 (r = 0.001 m) has a non-finite velocity (x = [");
  expect_contains(msg, "1 of 2 spheres are not finite; largest overlap: spheres 0 and 1");
  expect_contains(msg, "; dt = 7.74e-05 s, stable limit 0.000387 s");
}

// A sound run never trips it, and stays far from its thresholds: a driven, frictional, damped
// pile under gravity, with walls that move and a group that turns.
TEST(Watchdog, SoundDrivenRunsStayFarFromTheThresholds) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = 0.5;
  s.effects.gravity = Vec3(0, 0, -9.81);
  s.watchdog.check_interval = 1;
  testing::Random rng(11);
  s.particles = testing::random_spheres_in_shell(rng, 200, 0.01, 5e-4, 1.5e-3, 3.5, 1000, 0);
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), 0.01, 0, ShellContactRadius::concave, std::nullopt}};
  s.planes = {PlaneDef{"floor", Vec3(0, 0, -0.0105), Vec3::UnitZ(), 0}};
  s.drivers = {MoveWallDef{"floor", Vec3(0, 0, 0.02), 1e-3, std::nullopt},
               RotateGroupDef{GroupDef{GroupDef::Kind::body, 0}, Vec3::Zero(), Vec3::UnitY(), 2.0, 0.3, std::nullopt,
                              AfterDrive::release, false}};
  Simulation sim(s);
  EXPECT_NO_THROW(sim.run_for(0.2));
  EXPECT_GT(sim.watchdog().budget(), 0.0);
  EXPECT_LT(sim.watchdog().largest_energy_ratio(), 1.1);  // E <= budget up to integration error
  EXPECT_LT(sim.watchdog().largest_overlap_fraction(), 0.5);
}

// Energies of round-off are no blow-up: grains touching by 1e-13 of a radius carry 1e-39 J,
// whose rounding noise grows tenfold and more between checks (a soft-particle's first relaxed
// state, release 0.5.0's calibration). The same growth with a real overlap, or carried by motion,
// still stops the run.
// A watchdog of the default thresholds at dt = 1e-5 s, and the measurement of two spheres 0 and
// 1 touching by `fraction` of a radius with elastic energy E.
Watchdog default_dog() {
  Watchdog::Context context;
  context.dt = 1e-5;
  return Watchdog(WatchdogDef{}, context);
}
Measurement touching(double fraction, double E) {
  Measurement m;
  m.elastic_energy = E;
  m.deepest.fraction = fraction;
  m.deepest.i = 0, m.deepest.j = 1;
  return m;
}

TEST(Watchdog, RoundOffEnergiesAreNotABlowUp) {
  World world = make_world(two_spheres(1e-13));
  Watchdog dog = default_dog();
  Measurement m = touching(1e-13, 3e-39);
  dog.start(world, m);
  m.elastic_energy = 1.4e-34;  // 5e4 times the budget
  EXPECT_NO_THROW(dog.check(world, m));
  m.deepest.fraction = 1e-3;  // a real overlap: judged
  EXPECT_THROW(dog.check(world, m), NumericalError);
  m.deepest.fraction = 1e-13;
  world.p.v[0] = Vec3(1e-14, 0, 0);  // moving by 1e-17 m = 1e-14 r per step: still round-off
  EXPECT_NO_THROW(dog.check(world, m));
  world.p.v[0] = Vec3(1e-3, 0, 0);  // 1e-5 r per step: the energy is in the motion, judged
  EXPECT_THROW(dog.check(world, m), NumericalError);
}

// A tangential spring whose kt follows the overlap gains ½ |ξ|² dkt without work (a nested
// soft-particle's calm tangential point stopped so, docs/physics.md §13): the springs' energy is
// not judged; the same growth in the normal elastic energy, or in the motion, is.
TEST(Watchdog, TheTangentialSpringsEnergyIsNotJudged) {
  World world = make_world(two_spheres(1e-4));
  Watchdog dog = default_dog();
  Measurement m = touching(1e-4, 1e-12);  // all normal
  dog.start(world, m);
  m.spring_energy = 1e-9;  // 1000 times the budget, in the springs
  m.elastic_energy = 1e-12 + m.spring_energy;
  EXPECT_NO_THROW(dog.check(world, m));
  m.spring_energy = 0.0;  // the same energy in the normal law: a blow-up
  try {
    dog.check(world, m);
    ADD_FAILURE() << "a thousandfold normal elastic energy passed";
  } catch (const NumericalError& e) {
    expect_contains(e.what(), "kinetic + normal elastic energy");
  }
  m.elastic_energy = 1e-12 + 1e-9, m.spring_energy = 1e-9;
  m.kinetic_energy = 1e-9;  // or in the motion
  EXPECT_THROW(dog.check(world, m), NumericalError);
}

TEST(Watchdog, FreeFallIsPaidForByGravity) {
  // No energy at the start: what the sphere gains is gravity's work, not a blow-up.
  SceneDef s = testing::basic_scene();
  s.effects.gravity = Vec3(0, 0, -9.81);
  s.watchdog.check_interval = 1;
  ParticleDef p;
  p.r = r;
  p.x = Vec3(0, 0, 0.01);
  s.particles = {p};
  s.planes = {PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0}};  // undamped: it bounces back
  Simulation sim(s);
  EXPECT_NO_THROW(sim.run_for(0.2));
  EXPECT_LT(sim.watchdog().largest_energy_ratio(), 1.01);
}

TEST(Watchdog, ThresholdsComeFromTheSceneFile) {
  const auto scene = [](const std::string& watchdog) {
    return "materials: {grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}}\n"
           "effects: {normal: hertz}\n"
           "particles: [{x: [0, 0, 0], r: 1.0e-3, material: grain}]\n"
           "integration: {safety: 0.2, tangential_history: synchronized}\n"
           "neighbor: {skin: 0.2, level_ratio: 2.0}\n" +
           watchdog;
  };
  const auto parse = [&](const std::string& watchdog) {
    return parse_scene(ConfigNode::load_string(scene(watchdog), "s.yaml")).scene.watchdog;
  };
  const WatchdogDef defaults = parse("");
  EXPECT_EQ(defaults.max_overlap_fraction, WatchdogDef::kMaxOverlapFraction);
  EXPECT_EQ(defaults.energy_growth, WatchdogDef::kEnergyGrowth);
  EXPECT_EQ(defaults.check_interval, WatchdogDef::kCheckInterval);
  const WatchdogDef w = parse("watchdog: {max_overlap_fraction: 0.3, energy_growth: 50, check_interval: 7}\n");
  EXPECT_EQ(w.max_overlap_fraction, 0.3);
  EXPECT_EQ(w.energy_growth, 50.0);
  EXPECT_EQ(w.check_interval, 7);
  EXPECT_EQ(parse("watchdog: {energy_growth: 3}\n").max_overlap_fraction, WatchdogDef::kMaxOverlapFraction);

  const auto error = [&](const std::string& watchdog) {
    try {
      parse(watchdog);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  expect_contains(error("watchdog: {max_overlap_fraction: 0}\n"), "watchdog.max_overlap_fraction: 0 is not allowed; allowed: > 0");
  expect_contains(error("watchdog: {energy_growth: 1}\n"), "watchdog.energy_growth: 1 is not allowed; allowed: > 1");
  expect_contains(error("watchdog: {check_interval: 0}\n"), "watchdog.check_interval: 0 steps is not allowed; allowed: 1 <= check_interval <= 1e12 steps");
  expect_contains(error("watchdog: {check_interval: 2.5}\n"), "watchdog.check_interval: expected an integer");
  expect_contains(error("watchdog: {energy_grwoth: 5}\n"), "watchdog.energy_grwoth: unknown key; did you mean 'energy_growth'?");
  expect_contains(error("watchdog: 5\n"), "watchdog: expected a map of keys");

  // The same rules hold for a SceneDef built in code.
  SceneDef s = two_spheres(0.1);
  s.watchdog.check_interval = 0;
  try {
    Simulation sim(s);
    ADD_FAILURE() << "check_interval 0 accepted";
  } catch (const InputError& e) {
    expect_contains(e.what(), "watchdog.check_interval: 0 steps is not allowed");
  }
}

TEST(Watchdog, ThresholdsComeFromTheProfileSectionWhichNoStageRecords) {
  const std::string path = std::string(SOFTPACK_SOURCE_DIR) + "/tests/data/sweep-profile.yaml";
  const ConfigNode root = ConfigNode::load_file(path);
  const MeasurementSettings m = parse_measurement(root);
  ASSERT_TRUE(root.has("watchdog"));
  EXPECT_EQ(m.watchdog.max_overlap_fraction, root.at("watchdog").at("max_overlap_fraction").number());
  EXPECT_EQ(m.watchdog.check_interval, root.at("watchdog").at("check_interval").integer());
  EXPECT_NO_THROW(parse_packing(root));  // a profile section like any other

  // Absent: the defaults.
  YAML::Node copy = YAML::Clone(root.yaml());
  copy.remove("watchdog");
  const MeasurementSettings d = parse_measurement(ConfigNode::load_string(YAML::Dump(copy), "p.yaml"));
  EXPECT_EQ(d.watchdog.max_overlap_fraction, WatchdogDef::kMaxOverlapFraction);
  // Bad: named like any profile key.
  copy["watchdog"]["energy_growth"] = "0.5";
  try {
    parse_measurement(ConfigNode::load_string(YAML::Dump(copy), "p.yaml"));
    ADD_FAILURE() << "energy_growth 0.5 accepted";
  } catch (const InputError& e) {
    expect_contains(e.what(), "watchdog.energy_growth: 0.5 is not allowed; allowed: > 1");
  }
}

}  // namespace
}  // namespace softpack
