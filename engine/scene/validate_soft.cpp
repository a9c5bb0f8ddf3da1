// The rules of soft-particle contacts (scene key effects.soft_particles, particles[i].soft and
// .mass; contact/soft_particle_law.hpp): which laws a scene needs for the contacts it can have,
// and the radii those laws were measured at.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/validate.hpp"
#include "scene/validate_detail.hpp"

namespace softpack {

using validation::fail;

namespace {

void check_law(const SoftSceneLaw& law, const std::string& key, bool friction) {
  const SoftPowerLaw& n = law.normal;
  if (!(std::isfinite(n.a) && n.a > 0.0 && std::isfinite(n.b) && n.b > 0.0 && std::isfinite(n.c) && std::isfinite(n.delta) &&
        n.delta >= 0.0))
    fail(key + ".normal", "needs finite a > 0, b > 0, c and delta >= 0");
  if (!friction) return;
  if (!law.tangential) fail(key + ".tangential", "friction is declared: the law file must give the tangential law (Eq. 8)");
  if (law.mu.empty() || law.mu.size() != law.mu_dn.size())
    fail(key + ".friction", "friction is declared: the law file must give mu_soft at one delta_n at least");
  for (double mu : law.mu)
    if (!(std::isfinite(mu) && mu >= 0.0)) fail(key + ".friction.mu", fmt::format("{} is not allowed; allowed: a finite mu >= 0", mu));
}

void check_radius(const SoftParticleLaws& laws, const SoftSceneLaw& law, const std::string& law_key, double r, const std::string& key,
                  bool friction) {
  if (const std::string why = soft_radius_refusal(laws, law, law_key, r, friction); !why.empty()) fail(key + ".r", why);
}

}  // namespace

std::string soft_radius_refusal(const SoftParticleLaws& laws, const SoftSceneLaw& law, const std::string& law_key, double r, bool friction) {
  const bool scaled = law.normal_exponent.has_value() && (!friction || law.tangential_exponent.has_value());
  if (!scaled && std::abs(r / laws.R0 - 1.0) > 1e-9)
    return fmt::format("{:.6g} m differs from the law file's reference radius {:.6g} m and {} has no radius scaling "
                       "of the laws the scene runs ({}); allowed: r = {:.6g} m",
                       r, laws.R0, law_key, laws.source, laws.R0);
  if (scaled && (r < law.R_min * (1.0 - 1e-9) || r > law.R_max * (1.0 + 1e-9)))
    return fmt::format("{:.6g} m is outside the radii {} was measured at ({}); allowed: {:.6g} to {:.6g} m", r, law_key, laws.source,
                       law.R_min, law.R_max);
  return "";
}

void validate_soft_particles(const SceneDef& s, SoftLaws laws) {
  std::size_t soft = 0, solid = 0, enclosed = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const ParticleDef& p = s.particles[i];
    const std::string key = fmt::format("particles[{}]", i);
    if (p.mass) validation::check(key + ".mass", *p.mass, limits::kMass);
    if (!p.soft) {
      ++solid;
      continue;
    }
    ++soft;
    if (!s.effects.soft_particles)
      fail(key + ".soft", "a soft-particle needs effects.soft_particles (the law file its contacts follow); allowed: "
                          "soft: true with effects.soft_particles declared, or soft: false");
    // A soft-particle of a body lies in that body's shell (nested soft-particles, docs/nested.md),
    // which confines it by the soft-solid law.
    if (p.body != kNoBody && std::none_of(s.shells.begin(), s.shells.end(), [&](const ShellDef& sh) { return sh.body == p.body; }))
      fail(key + ".body", fmt::format("body {} has no shell; allowed: no body, or the body of a shell that encloses the "
                                      "soft-particle (nested soft-particles)",
                                      p.body));
    if (p.body != kNoBody) ++enclosed;
  }
  if (!s.effects.soft_particles) return;
  const SoftParticlesDef& def = *s.effects.soft_particles;
  const std::string key = "effects.soft_particles";
  if (s.effects.normal.empty()) fail(key, "soft-particle contacts run with the solid spheres' law: declare effects.normal");
  if (soft == 0)
    fail(key, "declared, but no sphere is soft; allowed: at least one sphere with soft: true (particles[i].soft), or no "
              "effects.soft_particles");
  if (!def.laws.soft_solid && !def.laws.soft_soft) {
    // A scene file's laws are read after its scene, by the program (the engine reads no JSON),
    // which then checks the rules below (formats/scene_laws.hpp load_scene_laws). Simulation asks
    // for them (SoftLaws::loaded): empty laws are refused here, not run.
    if (laws == SoftLaws::pending && !def.law_file.empty()) return;
    if (def.law_file.empty())
      fail(key + ".laws", "no laws: soft-particle contacts need a law file's laws (formats/law_file.hpp)");
    fail(key + ".laws", fmt::format("the law file {} has not been read: a program that runs a scene file reads its laws "
                                    "first (formats/scene_laws.hpp load_scene_laws)",
                                    def.law_file));
  }
  if (!(std::isfinite(def.laws.R0) && def.laws.R0 > 0.0)) fail(key + ".laws", "the law file's reference radius must be > 0");
  const bool friction = s.effects.friction;
  const bool need_solid = !s.planes.empty() || solid > 0 || enclosed > 0, need_soft = soft > 1;
  if (need_solid && !def.laws.soft_solid)
    fail(key + ".laws", fmt::format("the scene has {} the soft-particles can touch, but {} has no soft-solid law",
                                    !s.planes.empty() ? "planes" : solid > 0 ? "solid spheres" : "shells", def.laws.source));
  if (need_soft && !def.laws.soft_soft)
    fail(key + ".laws", fmt::format("the scene has {} soft-particles, but {} has no soft-soft law", soft, def.laws.source));
  if (def.laws.soft_solid) check_law(*def.laws.soft_solid, key + ".laws.soft-solid", friction);
  if (def.laws.soft_soft) check_law(*def.laws.soft_soft, key + ".laws.soft-soft", friction);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const ParticleDef& p = s.particles[i];
    if (!p.soft) continue;
    const std::string pkey = fmt::format("particles[{}]", i);
    if (need_solid) check_radius(def.laws, *def.laws.soft_solid, "soft-solid", p.r, pkey, friction);
    if (need_soft) check_radius(def.laws, *def.laws.soft_soft, "soft-soft", p.r, pkey, friction);
  }
}

}  // namespace softpack
