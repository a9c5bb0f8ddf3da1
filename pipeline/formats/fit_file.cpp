#include "formats/fit_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "formats/json_input.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

using fit::PowerLawFit;
using json = nlohmann::ordered_json;

constexpr const char *kSceneKey = "scene", *kNormal = "normal", *kTangential = "tangential";
constexpr const char *kProvenance = "provenance", *kCodeVersionKey = "code_version";
constexpr const char* kStampKey = "stamp";  // since stamps (issue 28); absent in older files
const std::string kError = "_error";  // the key of a coefficient's standard error: "a_error"

// The coefficients of a law with a standard error, as the file names them: Eq. 7 has all four,
// Eq. 8 the first three (its delta is Eq. 7's, written as "delta_used").
struct Coefficient {
  const char* key;
  double PowerLawFit::*value;
  double PowerLawFit::*error;
};
constexpr Coefficient kCoefficients[] = {{"a", &PowerLawFit::a, &PowerLawFit::a_error},
                                         {"b", &PowerLawFit::b, &PowerLawFit::b_error},
                                         {"c", &PowerLawFit::c, &PowerLawFit::c_error},
                                         {"delta", &PowerLawFit::delta, &PowerLawFit::delta_error}};
std::span<const Coefficient> coefficients(bool normal) { return std::span(kCoefficients).first(normal ? 4 : 3); }

json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json law(const PowerLawFit& f, bool normal) {
  json j;
  for (const Coefficient& c : coefficients(normal)) {
    j[c.key] = number_or_null(f.*c.value);
    j[c.key + kError] = number_or_null(f.*c.error);
  }
  if (!normal) j["delta_used"] = number_or_null(f.delta);
  j["points"] = f.points;
  j["weighted"] = f.weighted;
  if (f.weighting == "relative") j["weighting"] = f.weighting;
  j["chi2_per_dof"] = number_or_null(f.chi2_per_dof);
  j["range"] = json::array({f.dn_min, f.dn_max});
  json cov = json::array();
  for (Eigen::Index r = 0; r < f.covariance.rows(); ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < f.covariance.cols(); ++c) row.push_back(number_or_null(f.covariance(r, c)));
    cov.push_back(row);
  }
  j["covariance"] = cov;
  j["notes"] = f.notes;
  return j;
}

// {key: value ± error} of one law; `where` (e.g. "fit.json: normal") names it in messages.
std::map<std::string, table::Estimate> estimates(const nlohmann::json& j, const std::string& where, bool normal) {
  std::vector<std::string> keys;
  for (const Coefficient& c : coefficients(normal)) keys.push_back(c.key);
  if (!j.is_object()) throw InputError(fmt::format("{}: expected an object with {}", where, fmt::join(keys, ", ")));
  std::map<std::string, table::Estimate> out;
  for (const std::string& key : keys) {
    const auto v = j.find(key);
    if (v == j.end() || !v->is_number())
      throw InputError(fmt::format("{}.{}: {}; allowed: a number", where, key, v == j.end() ? "missing" : "not a number"));
    table::Estimate e{v->get<double>(), kNaN};
    const auto err = j.find(key + kError);
    if (err != j.end() && err->is_number()) e.error = err->get<double>();
    else if (err != j.end() && !err->is_null())
      throw InputError(fmt::format("{}.{}{}: not a number; allowed: a number or null", where, key, kError));
    out[key] = e;
  }
  return out;
}

json judged_json(const fit::Judgement& j) {
  return {{"chi2_per_dof", number_or_null(j.chi2_per_dof)},
          {"points", j.points},
          {"signed_points", j.signed_points},
          {"runs", j.runs},
          {"runs_z", number_or_null(j.runs_z)}};
}

json jackknife_json(const fit::Jackknife& k) {
  json cov = json::array();
  for (int r = 0; r < 3; ++r) {
    json row = json::array();
    for (int c = 0; c < 3; ++c) row.push_back(number_or_null(k.covariance(r, c)));
    cov.push_back(row);
  }
  return {{"done", k.done},        {"reason", k.reason},          {"samples", k.samples},
          {"a_error", number_or_null(k.a)}, {"b_error", number_or_null(k.b)}, {"c_error", number_or_null(k.c)},
          {"delta_error", number_or_null(k.delta)}, {"covariance", cov}};
}

json options_json(const fit::FitOptions& o) {
  return {{"form", o.form == fit::FitOptions::Form::clamped ? "clamped" : "loaded"},
          {"weighting", fit::weighting_name(o.weighting)},
          {"onset_force", o.onset_force},
          {"sigma_floor", o.sigma_floor},
          {"delta_n_max", number_or_null(o.delta_n_max)}};
}

double number_at(const nlohmann::json& j, const char* key, const std::string& where) {
  const auto v = j.find(key);
  if (v == j.end()) throw InputError(fmt::format("{}.{}: missing", where, key));
  if (v->is_null()) return kNaN;
  if (!v->is_number()) throw InputError(fmt::format("{}.{}: not a number; allowed: a number or null", where, key));
  return v->get<double>();
}

fit::Judgement read_judged(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(fmt::format("{}: expected an object", where));
  fit::Judgement out;
  out.chi2_per_dof = number_at(j, "chi2_per_dof", where);
  out.runs_z = number_at(j, "runs_z", where);
  out.points = static_cast<std::size_t>(number_at(j, "points", where));
  out.runs = static_cast<std::size_t>(number_at(j, "runs", where));
  out.signed_points = static_cast<std::size_t>(number_at(j, "signed_points", where));
  return out;
}

fit::Jackknife read_jackknife(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(fmt::format("{}: expected an object", where));
  fit::Jackknife out;
  out.done = j.value("done", false);
  out.reason = j.value("reason", "");
  out.samples = static_cast<std::size_t>(number_at(j, "samples", where));
  out.a = number_at(j, "a_error", where), out.b = number_at(j, "b_error", where);
  out.c = number_at(j, "c_error", where), out.delta = number_at(j, "delta_error", where);
  const auto cov = j.find("covariance");
  if (cov == j.end() || !cov->is_array() || cov->size() != 3)
    throw InputError(fmt::format("{}.covariance: expected 3 rows of 3", where));
  for (int r = 0; r < 3; ++r) {
    const auto& row = (*cov)[static_cast<std::size_t>(r)];
    if (!row.is_array() || row.size() != 3) throw InputError(fmt::format("{}.covariance: expected 3 rows of 3", where));
    for (int c = 0; c < 3; ++c) {
      const auto& v = row[static_cast<std::size_t>(c)];
      out.covariance(r, c) = v.is_number() ? v.get<double>() : kNaN;
    }
  }
  return out;
}

// The coefficients of a law as a PowerLawFit (no notes, no covariance), for the candidates.
fit::PowerLawFit read_law(const nlohmann::json& j, const std::string& where, bool normal) {
  const auto e = estimates(j, where, normal);
  fit::PowerLawFit f;
  f.a = e.at("a").value, f.a_error = e.at("a").error;
  f.b = e.at("b").value, f.b_error = e.at("b").error;
  f.c = e.at("c").value, f.c_error = e.at("c").error;
  if (normal) f.delta = e.at("delta").value, f.delta_error = e.at("delta").error;
  else f.delta = number_at(j, "delta_used", where);
  f.chi2_per_dof = number_at(j, "chi2_per_dof", where);
  return f;
}

}  // namespace

std::string fit_file_text(const FitFile& f) {
  json out;
  out[kSceneKey] = f.scene;
  out[kNormal] = law(f.normal, true);
  out[kTangential] = f.tangential ? law(*f.tangential, false) : json(nullptr);
  if (!f.tangential) out["tangential_reason"] = f.tangential_reason;
  if (f.options) {
    const fit::FitOptions& o = *f.options;
    out["options"] = options_json(o);
  }
  if (f.judged) out["judged"] = judged_json(*f.judged);
  if (f.jackknife) out["jackknife"] = jackknife_json(*f.jackknife);
  if (!f.candidates.empty()) {
    json list = json::array();
    for (const fit::CandidateFit& c : f.candidates) {
      json j;
      j["name"] = c.name;
      j["options"] = options_json(c.options);
      j[kNormal] = c.normal ? law(*c.normal, true) : json(nullptr);
      j[kTangential] = c.tangential ? law(*c.tangential, false) : json(nullptr);
      if (!c.reason.empty()) j["reason"] = c.reason;
      if (!c.tangential_reason.empty()) j["tangential_reason"] = c.tangential_reason;
      j["judged"] = judged_json(c.judged);
      j["jackknife"] = jackknife_json(c.jackknife);
      j["stable"] = c.stable;
      j["adequate"] = c.adequate;
      list.push_back(j);
    }
    out["candidates"] = list;
  }
  if (!f.weightings.empty()) {
    json alt;
    for (const FitFile::Alternative& w : f.weightings) {
      json j;
      j[kNormal] = w.normal ? law(*w.normal, true) : json(nullptr);
      j[kTangential] = w.tangential ? law(*w.tangential, false) : json(nullptr);
      if (!w.reason.empty()) j["reason"] = w.reason;
      alt[w.weighting] = j;
    }
    out["weightings"] = alt;
  }
  out["errors"] =
      "standard errors from s^2 (J^T W J)^-1 with s^2 = chi2/(n - p) (chi2_per_dof; W = 1/stderr^2 when weighted, else 1); "
      "delta_error by first-order propagation with the full covariance of (a, b, c); tangential c = -a delta^b with delta "
      "treated as exact";
  out["models"] = {{"normal", "Fn = a dn^b + c for dn >= delta, 0 below (Eq. 7); delta = (-c/a)^(1/b)"},
                   {"tangential", "kt = a dn^b + c for dn >= delta, 0 below (Eq. 8); c = -a delta^b, delta from the normal fit"}};
  out[kProvenance] = {{"program", "softpack-fit"},
                      {kCodeVersionKey, f.code_version},
                      {"inputs", json::array({{{"path", f.input.path},
                                               {"scene", f.scene},
                                               {"profile", f.input.profile},
                                               {"code_version", f.input.code_version},
                                               {"seeds", f.input.seeds}}})},
                      {"seconds", f.seconds},
                      {"cpu_seconds", f.cpu_seconds},
                      {kStampKey, f.stamp}};
  return out.dump(2) + "\n";
}

void write_fit_file(const std::string& path, const FitFile& f) { write_file_atomically(path, fit_file_text(f)); }

void write_fit_gnuplot_file(const std::string& path, const FitFile& f) {
  // Suffix of the figure scripts' variables: soft-solid -> _solid, soft-soft -> _soft.
  const std::string sfx = f.scene == "soft-solid" ? "solid" : "soft";
  const bool has_kt = f.tangential.has_value();
  const PowerLawFit kt = f.tangential.value_or(PowerLawFit{});
  const auto num = [](bool known, double x) { return known && std::isfinite(x) ? fmt::format("{}", x) : "NaN"; };
  std::string gp = fmt::format("# softpack-fit {} of {} ({}): Eq. 7 and Eq. 8 coefficients for gnuplot\n", f.code_version,
                               f.input.path, f.scene);
  gp += fmt::format("a_{0}={1}; b_{0}={2}; c_{0}={3}; delta_{0}={4}\n", sfx, num(true, f.normal.a), num(true, f.normal.b),
                    num(true, f.normal.c), num(true, f.normal.delta));
  gp += fmt::format("kt_a_{0}={1}; kt_b_{0}={2}; kt_c_{0}={3}; kt_delta_{0}={4}\n", sfx, num(has_kt, kt.a), num(has_kt, kt.b),
                    num(has_kt, kt.c), num(has_kt, kt.delta));
  write_file_atomically(path, gp);
}

FitEstimates read_fit_file(const std::string& path) {
  const nlohmann::json j = read_json_input(path, "a fit file (JSON)");
  if (!j.is_object()) throw InputError(fmt::format("{}: expected a JSON object (a softpack-fit file)", path));
  FitEstimates out;
  const auto scene = j.find(kSceneKey);
  if (scene == j.end() || !scene->is_string()) throw InputError(fmt::format("{}: {}: missing or not a string", path, kSceneKey));
  out.scene = scene->get<std::string>();
  if (!j.contains(kNormal)) throw InputError(fmt::format("{}: {}: missing (the Eq. 7 fit of softpack-fit)", path, kNormal));
  out.normal = estimates(j.at(kNormal), fmt::format("{}: {}", path, kNormal), true);
  const auto tan = j.find(kTangential);
  if (tan != j.end() && !tan->is_null()) out.tangential = estimates(*tan, fmt::format("{}: {}", path, kTangential), false);
  const auto prov = j.find(kProvenance);
  if (prov != j.end() && prov->is_object() && prov->contains(kCodeVersionKey) && prov->at(kCodeVersionKey).is_string())
    out.code_version = prov->at(kCodeVersionKey).get<std::string>();
  if (prov != j.end() && prov->is_object() && prov->contains(kStampKey)) {
    if (!prov->at(kStampKey).is_string()) throw InputError(fmt::format("{}: {}.{}: expected a string", path, kProvenance, kStampKey));
    out.stamp = prov->at(kStampKey).get<std::string>();
  }
  if (prov != j.end() && prov->is_object() && prov->contains("seconds") && prov->contains("cpu_seconds") &&
      prov->at("seconds").is_number() && prov->at("cpu_seconds").is_number())
    out.time = Elapsed{prov->at("seconds").get<double>(), prov->at("cpu_seconds").get<double>()};
  if (const auto v = j.find("judged"); v != j.end()) out.judged = read_judged(*v, path + ": judged");
  if (const auto v = j.find("jackknife"); v != j.end()) out.jackknife = read_jackknife(*v, path + ": jackknife");
  if (const auto v = j.find("candidates"); v != j.end()) {
    if (!v->is_array()) throw InputError(fmt::format("{}: candidates: expected a list", path));
    for (std::size_t k = 0; k < v->size(); ++k) {
      const auto& c = (*v)[k];
      const std::string where = fmt::format("{}: candidates[{}]", path, k);
      if (!c.is_object() || !c.contains("name") || !c.at("name").is_string())
        throw InputError(fmt::format("{}: expected an object with a name", where));
      fit::CandidateFit out_c;
      out_c.name = c.at("name").get<std::string>();
      if (c.contains(kNormal) && !c.at(kNormal).is_null()) out_c.normal = read_law(c.at(kNormal), where + ".normal", true);
      if (c.contains(kTangential) && !c.at(kTangential).is_null())
        out_c.tangential = read_law(c.at(kTangential), where + ".tangential", false);
      out_c.reason = c.value("reason", "");
      out_c.tangential_reason = c.value("tangential_reason", "");
      if (c.contains("judged")) out_c.judged = read_judged(c.at("judged"), where + ".judged");
      if (c.contains("jackknife")) out_c.jackknife = read_jackknife(c.at("jackknife"), where + ".jackknife");
      out_c.stable = c.value("stable", false);
      out_c.adequate = c.value("adequate", false);
      out.candidates.push_back(std::move(out_c));
    }
  }
  return out;
}

}  // namespace softpack
