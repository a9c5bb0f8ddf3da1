// What every study report writes the same way: a value with its error as a table cell, and a
// number that may be undefined as JSON.
#pragma once
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace softpack {

/// "value ± error" (4 and 2 significant digits), the value alone when the error is undefined,
/// "–" when the value is.
inline std::string value_cell(double value, double error) {
  if (!std::isfinite(value)) return "–";
  return std::isfinite(error) ? fmt::format("{:.4g} ± {:.2g}", value, error) : fmt::format("{:.4g}", value);
}

/// The number, or null where it is undefined (NaN, infinite).
inline nlohmann::json json_number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace softpack
