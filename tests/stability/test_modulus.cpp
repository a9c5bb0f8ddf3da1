// Stability for Young's modulus from 5e5 Pa (the paper's) to 5e10 Pa, by decades, with the
// automatic time step (integrate/time_step.hpp: dt = safety x Rayleigh time, dt ~ E^(-1/2)):
//  * an undamped head-on impact at the typical speed (modulus-impact.yaml): Hertz's contact
//    duration, restitution 1, energy conserved, at every E;
//  * a compressed frictional cluster in a shell (modulus-cluster.yaml) relaxed with the converged
//    protocol, its times scaled by sqrt(5e5 / E): it converges at every E, in the same number of
//    steps, to the same configuration (the problem is scale-free: forces ~ E, dt ~ E^(-1/2)).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "relax/relaxation.hpp"
#include "stability/stability.hpp"

namespace softpack {
namespace {

using stability::measured;
using stability::mechanical_energy;
using stability::non_finite;

const std::vector<double> kModuli{5e5, 5e6, 5e7, 5e8, 5e9, 5e10};

std::string decade(double E) { return "E = 5e" + std::to_string(std::lround(std::log10(E / 5.0))) + " Pa"; }

TEST(Modulus, ImpactFollowsHertzFrom5e5To5e10Pa) {
  const SceneFile base = stability::load("modulus-impact.yaml");
  double worst_duration = 0.0, worst_restitution = 0.0, worst_drift = 0.0;
  long fewest_steps = 1L << 40;
  for (const double E : kModuli) {
    SCOPED_TRACE("E = " + std::to_string(E));
    SceneFile f = base;
    f.scene.materials[0].E = E;
    Simulation sim(f.scene);
    EXPECT_NEAR(sim.dt(), base.scene.integration.safety.value() * sim.stable_limit().t_rayleigh, 1e-15 * sim.dt());
    const Particles& p = sim.particles();
    const Vec3 n = (p.x[1] - p.x[0]).normalized();
    const double u = -(p.v[1] - p.v[0]).dot(n);
    const double m12 = p.m[0] * p.m[1] / (p.m[0] + p.m[1]);
    const double kn = stability::hertz_kn(f.scene.materials[0], p.r[0] * p.r[1] / (p.r[0] + p.r[1]));
    const double h_max = std::pow(5.0 * m12 * u * u / (4.0 * kn), 0.4);
    const double I = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // int dx/sqrt(1-x^(5/2))
    const double t_c = 2.0 * I * h_max / u;
    const double E0 = mechanical_energy(sim);
    const long steps = sim.steps_for(*f.run.duration);  // grows as E^(1/2): 129 to 40800
    long in_contact = 0;
    for (long k = 0; k < steps; ++k) {
      sim.step();
      ASSERT_EQ(non_finite(sim), "");
      if (sim.residuals().contacts > 0) {
        ++in_contact;
        EXPECT_GT(p.F[1].dot((p.x[1] - p.x[0]).normalized()), 0.0) << "repulsive";
      }
    }
    ASSERT_EQ(sim.residuals().contacts, 0u) << "the impact must be over";
    const double restitution = (p.v[1] - p.v[0]).dot(n) / u;
    const double drift = std::abs(mechanical_energy(sim) - E0) / E0;
    // Steps in contact count whole steps: the duration is known to one step.
    const double duration_error = std::abs(static_cast<double>(in_contact) * sim.dt() - t_c) / sim.dt();
    measured(decade(E) + ": steps in contact", static_cast<double>(in_contact));
    measured(decade(E) + ": |contact duration - Hertz| / dt", duration_error);
    measured(decade(E) + ": |restitution - 1|", std::abs(restitution - 1.0));
    measured(decade(E) + ": energy drift", drift);
    worst_duration = std::max(worst_duration, duration_error);
    worst_restitution = std::max(worst_restitution, std::abs(restitution - 1.0));
    worst_drift = std::max(worst_drift, drift);
    fewest_steps = std::min(fewest_steps, in_contact);
  }
  // The contact lasts t_c ~ E^(-2/5) while dt ~ E^(-1/2): measured 19 steps at 5e5 Pa to 60
  // at 5e10 Pa, so the coarsest case is the softest. Measured worst: duration within 0.80 dt
  // of Hertz's (5e7 Pa), |e - 1| = 2.7e-4 and drift 5.4e-4 (5e6 Pa). Bounds: 2 steps, and
  // about 3 times the measured values.
  EXPECT_GE(fewest_steps, 15);
  EXPECT_LT(worst_duration, 2.0);
  EXPECT_LT(worst_restitution, 1e-3);
  EXPECT_LT(worst_drift, 2e-3);
}

TEST(Modulus, CompressedClusterRelaxesTheSameFrom5e5To5e10Pa) {
  const SceneFile base = stability::load("modulus-cluster.yaml");
  const double E_base = base.scene.materials[0].E;
  std::vector<Vec3> x_base;
  long steps_base = 0;
  double worst_shift = 0.0;
  for (const double E : kModuli) {
    SCOPED_TRACE("E = " + std::to_string(E));
    SceneFile f = base;
    f.scene.materials[0].E = E;
    auto def = std::get<ConvergedRelaxationDef>(*f.run.relaxation);
    const double scale = std::sqrt(E_base / E);  // every time of the problem scales so
    def.check_interval *= scale;
    def.max_time *= scale;
    Simulation sim(f.scene);
    ASSERT_EQ(non_finite(sim), "");
    const double F_scale = sim.residuals().mean_contact_force;
    const RelaxationReport rep = relax(sim, def, [&](const RelaxationCheck&) { ASSERT_EQ(non_finite(sim), ""); });
    const Measurement m = sim.residuals();
    measured(decade(E) + ": relaxation steps", static_cast<double>(rep.steps));
    measured(decade(E) + ": force ratio", m.force_ratio());
    ASSERT_TRUE(rep.converged && *rep.converged) << "force ratio " << m.force_ratio() << ", energy ratio " << m.energy_ratio();
    EXPECT_GT(m.contacts, 20u) << "the cluster stays compressed";
    const WallLoad& shell = sim.wall_load("shell");
    EXPECT_TRUE(shell.force.allFinite());
    // Forces scale as E: the mean contact force over its initial value is E-independent.
    EXPECT_GT(m.mean_contact_force, 0.01 * F_scale);
    if (x_base.empty()) {
      x_base = sim.particles().x;
      steps_base = rep.steps;
      continue;
    }
    EXPECT_EQ(rep.steps, steps_base) << "the same number of steps at every E";
    for (std::size_t i = 0; i < x_base.size(); ++i)
      worst_shift = std::max(worst_shift, (sim.particles().x[i] - x_base[i]).norm() / sim.particles().r[i]);
  }
  // Scale-free in exact arithmetic; only rounding differs between the moduli. Measured: the
  // final positions agree with those at 5e5 Pa to 1.1e-14 radii, in 1190 steps at every E.
  // Bound 1e-9 radii (a relaxation may amplify rounding).
  measured("largest shift from the 5e5 Pa configuration / r", worst_shift);
  EXPECT_LT(worst_shift, 1e-9);
}

}  // namespace
}  // namespace softpack
