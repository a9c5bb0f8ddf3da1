// The soft-particle laws written out by hand, for the tests that check the engine against them
// (tests/physics/test_soft_particles.cpp, test_many_body_law.cpp, test_many_body_stress.cpp), not
// through the engine's own code: the committed pairwise law file they start from (the radius
// study's, data/radius/report/laws.json), Eq. 7 of one of its scenes, a cap's volume v(δ) = δ²(3 − δ)/4 (over the sphere's)
// and base a(δ) = 2δ − δ² (over πR²; 1 past the hemisphere) as in contact/soft_particle_law.hpp, the depth whose cap has a
// given volume, and a soft-particle with its grains' mass.
#pragma once
#include <cmath>
#include <numbers>
#include <string>

#include "formats/law_file.hpp"
#include "scene/scene_def.hpp"

namespace softpack::testing {

inline const std::string kPairwiseLaws = std::string(SOFTPACK_SOURCE_DIR) + "/data/radius/report/laws.json";

inline const LawFile& pairwise_law_file() {
  static const LawFile f = read_law_file(kPairwiseLaws);
  return f;
}

// Eq. 7 / Eq. 8 from a fit's numbers: a dn^b + c above delta, 0 below.
inline double eq7(const LawFit& f, double dn) { return dn >= f.delta.value ? f.a.value * std::pow(dn, f.b.value) + f.c.value : 0.0; }

// Eq. 7 of `scene` ("soft-soft", "soft-solid") at the reference radius, from the file's numbers.
inline double eq7(const std::string& scene, double dn) {
  return eq7(pairwise_law_file().scenes.at(scene).normal, dn);
}

inline double cap_volume(double d) { return d * d * (3.0 - d) / 4.0; }
inline double cap_base(double d) { return d < 1.0 ? 2.0 * d - d * d : 1.0; }
// The depth δ* whose cap volume is eps, by bisection.
inline double cap_depth(double eps) {
  double lo = 0.0, hi = 2.0;
  for (int i = 0; i < 100; ++i) (cap_volume(0.5 * (lo + hi)) < eps ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// A soft-particle of radius r at x with its grains' mass (solid fraction 0.65, 2500 kg/m³).
inline ParticleDef soft_particle(const Vec3& x, double r) {
  ParticleDef p;
  p.x = x, p.r = r, p.soft = true;
  p.mass = 0.65 * 2500.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return p;
}

}  // namespace softpack::testing
