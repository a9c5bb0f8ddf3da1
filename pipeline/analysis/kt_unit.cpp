#include "analysis/kt_unit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/power_fit.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace softpack::table {

double metres_per_degree(double Rs) { return std::numbers::pi * Rs / 180.0; }

std::vector<KtReading> kt_readings(double Rs, const std::vector<std::string>& keys) {
  if (!(Rs > 0.0)) throw InputError(fmt::format("Rs = {} m is not allowed; allowed: Rs > 0", Rs));
  const std::vector<KtReading> all{{"m", "per metre of ht", "N/m", 1.0},
                                   {"mm", "per millimetre of ht", "N/mm", 1e-3},
                                   {"deg", "per degree of alpha", "N/deg", metres_per_degree(Rs)},
                                   {"rad", "per radian of alpha (= per unit of ht/Rs)", "N/rad", Rs}};
  if (keys.empty()) return all;
  std::vector<KtReading> out;
  for (const std::string& k : keys) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const KtReading& r) { return r.key == k; });
    if (it == all.end()) throw InputError(fmt::format("reading '{}' is not allowed; allowed: m, mm, deg, rad", k));
    out.push_back(*it);
  }
  return out;
}

double PublishedLaw::operator()(double dn) const {
  fit::PowerLawFit law;
  law.a = a, law.b = b, law.c = c, law.delta = delta;
  return fit::evaluate(law, dn);
}

KtUnitScene kt_unit_scene(const std::string& scene, const std::vector<double>& delta_n, const std::vector<double>& Fn,
                          const std::vector<double>& Fn_error, const std::vector<double>& kt_delta_n,
                          const std::vector<double>& kt, const std::vector<double>& kt_error, const PublishedLaw& normal,
                          const PublishedLaw& tangential, const std::vector<KtReading>& readings, double established_sigmas) {
  if (delta_n.size() != Fn.size() || Fn.size() != Fn_error.size() || kt_delta_n.size() != kt.size() ||
      kt.size() != kt_error.size())
    throw InputError(fmt::format("{}: the columns of the averages have different lengths", scene));
  KtUnitScene out;
  out.scene = scene;
  for (std::size_t j = 0; j < kt_delta_n.size(); ++j) {
    const double dn = kt_delta_n[j];
    std::size_t i = 0;
    while (i < delta_n.size() && std::abs(delta_n[i] - dn) > 1e-9) ++i;
    if (i == delta_n.size()) continue;  // no Fn at this Δn
    const double paper_Fn = normal(dn), paper_kt = tangential(dn);
    if (!(Fn[i] > 0.0) || !(kt[j] > 0.0) || !(paper_Fn > 0.0) || !(paper_kt > 0.0)) continue;
    KtUnitPoint p;
    p.delta_n = dn;
    p.ours = kt[j] / Fn[i];
    p.ours_error = p.ours * std::hypot(kt_error[j] / kt[j], Fn_error[i] / Fn[i]);
    p.paper = paper_kt / paper_Fn;
    p.established = Fn[i] > established_sigmas * Fn_error[i] && kt[j] > established_sigmas * kt_error[j];
    for (const KtReading& r : readings) p.q.push_back(p.ours * r.metres / p.paper);
    out.points.push_back(p);
  }
  for (std::size_t k = 0; k < readings.size(); ++k) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const KtUnitPoint& p : out.points)
      if (p.established) sum += std::log(p.q[k]), ++n;
    out.mean_log_q.push_back(n == 0 ? kNaN : sum / static_cast<double>(n));
  }
  return out;
}

std::string kt_unit_markdown(const std::vector<KtUnitScene>& scenes, const std::vector<KtReading>& readings) {
  std::string md =
      "# The unit of Table 2\n\nq = (kt/Fn ours, kt converted to the reading's unit) / (kt/Fn of the paper's fits), at the "
      "same Δn: 1 for the reading in which the paper's kt was printed, if the two soft-particles respond alike in shape "
      "(paper/paper.tex, \"The unit of Table 2\"). ours: kt/Fn of the seed averages [1/m of ht] ± standard error; paper: "
      "kt/Fn of Eqs. 7 and 8 with the published coefficients [paper's unit / N]. Not established: our Fn or kt within "
      "experiments/criteria.yaml's table2_unit.established_sigmas standard "
      "errors of zero, left out of the mean.\n\n";
  for (const KtUnitScene& s : scenes) {
    md += fmt::format("## {}\n\n| Δn | ours kt/Fn [1/m] | paper kt/Fn |", s.scene);
    for (const KtReading& r : readings) md += fmt::format(" q, {} |", r.unit);
    md += "\n|---|---|---|";
    for (std::size_t k = 0; k < readings.size(); ++k) md += "---|";
    md += "\n";
    for (const KtUnitPoint& p : s.points) {
      md += fmt::format("| {}{} | {:.4g} ± {:.2g} | {:.4g} |", p.delta_n, p.established ? "" : " (not established)", p.ours,
                        p.ours_error, p.paper);
      for (double q : p.q) md += fmt::format(" {:.3g} |", q);
      md += "\n";
    }
    if (s.points.empty()) md += "| (no Δn where both laws are positive) | | |\n";
    md += "\n";
  }
  md += "## Geometric mean of q over the established points\n\n| reading |";
  for (const KtUnitScene& s : scenes) md += " " + s.scene + " |";
  md += "\n|---|";
  for (std::size_t k = 0; k < scenes.size(); ++k) md += "---|";
  md += "\n";
  std::size_t best = readings.size();
  for (std::size_t k = 0; k < readings.size(); ++k) {
    md += fmt::format("| {} ({}) |", readings[k].name, readings[k].unit);
    for (const KtUnitScene& s : scenes) md += std::isfinite(s.mean_log_q[k]) ? fmt::format(" {:.3g} |", std::exp(s.mean_log_q[k])) : " – |";
    md += "\n";
    if (!scenes.empty() && std::isfinite(scenes.front().mean_log_q[k]) &&
        (best == readings.size() || std::abs(scenes.front().mean_log_q[k]) < std::abs(scenes.front().mean_log_q[best])))
      best = k;
  }
  if (best < readings.size())
    md += fmt::format("\nClosest to 1 on {}: {} ({}).\n", scenes.front().scene, readings[best].name, readings[best].unit);
  return md;
}

}  // namespace softpack::table
