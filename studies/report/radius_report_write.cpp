// The radius study's report written out (report/radius_report.hpp): table.md, radius.json,
// scaling.dat and friction.dat for the figures, and the law file.
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "core/types.hpp"
#include "io/atomic_file.hpp"
#include "report/radius_report.hpp"
#include "report/report_cells.hpp"

namespace softpack {
namespace {

std::string pm(const RadiusValue& v) { return value_cell(v.value, v.error); }

nlohmann::json js(const RadiusValue& v) {
  return {{"value", json_number(v.value)}, {"error", json_number(v.error)}};
}

const RadiusRow* row_of(const RadiusReport& r, const std::string& setting, const std::string& scene) {
  for (const RadiusRow& row : r.rows)
    if (row.setting == setting && row.scene == scene) return &row;
  return nullptr;
}

const RadiusScalingRow* scaling_of(const RadiusReport& r, const std::string& variant, const std::string& scene,
                                   const std::string& quantity) {
  for (const RadiusScalingRow& s : r.scaling)
    if (s.variant == variant && s.scene == scene && s.quantity == quantity && std::isfinite(s.exponent.value)) return &s;
  return nullptr;
}

LawValue law(const RadiusValue& v) { return LawValue{v.value, v.error}; }

}  // namespace

SceneLaws row_scene_laws(const RadiusRow& row) {
  SceneLaws s;
  s.normal = LawFit{law(row.a), law(row.b), law(row.c), law(row.delta), row.dn_min, row.dn_max};
  if (std::isfinite(row.kt_a.value)) {
    const double c = -row.kt_a.value * std::pow(row.delta.value, row.kt_b.value);  // Eq. 8: c = −a δ^b
    s.tangential = LawFit{law(row.kt_a), law(row.kt_b), LawValue{c, kNaN}, law(row.delta), row.kt_dn_min, row.kt_dn_max};
  }
  if (!row.mu.empty()) {
    FrictionLaw fr;
    for (std::size_t k = 0; k < row.mu.size(); ++k)
      if (std::isfinite(row.mu[k].value)) fr.delta_n.push_back(row.mu_delta_n[k]), fr.mu.push_back(law(row.mu[k]));
    if (!fr.delta_n.empty()) s.friction = fr;
  }
  return s;
}

LawFile radius_law_file(const RadiusReport& r, const Study& study, const std::string& code_version) {
  LawFile f;
  f.reference_radius = r.R0;
  for (const char* scene : {"soft-solid", "soft-soft"}) {
    const RadiusRow* row = row_of(r, "reference", scene);
    if (!row || !std::isfinite(row->a.value)) continue;
    SceneLaws s = row_scene_laws(*row);
    // The fixed variant is what a soft-particle of another size made of the same grains is;
    // the self-similar one stands in where the fixed one has not run.
    for (const char* variant : {"fixed", "self_similar"}) {
      const RadiusScalingRow* n = scaling_of(r, variant, scene, "Fn");
      const RadiusScalingRow* t = scaling_of(r, variant, scene, "kt");
      const std::string name = std::string(variant) == "fixed" ? "fixed" : "self-similar";
      if (n && !s.normal_scaling) s.normal_scaling = RadiusScaling{law(n->exponent), n->R_min, n->R_max, name};
      if (t && !s.tangential_scaling) s.tangential_scaling = RadiusScaling{law(t->exponent), t->R_min, t->R_max, name};
    }
    f.scenes[scene] = s;
  }
  if (!r.mixed.empty() && !r.mixed.front().deviation.empty()) {
    MixingRule m;
    m.checked_ratio = r.mixed.front().ratio;
    m.deviation = law(r.mixed.front().deviation.front());
    f.mixing = m;
  }
  f.provenance.study = study.path;
  f.provenance.seeds = study.seeds;
  f.provenance.code_version = code_version;
  const auto now = std::chrono::system_clock::now();
  f.provenance.created = fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(now));
  f.provenance.notes =
      "Laws of the study's reference (fast measurement, docs/accuracy.md) at R0; radius scaling of the fixed variant "
      "(same grains) where it ran; mu_soft averaged over the sliding plateau (docs/radius.md).";
  return f;
}

std::string write_radius_report(const RadiusReport& r, const Study& study, const std::string& out_dir,
                                const std::string& title) {
  std::filesystem::create_directories(out_dir);
  std::string t = fmt::format("# {}\n\nR0 = {} m (the reference). Every value over the setting's seeds ± its seed-to-seed "
                              "standard error (fits: jackknife). Eq. 7: Fn = a Δn^b + c above δ; Eq. 8: kt = a Δn^b + c "
                              "[N per metre of ht]; μ_soft = Ft / Fn in the contact's frame on the sliding plateau "
                              "(ht / Rs >= {}), and its largest value. docs/radius.md says how each is measured.\n\n",
                              title, r.R0, study.mu_from_ht_over_Rs);
  t += "## Laws per radius\n\n| setting | scene | Rs [m] | r_max [m] | grains | δ | a [N] | b | kt a [N/m] | kt b |";
  for (double d : r.Fn_delta_n) t += fmt::format(" Fn({}) [N] |", d);
  for (double d : r.kt_delta_n) t += fmt::format(" kt({}) [N/m] |", d);
  t += "\n|";
  for (std::size_t k = 0; k < 10 + r.Fn_delta_n.size() + r.kt_delta_n.size(); ++k) t += "---|";
  t += "\n";
  for (const RadiusRow& row : r.rows) {
    t += fmt::format("| {} | {} | {} | {:.4g} | {:.0f} | {} | {} | {} | {} | {} |", row.setting, row.scene, row.Rs, row.r_max,
                     row.grains, pm(row.delta), pm(row.a), pm(row.b), pm(row.kt_a), pm(row.kt_b));
    for (const RadiusValue& v : row.Fn) t += fmt::format(" {} |", pm(v));
    for (const RadiusValue& v : row.kt) t += fmt::format(" {} |", pm(v));
    t += "\n";
  }
  for (const RadiusRow& row : r.rows)
    if (!row.note.empty()) t += fmt::format("\n- {} {}: {}", row.setting, row.scene, row.note);
  t += "\n## Friction coefficient μ_soft (grain friction μ = 0.3)\n\n| setting | scene | Rs [m] | Δn | μ_soft (plateau) | largest Ft/Fn |\n|---|---|---|---|---|---|\n";
  for (const RadiusRow& row : r.rows)
    for (std::size_t k = 0; k < row.mu.size(); ++k)
      t += fmt::format("| {} | {} | {} | {} | {} | {} |\n", row.setting, row.scene, row.Rs, row.mu_delta_n[k], pm(row.mu[k]),
                       pm(row.mu_peak[k]));
  // μ_soft is dimensionless: self-similar soft-particles must have one μ_soft at every radius.
  // Their radii are the same seeds' packings scaled, so not independent samples: the mean over
  // the radii keeps the error of one radius (the rms of theirs), beside the largest deviation.
  if (const auto it = study.radius_variants.find("self_similar"); it != study.radius_variants.end()) {
    t += "\nOver the self-similar radii (the same packings scaled, so not independent: the error is one radius's, "
         "the rms of theirs; the largest deviation of a radius from the mean in its own errors):\n\n"
         "| scene | Δn | μ_soft | largest |dev| / σ | radii |\n|---|---|---|---|---|\n";
    for (const char* scene : {"soft-solid", "soft-soft"}) {
      const RadiusRow* ref = row_of(r, "reference", scene);
      if (!ref) continue;
      for (std::size_t k = 0; k < ref->mu_delta_n.size(); ++k) {
        std::vector<RadiusValue> v;
        for (const std::string& n : it->second)
          if (const RadiusRow* row = row_of(r, n, scene); row && k < row->mu.size() && row->mu[k].error > 0.0)
            v.push_back(row->mu[k]);
        if (v.size() < 2) continue;
        double mean = 0.0, e2 = 0.0, worst = 0.0;
        for (const RadiusValue& x : v) mean += x.value, e2 += x.error * x.error;
        mean /= static_cast<double>(v.size());
        for (const RadiusValue& x : v) worst = std::max(worst, std::abs(x.value - mean) / x.error);
        t += fmt::format("| {} | {} | {} | {:.2f} | {} |\n", scene, ref->mu_delta_n[k],
                         pm({mean, std::sqrt(e2 / static_cast<double>(v.size()))}), worst, v.size());
      }
    }
  }
  t += "\n## Scaling with the radius, X(R) = X(R0) (R/R0)^n\n\nHertz: the exponent of a self-similar packing of Hertz "
       "grains (and of a solid sphere) in the quasi-static limit, 2 for Fn and a, 1 for kt [N/m]; z = (n − Hertz) / σ.\n\n"
       "| variant | scene | quantity | n | Hertz | z | χ²/dof | radii | R [m] |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const RadiusScalingRow& s : r.scaling) {
    const double hertz = s.quantity.rfind("kt", 0) == 0 ? 1.0 : 2.0;
    t += fmt::format("| {} | {} | {} | {} | {} | {:+.1f} | {:.3g} | {} | {} – {} |\n", s.variant, s.scene, s.quantity, pm(s.exponent),
                     hertz, (s.exponent.value - hertz) / s.exponent.error, s.chi2_per_dof, s.radii, s.R_min, s.R_max);
  }
  if (!r.mixed.empty()) {
    t += "\n## Two radii: soft-soft of R1 = Rs and R2 = k Rs against rules for the equal-size law\n\n"
         "| setting | k | rule | mean of measured / predicted − 1 (± over the loaded points) |\n|---|---|---|---|\n";
    for (const MixedRow& m : r.mixed)
      for (std::size_t k = 0; k < m.rules.size(); ++k)
        t += fmt::format("| {} | {} | {} | {} |\n", m.setting, m.ratio, m.rules[k], pm(m.deviation[k]));
  }
  if (!r.missing.empty()) t += fmt::format("\nNo normal results yet: {}.\n", fmt::join(r.missing, ", "));

  nlohmann::json j;
  j["R0"] = r.R0;
  for (const RadiusRow& row : r.rows) {
    nlohmann::json x{{"setting", row.setting}, {"scene", row.scene}, {"Rs", row.Rs}, {"r_max", row.r_max}, {"grains", row.grains},
                     {"seeds", row.seeds}, {"delta", js(row.delta)}, {"a", js(row.a)}, {"b", js(row.b)}, {"c", js(row.c)},
                     {"kt_a", js(row.kt_a)}, {"kt_b", js(row.kt_b)}, {"note", row.note}};
    for (std::size_t k = 0; k < row.Fn.size(); ++k) x["Fn"][fmt::format("{}", r.Fn_delta_n[k])] = js(row.Fn[k]);
    for (std::size_t k = 0; k < row.kt.size(); ++k) x["kt"][fmt::format("{}", r.kt_delta_n[k])] = js(row.kt[k]);
    for (std::size_t k = 0; k < row.mu.size(); ++k)
      x["mu"][fmt::format("{}", row.mu_delta_n[k])] = {{"plateau", js(row.mu[k])}, {"peak", js(row.mu_peak[k])}};
    j["rows"].push_back(x);
  }
  for (const RadiusScalingRow& s : r.scaling)
    j["scaling"].push_back({{"variant", s.variant}, {"scene", s.scene}, {"quantity", s.quantity}, {"exponent", js(s.exponent)},
                            {"chi2_per_dof", json_number(s.chi2_per_dof)},
                            {"R_min", s.R_min}, {"R_max", s.R_max}});
  for (const MixedRow& m : r.mixed) {
    nlohmann::json x{{"setting", m.setting}, {"ratio", m.ratio}, {"delta_n", m.delta_n}, {"measured", m.measured},
                     {"predicted_reduced_radius", m.predicted}};
    for (std::size_t k = 0; k < m.rules.size(); ++k) x["rules"].push_back({{"rule", m.rules[k]}, {"deviation", js(m.deviation[k])}});
    j["mixed"].push_back(x);
  }
  j["missing"] = r.missing;
  write_file_atomically(out_dir + "/radius.json", j.dump(2) + "\n");

  // scaling.dat: one line per (variant, scene, radius): R/R0, then Fn / Fn(R0) and its error at
  // each compared delta_n (figures/radius_scaling.gp).
  std::string dat = fmt::format("# variant scene R/R0, then Fn/Fn(R0) and its error at delta_n = {}\n", fmt::join(r.Fn_delta_n, ", "));
  for (const auto& [variant, names] : study.radius_variants) {
    if (variant == "mixed") continue;
    for (const char* scene : {"soft-solid", "soft-soft"}) {
      const RadiusRow* ref = row_of(r, "reference", scene);
      if (!ref) continue;
      for (const std::string& n : names)
        if (const RadiusRow* row = row_of(r, n, scene)) {
          dat += fmt::format("{} {} {:.6g}", variant, scene, row->Rs / r.R0);
          for (std::size_t k = 0; k < row->Fn.size(); ++k)
            dat += fmt::format(" {:.6g} {:.6g}", row->Fn[k].value / ref->Fn[k].value, row->Fn[k].error / ref->Fn[k].value);
          dat += "\n";
        }
    }
  }
  write_file_atomically(out_dir + "/scaling.dat", dat);
  // friction.dat: one line per (setting, scene, sliding delta_n) (figures/radius_friction.gp).
  std::string fr = "# setting scene Rs/R0 delta_n mu_soft error peak error\n";
  for (const RadiusRow& row : r.rows)
    for (std::size_t k = 0; k < row.mu.size(); ++k)
      fr += fmt::format("{} {} {:.6g} {} {:.6g} {:.6g} {:.6g} {:.6g}\n", row.setting, row.scene, row.Rs / r.R0, row.mu_delta_n[k],
                        row.mu[k].value, row.mu[k].error, row.mu_peak[k].value, row.mu_peak[k].error);
  write_file_atomically(out_dir + "/friction.dat", fr);
  write_file_atomically(out_dir + "/table.md", t);
  return t;
}

}  // namespace softpack
