#include "formats/verdict_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace softpack {
namespace {

using vjson = nlohmann::ordered_json;
vjson vnum(double x) { return std::isfinite(x) ? vjson(x) : vjson(nullptr); }

std::string vg(double x, const char* f = "{:.4g}") { return std::isfinite(x) ? fmt::format(fmt::runtime(f), x) : "—"; }

std::string vlabel(const std::string& key) { return key == "delta" ? "δ" : key; }

// A deviation in whole percent, "+12", "-51", "0" (never "-0").
std::string vpercent(double x) { return std::abs(100.0 * x) < 0.5 ? std::string("0") : fmt::format("{:+.0f}", 100.0 * x); }

}  // namespace

std::string verdict_json_text(const VerdictInputs& v) {
  vjson out;
  out["criteria"] = v.criteria_path;
  vjson pf;
  for (const FitEstimates& f : v.fits) {
    vjson s;
    if (f.judged)
      s["judged"] = {{"chi2_per_dof", vnum(f.judged->chi2_per_dof)},
                     {"runs_z", vnum(f.judged->runs_z)},
                     {"adequate", f.judged->chi2_per_dof <= v.fit_criteria.chi2_per_dof_max &&
                                      std::abs(f.judged->runs_z) <= v.fit_criteria.runs_z_max}};
    if (f.jackknife)
      s["jackknife"] = {{"a_error", vnum(f.jackknife->a)}, {"b_error", vnum(f.jackknife->b)},
                        {"c_error", vnum(f.jackknife->c)}, {"delta_error", vnum(f.jackknife->delta)}};
    pf[f.scene] = s;
  }
  out["profile_fit"] = pf;
  vjson cands;
  for (std::size_t k = 0; k < v.fit_criteria.candidates.size(); ++k) {
    vjson c;
    for (const FitEstimates& f : v.fits) {
      const fit::CandidateFit& x = f.candidates.at(k);
      vjson s;
      if (x.normal) {
        s["a"] = vnum(x.normal->a), s["b"] = vnum(x.normal->b), s["c"] = vnum(x.normal->c), s["delta"] = vnum(x.normal->delta);
      }
      s["chi2_per_dof"] = vnum(x.judged.chi2_per_dof);
      s["runs_z"] = vnum(x.judged.runs_z);
      s["jackknife_b"] = vnum(x.jackknife.b);
      s["jackknife_delta"] = vnum(x.jackknife.delta);
      s["stable"] = x.stable;
      s["adequate"] = x.adequate;
      if (!x.reason.empty()) s["reason"] = x.reason;
      c[f.scene] = s;
    }
    cands[v.fit_criteria.candidates[k].name] = c;
  }
  const bool chosen = v.selection.chosen < v.fit_criteria.candidates.size();
  out["selection"] = {{"chosen", chosen ? v.fit_criteria.candidates[v.selection.chosen].name : std::string("none")},
                      {"why", v.selection.why},
                      {"any_stable", v.selection.any_stable},
                      {"profile_fit_is_chosen", v.profile_fit_is_chosen},
                      {"candidates", cands}};
  vjson q;
  for (const auto& [scene, values] : v.verdict.unit.q) {
    vjson a = vjson::array();
    for (double x : values) a.push_back(vnum(x));
    q[scene] = a;
  }
  out["unit"] = {{"readings", v.verdict.unit.readings},
                 {"q", q},
                 {"selected", v.verdict.unit.selected},
                 {"test_q", vnum(v.verdict.unit.test_q)},
                 {"passed", v.verdict.unit.passed}};
  vjson lines = vjson::array();
  for (const verdict::Line& l : v.verdict.lines)
    lines.push_back({{"table", l.table}, {"scene", l.scene}, {"key", l.key}, {"ours", vnum(l.ours)}, {"error", vnum(l.error)},
                     {"paper", vnum(l.paper)}, {"deviation", vnum(l.deviation)}, {"tolerance", l.tolerance}, {"status", l.status}});
  out["lines"] = lines;
  vjson curves = vjson::array();
  for (const verdict::Curve& c : v.verdict.curves)
    curves.push_back({{"scene", c.scene}, {"points", c.points}, {"within_two", c.within_two},
                      {"median_abs_z", vnum(c.median_abs_z)}, {"ratio_min", vnum(c.ratio_min)}, {"ratio_max", vnum(c.ratio_max)},
                      {"joint_chi2", vnum(c.joint_chi2)}, {"joint_p", vnum(c.joint_p)},
                      {"jointly_consistent", c.jointly_consistent}, {"force_below_delta", c.force_below_delta}});
  out["curves"] = curves;
  out["reproduced"] = v.verdict.reproduced;
  out["judged"] = v.verdict.judged;
  out["provenance"] = v.provenance;
  return out.dump(2) + "\n";
}

std::string verdict_markdown(const VerdictInputs& v) {
  std::string md = "# The verdict against the paper\n\nBy the preregistered rules of " + v.criteria_path +
                   " (paper/preregistration.md).\n\n## The fit\n\n| candidate | scene | a [N] | b | δ | χ²/dof (every point) | "
                   "runs z | jackknife b | jackknife δ | stable | adequate |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < v.fit_criteria.candidates.size(); ++k)
    for (const FitEstimates& f : v.fits) {
      const fit::CandidateFit& x = f.candidates.at(k);
      md += fmt::format("| {}{} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", x.name,
                        k == v.selection.chosen ? " (**chosen**)" : "", f.scene, x.normal ? vg(x.normal->a) : "—",
                        x.normal ? vg(x.normal->b) : "—", x.normal ? vg(x.normal->delta) : "—", vg(x.judged.chi2_per_dof, "{:.3g}"),
                        vg(x.judged.runs_z, "{:.2f}"), vg(x.jackknife.b, "{:.2g}"), vg(x.jackknife.delta, "{:.2g}"),
                        x.stable ? "yes" : "no", x.adequate ? "yes" : "no");
    }
  md += fmt::format("\nChosen: {}.{}\n", v.selection.why,
                    v.profile_fit_is_chosen ? " It is the profile's fit."
                                            : " **The profile's fit is not the chosen candidate** (on the select seeds the "
                                              "rule decides the profile; on others it is reported).");
  md += "\n## Table 2's unit\n\n| reading |";
  for (const auto& [scene, q] : v.verdict.unit.q) md += fmt::format(" q {} |", scene);
  md += "\n|---|";
  for (std::size_t i = 0; i < v.verdict.unit.q.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t r = 0; r < v.verdict.unit.readings.size(); ++r) {
    md += fmt::format("| N/{} |", v.verdict.unit.readings[r]);
    for (const auto& [scene, q] : v.verdict.unit.q) md += fmt::format(" {} |", vg(q[r], "{:.3g}"));
    md += "\n";
  }
  md += fmt::format("\nSelected: {}; tested: q = {} ({}).\n",
                    v.verdict.unit.selected.empty() ? "none" : "N/" + v.verdict.unit.selected, vg(v.verdict.unit.test_q, "{:.3g}"),
                    v.verdict.unit.passed ? "passed: Table 2's a is judged in it" : "failed: Table 2's a is unit undetermined");
  md += "\n## The coefficients\n\n| table | scene | | ours | paper | deviation | tolerance | status |\n|---|---|---|---|---|---|---|---|\n";
  for (const verdict::Line& l : v.verdict.lines)
    md += fmt::format("| {} | {} | {} | {} ± {} | {} | {} | {} | {} |\n", l.table, l.scene, vlabel(l.key), vg(l.ours), vg(l.error, "{:.2g}"),
                      vg(l.paper), std::isfinite(l.deviation) ? fmt::format("{} %", vpercent(l.deviation)) : "—", l.tolerance,
                      l.status);
  md += fmt::format("\n{} of {} judged coefficients reproduced.\n\n## The curves\n\n| scene | points | within 2σ | median |z| | "
                    "ours/paper | joint χ² (3 dof) | p |\n|---|---|---|---|---|---|---|\n",
                    v.verdict.reproduced, v.verdict.judged);
  for (const verdict::Curve& c : v.verdict.curves)
    md += fmt::format("| {} | {} | {} | {} | {}–{} | {} | {} |\n", c.scene, c.points, c.within_two, vg(c.median_abs_z, "{:.3g}"),
                      vg(c.ratio_min, "{:.3g}"), vg(c.ratio_max, "{:.3g}"), vg(c.joint_chi2, "{:.3g}"), vg(c.joint_p, "{:.2g}"));
  md += "\n<!-- " + v.provenance + " -->\n";
  return md;
}

std::string verdict_latex(const VerdictInputs& v) {
  std::string t = fmt::format("% {}\n", v.provenance) + "\\begin{tabular}{lllrrrll}\n\\toprule\n & & & ours & paper & deviation & tolerance & \\\\\n\\midrule\n";
  std::string previous;
  for (const verdict::Line& l : v.verdict.lines) {
    const std::string head = fmt::format("Table {}, {}", l.table == "table1" ? 1 : 2, l.scene);
    const std::string key = l.key == "delta" ? std::string("$\\delta$") : fmt::format("${}$", l.key);
    const std::string tolerance =
        l.tolerance.rfind("±", 0) == 0 ? fmt::format("$\\pm${}", l.tolerance.substr(std::string("±").size())) : l.tolerance;
    t += fmt::format("{} & {} & & ${}$ & {} & {} & {} & {} \\\\\n", head == previous ? "" : head, key,
                     std::isfinite(l.ours) ? fmt::format("{:.4g} \\pm {:.2g}", l.ours, l.error) : "\\text{---}", vg(l.paper),
                     std::isfinite(l.deviation) ? fmt::format("${}\\,\\%$", vpercent(l.deviation)) : "---",
                     tolerance,
                     l.status);
    previous = head;
  }
  t += "\\bottomrule\n\\end{tabular}\n";
  // LaTeX has no %: the tolerances' "%" is escaped.
  std::string out;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '%' && i > 0 && t[i - 1] != '\n' && t[i - 1] != '\\') out += "\\%";
    else out += t[i];
  }
  return out;
}

}  // namespace softpack
