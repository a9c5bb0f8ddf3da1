// Soft-particle contacts (effects.soft_particles, contact/soft_particle_law.hpp) against the law
// file they are read from: the committed laws of the radius study (data/radius/report/laws.json),
// evaluated here from the file's numbers with the paper's Eq. 7 and Eq. 8 written out again, not
// through the engine's SoftPowerLaw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "formats/scene_laws.hpp"
#include "scene/scene_yaml.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/scenes.hpp"
#include "support/written_out_laws.hpp"

namespace softpack {
namespace {

using testing::eq7;
using testing::soft_particle;
const std::string& kLaws = testing::kPairwiseLaws;
const LawFile& law_file() { return testing::pairwise_law_file(); }

const SceneLaws& scene_laws(const std::string& name) { return law_file().scenes.at(name); }

SceneDef soft_scene(bool friction) {
  SceneDef s = testing::basic_scene();
  s.effects.soft_particles = SoftParticlesDef{soft_particle_laws(law_file(), kLaws), GrainContactRule::wall,
                                              SoftParticlesDef::BeyondRange::report};
  s.effects.friction = friction;
  return s;
}


// One soft-particle of radius R held at overlap h = dn R above the plane z = 0.
SceneDef on_a_wall(double R, double dn, bool friction) {
  SceneDef s = soft_scene(friction);
  s.particles = {soft_particle(Vec3(0, 0, R - dn * R), R)};
  s.planes.push_back(PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0});
  s.drivers = {HoldGroupDef{GroupDef{}}};
  return s;
}

TEST(SoftParticles, OnAWallTheNormalForceIsTheLawFilesEq7) {
  const SceneLaws& law = scene_laws("soft-solid");
  const double R0 = law_file().reference_radius;
  const double n = law.normal_scaling->exponent.value;
  for (const double R : {R0, 0.75 * R0, 2.0 * R0})
    for (const double dn : {0.12, 0.2, 0.3, 0.45}) {
      Simulation sim(on_a_wall(R, dn, false));
      const double expected = std::pow(R / R0, n) * eq7(law.normal, dn);
      ASSERT_GT(expected, 0.0);
      const Vec3 F = sim.particles().F[0];
      EXPECT_NEAR(F.z(), expected, 1e-9 * expected) << "R = " << R << ", dn = " << dn;
      EXPECT_EQ(F.x(), 0.0);
      EXPECT_NEAR(-sim.plane_loads()[0].force.z(), expected, 1e-9 * expected);
    }
}

TEST(SoftParticles, BelowDeltaASoftParticleTouchesAWallWithoutForce) {
  const double delta = scene_laws("soft-solid").normal.delta.value;
  Simulation sim(on_a_wall(law_file().reference_radius, 0.5 * delta, false));
  EXPECT_EQ(sim.particles().F[0], Vec3::Zero());
  EXPECT_EQ(sim.residuals().contacts, 1u);  // closed, but Eq. 7 gives 0 below delta
}

// The tangential spring: a spring xi installed in the held soft-particle's wall contact gives
// Ft = -kt(dn) xi (Eq. 8) below the Coulomb limit, and |Ft| = mu_soft(dn) Fn beyond it.
TEST(SoftParticles, OnAWallTheTangentialSpringIsTheLawFilesEq8AndSlidesAtMuSoft) {
  const SceneLaws& law = scene_laws("soft-solid");
  const double R0 = law_file().reference_radius;
  const double nF = law.normal_scaling->exponent.value, nt = law.tangential_scaling->exponent.value;
  for (const double R : {R0, 1.5 * R0})
    for (const double dn : {0.25, 0.35, 0.5}) {
      const double Fn = std::pow(R / R0, nF) * eq7(law.normal, dn);
      const double kt = std::pow(R / R0, nt) * eq7(*law.tangential, dn);
      const double mu = dn <= 0.3 ? law.friction->mu[0].value
                        : dn <= 0.4 ? law.friction->mu[0].value + (dn - 0.3) / 0.1 * (law.friction->mu[1].value - law.friction->mu[0].value)
                                    : law.friction->mu[1].value + (dn - 0.4) / 0.1 * (law.friction->mu[2].value - law.friction->mu[1].value);
      ASSERT_GT(kt, 0.0);
      for (const double fraction : {0.3, 3.0}) {  // of the Coulomb limit
        Simulation sim(on_a_wall(R, dn, true));
        SimulationState st = sim.state();
        const double ht = fraction * mu * Fn / kt;
        st.plane_springs = {{SimulationState::WallSpring{0, Vec3(ht, 0, 0)}}};
        sim.restore(st);
        sim.run_steps(1);  // held: the spring does not move; the force is the law's
        const Vec3 F = sim.particles().F[0];
        if (fraction < 1.0) EXPECT_NEAR(-F.x(), kt * ht, 1e-9 * kt * ht) << "R = " << R << ", dn = " << dn;
        else EXPECT_NEAR(-F.x(), mu * Fn, 1e-9 * mu * Fn) << "R = " << R << ", dn = " << dn;
        EXPECT_NEAR(F.z(), Fn, 1e-9 * Fn);
      }
    }
}

// Radii R1 != R2: the law file's mixing rule, the soft-soft law at R_eq = 2 R1 R2 / (R1 + R2)
// with the radius scaling at R_eq. A solid sphere against a soft-particle: the soft-solid law
// at R = Rs (`wall`) or R = Rs r / (Rs + r) (`reduced-radius`).
TEST(SoftParticles, TwoRadiiUseTheLawFilesMixingRuleAndASolidSphereTheChosenOne) {
  ASSERT_EQ(law_file().mixing->rule, "reduced-radius");
  const double R0 = law_file().reference_radius;
  const auto pair_force = [&](SceneDef s, double R1, double R2, double h, bool second_soft) {
    ParticleDef b = soft_particle(Vec3(R1 + R2 - h, 0, 0), R2);
    b.soft = second_soft;
    b.mass.reset();
    s.particles = {soft_particle(Vec3::Zero(), R1), b};
    s.drivers = {HoldGroupDef{GroupDef{}}};
    Simulation sim(s);
    EXPECT_EQ(sim.particles().F[0].x(), -sim.particles().F[1].x());
    return -sim.particles().F[0].x();  // repulsion pushes sphere 0 towards -x
  };
  const SceneLaws& soft = scene_laws("soft-soft");
  for (const double ratio : {0.6, 1.0, 1.8}) {
    const double R1 = R0, R2 = ratio * R0, Req = 2 * R1 * R2 / (R1 + R2), dn = 0.35;
    const double expected = std::pow(Req / R0, soft.normal_scaling->exponent.value) * eq7(soft.normal, dn);
    EXPECT_NEAR(pair_force(soft_scene(false), R1, R2, dn * Req, true), expected, 1e-9 * expected) << "R2/R1 = " << ratio;
  }
  const SceneLaws& solid = scene_laws("soft-solid");
  const double r = 0.4 * R0;
  for (const GrainContactRule rule : {GrainContactRule::wall, GrainContactRule::reduced_radius}) {
    SceneDef s = soft_scene(false);
    s.effects.soft_particles->grain_contact = rule;
    const double R = rule == GrainContactRule::wall ? R0 : R0 * r / (R0 + r), dn = 0.3;
    const double expected = std::pow(R / R0, solid.normal_scaling->exponent.value) * eq7(solid.normal, dn);
    EXPECT_NEAR(pair_force(s, R0, r, dn * R, false), expected, 1e-9 * expected);
  }
}

// A cloud of soft-particles and solid spheres with every effect: linear and angular momentum are
// conserved (equal and opposite forces at one contact point), as for solid spheres only
// (Conservation.MomentaOfA1000SpherePolydisperseCloud); with the pairwise laws and with the
// many-body law (law file version 2, issue 33), whose force reads every contact of its bodies.
void momenta_of_a_mixed_cloud(bool many_body, bool kt_gain = false, bool third = false) {
  SceneDef s = soft_scene(true);
  if (many_body) s.effects.soft_particles->laws.many_body = ManyBodyLaw{0.9, kt_gain};
  if (third) s.effects.soft_particles->laws.many_body = ManyBodyLaw{0.6, true, true, 1.3, 0.7, 0.3};  // the union form, its own βs, g
  s.effects.rotation = true;
  s.effects.restitution = 0.6;
  const double R0 = law_file().reference_radius;
  testing::Random rng(17);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      for (int m = 0; m < 3; ++m) {
        const Vec3 x(1.7 * R0 * k, 1.7 * R0 * l, 1.7 * R0 * m);
        ParticleDef p = (k + l + m) % 2 ? soft_particle(x, R0 * (0.8 + 0.4 * rng.uniform())) : ParticleDef{};
        if (!p.soft) p.x = x, p.r = R0 * (0.3 + 0.4 * rng.uniform());
        p.v = rng.in_box(0.3), p.w = rng.in_box(5.0);
        s.particles.push_back(p);
      }
  Simulation sim(s);
  const auto momenta = [&] {
    const Particles& p = sim.particles();
    Vec3 P = Vec3::Zero(), L = Vec3::Zero();
    double scale_P = 0.0, scale_L = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      P += p.m[i] * p.v[i];
      L += p.x[i].cross(p.m[i] * p.v[i]) + p.w[i] / p.inv_I[i];
      scale_P += p.m[i] * p.v[i].norm();
      scale_L += p.x[i].cross(p.m[i] * p.v[i]).norm() + p.w[i].norm() / p.inv_I[i];
    }
    return std::tuple{P, L, scale_P, scale_L};
  };
  const auto [P0, L0, sP, sL] = momenta();
  long soft_contacts = 0;
  double most = 0.0;  // the largest body state (many-body): some soft-particle has several contacts
  for (int chunk = 0; chunk < 40; ++chunk) {
    sim.run_steps(200);
    const ContactFamily& soft = sim.contact_lists().family.at(kSoftParticleFamily);
    for (std::size_t k = 0; k < soft.pairs.size(); ++k) soft_contacts += soft.pairs.spring[k] != Vec3::Zero();
    for (const double e : soft.body_state) most = std::max(most, e);
  }
  const auto [P1, L1, sP1, sL1] = momenta();
  EXPECT_GT(soft_contacts, 0) << "the cloud must have closed soft contacts with sliding springs";
  EXPECT_EQ(most > 0.0, many_body);
  EXPECT_LT((P1 - P0).norm(), 1e-12 * sP);
  EXPECT_LT((L1 - L0).norm(), 1e-12 * sL);
}

TEST(SoftParticles, MomentaOfAMixedCloudAreConserved) { momenta_of_a_mixed_cloud(false); }
TEST(SoftParticles, MomentaOfAMixedCloudAreConservedWithTheManyBodyLaw) { momenta_of_a_mixed_cloud(true); }
TEST(SoftParticles, MomentaOfAMixedCloudAreConservedWithTheManyBodyLawsTangentialGain) { momenta_of_a_mixed_cloud(true, true); }
TEST(SoftParticles, MomentaOfAMixedCloudAreConservedWithTheManyBodyLawsThirdVersion) { momenta_of_a_mixed_cloud(true, true, true); }

// Without damping and friction the soft laws are elastic (Fn depends on h alone): a soft-particle
// thrown at a wall and one thrown at another come back with the energy they had (to the time
// step's error), and the watchdog, which counts their elastic energy, lets both runs through.
TEST(SoftParticles, AnElasticSoftCollisionConservesEnergyAndTheWatchdogHolds) {
  const double R0 = law_file().reference_radius;
  for (const bool pair : {false, true}) {
    SceneDef s = soft_scene(false);
    ParticleDef a = soft_particle(Vec3(0, 0, 1.05 * R0), R0);
    a.v = Vec3(0, 0, -0.2);
    s.particles = {a};
    if (pair) {
      ParticleDef b = soft_particle(Vec3(0, 0, -1.05 * R0), R0);
      b.v = Vec3(0, 0, 0.2);
      s.particles.push_back(b);
    } else {
      s.planes.push_back(PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0});
    }
    Simulation sim(s);
    const auto energy = [&] { return sim.residuals().kinetic_energy + sim.residuals().elastic_energy; };
    const double E0 = energy();
    double max_drift = 0.0, deepest = 0.0;
    for (int k = 0; k < 400; ++k) {
      sim.run_steps(10);
      max_drift = std::max(max_drift, std::abs(energy() - E0));
      deepest = std::max(deepest, sim.residuals().deepest.fraction);
    }
    EXPECT_GT(deepest, 0.2) << "the collision must go deep into the law";
    EXPECT_LT(max_drift, 2e-3 * E0) << (pair ? "two soft-particles" : "soft-particle on a wall");
    EXPECT_NEAR(sim.particles().v[0].z(), 0.2, 1e-3 * 0.2) << "it comes back with its speed";
    EXPECT_EQ(sim.force_field().range().beyond_range, 0);
  }
}

TEST(SoftParticles, BeyondTheMeasuredRangeAContactIsCountedOrStopsTheRun) {
  const double R0 = law_file().reference_radius;
  const double top = scene_laws("soft-solid").normal.delta_n_max;
  SceneDef s = on_a_wall(R0, top + 0.1, false);
  {
    Simulation sim(s);
    sim.run_steps(3);
    const RangeStats stats = sim.force_field().range();
    EXPECT_EQ(stats.beyond_range, 4);  // the construction's evaluation and three steps
    EXPECT_NEAR(stats.max_dn, top + 0.1, 1e-12);
    EXPECT_EQ(stats.plane, 0);
  }
  s.effects.soft_particles->beyond_range = SoftParticlesDef::BeyondRange::stop;
  try {
    Simulation sim(s);
    FAIL() << "a contact beyond the measured range must stop the run";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the range its law was measured on"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("laws.json"), std::string::npos) << e.what();
  }
  // The watchdog's overlap limit reads a soft contact's depth as its dn.
  s = on_a_wall(R0, 1.2, false);
  EXPECT_THROW(Simulation{s}, NumericalError);
}

TEST(SoftParticles, ARunWithSoftSpringsContinuesBitForBitFromItsState) {
  SceneDef s = soft_scene(true);
  s.effects.rotation = true;
  s.effects.restitution = 0.5;
  const double R0 = law_file().reference_radius;
  ParticleDef a = soft_particle(Vec3(0, 0, 0.75 * R0), R0);
  a.v = Vec3(0.05, 0.02, -0.05);
  ParticleDef b = soft_particle(Vec3(0.3 * R0, 0, 2.45 * R0), R0);
  b.v = Vec3(-0.05, 0, -0.1);
  s.particles = {a, b};
  s.planes.push_back(PlaneDef{"floor", Vec3::Zero(), Vec3::UnitZ(), 0});
  s.effects.gravity = Vec3(0, 0, -9.81);
  Simulation first(s);
  first.run_steps(300);
  const SimulationState st = first.state();
  ASSERT_FALSE(st.plane_springs.at(0).empty()) << "the wall contact must carry a spring";
  Simulation second(s);
  second.restore(st);
  first.run_steps(300);
  second.run_steps(300);
  EXPECT_EQ(state_digest(first.state()), state_digest(second.state()));
}

// A scene without soft-particles has none of their state: no flags, no lists, no model
// (its result bits are ResultBits.ThreeRunsKeepTheDigestsOfTheirRelease's, unchanged).
TEST(SoftParticles, ASceneWithoutThemAllocatesNothingForThem) {
  SceneDef s = testing::basic_scene();
  testing::Random rng(3);
  s.particles = testing::random_spheres_in_shell(rng, 50, 0.02, 1e-3, 2e-3, 3.5, 100, kNoBody);
  Simulation sim(s);
  EXPECT_TRUE(sim.particles().family.empty());
  EXPECT_EQ(sim.contact_lists().family.size(), 1u);
}

TEST(SoftParticles, TheSceneRulesNameTheKey) {
  const double R0 = law_file().reference_radius;
  const auto refusal = [](const SceneDef& s) {
    try {
      Simulation sim(s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  SceneDef s = on_a_wall(R0, 0.3, false);
  s.effects.soft_particles.reset();
  EXPECT_NE(refusal(s).find("particles[0].soft: a soft-particle needs effects.soft_particles"), std::string::npos) << refusal(s);
  s = on_a_wall(3.0 * R0, 0.3, false);
  EXPECT_NE(refusal(s).find("particles[0].r: 0.048 m is outside the radii soft-solid was measured at"), std::string::npos) << refusal(s);
  s = on_a_wall(R0, 0.3, true);
  s.effects.soft_particles->laws.soft_solid->mu.clear();
  EXPECT_NE(refusal(s).find("effects.soft_particles.laws.soft-solid.friction"), std::string::npos) << refusal(s);
  s = on_a_wall(R0, 0.3, false);
  s.particles.push_back(soft_particle(Vec3(0, 0, 3 * R0), R0));
  s.effects.soft_particles->laws.soft_soft.reset();
  EXPECT_NE(refusal(s).find("has no soft-soft law"), std::string::npos) << refusal(s);
  s = on_a_wall(R0, 0.3, false);
  s.particles[0].body = 0;
  EXPECT_NE(refusal(s).find("particles[0].body"), std::string::npos) << refusal(s);
  s = on_a_wall(R0, 0.3, false);
  s.integration.safety.reset();
  s.integration.dt = 1e-2;
  EXPECT_NE(refusal(s).find("soft-particle contacts' limit"), std::string::npos) << refusal(s);
}

// A scene file names its law file; the engine reads no JSON, so its reader leaves the laws empty
// and a Simulation refuses them until the program has read them (load_scene_laws).
TEST(SoftParticles, ASceneFileRunsOnlyWithTheLawsItNames) {
  const std::string text = "materials:\n  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}\n"
                           "effects:\n  normal: hertz\n"
                           "  soft_particles: {laws: " + kLaws + ", grain_contact: reduced-radius, beyond_range: stop}\n"
                           "particles:\n  - {x: [0.0, 0.0, 0.0112], r: 0.016, material: grain, mass: 0.02, soft: true}\n"
                           "planes:\n  - {name: floor, point: [0.0, 0.0, 0.0], normal: [0.0, 0.0, 1.0], material: grain}\n"
                           "drivers:\n  - {type: hold, group: all}\n"
                           "integration: {safety: 0.2, tangential_history: synchronized}\n"
                           "neighbor: {skin: 0.2, level_ratio: 2.0}\n";
  SceneFile f = parse_scene(ConfigNode::load_string(text, "scene.yaml"));
  ASSERT_TRUE(f.scene.effects.soft_particles);
  const SoftParticlesDef& def = *f.scene.effects.soft_particles;
  EXPECT_EQ(def.law_file, kLaws);
  EXPECT_EQ(def.grain_contact, GrainContactRule::reduced_radius);
  EXPECT_EQ(def.beyond_range, SoftParticlesDef::BeyondRange::stop);
  EXPECT_TRUE(f.scene.particles[0].soft);
  EXPECT_FALSE(def.laws.soft_solid || def.laws.soft_soft);
  try {
    Simulation sim(f.scene);
    ADD_FAILURE() << "a Simulation was built without the soft-particle laws";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("effects.soft_particles.laws: the law file " + kLaws + " has not been read"),
              std::string::npos)
        << e.what();
  }
  load_scene_laws(f);
  EXPECT_EQ(def.laws.source, kLaws);
  EXPECT_EQ(def.laws.R0, law_file().reference_radius);
  Simulation sim(f.scene);
  const double expected = eq7(scene_laws("soft-solid").normal, 0.3);  // R = R0, h = 0.3 R0
  EXPECT_NEAR(-sim.plane_loads()[0].force.z(), expected, 1e-9 * expected);
}

}  // namespace
}  // namespace softpack
