// Adding a normal law is one type plus one registration line (docs/architecture.md). This test
// does exactly that with a law no scene of the project uses, a linear spring-dashpot,
//
//   Fn = kn h,   kn = R12 / D,   gamma_n = alpha sqrt(m12 kn)   (no h^(1/4) factor),
//
// whose collision has a closed form: with zeta = alpha / 2 the contact lasts
// t_c = pi / (w0 sqrt(1 - zeta^2)), w0 = sqrt(kn / m12), and the restitution is
// e = exp(-pi zeta / sqrt(1 - zeta^2)), so alpha(e) = 2 (-ln e) / sqrt(pi^2 + ln^2 e). The engine
// runs it through the same force loops, residuals and watchdog as Hertz's law.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "forces/compile_loops.hpp"
#include "scene/scene_yaml.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

struct LinearTestNormal {
  static constexpr const char* name = "linear-test";
  static double stiffness(double R12, double D) { return R12 / D; }  // [N/m]
  template <class T>
  static T force(const T& kn, const T& h, const T&) {
    return kn * h;
  }
  template <class T>
  static T damping_scale(const T&) {
    return T(1.0);
  }
  static double energy(double kn, double h) { return 0.5 * kn * h * h; }
  static double damping_coefficient(double e) {
    const double l = std::log(e);
    return 2.0 * -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
  }
};

// The registration line.
const bool registered = (add_normal_law(make_normal_law<LinearTestNormal>()), true);

// Two equal spheres approaching head-on at relative speed 2 v0 along x; returns the relative
// speed after they part and the time they touched.
struct Collision {
  double restitution = 0.0, contact_time = 0.0;
};

Collision collide(const std::optional<double>& restitution, double dt) {
  SceneDef s = testing::basic_scene();
  s.effects.normal = "linear-test";
  s.effects.restitution = restitution;
  s.integration.safety.reset();
  s.integration.dt = dt;
  const double r = 1e-3, v0 = 0.01;
  ParticleDef a, b;
  a.r = b.r = r;
  a.x = Vec3(-r - 1e-6, 0, 0), b.x = Vec3(r + 1e-6, 0, 0);
  a.v = Vec3(v0, 0, 0), b.v = Vec3(-v0, 0, 0);
  s.particles = {a, b};
  Simulation sim(s);
  Collision c;
  bool touched = false;
  for (long step = 0; step < 100000; ++step) {
    sim.step();
    const double gap = (sim.particles().x[1] - sim.particles().x[0]).norm() - 2 * r;
    if (gap < 0.0) touched = true, c.contact_time += sim.dt();
    if (touched && gap > 0.0) break;
  }
  c.restitution = (sim.particles().v[1] - sim.particles().v[0]).x() / (2 * v0);
  return c;
}

TEST(NormalLawRegistry, ATestLawRunsThroughTheEngineAndMatchesItsClosedForm) {
  ASSERT_TRUE(registered);
  const Material m = testing::paper_grain();
  const double r = 1e-3, m12 = 0.5 * m.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double kn = LinearTestNormal::stiffness(0.5 * r, hertz_D(m, m)), w0 = std::sqrt(kn / m12);
  for (const double e : {1.0, 0.8, 0.5}) {
    const double zeta = e < 1.0 ? 0.5 * LinearTestNormal::damping_coefficient(e) : 0.0;
    const double t_c = std::numbers::pi / (w0 * std::sqrt(1.0 - zeta * zeta));
    const Collision c = collide(e < 1.0 ? std::optional<double>(e) : std::nullopt, t_c / 2000.0);
    EXPECT_NEAR(c.restitution, e, 2e-3) << "restitution " << e;
    EXPECT_NEAR(c.contact_time, t_c, 2e-3 * t_c) << "restitution " << e;
  }
}

TEST(NormalLawRegistry, ResidualsAndTheWatchdogUseTheSceneLaw) {
  SceneDef s = testing::basic_scene();
  s.effects.normal = "linear-test";
  ParticleDef a, b;
  a.r = b.r = 1e-3;
  a.x = Vec3(-1e-3 + 2e-5, 0, 0), b.x = Vec3(1e-3 - 2e-5, 0, 0);  // overlap h = 4e-5 m
  s.particles = {a, b};
  const Simulation sim(s);
  const double kn = LinearTestNormal::stiffness(0.5e-3, hertz_D(testing::paper_grain(), testing::paper_grain()));
  const double h = 2e-3 - (b.x - a.x).norm();
  const Measurement meas = sim.residuals();
  EXPECT_EQ(meas.contacts, 1u);
  EXPECT_NEAR(meas.elastic_energy, 0.5 * kn * h * h, 1e-12 * 0.5 * kn * h * h);
  EXPECT_NEAR(meas.mean_contact_force, kn * h, 1e-12 * kn * h);
  EXPECT_NEAR(sim.particles().F[1].x(), kn * h, 1e-12 * kn * h);  // the loops' force, at construction
}

TEST(NormalLawRegistry, SceneFilesNameTheLawAndUnknownNamesAreRefused) {
  const std::string scene = R"(materials: {grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}}
effects: {normal: linear-test}
particles:
  - {x: [0, 0, 0], r: 1.0e-3, material: grain}
integration: {safety: 0.2, tangential_history: synchronized}
neighbor: {skin: 0.2, level_ratio: 2.0}
)";
  const SceneFile f = parse_scene(ConfigNode::load_string(scene, "scene.yaml"));
  EXPECT_EQ(f.scene.effects.normal, "linear-test");
  EXPECT_NO_THROW(Simulation{f.scene});
  SceneDef bad = f.scene;
  bad.effects.normal = "herts";
  try {
    const Simulation sim(bad);
    FAIL() << "an unknown law was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("effects.normal: 'herts' is not a normal law of this engine (did you mean 'hertz'?); "
                                         "allowed: hertz, linear-test"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(add_normal_law(make_normal_law<LinearTestNormal>()), std::invalid_argument);  // the name is taken
}

}  // namespace
}  // namespace softpack
