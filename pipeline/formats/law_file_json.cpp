#include "formats/law_file_json.hpp"

#include <cmath>
#include <string>

namespace softpack::law_json {
namespace {

using json = nlohmann::ordered_json;

json num(double x) { return std::isnan(x) ? json(nullptr) : json(x); }  // ±inf stays: the check refuses it

json value_json(const LawValue& v, const char* unit) { return {{"value", num(v.value)}, {"error", num(v.error)}, {"unit", unit}}; }

json fit_json(const LawFit& f, const char* unit) {
  return {{"a", value_json(f.a, unit)},
          {"b", value_json(f.b, kOne)},
          {"c", value_json(f.c, unit)},
          {"delta", value_json(f.delta, kOne)},
          {"delta_n_range", json::array({num(f.delta_n_min), num(f.delta_n_max)})}};
}

json scaling_json(const RadiusScaling& s) {
  return {{"exponent", value_json(s.exponent, kOne)},
          {"radius_range", {{"value", json::array({num(s.R_min), num(s.R_max)})}, {"unit", kMetre}}},
          {"variant", s.variant}};
}

// The stress term's p_i (contact/soft_particle_law.hpp ManyBodyLaw::SoftStress), for the models' text.
std::string stress_text(const std::string& form) {
  if (form == "normal") return "p_i = 3 (n.S_i.n - Fn) / (4 pi R_i^2)";
  if (form == "lateral") return "p_i = 3 (tr S_i - n.S_i.n) / (8 pi R_i^2)";
  return "p_i = (tr S_i - Fn) / (4 pi R_i^2)";
}

}  // namespace

json file(const LawFile& f) {
  json out;
  out["format"] = kFormat;
  out["version"] = f.version;
  out["reference_radius"] = {{"value", num(f.reference_radius)}, {"unit", kMetre}};
  out["models"] = {{"normal", "Fn = a dn^b + c for dn >= delta, 0 below (Eq. 7); dn = hn / R"},
                   {"tangential", "kt = a dn^b + c for dn >= delta, 0 below (Eq. 8); Ft = kt ht until |Ft| = mu_soft Fn"},
                   {"friction", "mu_soft = |Ft| / Fn while the contact slides, measured at each dn"},
                   {"radius_scaling", "X(R) = X(R0) (R/R0)^exponent at fixed dn"},
                   {"mixing", "radii R1 != R2: the soft-soft law at R_eq = 2 R1 R2 / (R1 + R2)"}};
  if (f.many_body)
    out["models"]["many_body"] =
        "volumetric: Fn_k = X(d*) a(dn_k) / a(d*), v(d*) = v(dn_k) + beta (E - v(dn_k)), v(d) = d^2 (3 - d) / 4, a(d) = 2d - d^2, " +
        std::string(f.many_body->form == "volumetric-union" ? "E the volume the soft-particle's contact caps cut together (their union)"
                                                            : "E the sum of v over the soft-particle's contacts") +
        std::string(f.many_body->grain ? "; a grain of radius r: X times ((r/R) / (1 + r/R))^grain.exponent, beta = grain.beta" : "") +
        std::string(f.many_body->soft_beta ? "; two soft-particles: beta = soft_soft.beta, E - v the mean of theirs" : "") +
        (f.many_body->soft_stress ? "; two soft-particles i, j: Fn + kappa pi R^2 a(dn) (p_i + p_j) / 2, p_i the stress of i's other contacts (" +
                                        f.many_body->soft_stress->form + ": " + stress_text(f.many_body->soft_stress->form) + ")"
                                  : std::string()) +
        std::string(f.many_body->tangential == "gain" ? "; kt_k = Eq. 8 at dn_k times Fn_k / X(dn_k)" : "");
  json scenes = json::object();
  for (const auto& [name, s] : f.scenes) {
    json j;
    j["normal"] = fit_json(s.normal, kForce);
    if (s.tangential) j["tangential"] = fit_json(*s.tangential, kStiffness);
    if (s.friction) {
      json mu = json::array();
      for (const LawValue& m : s.friction->mu) mu.push_back(value_json(m, kOne));
      json dn = json::array();
      for (double x : s.friction->delta_n) dn.push_back(num(x));
      j["friction"] = {{"delta_n", dn}, {"mu", mu}};
    }
    if (s.normal_scaling) j["normal_scaling"] = scaling_json(*s.normal_scaling);
    if (s.tangential_scaling) j["tangential_scaling"] = scaling_json(*s.tangential_scaling);
    scenes[name] = j;
  }
  out["scenes"] = scenes;
  if (f.mixing)
    out["mixing"] = {{"rule", f.mixing->rule}, {"checked_ratio", num(f.mixing->checked_ratio)}, {"deviation", value_json(f.mixing->deviation, kOne)}};
  if (f.many_body) {
    const ManyBodyFit& m = *f.many_body;
    out["many_body"] = {{"form", m.form}, {"beta", value_json(m.beta, kOne)}, {"tangential", m.tangential}, {"source", m.source}};
    if (m.grain) out["many_body"]["grain"] = {{"exponent", value_json(m.grain->exponent, kOne)}, {"beta", value_json(m.grain->beta, kOne)}};
    if (m.soft_beta) out["many_body"]["soft_soft"] = {{"beta", value_json(*m.soft_beta, kOne)}};
    if (m.soft_stress) out["many_body"]["soft_soft"]["stress"] = {{"form", m.soft_stress->form}, {"kappa", value_json(m.soft_stress->kappa, kOne)}};
  }
  const LawFileProvenance& p = f.provenance;
  out["provenance"] = {{"study", p.study}, {"seeds", p.seeds}, {"code_version", p.code_version}, {"created", p.created}, {"notes", p.notes}};
  return out;
}

}  // namespace softpack::law_json
