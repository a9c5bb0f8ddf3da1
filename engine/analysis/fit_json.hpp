// The fit file (softpack-fit → softpack-table), header-only so that the engine library needs
// no JSON: include it from targets that link nlohmann_json::nlohmann_json.
//
//   {"scene": "soft-solid",
//    "normal": {"a", "a_error", "b", "b_error", "c", "c_error", "delta", "delta_error",
//               "points", "weighted", "chi2_per_dof", "range": [dn_min, dn_max],
//               "covariance": [[…]], "notes": […]},
//    "tangential": {the same without delta/delta_error, plus "delta_used"} or null,
//    "tangential_reason": "…" (only when "tangential" is null),
//    "errors": "…", "provenance": {…}}
//
// Undefined errors (NaN, e.g. δ's when c >= 0) are written as null.
#pragma once
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/fit_table.hpp"
#include "analysis/power_fit.hpp"
#include "core/error.hpp"

namespace softpack::fit {

inline nlohmann::ordered_json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

/// `normal`: Eq. 7 (with delta, delta_error); otherwise Eq. 8 (with delta_used).
inline nlohmann::ordered_json to_json(const PowerLawFit& f, bool normal) {
  nlohmann::ordered_json j;
  j["a"] = number_or_null(f.a);
  j["a_error"] = number_or_null(f.a_error);
  j["b"] = number_or_null(f.b);
  j["b_error"] = number_or_null(f.b_error);
  j["c"] = number_or_null(f.c);
  j["c_error"] = number_or_null(f.c_error);
  if (normal) {
    j["delta"] = number_or_null(f.delta);
    j["delta_error"] = number_or_null(f.delta_error);
  } else {
    j["delta_used"] = number_or_null(f.delta);
  }
  j["points"] = f.points;
  j["weighted"] = f.weighted;
  j["chi2_per_dof"] = number_or_null(f.chi2_per_dof);
  j["range"] = nlohmann::ordered_json::array({f.dn_min, f.dn_max});
  nlohmann::ordered_json cov = nlohmann::ordered_json::array();
  for (Eigen::Index r = 0; r < f.covariance.rows(); ++r) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index c = 0; c < f.covariance.cols(); ++c) row.push_back(number_or_null(f.covariance(r, c)));
    cov.push_back(row);
  }
  j["covariance"] = cov;
  j["notes"] = f.notes;
  return j;
}

/// {key: value ± error} of one law of a fit file; `where` (e.g. "fit.json: normal") names the
/// object in messages. A missing or non-numeric value throws InputError; a null error is NaN.
inline std::map<std::string, table::Estimate> estimates_from_json(const nlohmann::json& law, const std::string& where,
                                                                  const std::vector<std::string>& keys) {
  if (!law.is_object()) throw InputError(fmt::format("{}: expected an object with {}", where, fmt::join(keys, ", ")));
  std::map<std::string, table::Estimate> out;
  for (const std::string& key : keys) {
    const auto v = law.find(key);
    if (v == law.end() || !v->is_number())
      throw InputError(fmt::format("{}.{}: {}; allowed: a number", where, key, v == law.end() ? "missing" : "not a number"));
    table::Estimate e{v->get<double>(), std::numeric_limits<double>::quiet_NaN()};
    const auto err = law.find(key + "_error");
    if (err != law.end() && err->is_number()) e.error = err->get<double>();
    else if (err != law.end() && !err->is_null())
      throw InputError(fmt::format("{}.{}_error: not a number; allowed: a number or null", where, key));
    out[key] = e;
  }
  return out;
}

}  // namespace softpack::fit
