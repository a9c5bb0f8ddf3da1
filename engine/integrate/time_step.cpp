#include "integrate/time_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace softpack {

namespace {

double sphere_mass(const SceneDef& scene, const ParticleDef& p) {
  return p.mass ? *p.mass : scene.materials.at(p.material).density * 4.0 / 3.0 * std::numbers::pi * p.r * p.r * p.r;
}

// The stiffest soft contact, dFn/dh = S_F a b Δn^(b-1) / R at the top of the measured range,
// with the lightest sphere of the scene (or a wall) as partner.
void soft_limit(const SceneDef& scene, StableLimit& out) {
  const SoftParticleLaws& laws = scene.effects.soft_particles->laws;
  double m_min = std::numeric_limits<double>::infinity();
  for (const ParticleDef& p : scene.particles) m_min = std::min(m_min, sphere_mass(scene, p));
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const ParticleDef& p = scene.particles[i];
    if (!p.soft) continue;
    const double m_soft = sphere_mass(scene, p);
    const double m12 = m_soft * m_min / (m_soft + m_min);
    for (const auto* law : {&laws.soft_solid, &laws.soft_soft}) {
      if (!*law) continue;
      const SoftPowerLaw& n = (*law)->normal;
      const double scale = (*law)->normal_exponent ? std::pow(p.r / laws.R0, *(*law)->normal_exponent) : 1.0;
      const double k = scale * n.a * n.b * std::pow(std::max(n.dn_max, n.delta), n.b - 1.0) / p.r;
      if (!(k > 0.0)) continue;
      const double t = std::sqrt(m12 / k);
      if (t < out.t_soft) out.t_soft = t, out.soft_particle = static_cast<int>(i);
    }
  }
}

}  // namespace

double rayleigh_time(double r, const Material& m) {
  return std::numbers::pi * r * std::sqrt(m.density / shear_modulus(m)) / (0.1631 * m.nu + 0.8766);
}

StableLimit stable_limit(const SceneDef& scene) {
  StableLimit out;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const auto& p = scene.particles[i];
    const double t = rayleigh_time(p.r, scene.materials.at(p.material));
    if (out.particle < 0 || t < out.t_rayleigh) out.t_rayleigh = t, out.particle = static_cast<int>(i);
  }
  if (scene.effects.soft_particles) soft_limit(scene, out);
  return out;
}

double choose_time_step(const SceneDef& scene) {
  const StableLimit lim = stable_limit(scene);
  if (lim.particle < 0) throw InputError("particles: the scene has no spheres");
  const auto& p = scene.particles[lim.particle];
  if (scene.integration.dt && *scene.integration.dt > lim.t_soft)
    throw InputError(fmt::format("integration.dt: {:.6g} s exceeds the soft-particle contacts' limit {:.6g} s (sqrt(m/k) of the "
                                 "stiffest contact of particles[{}] at the end of its law's measured range); use dt <= {:.6g} s",
                                 *scene.integration.dt, lim.t_soft, lim.soft_particle, lim.t_soft));
  if (scene.integration.safety && lim.t_soft < lim.t_rayleigh) return *scene.integration.safety * lim.t_soft;
  if (scene.integration.dt) {
    const double dt = *scene.integration.dt;
    if (dt > lim.t_rayleigh)
      throw InputError(fmt::format(
          "integration.dt: {:.6g} s exceeds the stable limit {:.6g} s (the Rayleigh time of the "
          "smallest, softest sphere: particles[{}], r = {:.6g} m, material '{}'); use dt <= "
          "{:.6g} s or integration.safety < 1",
          dt, lim.t_rayleigh, lim.particle, p.r, scene.materials[p.material].name, lim.t_rayleigh));
    return dt;
  }
  return *scene.integration.safety * lim.t_rayleigh;
}

}  // namespace softpack
