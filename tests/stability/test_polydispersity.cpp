// Stability at polydispersity 10, 100 and 1000 (scenes in experiments/stability/):
//  * a tiny frictional sphere squeezed between two large ones, wedged (tan(theta) < mu): it
//    relaxes to a two-force balance with repulsive contacts and |Ft| / Fn = tan(theta), without
//    creeping out; expelled (tan(theta) > mu, undamped): it leaves finitely, and its energy never
//    exceeds the work the drivers did;
//  * a packing generated at each Pi (packing-pi.yaml) in its shell, loaded by a plane wall and
//    relaxed with the converged protocol (packing-in-shell.yaml): no NaN, convergence, a
//    repulsive wall load balanced by the shell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "packing/generator.hpp"
#include "relax/relaxation.hpp"
#include "stability/stability.hpp"

namespace softpack {
namespace {

using stability::measured;
using stability::non_finite;

// The tiny-sphere scenes at polydispersity Pi: the small radius becomes R / Pi; the tilt theta of
// the contact normals and the squeeze in units of the small radius are kept (the scene touches
// exactly at the start); durations scale with the small radius, as the time step does.
SceneFile tiny_scene(const std::string& name, double Pi) {
  SceneFile f = stability::load(name);
  auto& P = f.scene.particles;
  const double R = P[0].r, r = P[2].r;
  const double theta = std::atan2(P[2].x.y(), P[1].x.x());
  const double gap = (P[2].x - P[1].x).norm() - R - r;
  if (std::abs(gap) > 1e-9 * r) throw std::runtime_error(name + ": the small sphere must touch the large ones");
  const double r_new = R / Pi, k = r_new / r, d = R + r_new;
  P[2].r = r_new;
  P[0].x = Vec3(-d * std::cos(theta), 0, 0);
  P[1].x = Vec3(d * std::cos(theta), 0, 0);
  P[2].x = Vec3(0, d * std::sin(theta), 0);
  for (DriverDef& drv : f.scene.drivers) *std::get<TranslateGroupDef>(drv).distance *= k;
  *f.run.duration *= k;
  if (f.run.relaxation) {
    auto& c = std::get<ConvergedRelaxationDef>(*f.run.relaxation);
    c.check_interval *= k;
    c.max_time *= k;
  }
  return f;
}

// Contact of the small sphere (2) with large sphere `b` (0 or 1): normal and tangential parts of
// the force on the small sphere. A held large sphere feels only this contact, so the force on
// the small one is -F[b].
struct SmallContact {
  double Fn = 0.0, Ft = 0.0;
  double tan_tilt = 0.0;  ///< tan of the angle between the normal and the x axis
};
SmallContact small_contact(const Simulation& sim, int b) {
  const Particles& p = sim.particles();
  const Vec3 n = (p.x[2] - p.x[b]).normalized();
  const Vec3 F = -p.F[b];
  SmallContact c;
  c.Fn = F.dot(n);
  c.Ft = (F - c.Fn * n).norm();
  c.tan_tilt = std::abs(n.y() / n.x());
  return c;
}

class TinySphere : public ::testing::TestWithParam<double> {};  // param: Pi = R / r

TEST_P(TinySphere, WedgedBetweenTwoLargeOnesRelaxesToATwoForceBalance) {
  const double Pi = GetParam();
  const SceneFile f = tiny_scene("tiny-wedged.yaml", Pi);
  const double mu = f.scene.materials[0].mu;
  Simulation sim(f.scene);
  const Vec3 x0 = sim.particles().x[2];
  const double r = sim.particles().r[2];
  // The squeeze: run.duration, and the last step or so the rounding of the duration left.
  const long squeeze = sim.steps_for(*f.run.duration);
  for (long k = 0; k < squeeze || (sim.drivers_moving() && k < 2 * squeeze); ++k) {
    sim.step();
    ASSERT_EQ(non_finite(sim), "");
  }
  ASSERT_FALSE(sim.drivers_moving()) << "the squeeze must be over";
  const RelaxationReport rep = relax(sim, *f.run.relaxation, [&](const RelaxationCheck&) { ASSERT_EQ(non_finite(sim), ""); });
  ASSERT_TRUE(rep.converged && *rep.converged) << "force ratio " << rep.checks.back().residuals.force_ratio();
  EXPECT_EQ(sim.residuals().contacts, 2u) << "the small sphere must stay wedged";
  ASSERT_GT((sim.particles().x[1] - sim.particles().x[0]).norm(), 2 * sim.particles().r[0])
      << "the large spheres must not touch each other";
  const double creep = (sim.particles().x[2] - x0).norm() / r;
  double worst_balance = 0.0, worst_ratio_error = 0.0;
  for (const int b : {0, 1}) {
    const SmallContact c = small_contact(sim, b);
    EXPECT_GT(c.Fn, 0.0) << "repulsive";
    EXPECT_LT(c.tan_tilt, mu) << "inside the friction cone";
    EXPECT_LE(c.Ft, mu * c.Fn * (1 + 1e-12));
    // A two-force body: both contact forces along the line joining the contact points (x).
    worst_balance = std::max(worst_balance, std::abs(sim.particles().F[b].y()) / sim.particles().F[b].norm());
    worst_ratio_error = std::max(worst_ratio_error, std::abs(c.Ft / c.Fn - c.tan_tilt));
  }
  measured("steps", static_cast<double>(sim.step_count()));
  measured("final force ratio", sim.residuals().force_ratio());
  measured("displacement of the small sphere / r", creep);
  measured("|F_y| / |F| of the contact forces", worst_balance);
  measured("| |Ft|/Fn - tan(theta) |", worst_ratio_error);
  // The converged protocol stops at force ratio 1e-6: the balance holds to that order (measured
  // 1e-8 at Pi = 10, 3e-9 at Pi = 1000); bounds 1e-6. The small sphere moves by the elastic
  // stretch of its springs, measured 5.7e-4 r at every Pi; it must not creep out: bound 5e-3 r.
  EXPECT_LT(worst_balance, 1e-6);
  EXPECT_LT(worst_ratio_error, 1e-6);
  EXPECT_LT(creep, 5e-3);
}

TEST_P(TinySphere, ExpelledFromBetweenTwoLargeOnesLeavesFinitelyWithinTheWorkDone) {
  const double Pi = GetParam();
  const SceneFile f = tiny_scene("tiny-expelled.yaml", Pi);
  const double mu = f.scene.materials[0].mu;
  Simulation sim(f.scene);
  const double R = sim.particles().r[0];
  const long steps = sim.steps_for(*f.run.duration);
  // Work of the drivers on the small sphere: they move the large spheres against the force the
  // small one exerts, W = -sum over steps of F_b . dx_b (trapezoid in F).
  double work = 0.0, largest_share = 0.0, largest_ratio = 0.0;
  for (long k = 0; k < steps; ++k) {
    const Vec3 F0 = sim.particles().F[0], F1 = sim.particles().F[1];
    const Vec3 x0 = sim.particles().x[0], x1 = sim.particles().x[1];
    sim.step();
    ASSERT_EQ(non_finite(sim), "");
    const Particles& p = sim.particles();
    ASSERT_GT((p.x[1] - p.x[0]).norm(), 2 * R) << "the large spheres must not touch each other";
    work -= 0.5 * (F0 + p.F[0]).dot(p.x[0] - x0) + 0.5 * (F1 + p.F[1]).dot(p.x[1] - x1);
    const double E = stability::mechanical_energy(sim);
    if (work > 0.0) largest_share = std::max(largest_share, E / work);
    if (sim.residuals().contacts > 0) {
      const SmallContact c = small_contact(sim, 0);
      EXPECT_GT(c.Fn, 0.0) << "repulsive, step " << k;
      largest_ratio = std::max(largest_ratio, c.Ft / c.Fn);
    }
  }
  const Vec3 v = sim.particles().v[2];
  EXPECT_EQ(sim.residuals().contacts, 0u) << "the small sphere must have left";
  EXPECT_GT(v.y(), 0.0) << "expelled along +y";
  measured("driver work / (m v^2 / 2) of the small sphere", work / (0.5 * sim.particles().m[2] * v.squaredNorm()));
  measured("largest E / W", largest_share);
  measured("largest |Ft| / Fn", largest_ratio);
  measured("exit speed [m/s]", v.norm());
  // Sliding: the Coulomb limit is reached and never exceeded.
  EXPECT_NEAR(largest_ratio, mu, 1e-9);
  // Energy only comes from the drivers (friction dissipates): E <= W, up to the O(dt^2)
  // difference between the trapezoid rule and velocity Verlet. Measured: E / W at most 0.998
  // (every Pi), and at the end W = 1.16 (Pi = 10) to 1.48 (Pi = 1000) times the small sphere's
  // kinetic energy, which leaves at 0.33-0.34 m/s, 34 times the squeeze speed (a small tilt
  // turns the squeeze into a fast sideways launch). Bound: E / W < 1.005.
  EXPECT_LT(largest_share, 1.005);
  EXPECT_GT(largest_share, 0.5) << "most of the work must reach the small sphere";
}

INSTANTIATE_TEST_SUITE_P(Polydispersity, TinySphere, ::testing::Values(10.0, 100.0, 1000.0),
                         [](const auto& info) { return "Pi" + std::to_string(static_cast<int>(info.param)); });

// A packing of packing-pi.yaml generated at polydispersity Pi, loaded and relaxed in the scene of
// packing-in-shell.yaml.
void load_and_relax_packing(double Pi) {
  const ConfigNode root = ConfigNode::load_file(stability::scene_path("packing-pi.yaml"));
  PackingParameters p = parse_packing(root).parameters;
  p.polydispersity = Pi;
  const std::uint64_t seed = parse_seeds(root).front();
  const Packing pk = generate_packing(p, seed);

  SceneFile f = stability::load("packing-in-shell.yaml");
  ASSERT_EQ(f.scene.particles.size(), 1u) << "one placeholder sphere, replaced by the packing";
  ASSERT_EQ(f.scene.shells.size(), 1u);
  ASSERT_EQ(f.scene.shells[0].radius, p.Rs) << "the shell of the scene is the packing's";
  const ParticleDef placeholder = f.scene.particles[0];
  f.scene.particles.clear();
  for (std::size_t i = 0; i < pk.radii.size(); ++i) {
    ParticleDef d = placeholder;
    d.x = f.scene.shells[0].centre + pk.centres[i];
    d.r = pk.radii[i];
    f.scene.particles.push_back(d);
  }
  const auto [r_min, r_max] = std::minmax_element(pk.radii.begin(), pk.radii.end());
  measured("spheres", static_cast<double>(pk.radii.size()));
  measured("largest / smallest radius", *r_max / *r_min);
  EXPECT_GT(*r_max / *r_min, 0.7 * Pi) << "the packing must span the polydispersity";

  Simulation sim(f.scene);
  // The push: run.duration, and the step or so the rounding of the duration left.
  const long push = sim.steps_for(*f.run.duration);
  for (long k = 0; k < push; k += 1000) {
    sim.run_steps(std::min(1000L, push - k));
    ASSERT_EQ(non_finite(sim), "");
  }
  for (long k = 0; k < 10 && sim.drivers_moving(); ++k) sim.step();
  ASSERT_FALSE(sim.drivers_moving()) << "the wall must have reached its depth";
  const RelaxationReport rep = relax(sim, *f.run.relaxation, [&](const RelaxationCheck&) { ASSERT_EQ(non_finite(sim), ""); });
  const Measurement m = sim.residuals();
  const auto& def = std::get<ConvergedRelaxationDef>(*f.run.relaxation);
  measured("steps", static_cast<double>(sim.step_count()));
  measured("relaxation time [s]", rep.simulated_time);
  measured("contacts", static_cast<double>(m.contacts));
  measured("force ratio", m.force_ratio());
  measured("energy ratio", m.energy_ratio());
  measured("largest overlap / smaller radius (watchdog)", sim.watchdog().largest_overlap_fraction());
  measured("largest energy / budget - 1 (watchdog)", sim.watchdog().largest_energy_ratio() - 1.0);
  ASSERT_TRUE(rep.converged && *rep.converged) << "force ratio " << m.force_ratio() << ", energy ratio " << m.energy_ratio();
  EXPECT_LT(m.force_ratio(), def.force_tolerance);
  EXPECT_LT(m.energy_ratio(), def.energy_tolerance);
  EXPECT_GT(m.contacts, 20u) << "the wall must load the packing";
  // Energy bounded: kinetic + elastic never above the work the wall and the initial state put
  // in (the watchdog's budget), up to the integration error; measured at most 1 + 7.8e-4 (Pi =
  // 100). Bound 1.01.
  EXPECT_LT(sim.watchdog().largest_energy_ratio(), 1.01);
  const WallLoad& wall = sim.wall_load("wall");
  const WallLoad& shell = sim.wall_load("shell");
  const Vec3 normal = f.scene.planes[0].normal.normalized();
  EXPECT_LT(wall.force.dot(normal), 0.0) << "the packing must push the wall back";
  // In balance the shell holds what the wall pushes in. The residual is the sum of the
  // unbalanced forces, at most (spheres x force tolerance x mean contact force); measured 1.5e-4
  // to 1.8e-4 of the wall load; bound 2e-3.
  const double imbalance = (wall.force + shell.force).norm() / wall.force.norm();
  measured("|wall + shell load| / |wall load|", imbalance);
  EXPECT_LT(imbalance, 2e-3);
}

TEST(PolydispersePacking, LoadedAndRelaxedAtPi10) { load_and_relax_packing(10.0); }
TEST(PolydispersePacking, LoadedAndRelaxedAtPi100) { load_and_relax_packing(100.0); }
TEST(PolydispersePacking, SlowLoadedAndRelaxedAtPi1000) { load_and_relax_packing(1000.0); }

}  // namespace
}  // namespace softpack
