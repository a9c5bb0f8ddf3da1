// Static contact forces equal paper Eq. 3, Fn = sqrt(R12) h^(3/2) / D with D from Eq. 4, to
// 1e-12 relative, for sphere-sphere, sphere-plane and sphere-inside-shell contacts and for
// one and two materials. The expected values are written as the formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kTolerance = 1e-12;  // relative

double eq3(double R12, double h, const Material& a, const Material& b) {
  const double D = 0.75 * ((1 - a.nu * a.nu) / a.E + (1 - b.nu * b.nu) / b.E);  // Eq. 4
  return std::sqrt(R12) * std::pow(h, 1.5) / D;
}

SceneDef two_material_scene() {
  SceneDef s = testing::basic_scene();
  s.materials = {testing::paper_grain(), testing::stiff_grain()};
  return s;
}

class StaticForce : public ::testing::TestWithParam<int> {};  // param: material of the partner

TEST_P(StaticForce, SphereSphere) {
  const int partner = GetParam();
  SceneDef s = two_material_scene();
  const double R1 = 1.3e-3, R2 = 0.7e-3, h = 2.1e-5;
  ParticleDef a, b;
  a.r = R1;
  b.r = R2;
  b.material = partner;
  const Vec3 dir = Vec3(1, 2, -0.5).normalized();
  a.x = Vec3(1e-3, -2e-3, 5e-4);
  b.x = a.x + (R1 + R2 - h) * dir;
  s.particles = {a, b};
  const Simulation sim(s);
  const double expected = eq3(R1 * R2 / (R1 + R2), h, s.materials[0], s.materials[partner]);
  const Vec3 F = sim.particles().F[1];
  EXPECT_NEAR(F.norm(), expected, kTolerance * expected);
  EXPECT_NEAR(F.normalized().dot(dir), 1.0, 1e-14);  // repulsive, along the line of centres
  EXPECT_LT((sim.particles().F[0] + F).norm(), 1e-15 * expected);
}

TEST_P(StaticForce, SpherePlaneIsASphereOfInfiniteRadius) {
  const int wall_material = GetParam();
  SceneDef s = two_material_scene();
  const double r = 1.1e-3, h = 3.3e-5;
  const Vec3 normal = Vec3(0.3, -0.2, 1).normalized();
  s.planes = {PlaneDef{"wall", Vec3(0.01, 0.02, -0.003), normal, wall_material}};
  ParticleDef p;
  p.r = r;
  p.x = s.planes[0].point + (r - h) * normal + Vec3(0.2, 0.3, 0).cross(normal);
  s.particles = {p};
  const Simulation sim(s);
  const double expected = eq3(r, h, s.materials[0], s.materials[wall_material]);  // R12 = r
  EXPECT_NEAR(sim.particles().F[0].norm(), expected, kTolerance * expected);
  EXPECT_NEAR(sim.particles().F[0].normalized().dot(normal), 1.0, 1e-14);
  // The wall reports the opposite force.
  EXPECT_LT((sim.plane_loads()[0].force + sim.particles().F[0]).norm(), 1e-15 * expected);
}

TEST_P(StaticForce, SphereInsideShellUsesTheConcaveReducedRadius) {
  const int shell_material = GetParam();
  for (const ShellContactRadius choice : {ShellContactRadius::concave, ShellContactRadius::particle}) {
    SceneDef s = two_material_scene();
    const double Rs = 0.016, r = 2.4e-3, h = 4.0e-5;
    const Vec3 c(0.001, 0.002, 0.003), dir = Vec3(-1, 0.5, 2).normalized();
    s.shells = {ShellDef{"shell", 0, c, Rs, shell_material, choice, std::nullopt}};
    ParticleDef p;
    p.r = r;
    p.body = 0;
    p.x = c + (Rs - r + h) * dir;
    s.particles = {p};
    const Simulation sim(s);
    // Hertz for a convex sphere inside a concave one: 1/R12 = 1/r - 1/Rs.
    const double R12 = choice == ShellContactRadius::concave ? r * Rs / (Rs - r) : r;
    const double expected = eq3(R12, h, s.materials[0], s.materials[shell_material]);
    EXPECT_NEAR(sim.particles().F[0].norm(), expected, kTolerance * expected);
    EXPECT_NEAR(sim.particles().F[0].normalized().dot(-dir), 1.0, 1e-14);  // pushed inward
    EXPECT_LT((sim.shell_loads()[0].force + sim.particles().F[0]).norm(), 1e-15 * expected);
  }
}

INSTANTIATE_TEST_SUITE_P(Materials, StaticForce, ::testing::Values(0, 1),
                         [](const auto& info) { return info.param == 0 ? "OneMaterial" : "TwoMaterials"; });

TEST(StaticForce, ShellIgnoresSpheresOfOtherBodies) {
  SceneDef s = testing::basic_scene();
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), 0.016, 0, ShellContactRadius::concave, std::nullopt}};
  ParticleDef own, other;
  own.r = other.r = 1e-3;
  own.body = 0;
  own.x = Vec3(0.0155, 0, 0);   // overlaps its shell
  other.body = 1;
  other.x = Vec3(-0.0155, 0, 0);  // would overlap, but is not the shell's
  s.particles = {own, other};
  const Simulation sim(s);
  EXPECT_GT(sim.particles().F[0].norm(), 0.0);
  EXPECT_EQ(sim.particles().F[1], Vec3::Zero());
}

TEST(StaticForce, ShellTorqueVanishesForRadialForces) {
  SceneDef s = testing::basic_scene();
  s.shells = {ShellDef{"shell", 0, Vec3(1, 2, 3), 0.016, 0, ShellContactRadius::concave, std::nullopt}};
  ParticleDef p;
  p.r = 1e-3;
  p.body = 0;
  p.x = Vec3(1, 2, 3) + Vec3(0.0151, 0, 0);
  s.particles = {p};
  const Simulation sim(s);
  EXPECT_LT(sim.shell_loads()[0].torque.norm(), 1e-18);
}

}  // namespace
}  // namespace softpack
