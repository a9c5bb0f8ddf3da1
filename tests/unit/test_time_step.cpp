// Time step from the Rayleigh limit; a step above the limit is refused with a clear message.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "integrate/time_step.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

SceneDef two_sizes() {
  SceneDef s = testing::basic_scene();
  s.materials.push_back(testing::stiff_grain());
  ParticleDef a, b;
  a.r = 1e-3;
  b.r = 5e-4;
  b.x = Vec3(1, 0, 0);
  b.material = 1;
  s.particles = {a, b};
  return s;
}

TEST(TimeStep, RayleighTimeFormula) {
  const Material m = testing::paper_grain();
  const double G = m.E / (2 * (1 + m.nu));
  EXPECT_DOUBLE_EQ(rayleigh_time(1e-3, m), std::numbers::pi * 1e-3 * std::sqrt(m.density / G) / (0.1631 * m.nu + 0.8766));
}

TEST(TimeStep, LimitIsSetByTheSmallestSoftestSphere) {
  const SceneDef s = two_sizes();
  const StableLimit lim = stable_limit(s);
  const double ta = rayleigh_time(1e-3, s.materials[0]), tb = rayleigh_time(5e-4, s.materials[1]);
  EXPECT_DOUBLE_EQ(lim.t_rayleigh, std::min(ta, tb));
  EXPECT_EQ(lim.particle, ta < tb ? 0 : 1);
  EXPECT_DOUBLE_EQ(Simulation(s).dt(), 0.2 * lim.t_rayleigh);
}

TEST(TimeStep, StepAboveTheLimitIsRefusedWithTheLimitInTheMessage) {
  SceneDef s = two_sizes();
  s.integration.safety.reset();
  s.integration.dt = 1.01 * stable_limit(s).t_rayleigh;
  try {
    Simulation sim(s);
    FAIL() << "accepted an unstable step";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("integration.dt"), std::string::npos) << msg;
    EXPECT_NE(msg.find("stable limit"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fmt::format("{:.6g}", stable_limit(s).t_rayleigh)), std::string::npos) << msg;
  }
  s.integration.dt = 0.99 * stable_limit(s).t_rayleigh;
  EXPECT_NO_THROW(Simulation{s});
}

}  // namespace
}  // namespace softpack
