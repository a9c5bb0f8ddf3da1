// Tables 1 and 2 of the paper with our fitted coefficients beside the published ones:
// per scene, "ours" (value ± standard error, rounded to the error's two significant digits),
// "paper" (as published) and the relative deviation (ours − paper)/|paper| in %. Written as
// Markdown and as a LaTeX booktabs `tabular` fragment. A missing fit (e.g. no tangential fit)
// gives "—" cells.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace softpack::table {

/// A fitted value and its standard error (NaN: unknown, printed without "±").
struct Estimate {
  double value = 0.0;
  double error = 0.0;
};

struct Row {
  std::string key;        ///< "a", "b", "c", "delta"
  std::string markdown;   ///< label, e.g. "a [N]"
  std::string latex;      ///< label, e.g. "$a$ [N]"
};

struct Column {
  std::string scene;
  std::optional<std::map<std::string, Estimate>> ours;  ///< nullopt: no fit ("—")
  std::map<std::string, double> published;              ///< a missing key: "—"
  std::map<std::string, std::string> published_text{};  ///< as written in the source (else "{}" of the value)
};

struct Table {
  std::string title;  ///< first header cell, e.g. "Table 1 (normal, Eq. 7)"
  std::vector<Row> rows;
  std::vector<Column> columns;
};

/// Rows of Table 1 (a [N], b, c [N], δ) and Table 2 (a [N/m], b, c [N/m]).
std::vector<Row> table1_rows();
std::vector<Row> table2_rows();

/// (ours − published)/|published| · 100; NaN when published is 0.
double relative_deviation_percent(double ours, double published);

/// "73.7 ± 1.2", "-0.0350 ± 0.0012", "(3.40 ± 0.21)e5" style (Markdown: "×10^5"; LaTeX math).
/// The error is rounded to 2 significant digits and the value to the same decimal; an error
/// of 0, NaN or below 1e-6 of the value prints the value to 5 significant digits without "±".
std::string format_estimate_markdown(const Estimate& e);
std::string format_estimate_latex(const Estimate& e);
/// "+12.3%", "-31%", "+4.5e+05%"; "—" when undefined.
std::string format_deviation_markdown(double percent);

std::string to_markdown(const Table& t);
/// A booktabs tabular, preceded by "% <comment>" lines (one per line of `comment`).
std::string to_latex(const Table& t, const std::string& comment);

}  // namespace softpack::table
