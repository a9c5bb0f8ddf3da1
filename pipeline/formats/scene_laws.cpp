#include "formats/scene_laws.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "scene/validate.hpp"

namespace softpack {

void load_scene_laws(SceneFile& file) {
  if (!file.scene.effects.soft_particles || file.scene.effects.soft_particles->law_file.empty()) return;
  SoftParticlesDef& def = *file.scene.effects.soft_particles;
  const std::string key = "effects.soft_particles.laws";
  try {
    std::error_code ec;
    if (!std::filesystem::exists(def.law_file, ec) && !ec)  // other failures: read_law_file's message
      throw InputError(fmt::format("{}: '{}' does not exist; allowed: a law file (JSON, \"format\": \"softpack-laws\"), its "
                                   "path absolute or relative to the scene file's folder",
                                   key, def.law_file));
    try {
      def.laws = soft_particle_laws(read_law_file(def.law_file), def.law_file);
    } catch (const InputError& e) {
      throw InputError(key + ": " + e.what());
    }
    validate_soft_particles(file.scene);
  } catch (const InputError& e) {
    throw file.root.locate(e);
  }
}

// What a simulation runs on (formats/law_file.hpp soft_particle_laws): the file's values as the
// engine's laws.
namespace {

SoftPowerLaw power_law(const LawFit& fit) {
  SoftPowerLaw x;
  x.a = fit.a.value, x.b = fit.b.value, x.c = std::isfinite(fit.c.value) ? fit.c.value : 0.0;
  x.delta = fit.delta.value;
  if (!std::isfinite(x.delta)) x.delta = x.c < 0.0 ? std::pow(-x.c / x.a, 1.0 / x.b) : 0.0;
  x.dn_min = fit.delta_n_min, x.dn_max = fit.delta_n_max;
  return x;
}

SoftSceneLaw scene_law(const SceneLaws& s) {
  SoftSceneLaw out;
  out.normal = power_law(s.normal);
  if (s.tangential) out.tangential = power_law(*s.tangential);
  if (s.friction) {
    out.mu_dn = s.friction->delta_n;
    for (const LawValue& mu : s.friction->mu) out.mu.push_back(mu.value);
  }
  if (s.normal_scaling) {
    out.normal_exponent = s.normal_scaling->exponent.value;
    out.R_min = s.normal_scaling->R_min, out.R_max = s.normal_scaling->R_max;
  }
  if (s.tangential_scaling) {
    out.tangential_exponent = s.tangential_scaling->exponent.value;
    if (s.normal_scaling) {
      out.R_min = std::max(out.R_min, s.tangential_scaling->R_min), out.R_max = std::min(out.R_max, s.tangential_scaling->R_max);
    } else {
      out.R_min = s.tangential_scaling->R_min, out.R_max = s.tangential_scaling->R_max;
    }
  }
  return out;
}

}  // namespace

SoftParticleLaws soft_particle_laws(const LawFile& f, const std::string& source) {
  SoftParticleLaws out;
  out.R0 = f.reference_radius;
  out.source = source;
  if (auto it = f.scenes.find("soft-solid"); it != f.scenes.end()) out.soft_solid = scene_law(it->second);
  if (auto it = f.scenes.find("soft-soft"); it != f.scenes.end()) out.soft_soft = scene_law(it->second);
  if (f.many_body) {
    const ManyBodyFit& m = *f.many_body;
    ManyBodyLaw& law = out.many_body.emplace();
    law.beta = m.beta.value, law.tangential_gain = m.tangential == "gain", law.union_of_caps = m.form == "volumetric-union";
    if (m.grain) law.grain_exponent = m.grain->exponent.value, law.grain_beta = m.grain->beta.value;
    if (m.soft_beta) law.soft_beta = m.soft_beta->value;
    if (m.soft_stress) {
      using Form = ManyBodyLaw::SoftStress::Form;
      const std::string& form = m.soft_stress->form;
      law.soft_stress = ManyBodyLaw::SoftStress{form == "normal" ? Form::normal : form == "lateral" ? Form::lateral : Form::mean, m.soft_stress->kappa.value};
    }
  }
  return out;
}

SoftParticleLaws read_soft_particle_laws(const std::string& key, const std::string& laws, const std::string& many_body) {
  SoftParticleLaws l;
  try {
    l = soft_particle_laws(read_law_file(laws), laws);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}.laws: {}", key, e.what()));
  }
  if (many_body.empty()) return l;
  try {
    l.many_body = soft_particle_laws(read_law_file(many_body), many_body).many_body;
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}.many_body: {}", key, e.what()));
  }
  if (!l.many_body)
    throw InputError(fmt::format("{}.many_body: {} has no many-body law (`many_body`); allowed: a law file of version 2 or later "
                                 "with one", key, many_body));
  return l;
}

}  // namespace softpack
