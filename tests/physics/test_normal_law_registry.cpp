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
#include "core/parallel.hpp"
#include "contact/tsuji_model.hpp"
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

// A law with a body state (contact/hertz_normal.hpp): each sphere counts its closed contacts N
// in the per-body pass, and a contact's force is that of a linear spring times N1 + N2 (a wall's
// N: 0), so that one contact's force depends on all the contacts of its two spheres.
struct CountingTestNormal {
  static constexpr const char* name = "counting-test";
  static constexpr bool kBodyState = true;
  static double stiffness(double R12, double D) { return R12 / D; }  // [N/m]
  template <class T>
  static T body_term(const T&) {
    return T(1.0);
  }
  template <class T>
  static T force(const T& kn, const T& h, const T&, const T& n1, const T& n2) {
    return kn * h * (n1 + n2);
  }
  template <class T>
  static T damping_scale(const T&) {
    return T(1.0);
  }
  static double energy(double kn, double h, double n1, double n2) { return 0.5 * kn * h * h * (n1 + n2); }
  static double damping_coefficient(double e) { return LinearTestNormal::damping_coefficient(e); }
};

// The registration lines.
const bool registered = (add_contact_model(make_contact_model<TsujiModel<LinearTestNormal>>()), true);
const bool registered_counting = (add_contact_model(make_contact_model<TsujiModel<CountingTestNormal>>()), true);

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
    EXPECT_NE(std::string(e.what()).find("effects.normal: 'herts' is not a contact model of this engine (did you mean 'hertz'?); "
                                         "allowed: hertz, linear-test, counting-test"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(add_contact_model(make_contact_model<TsujiModel<LinearTestNormal>>()), std::invalid_argument);  // the name is taken
}

// Three spheres in a row, B - A - C, and a plane under C: A has two contacts, B one, C two (A
// and the plane). By hand, with kn = R12 / D (R12 = r/2 for the pairs, r for the plane):
//   F_B = 3 kn hB,  F_A = 4 kn hC - 3 kn hB,  F_C = 2 kn_w hW - 4 kn hC  (along x),
// the plane's load -2 kn_w hW; the same bits on 1, 2 and 3 threads (sphere 0 owns both pairs:
// on two threads both are ghosts of the second share, for their sphere j).
TEST(NormalLawRegistry, ALawWithABodyStateReadsEveryContactOfItsBodies) {
  ASSERT_TRUE(registered_counting);
  const double r = 1e-3, hB = 2e-6, hC = 3e-6, hW = 5e-6;
  SceneDef s = testing::basic_scene();
  s.effects.normal = "counting-test";
  ParticleDef a, b, c;
  a.r = b.r = c.r = r;
  a.x = Vec3::Zero(), b.x = Vec3(2 * r - hB, 0, 0), c.x = Vec3(-(2 * r - hC), 0, 0);
  s.particles = {a, b, c};
  s.planes = {PlaneDef{"floor", Vec3(c.x.x() - r + hW, 0, 0), Vec3::UnitX(), 0}};
  const double D = hertz_D(testing::paper_grain(), testing::paper_grain());
  const double kn = CountingTestNormal::stiffness(0.5 * r, D), kn_w = CountingTestNormal::stiffness(r, D);
  const double hb = 2 * r - (b.x - a.x).norm(), hc = 2 * r - (a.x - c.x).norm();  // the overlaps the engine sees
  const double FB = 3 * kn * hb, FC = 4 * kn * hc, FW = 2 * kn_w * hW;
  const int before = parallel::threads();
  std::vector<Vec3> one_thread;
  for (const int threads : {1, 2, 3}) {
    parallel::set_threads(threads);
    const Simulation sim(s);
    const std::vector<Vec3>& F = sim.particles().F;
    EXPECT_NEAR(F[1].x(), FB, 1e-12 * FB) << threads << " threads";
    EXPECT_NEAR(F[0].x(), FC - FB, 1e-12 * FC) << threads << " threads";
    EXPECT_NEAR(F[2].x(), FW - FC, 1e-12 * FC) << threads << " threads";
    EXPECT_NEAR(sim.plane_loads()[0].force.x(), -FW, 1e-12 * FW) << threads << " threads";
    EXPECT_LE((F[0] + F[1] + F[2] + sim.plane_loads()[0].force).norm(), 1e-12 * FC) << threads << " threads";
    const Measurement meas = sim.residuals();  // the walk over closed contacts reads the same states
    EXPECT_EQ(meas.contacts, 3u);
    EXPECT_NEAR(meas.mean_contact_force, (FB + FC + FW) / 3, 1e-12 * FC);
    if (threads == 1) one_thread = F;
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(F[i], one_thread[i]) << threads << " threads: not the bits of one, sphere " << i;
  }
  parallel::set_threads(before);
}

// A free cluster of overlapping spheres with friction, rotation and damping under the counting
// law: every pair force acts on both spheres with opposite signs, so the total momentum stays
// what it was (zero) to 1e-12 of the spheres' summed momenta, on 1 and 2 threads with the same
// bits. An active set is refused with such a law.
TEST(NormalLawRegistry, ABodyStateLawConservesMomentum) {
  testing::Random rng(32);
  SceneDef s = testing::basic_scene();
  s.effects.normal = "counting-test";
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = 0.7;
  const double r = 1e-3;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        ParticleDef p;
        p.r = r * rng.uniform(0.9, 1.1);
        p.x = 1.8 * r * Vec3(i, j, k) + rng.in_box(0.05 * r);
        p.v = rng.in_box(0.01);
        s.particles.push_back(p);
      }
  Vec3 mean = Vec3::Zero();
  for (const ParticleDef& p : s.particles) mean += p.v;
  mean /= static_cast<double>(s.particles.size());
  for (ParticleDef& p : s.particles) p.v -= mean;  // equal masses within 1.1^3: momentum near zero, not exactly
  const int before = parallel::threads();
  std::vector<Vec3> x_one;
  for (const int threads : {1, 2}) {
    parallel::set_threads(threads);
    Simulation sim(s);
    const auto momentum = [&](double& scale) {
      Vec3 P = Vec3::Zero();
      scale = 0.0;
      for (std::size_t i = 0; i < sim.particles().size(); ++i) {
        P += sim.particles().m[i] * sim.particles().v[i];
        scale += sim.particles().m[i] * sim.particles().v[i].norm();
      }
      return P;
    };
    double scale0 = 0.0, scale = 0.0;
    const Vec3 P0 = momentum(scale0);
    ASSERT_GT(sim.residuals().contacts, 200u);
    sim.run_steps(500);
    const Vec3 P = momentum(scale);
    EXPECT_LE((P - P0).norm(), 1e-12 * scale0) << threads << " threads";
    if (threads == 1) x_one = sim.particles().x;
    EXPECT_EQ(sim.particles().x, x_one) << threads << " threads: not the bits of one";
    try {
      sim.set_active_set(ActiveSetDef{});
      ADD_FAILURE() << "an active set was accepted with a law that has a body state";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("not available with the normal law 'counting-test'"), std::string::npos) << e.what();
    }
  }
  parallel::set_threads(before);
}

}  // namespace
}  // namespace softpack
