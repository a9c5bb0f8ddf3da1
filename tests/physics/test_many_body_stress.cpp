// The many-body law's soft-soft stress term in the engine (issue 33; contact/soft_particle_law.hpp
// ManyBodyLaw::SoftStress; a law file of version 4 with many_body.soft_soft.stress): one contact is
// the law without the term, three soft-particles in a line and in an L press by the formula
// written out here (the base forces from Eq. 7 of the file's numbers, δ* by bisection, the tensors
// written out), the closed-contact walk sees the loops' force, momenta are conserved, and the bits
// do not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/parallel.hpp"
#include "formats/law_file.hpp"
#include "forces/contact_walk.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/written_out_laws.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace many_body_stress {  // a name of its own: the unity build may put it beside test_many_body_law.cpp
namespace {

using testing::cap_base;
using testing::cap_depth;
using testing::cap_volume;
using testing::eq7;
using testing::soft_particle;

constexpr double kBetaSoft = 0.4, kKappa = 2.5;

double R0() { return testing::pairwise_law_file().reference_radius; }

// The file's laws with the many-body law (volumetric), β_ss and, with a form, the stress term.
SoftParticleLaws laws(const std::string& form, double kappa = kKappa) {
  LawFile f = testing::pairwise_law_file();
  f.version = 4, f.many_body = ManyBodyFit{"volumetric", {0.9, 0.0}, "test", "pairwise"};
  f.many_body->soft_beta = LawValue{kBetaSoft, 0.0};
  if (!form.empty()) f.many_body->soft_stress = ManyBodyStressFit{form, {kappa, 0.0}};
  return soft_particle_laws(f, testing::kPairwiseLaws);
}

// The many-body law's base force of a soft-soft contact at dn whose two soft-particles' other caps are o1, o2.
double base(double dn, double o1, double o2) {
  const double others = 0.5 * (o1 + o2);
  if (others == 0.0) return eq7("soft-soft", dn);
  const double star = cap_depth(cap_volume(dn) + kBetaSoft * others);
  return eq7("soft-soft", star) * cap_base(dn) / cap_base(star);
}

SceneDef held(const SoftParticleLaws& l, std::vector<ParticleDef> particles) {
  SceneDef s = testing::basic_scene();
  s.effects.soft_particles = SoftParticlesDef{l, GrainContactRule::wall, SoftParticlesDef::BeyondRange::report};
  s.particles = std::move(particles);
  s.drivers = {HoldGroupDef{GroupDef{}}};
  return s;
}

TEST(ManyBodyStress, OneSoftSoftContactIsTheLawWithoutTheTerm) {
  for (const std::string form : {"mean", "normal", "lateral"})
    for (const double dn : {0.25, 0.32, 0.4}) {
      Simulation sim(held(laws(form), {soft_particle(Vec3::Zero(), R0()), soft_particle(Vec3(2.0 * R0() * (1.0 - dn / 2.0), 0, 0), R0())}));
      const double F = eq7("soft-soft", dn);
      ASSERT_GT(F, 0.0);
      EXPECT_NEAR(-sim.particles().F[0].x(), F, 1e-9 * F) << form << ", dn " << dn;
      EXPECT_NEAR(sim.particles().F[1].x(), F, 1e-9 * F) << form << ", dn " << dn;
      EXPECT_FALSE(sim.contact_lists().family.at(kSoftParticleFamily).body_stress.empty()) << "the stress pass must have run";
    }
}

// A, B, C of radius R0 along x (line) or A, B along x and C above B (L), held: the force on A is
// the A-B contact's, Fn_base + κ π R0² cap_base(Δn_AB) (p_A + p_B) / 2 with the tensors written out (S_A
// = F_AB x x, S_B = F_AB x x + F_BC u u, u = x or y): in the line `normal` gets the B-C contact's
// push (n·S_B·n − F_AB = F_BC) and `lateral` none; in the L the other way round.
TEST(ManyBodyStress, ThreeSoftParticlesPressByTheFormulaWrittenOut) {
  const double R = R0(), dAB = 0.3, dBC = 0.36, surface = 4.0 * std::numbers::pi * R * R;
  const double F_AB = base(dAB, 0.0, cap_volume(dBC)), F_BC = base(dBC, cap_volume(dAB), 0.0);
  ASSERT_GT(F_AB, eq7("soft-soft", dAB));  // the caps' part of the law is in the base force
  for (const bool line : {true, false})
    for (const std::string form : {"mean", "normal", "lateral"}) {
      const Vec3 B(2.0 * R - dAB * R, 0, 0), C = B + (2.0 * R - dBC * R) * (line ? Vec3::UnitX() : Vec3::UnitY());
      Simulation sim(held(laws(form), {soft_particle(Vec3::Zero(), R), soft_particle(B, R), soft_particle(C, R)}));
      const double nSn_B = F_AB + (line ? F_BC : 0.0), tr_B = F_AB + F_BC;  // along x
      const double p_A = 0.0;  // A's only contact is this one: tr S_A − F_AB, n·S_A·n − F_AB, tr S_A − n·S_A·n are 0
      const double p_B = form == "mean" ? (tr_B - F_AB) / surface : form == "normal" ? 3.0 * (nSn_B - F_AB) / surface : 3.0 * (tr_B - nSn_B) / (2.0 * surface);
      const double expected = F_AB + kKappa * std::numbers::pi * R * R * cap_base(dAB) * 0.5 * (p_A + p_B);
      if ((form == "normal") == line || form == "mean") EXPECT_GT(expected, 1.05 * F_AB) << form << (line ? ", line" : ", L");
      else EXPECT_EQ(expected, F_AB) << form << (line ? ", line" : ", L");
      EXPECT_NEAR(-sim.particles().F[0].x(), expected, 1e-9 * expected) << form << (line ? ", line" : ", L");
      EXPECT_NEAR(sim.particles().F[0].y(), 0.0, 1e-12 * expected);
      // The walk over closed contacts (residuals, watchdog, force_between) sees the loops' force.
      int seen = 0;
      for_each_closed_contact(sim.world(), sim.contact_lists(), sim.force_field(), [&](const ClosedContact& c) {
        if (c.i != 0) return;
        ++seen;
        EXPECT_NEAR(c.Fn(), -sim.particles().F[0].x(), 1e-12 * expected) << form;
      });
      EXPECT_EQ(seen, 1);
    }
}

// Soft-particles of unequal radii in mutual contact, and a plane under them: the forces on the
// spheres and on the wall add to zero, and the stress term changed them.
TEST(ManyBodyStress, MomentaAreConservedWithTheStressTerm) {
  for (const std::string form : {"mean", "normal", "lateral"}) {
    testing::Random rng(41);
    const auto scene = [&](const std::string& f) {
      std::vector<ParticleDef> ps;
      const double s = 1.55 * R0();
      for (const Vec3& x : {Vec3(0, 0, 0), Vec3(s, 0, 0), Vec3(0.5 * s, 0.87 * s, 0), Vec3(0.5 * s, 0.29 * s, 0.82 * s), Vec3(0.5 * s, 0.29 * s, -0.82 * s)})
        ps.push_back(soft_particle(x, R0() * (0.9 + 0.2 * rng.uniform())));
      SceneDef sc = held(laws(f), ps);
      sc.planes.push_back(PlaneDef{"floor", Vec3(0, 0, -0.82 * s - 0.7 * R0()), Vec3::UnitZ(), 0});
      return sc;
    };
    Simulation sim(scene(form)), without(scene(""));
    EXPECT_TRUE(without.contact_lists().family.at(kSoftParticleFamily).body_stress.empty()) << "no stress term: no pass, no tensors";
    Vec3 sum = sim.plane_loads()[0].force;
    double largest = sim.plane_loads()[0].force.norm(), changed = 0.0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i) {
      sum += sim.particles().F[i], largest = std::max(largest, sim.particles().F[i].norm());
      changed = std::max(changed, (sim.particles().F[i] - without.particles().F[i]).norm());
    }
    ASSERT_GT(largest, 0.0);
    EXPECT_GT(sim.plane_loads()[0].force.norm(), 0.0) << "the plane must touch";
    EXPECT_GT(changed, 1e-3 * largest) << form << ": the stress term must act";
    EXPECT_LT(sum.norm(), 1e-12 * largest) << form;
  }
}

// A cloud of soft-particles and grains in motion under the stress term (each form), with friction,
// rotation and damping: the bits of one thread on 2, 3 and 8.
TEST(ManyBodyStress, TheStressTermGivesTheSameBitsForAnyThreadCount) {
  for (const std::string form : {"normal", "lateral"}) {
    const auto run = [&] {
      SceneDef s = held(laws(form), {});
      s.drivers.clear();
      s.effects.soft_particles->laws.many_body->tangential_gain = true;
      s.effects.friction = true, s.effects.rotation = true, s.effects.restitution = 0.6;
      testing::Random rng(31);
      for (int k = 0; k < 6; ++k)
        for (int l = 0; l < 6; ++l)
          for (int m = 0; m < 6; ++m) {
            const Vec3 x(1.6 * R0() * k, 1.6 * R0() * l, 1.6 * R0() * m);
            ParticleDef p = (k + l + m) % 4 ? soft_particle(x, R0() * (0.85 + 0.3 * rng.uniform())) : ParticleDef{};
            if (!p.soft) p.x = x, p.r = R0() * (0.3 + 0.5 * rng.uniform());
            p.v = rng.in_box(0.3), p.w = rng.in_box(5.0);
            s.particles.push_back(p);
          }
      s.planes.push_back(PlaneDef{"floor", Vec3(0, 0, -0.6 * R0()), Vec3::UnitZ(), 0});
      Simulation sim(s);
      sim.run_steps(300);
      int stressed = 0;  // spheres with a closed contact's force in their tensor
      for (const SymmetricTensor& S : sim.contact_lists().family.at(kSoftParticleFamily).body_stress) stressed += S[0] + S[1] + S[2] > 0.0;
      EXPECT_GT(stressed, 20) << "the cloud must have soft-particles under stress";
      Fnv1a h;
      add_bits(h, sim.state());
      return h.value;
    };
    const int before = parallel::threads();
    parallel::set_threads(1);
    const std::uint64_t one = run();
    for (const int threads : {2, 3, 8}) {
      parallel::set_threads(threads);
      EXPECT_EQ(run(), one) << form << ", " << threads << " threads";
    }
    parallel::set_threads(before);
  }
}

}  // namespace
}  // namespace many_body_stress
}  // namespace softpack
