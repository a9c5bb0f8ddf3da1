#include "state/world.hpp"

#include <numbers>

namespace softpack {

World make_world(const SceneDef& scene) {
  World w;
  Particles& p = w.p;
  const bool rotation = scene.effects.rotation;
  const std::size_t n = scene.particles.size();
  p.x.resize(n);
  p.v.resize(n);
  p.F.assign(n, Vec3::Zero());
  p.r.resize(n);
  p.m.resize(n);
  p.inv_m.resize(n);
  p.body.resize(n);
  p.material.resize(n);
  if (scene.effects.soft_particles) p.family.resize(n);
  if (rotation) {
    p.w.resize(n);
    p.T.assign(n, Vec3::Zero());
    p.inv_I.resize(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const ParticleDef& d = scene.particles[i];
    const double rho = scene.materials[d.material].density;
    p.x[i] = d.x;
    p.v[i] = d.v;
    p.r[i] = d.r;
    p.m[i] = d.mass ? *d.mass : rho * 4.0 / 3.0 * std::numbers::pi * d.r * d.r * d.r;
    p.inv_m[i] = 1.0 / p.m[i];
    p.body[i] = d.body;
    p.material[i] = d.material;
    if (!p.family.empty()) p.family[i] = d.soft ? kSoftParticleFamily : 0;
    if (rotation) {
      p.w[i] = d.spin_locked ? Vec3(Vec3::Zero()) : d.w;
      p.inv_I[i] = d.spin_locked ? 0.0 : 1.0 / (0.4 * p.m[i] * d.r * d.r);  // solid sphere, I = 2/5 m r^2; locked: I infinite
    }
  }
  for (const PlaneDef& d : scene.planes) w.planes.push_back(PlaneWall{d.point, d.normal.normalized(), Vec3::Zero(), d.material});
  for (const ShellDef& d : scene.shells)
    w.shells.push_back(
        SphericalShell{d.centre, d.radius, d.body, Vec3::Zero(), Vec3::Zero(), d.material, d.contact_radius, d.mass.value_or(0.0)});
  w.plane_loads.resize(w.planes.size());
  w.shell_loads.resize(w.shells.size());
  return w;
}


}  // namespace softpack
