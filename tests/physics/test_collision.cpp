// Binary impacts against analytic Hertz results.
//  * undamped head-on collision of two unequal spheres: contact duration within 1% of
//    t_c = 2 I h_max / u with h_max = (5 m12 u^2 / (4 kn))^(2/5) and
//    I = int_0^1 dx / sqrt(1 - x^(5/2)) = (2/5) B(2/5, 1/2); restitution 1 within 1e-4;
//    energy drift below 1e-6;
//  * damped impacts: the measured restitution is the prescribed e (Tsuji damping with alpha(e)
//    from the scaled impact equation, contact/viscous_damping.hpp), within 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

struct Impact {
  double contact_duration = 0.0;
  double restitution = 0.0;
  double energy_drift = 0.0;  // relative
  double analytic_duration = 0.0;
};

Impact collide(std::optional<double> e, bool friction) {
  SceneDef s = testing::basic_scene();
  s.materials = {testing::paper_grain(), testing::stiff_grain()};
  s.effects.restitution = e;
  s.effects.friction = friction;
  s.effects.rotation = friction;
  const double R1 = 1.0e-3, R2 = 2.5e-3, u = 0.05;  // relative approach speed [m/s]
  ParticleDef a, b;
  a.r = R1;
  b.r = R2;
  b.material = 1;
  const Vec3 dir = Vec3(1, 1, 0.5).normalized();
  a.x = Vec3::Zero();
  b.x = (R1 + R2 + 1e-5) * dir;
  // Centre of mass at rest.
  const double m1 = s.materials[0].density * 4.0 / 3.0 * std::numbers::pi * std::pow(R1, 3);
  const double m2 = s.materials[1].density * 4.0 / 3.0 * std::numbers::pi * std::pow(R2, 3);
  a.v = u * m2 / (m1 + m2) * dir;
  b.v = -u * m1 / (m1 + m2) * dir;
  s.particles = {a, b};

  const double m12 = m1 * m2 / (m1 + m2);
  const double kn = std::sqrt(R1 * R2 / (R1 + R2)) / hertz_D(s.materials[0], s.materials[1]);
  const double h_max = std::pow(5.0 * m12 * u * u / (4.0 * kn), 0.4);
  const double I = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  Impact out;
  out.analytic_duration = 2.0 * I * h_max / u;
  s.integration.safety.reset();
  s.integration.dt = out.analytic_duration / 4000.0;

  Simulation sim(s);
  const auto energy = [&] {
    const Measurement m = sim.residuals();
    return m.kinetic_energy + m.elastic_energy;
  };
  const double E0 = energy();
  const auto gap = [&] { return (sim.particles().x[1] - sim.particles().x[0]).norm() - (R1 + R2); };
  long in_contact = 0;
  while (gap() > 0) sim.step();
  while (gap() <= 0) {
    sim.step();
    ++in_contact;
  }
  sim.run_steps(10);
  out.contact_duration = static_cast<double>(in_contact) * sim.dt();
  const Vec3 v_rel = sim.particles().v[1] - sim.particles().v[0];
  out.restitution = v_rel.dot(dir) / u;
  out.energy_drift = std::abs(energy() - E0) / E0;
  return out;
}

TEST(HeadOnCollision, UndampedMatchesHertz) {
  for (const bool friction : {false, true}) {
    const Impact r = collide(std::nullopt, friction);
    EXPECT_NEAR(r.contact_duration, r.analytic_duration, 0.01 * r.analytic_duration);
    EXPECT_NEAR(r.restitution, 1.0, 1e-4);
    EXPECT_LT(r.energy_drift, 1e-6);
  }
}

TEST(DampedCollision, RestitutionIsThePrescribedOne) {
  for (const double e : {0.3, 0.5, 0.8, 0.95}) {
    const Impact r = collide(e, false);
    EXPECT_NEAR(r.restitution, e, 1e-3) << "e = " << e;
  }
}

}  // namespace
}  // namespace softpack
