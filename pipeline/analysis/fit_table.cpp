#include "analysis/fit_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "core/types.hpp"

namespace softpack::table {
namespace {

const std::string kDash = "—";

/// The digits of a value (and its error) sharing one decimal position and one power of ten.
struct Parts {
  std::string value, error;  ///< error empty: none
  int exponent = 0;          ///< the numbers are value·10^exponent
};

/// Drops the sign of a number that rounds to zero ("-0.00" → "0.00").
std::string unsign_zero(std::string s) {
  if (!s.empty() && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos) s.erase(0, 1);
  return s;
}

Parts split(const Estimate& e) {
  Parts parts;
  double v = e.value, err = e.error;
  // An error below 1e-6 of the value (exact data) is not worth printing.
  const bool has_error = std::isfinite(err) && err > 0.0 && !(err < 1e-6 * std::abs(v));
  const double ref = has_error ? std::max(std::abs(v), err) : std::abs(v);
  const int lead = ref > 0.0 && std::isfinite(ref) ? static_cast<int>(std::floor(std::log10(ref))) : 0;
  // Plain decimals from 1e-4 to 1e5, a common power of ten outside.
  parts.exponent = (lead >= 5 || lead <= -5) ? lead : 0;
  const double scale = std::pow(10.0, -parts.exponent);
  v *= scale, err *= scale;
  if (!std::isfinite(v)) {
    parts.value = fmt::format("{}", v);
    return parts;
  }
  if (!has_error) {
    parts.value = unsign_zero(fmt::format("{:.5g}", v));
    return parts;
  }
  const int decimals = 1 - static_cast<int>(std::floor(std::log10(err)));  // two significant digits of the error
  if (decimals >= 0) {
    parts.value = unsign_zero(fmt::format("{:.{}f}", v, decimals));
    parts.error = fmt::format("{:.{}f}", err, decimals);
  } else {
    const double q = std::pow(10.0, -decimals);
    parts.value = unsign_zero(fmt::format("{:.0f}", std::round(v / q) * q));
    parts.error = fmt::format("{:.0f}", std::round(err / q) * q);
  }
  return parts;
}

std::string deviation_number(double percent) {
  if (!std::isfinite(percent)) return "";
  const double m = std::abs(percent);
  if (m < 100.0) {
    const std::string s = fmt::format("{:+.1f}", percent);
    return s == "+0.0" || s == "-0.0" ? "0.0" : s;
  }
  if (m < 1e5) return fmt::format("{:+.0f}", percent);
  // Two significant digits and a power of ten, written "+1.1×10^6" (LaTeX: see latex_number).
  const int exponent = static_cast<int>(std::floor(std::log10(m)));
  const std::string mantissa = fmt::format("{:+.1f}", percent / std::pow(10.0, exponent));
  return fmt::format("{}×10^{}", mantissa, exponent);
}

/// A number of deviation_number or format_estimate_markdown in LaTeX math: "×10^6" -> "\times10^{6}".
std::string latex_number(const std::string& s) {
  const std::string marker = "×10^";
  const std::size_t times = s.find(marker);
  if (times == std::string::npos) return s;
  std::string out(s, 0, times);
  out.append("\\times10^{").append(s, times + marker.size(), std::string::npos).append("}");
  return out;
}

std::string published_text(const Column& c, const std::string& key) {
  const auto it = c.published.find(key);
  if (it == c.published.end()) return "";
  const auto text = c.published_text.find(key);
  return text != c.published_text.end() ? text->second : fmt::format("{}", it->second);
}

/// The three cells of one scene in one row, empty strings for "—".
struct Cells {
  std::optional<Estimate> ours;
  std::string published;
  double deviation = kNaN;
};

Cells cells(const Column& c, const std::string& key) {
  Cells out;
  if (c.ours) {
    const auto it = c.ours->find(key);
    if (it != c.ours->end()) out.ours = it->second;
  }
  out.published = published_text(c, key);
  const auto p = c.published.find(key);
  if (out.ours && p != c.published.end()) out.deviation = relative_deviation_percent(out.ours->value, p->second);
  return out;
}

}  // namespace

std::vector<Row> table1_rows() {
  return {{"a", "a [N]", "$a$ [N]"}, {"b", "b", "$b$"}, {"c", "c [N]", "$c$ [N]"}, {"delta", "δ", "$\\delta$"}};
}

std::vector<Row> table2_rows() {
  return {{"a", "a [N/m]", "$a$ [N/m]"}, {"b", "b", "$b$"}, {"c", "c [N/m]", "$c$ [N/m]"}};
}

double relative_deviation_percent(double ours, double published) {
  if (published == 0.0) return kNaN;
  return (ours - published) / std::abs(published) * 100.0;
}

std::string format_estimate_markdown(const Estimate& e) {
  const Parts p = split(e);
  const std::string body = p.error.empty() ? p.value : p.value + " ± " + p.error;
  if (p.exponent == 0) return body;
  return (p.error.empty() ? body : "(" + body + ")") + fmt::format("×10^{}", p.exponent);
}

std::string format_estimate_latex(const Estimate& e) {
  const Parts p = split(e);
  const std::string body = p.error.empty() ? p.value : p.value + " \\pm " + p.error;
  if (p.exponent == 0) return "$" + body + "$";
  return "$" + (p.error.empty() ? body : "(" + body + ")") + fmt::format("\\times10^{{{}}}$", p.exponent);
}

std::string format_deviation_markdown(double percent) {
  const std::string n = deviation_number(percent);
  return n.empty() ? kDash : n + "%";
}

std::string to_markdown(const Table& t) {
  std::ostringstream out;
  out << "| " << t.title << " |";
  for (const Column& c : t.columns) out << " " << c.scene << " ours | " << c.scene << " paper | " << c.scene << " deviation |";
  out << "\n|---|";
  for (std::size_t k = 0; k < t.columns.size(); ++k) out << "---:|---:|---:|";
  out << "\n";
  for (const Row& r : t.rows) {
    out << "| " << r.markdown << " |";
    for (const Column& c : t.columns) {
      const Cells x = cells(c, r.key);
      out << " " << (x.ours ? format_estimate_markdown(*x.ours) : kDash) << " | "
          << (x.published.empty() ? kDash : x.published) << " | " << format_deviation_markdown(x.deviation) << " |";
    }
    out << "\n";
  }
  return out.str();
}

std::string to_latex(const Table& t, const std::string& comment) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "% " << line << "\n";
  const std::size_t n = t.columns.size();
  out << "\\begin{tabular}{l";
  for (std::size_t k = 0; k < n; ++k) out << "rrr";
  out << "}\n\\toprule\n";
  for (const Column& c : t.columns) out << " & \\multicolumn{3}{c}{" << c.scene << "}";
  out << " \\\\\n";
  for (std::size_t k = 0; k < n; ++k) out << (k ? " " : "") << fmt::format("\\cmidrule(lr){{{}-{}}}", 2 + 3 * k, 4 + 3 * k);
  out << "\n";
  for (std::size_t k = 0; k < n; ++k) out << " & ours & paper & dev.";
  out << " \\\\\n\\midrule\n";
  for (const Row& r : t.rows) {
    out << r.latex;
    for (const Column& c : t.columns) {
      const Cells x = cells(c, r.key);
      const std::string dev = deviation_number(x.deviation);
      out << " & " << (x.ours ? format_estimate_latex(*x.ours) : "---") << " & ";
      if (x.published.empty()) out << "---";
      else out << "$" << x.published << "$";
      out << " & ";
      if (dev.empty()) out << "---";
      else out << "$" << latex_number(dev) << "$\\,\\%";
    }
    out << " \\\\\n";
  }
  out << "\\bottomrule\n\\end{tabular}\n";
  return out.str();
}

}  // namespace softpack::table
