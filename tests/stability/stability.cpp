#include "stability/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace softpack::stability {

std::string scene_path(const std::string& name) { return std::string(SOFTPACK_SOURCE_DIR) + "/experiments/stability/" + name; }

SceneFile load(const std::string& name) { return load_scene_file(scene_path(name)); }

std::string non_finite(const Simulation& sim) {
  std::ostringstream out;
  const Particles& p = sim.particles();
  std::size_t bad = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool ok = p.x[i].allFinite() && p.v[i].allFinite() && p.F[i].allFinite();
    if (p.rotates()) ok = ok && p.w[i].allFinite() && p.T[i].allFinite();
    if (!ok && bad++ == 0)
      out << "sphere " << i << ": x = " << p.x[i].transpose() << ", v = " << p.v[i].transpose()
          << ", F = " << p.F[i].transpose() << "; ";
  }
  if (bad) out << bad << " of " << p.size() << " spheres not finite; ";
  for (const auto* loads : {&sim.plane_loads(), &sim.shell_loads()})
    for (const WallLoad& l : *loads)
      if (!l.force.allFinite() || !l.torque.allFinite()) out << "a wall load is not finite; ";
  const Measurement m = sim.residuals();
  if (!std::isfinite(m.kinetic_energy) || !std::isfinite(m.elastic_energy) || !std::isfinite(m.max_unbalanced_force) ||
      !std::isfinite(m.mean_contact_force))
    out << "residuals not finite (kinetic " << m.kinetic_energy << ", elastic " << m.elastic_energy << ", max force "
        << m.max_unbalanced_force << ", mean force " << m.mean_contact_force << "); ";
  std::string s = out.str();
  if (!s.empty()) s = "step " + std::to_string(sim.step_count()) + ": " + s;
  return s;
}

double mechanical_energy(const Simulation& sim) {
  const Measurement m = sim.residuals();
  return m.kinetic_energy + m.elastic_energy;
}

void measured(const std::string& what, double value) {
  std::printf("[ measured ] %s = %.3g\n", what.c_str(), value);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  ::testing::Test::RecordProperty(what, text);
}

double hertz_kn(const Material& m, double R12) { return std::sqrt(R12) / hertz_D(m, m); }

}  // namespace softpack::stability
