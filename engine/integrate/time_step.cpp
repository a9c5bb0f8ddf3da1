#include "integrate/time_step.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace softpack {

double rayleigh_time(double r, const Material& m) {
  return std::numbers::pi * r * std::sqrt(m.density / shear_modulus(m)) / (0.1631 * m.nu + 0.8766);
}

StableLimit stable_limit(const SceneDef& scene) {
  StableLimit out;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const auto& p = scene.particles[i];
    const double t = rayleigh_time(p.r, scene.materials.at(p.material));
    if (out.particle < 0 || t < out.t_rayleigh) out = {t, static_cast<int>(i)};
  }
  return out;
}

double choose_time_step(const SceneDef& scene) {
  const StableLimit lim = stable_limit(scene);
  if (lim.particle < 0) throw InputError("particles: the scene has no spheres");
  const auto& p = scene.particles[lim.particle];
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
