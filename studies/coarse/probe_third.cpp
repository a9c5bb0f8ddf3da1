#include "coarse/probe_third.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

constexpr double kBetaMax = 3.0, kExponentMax = 4.0;  // the fits' ranges (the plan: β in [0, 3])

std::vector<std::string> with_kind(const std::vector<std::string>& names, const std::string& kind) {
  std::vector<std::string> out;
  for (const std::string& a : names) out.push_back(a + ":" + kind);
  return out;
}
template <class T>
std::vector<T> joined(std::vector<T> a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
std::vector<ProbeWallForce> without_seed(const std::vector<ProbeWallForce>& v, std::uint64_t seed) {
  std::vector<ProbeWallForce> out;
  for (const ProbeWallForce& w : v)
    if (w.seed != seed) out.push_back(w);
  return out;
}

// The grain kinds' arrangements: the single contacts and those of two or more.
struct GrainRuns {
  std::vector<std::string> ones, several;
};
GrainRuns grain_runs(const ManyBodyProbe& plan, const std::vector<std::string>& kinds) {
  GrainRuns r;
  for (const std::string& kind : kinds)
    for (const std::string& a : plan.bodies(kind)) (a.rfind("one:", 0) == 0 ? r.ones : r.several).push_back(a);
  return r;
}

// p, then β of the grains (the chosen count form), on `points` (walls and bodies).
std::pair<double, double> fit_grains(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& points, const std::string& form,
                                     const GrainRuns& fit) {
  const auto F1 = fit_single_contact(plan, points);
  const double p = fit_parameter(ProbeLaw{"pairwise", 0.0, F1}, kExponentMax, points, fit.ones, plan, &ProbeLaw::grain_exponent);
  ProbeLaw law{form, 0.0, F1, p};
  return {p, fit_parameter(law, kBetaMax, points, fit.several, plan)};
}

}  // namespace

ThirdVersion analyse_third_version(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& bodies,
                                   const SecondPart& second, double beta_before) {
  if (!plan.third) throw InputError("the plan has no third_version: nothing to analyse");
  const ManyBodyProbe::ThirdVersionPlan& t = *plan.third;
  ThirdVersion out;
  const std::vector<ProbeWallForce> all = joined(walls, bodies);
  const auto F1 = fit_single_contact(plan, walls);

  // 1. The count of contacts: each form's β on the fit runs, the rule on the held-out ones.
  const std::vector<std::string> fit = joined(plan.fit, with_kind(t.count_fit, "wall")),
                                  held = joined(plan.held_out, with_kind(t.count_held_out, "wall"));
  for (const std::string& form : t.count_forms) {
    ThirdVersion::CountForm c{form, {}, {}, {}, {}};
    ProbeLaw law{form, 0.0, F1};
    law.parameter = c.beta.value = fit_parameter(law, kBetaMax, all, fit, plan);
    c.beta.se = jackknife_parameter(form, kBetaMax, all, fit, plan);
    if (c.beta.value > 0.999 * kBetaMax) out.notes.push_back(fmt::format("{}: β at the end of its range [0, {}]", form, kBetaMax));
    c.fit = probe_error(law, all, fit, plan), c.held_out = probe_error(law, all, held, plan);
    for (const std::string& a : joined(fit, held)) c.by_arrangement[a] = probe_error(law, all, {a}, plan);
    out.count.push_back(c);
  }
  const ThirdVersion::CountForm* chosen = &out.count.front();  // the least held-out error (the forms have one parameter each)
  for (const ThirdVersion::CountForm& c : out.count)
    if (c.held_out.rms_log < chosen->held_out.rms_log) chosen = &c;
  out.count_chosen = chosen->name;
  const ProbeLaw walls_law{chosen->name, chosen->beta.value, F1};

  // 2. Grains: p on the fit kinds' single contacts, then their β; the held-out kinds predicted.
  const GrainRuns grain_fit = grain_runs(plan, t.grain_fit), grain_held = grain_runs(plan, t.grain_held_out);
  std::tie(out.grain_p.value, out.grain_beta.value) = fit_grains(plan, all, out.count_chosen, grain_fit);
  std::vector<double> p_j, beta_j;
  for (const std::uint64_t seed : plan.seeds) {
    const auto [p, beta] = fit_grains(plan, without_seed(all, seed), out.count_chosen, grain_fit);
    p_j.push_back(p), beta_j.push_back(beta);
  }
  out.grain_p.se = jackknife_error(p_j), out.grain_beta.se = jackknife_error(beta_j);
  const ProbeLaw grain_law{out.count_chosen, out.grain_beta.value, F1, out.grain_p.value}, before{"volumetric", beta_before, F1};
  for (const std::string& a : joined(joined(grain_fit.ones, grain_fit.several), joined(grain_held.ones, grain_held.several)))
    out.grain[a] = probe_error(grain_law, all, {a}, plan), out.grain_before[a] = probe_error(before, all, {a}, plan);
  out.grain_fit = probe_error(grain_law, all, joined(grain_fit.ones, grain_fit.several), plan);
  out.grain_held_out = probe_error(grain_law, all, joined(grain_held.ones, grain_held.several), plan);

  // 3. Soft-particles: the engine's mean rule counts half the centre's others, so β_ss is twice
  // the β fitted on the centre's.
  std::vector<std::string> soft;
  for (const std::string& a : plan.bodies("soft"))
    if (a != "one:soft") soft.push_back(a);
  try {
    const auto F1_soft = fit_single_contact(plan, bodies, "one:soft");
    ProbeLaw law{out.count_chosen, 0.0, F1_soft};
    law.parameter = fit_parameter(law, kBetaMax, bodies, soft, plan);
    out.soft_beta = {2.0 * law.parameter, 2.0 * jackknife_parameter(out.count_chosen, kBetaMax, bodies, soft, plan, "one:soft")};
    for (const std::string& a : soft) out.soft[a] = probe_error(law, bodies, {a}, plan);
    out.soft_fit = probe_error(law, bodies, soft, plan);
  } catch (const InputError& e) {
    out.notes.push_back(fmt::format("soft: no β_ss: {}", e.what()));
  }

  // 4. The tangential gain: kt / kt_one against the walls' law's Fn / F1 at the first wall.
  double sum = 0.0, sum2 = 0.0;
  for (const auto& [radius, by_arrangement] : second.shear)
    for (const auto& [name, by_dn] : by_arrangement) {
      if (name == "one") continue;
      const ProbeArrangement a = builtin_arrangement(name, plan.seeds.front());
      for (const auto& [dn, s] : by_dn) {
        std::vector<double> delta_n;
        for (const ProbeWall& w : a.walls) delta_n.push_back(w.w * dn);
        const double F1_dn = fit::evaluate(F1.at(radius), dn);
        if (s.kt.seeds == 0 || !(F1_dn > 0.0)) continue;
        const double gain = walls_law.predict(probe_point(a, radius, 0, delta_n, 0, 0.0)) / F1_dn, r = std::log(gain) - s.kt.mean;
        out.gain.push_back({radius, name, dn, s.kt, gain});
        sum += r, sum2 += r * r, ++out.gain_error.points;
      }
    }
  if (out.gain_error.points > 0) {
    const double n = static_cast<double>(out.gain_error.points);
    out.gain_error.mean_log = sum / n, out.gain_error.rms_log = std::sqrt(sum2 / n);
  }
  return out;
}

namespace {

std::string fitted_text(const FittedValue& v) { return fmt::format("{:.3f} ± {:.3f}", v.value, v.se); }
nlohmann::json fitted_json(const FittedValue& v) { return {{"value", v.value}, {"se", v.se}}; }

}  // namespace

ThirdVersion write_third_version(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& walls,
                                 const std::vector<ProbeWallForce>& bodies, const SecondPart& second, double beta_before,
                                 const std::string& out_dir) {
  const ThirdVersion a = analyse_third_version(plan, walls, bodies, second, beta_before);
  const ManyBodyProbe::ThirdVersionPlan& t = *plan.third;
  nlohmann::json j;
  j["plan"] = plan_path, j["code_version"] = code_version(), j["count_chosen"] = a.count_chosen, j["notes"] = a.notes;
  std::string md = fmt::format(
      "# The many-body law's third version (generated by softpack-coarse probe-report, {})\n\n"
      "Plan: `{}` (`third_version`; paper/many-body.md, \"Next\"). Seeds {}. An error is as in probe.md: exp(rms ln(pred/meas)) "
      "(mean of the logarithm), over the points above the floor; ± is the jackknife over the seeds.\n\n",
      code_version(), plan_path, fmt::join(plan.seeds, ", "));
  md += "## 1. The count of contacts (walls)\n\nβ fitted on `fit` and " + fmt::format("{}", fmt::join(t.count_fit, ", ")) +
        "; the form chosen on `held_out` and " + fmt::format("{}", fmt::join(t.count_held_out, ", ")) +
        " (the least error).\n\n| form | β | fit runs | held-out runs |\n|---|---|---|---|\n";
  for (const ThirdVersion::CountForm& c : a.count) {
    md += fmt::format("| {} | {} | {} | {} |\n", c.name, fitted_text(c.beta), error_factor(c.fit), error_factor(c.held_out));
    nlohmann::json cj{{"beta", fitted_json(c.beta)}, {"fit", probe_error_json(c.fit)}, {"held_out", probe_error_json(c.held_out)}};
    for (const auto& [name, e] : c.by_arrangement) cj["arrangements"][name] = probe_error_json(e);
    j["count"][c.name] = cj;
  }
  md += "\n| arrangement | role |";
  for (const ThirdVersion::CountForm& c : a.count) md += fmt::format(" {} |", c.name);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < a.count.size(); ++i) md += "---|";
  md += "\n";
  const std::vector<std::string> fit = joined(plan.fit, with_kind(t.count_fit, "wall"));
  for (const auto& [name, e] : a.count.front().by_arrangement) {
    md += fmt::format("| {} | {} |", name, std::find(fit.begin(), fit.end(), name) != fit.end() ? "fit" : "held out");
    for (const ThirdVersion::CountForm& c : a.count) md += fmt::format(" {} |", error_factor(c.by_arrangement.at(name)));
    md += "\n";
  }
  md += fmt::format("\nChosen by the rule: **{}**.\n\n", a.count_chosen);

  md += fmt::format("## 2. Grains: F1 g(X), g(X) = (X / (1 + X))^p\n\np = {} (on the single contacts of {}), the grains' β = {} ({}, on their "
                    "arrangements of two or more). Error of the third version and of the engine until now (a grain as a wall, the walls' "
                    "β = {:.3f}):\n\n| arrangement | role | third version | until now |\n|---|---|---|---|\n",
                    fitted_text(a.grain_p), fmt::join(t.grain_fit, ", "), fitted_text(a.grain_beta), a.count_chosen, beta_before);
  for (const auto& [name, e] : a.grain) {
    const std::string kind = name.substr(name.find(':') + 1);
    const bool held = std::find(t.grain_held_out.begin(), t.grain_held_out.end(), kind) != t.grain_held_out.end();
    md += fmt::format("| {} | {} | {} | {} |\n", name, held ? "held out" : "fit", error_factor(e), error_factor(a.grain_before.at(name)));
    j["grain"]["arrangements"][name] = {{"third", probe_error_json(e)}, {"before", probe_error_json(a.grain_before.at(name))}, {"held_out", held}};
  }
  md += fmt::format("\nAll fit runs: {}; all held-out runs: {}.\n\n", error_factor(a.grain_fit), error_factor(a.grain_held_out));
  j["grain"]["p"] = fitted_json(a.grain_p), j["grain"]["beta"] = fitted_json(a.grain_beta);
  j["grain"]["fit"] = probe_error_json(a.grain_fit), j["grain"]["held_out"] = probe_error_json(a.grain_held_out);

  md += fmt::format("## 3. Soft-particles: the engine's mean rule\n\nβ_ss = {} (twice the β fitted on the centre's contacts; no soft run is "
                    "left out, so these are fit errors):\n\n| arrangement | error |\n|---|---|\n",
                    fitted_text(a.soft_beta));
  for (const auto& [name, e] : a.soft) md += fmt::format("| {} | {} |\n", name, error_factor(e)), j["soft"]["arrangements"][name] = probe_error_json(e);
  md += fmt::format("\nAll: {}.\n\n", error_factor(a.soft_fit));
  j["soft"]["beta"] = fitted_json(a.soft_beta), j["soft"]["fit"] = probe_error_json(a.soft_fit);

  md += "## 4. The tangential gain: kt / kt_one against the walls' law's Fn / F1 (no parameter)\n\n"
        "| radius | arrangement | Δn | kt / kt_one measured | predicted | predicted / measured |\n|---|---|---|---|---|---|\n";
  for (const ThirdVersion::Gain& g : a.gain) {
    const double r = std::log(g.predicted) - g.kt.mean;
    md += fmt::format("| {} | {} | {} | {:.3f} ± {:.3f} | {:.3f} | {:.3f}{} |\n", g.radius, g.arrangement, g.delta_n, std::exp(g.kt.mean), g.kt.se,
                      g.predicted, std::exp(r), std::abs(r) <= 2.0 * g.kt.se ? "" : " *");
    j["gain"].push_back({{"radius", g.radius}, {"arrangement", g.arrangement}, {"delta_n", g.delta_n}, {"kt_ratio_mean_log", g.kt.mean},
                         {"kt_ratio_se_log", g.kt.se}, {"predicted", g.predicted}});
  }
  md += fmt::format("\n(± the standard error of the mean log; * further than 2 of them.) Over the rows: {}.\n", error_factor(a.gain_error));
  j["gain_error"] = probe_error_json(a.gain_error);
  for (const std::string& n : a.notes) md += fmt::format("\n- {}", n);
  std::filesystem::create_directories(out_dir);
  write_file_atomically(out_dir + "/third-version.md", md + "\n");
  write_file_atomically(out_dir + "/third-version.json", j.dump(2) + "\n");
  return a;
}

}  // namespace softpack
