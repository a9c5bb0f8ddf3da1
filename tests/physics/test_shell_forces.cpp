// The vectorised sphere-shell loop (sim/shell_forces.cpp) computes exactly what the per-contact
// loop it replaced computed (kept below as the reference: the shell loop of the simulation, its
// wall_contact(), advance_spring() and contact_force()), for every combination of effects, on a
// moving, turning shell with touching and open entries, sticking, sliding and tilted springs.
// Equal values, not merely close: the archived paper results depend on them.
#include <gtest/gtest.h>

#include "contact/contact_force.hpp"
#include "sim/shell_forces.hpp"
#include "support/effect_combinations.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

struct World {
  std::vector<Vec3> x, v, w, F, T;
  std::vector<double> r;
  SphericalShell shell;
  WallList list;
  Vec3 load_force = Vec3::Zero(), load_torque = Vec3::Zero();
};

World random_world(bool friction) {
  testing::Random rng(23);
  World wd;
  wd.shell.centre = Vec3(1e-3, -2e-3, 5e-4);
  wd.shell.radius = 0.02;
  wd.shell.velocity = Vec3(0.01, -0.02, 0.005);
  wd.shell.spin = Vec3(0.5, -1.0, 2.0);
  const int n = 300;
  for (int i = 0; i < n; ++i) {
    const double r = rng.uniform(5e-4, 2e-3);
    // Centres at Rs - r + h with h from -0.2 r (open) to +0.1 r (touching).
    const Vec3 dir = rng.in_box(1.0).normalized();
    wd.x.push_back(wd.shell.centre + (wd.shell.radius - r + rng.uniform(-0.2, 0.1) * r) * dir);
    wd.r.push_back(r);
    wd.v.push_back(rng.in_box(0.05));
    wd.w.push_back(rng.in_box(30.0));
    WallEntry e;
    e.i = i;
    e.k.kn = rng.uniform(1e6, 2e6);
    e.k.kt0 = rng.uniform(1e6, 2e6);
    e.k.gamma0 = rng.uniform(1e-2, 1e-1);
    e.k.gamma_t0 = rng.uniform(1e-2, 1e-1);
    e.k.mu = rng.uniform(0.1, 0.5);
    wd.list.entries.push_back(e);
    // Springs: most small (sticking), some large (sliding), all tilted out of the plane; a few zero.
    if (friction) wd.list.spring.push_back(i % 17 == 0 ? Vec3::Zero() : rng.in_box(rng.uniform() < 0.8 ? 1e-7 : 1e-4));
  }
  wd.F.assign(n, Vec3::Zero());
  wd.T.assign(n, Vec3::Zero());
  return wd;
}

// The per-contact loop of Simulation::compute_forces_for before it was vectorised.
void reference(World& wd, const PairForceEffects& fx, double dt) {
  const SphericalShell& s = wd.shell;
  const double half_dt = 0.5 * dt;
  Vec3 no_spring = Vec3::Zero();
  for (std::size_t k = 0; k < wd.list.entries.size(); ++k) {
    const int i = wd.list.entries[k].i;
    const Vec3 d = wd.x[i] - s.centre;
    const double dist = d.norm();
    const double h = dist + wd.r[i] - s.radius;
    if (h <= 0.0) {
      if (fx.friction) wd.list.spring[k].setZero();
      continue;
    }
    const Vec3 nrm = d * (-1.0 / dist);
    const Vec3 surface_velocity = s.surface_velocity(wd.x[i] - (wd.r[i] - 0.5 * h) * nrm);
    Vec3 n_half = nrm, surface_velocity_half = surface_velocity;
    double h_half = h;
    if (fx.friction && fx.synchronized) {
      const Vec3 d_half = d - half_dt * (wd.v[i] - s.velocity);
      const double dist_half = d_half.norm();
      n_half = d_half * (-1.0 / dist_half);
      h_half = dist_half + wd.r[i] - s.radius;
      surface_velocity_half = s.surface_velocity(s.centre + d_half - (wd.r[i] - 0.5 * h_half) * n_half);
    }
    // wall_contact
    Vec3 vc = wd.v[i] - surface_velocity;
    const double ai = wd.r[i] - 0.5 * h;
    if (fx.rotation) vc -= (ai * wd.w[i]).cross(nrm);
    Vec3& spring = fx.friction ? wd.list.spring[k] : no_spring;
    if (fx.friction) {
      if (fx.synchronized) {
        Vec3 vc_half = wd.v[i] - surface_velocity_half;
        if (fx.rotation) vc_half -= ((wd.r[i] - 0.5 * h_half) * wd.w[i]).cross(n_half);
        advance_spring(spring, n_half, vc_half, nrm, dt);
      } else {
        advance_spring(spring, nrm, vc, nrm, dt);
      }
    }
    const ContactCoefficients& c = wd.list.entries[k].k;
    const ContactForce cf = fx.friction ? (fx.damping ? contact_force<true, true>(nrm, h, vc, c, spring)
                                                      : contact_force<true, false>(nrm, h, vc, c, spring))
                                        : (fx.damping ? contact_force<false, true>(nrm, h, vc, c, spring)
                                                      : contact_force<false, false>(nrm, h, vc, c, spring));
    wd.F[i] += cf.F;
    if (fx.rotation) wd.T[i] -= ai * nrm.cross(cf.Ft);
    wd.load_force -= cf.F;
    wd.load_torque += (wd.x[i] - ai * nrm - s.centre).cross(-cf.F);
  }
}

void expect_equal(const Vec3& a, const Vec3& b, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]) << what << ", component " << c;
}

class ShellForces : public ::testing::TestWithParam<int> {};  // bits: friction, damping, rotation, sync

TEST_P(ShellForces, VectorisedLoopGivesThePerContactLoopsValues) {
  const int bits = GetParam();
  const PairForceEffects fx = testing::effects_of(bits);
  World ref = random_world(fx.friction), vec = ref;
  const double dt = 1e-6;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < ref.x.size(); ++i) touching += ref.shell.overlap(ref.x[i], ref.r[i]) > 0.0;
  EXPECT_GT(touching, 40u);
  EXPECT_LT(touching, ref.x.size() - 40);
  // Three steps, so that springs advanced by the loop are advanced again.
  for (int step = 0; step < 3; ++step) {
    reference(ref, fx, dt);
    accumulate_shell_forces(vec.list, vec.shell,
                            PairForceArrays{vec.x.data(), vec.v.data(), fx.rotation ? vec.w.data() : nullptr, vec.r.data(),
                                            vec.F.data(), fx.rotation ? vec.T.data() : nullptr},
                            fx, dt, vec.load_force, vec.load_torque);
    for (std::size_t i = 0; i < ref.x.size(); ++i) {
      expect_equal(vec.F[i], ref.F[i], "F of sphere " + std::to_string(i));
      if (fx.rotation) expect_equal(vec.T[i], ref.T[i], "T of sphere " + std::to_string(i));
      if (fx.friction) expect_equal(vec.list.spring[i], ref.list.spring[i], "spring of entry " + std::to_string(i));
    }
    expect_equal(vec.load_force, ref.load_force, "shell load force");
    expect_equal(vec.load_torque, ref.load_torque, "shell load torque");
    ASSERT_FALSE(::testing::Test::HasFailure()) << "step " << step;
  }
  EXPECT_GT(ref.load_force.norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Effects, ShellForces, testing::effect_combinations(), testing::effects_name);

}  // namespace
}  // namespace softpack
