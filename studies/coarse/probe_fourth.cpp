#include "coarse/probe_fourth.hpp"

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

// The engine's parameter in [0, 10] (the plan); the probe's centre carries all the others, which
// the mean rule halves, so the law below takes half of it.
constexpr double kParameterMax = 10.0, kMeanRule = 0.5;

std::vector<std::string> confined_names(const ManyBodyProbe& plan, const std::vector<std::string>& arrangements) {
  std::vector<std::string> out;
  for (const auto& [kind, runs] : plan.confined_groups)
    for (const std::string& a : arrangements) out.push_back(a + ":" + kind);
  return out;
}

ProbeLaw law_of(const std::string& form, double engine_parameter, const std::map<std::string, fit::PowerLawFit>& X) {
  ProbeLaw law{form == "third" ? "volumetric-union" : form, kMeanRule * engine_parameter, X};
  law.count_predicted_force = true;
  return law;
}

// The form's engine parameter fitted on `fit` of `points` (X fitted again on them).
double fit_form(const ManyBodyProbe& plan, const std::string& form, const std::vector<ProbeWallForce>& points, const std::vector<std::string>& fit) {
  const ProbeLaw law = law_of(form, 0.0, fit_single_contact(plan, points, "one:soft"));
  return fit_parameter(law, kMeanRule * kParameterMax, points, fit, plan) / kMeanRule;
}

}  // namespace

FourthVersion analyse_fourth_version(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& soft, const std::vector<ProbeWallForce>& confined,
                                     const FittedValue& beta_ss) {
  if (!plan.fourth) throw InputError("the plan has no fourth_version: nothing to analyse");
  const ManyBodyProbe::FourthVersionPlan& f = *plan.fourth;
  // The points: every contact of the soft arrangements (each a soft-soft one), the first contact
  // of the confined runs (the others are walls).
  std::vector<ProbeWallForce> points = soft;
  for (const ProbeWallForce& w : confined)
    if (w.wall == 0) points.push_back(w);
  std::vector<std::string> unconfined;
  for (const std::string& a : plan.bodies("soft"))
    if (a != "one:soft") unconfined.push_back(a);
  std::vector<std::string> fit = confined_names(plan, f.fit);
  fit.insert(fit.end(), unconfined.begin(), unconfined.end());
  const std::vector<std::string> held = confined_names(plan, f.held_out);
  const auto X = fit_single_contact(plan, points, "one:soft");

  FourthVersion out;
  std::vector<std::string> forms{"third"};
  forms.insert(forms.end(), f.soft_forms.begin(), f.soft_forms.end());
  for (const std::string& name : forms) {
    FourthVersion::Form c{name, beta_ss, {}, {}, {}, {}, {}};
    if (name != "third") {
      c.parameter.value = fit_form(plan, name, points, fit);
      std::vector<double> theta;
      for (const std::uint64_t seed : plan.seeds) {
        std::vector<ProbeWallForce> rest;
        for (const ProbeWallForce& w : points)
          if (w.seed != seed) rest.push_back(w);
        theta.push_back(fit_form(plan, name, rest, fit));
      }
      c.parameter.se = jackknife_error(theta);
      if (c.parameter.value > 0.999 * kParameterMax) out.notes.push_back(fmt::format("{}: its parameter at the end of its range [0, {}]", name, kParameterMax));
    }
    const ProbeLaw law = law_of(name, c.parameter.value, X);
    c.fit = probe_error(law, points, fit, plan), c.held_out = probe_error(law, points, held, plan);
    c.unconfined = probe_error(law, points, unconfined, plan);
    for (const auto& [radius, Rs] : plan.radii) {
      std::vector<ProbeWallForce> of_radius;
      for (const ProbeWallForce& w : points)
        if (w.radius == radius) of_radius.push_back(w);
      c.held_out_by_radius[radius] = probe_error(law, of_radius, held, plan);
    }
    for (const std::string& a : fit) c.by_arrangement[a] = probe_error(law, points, {a}, plan);
    for (const std::string& a : held) c.by_arrangement[a] = probe_error(law, points, {a}, plan);
    out.forms.push_back(c);
  }
  // The rule: the least held-out error among the plan's forms; into the engine only if below the
  // third version's at each radius.
  const FourthVersion::Form* chosen = nullptr;
  for (const FourthVersion::Form& c : out.forms)
    if (c.name != "third" && (!chosen || c.held_out.rms_log < chosen->held_out.rms_log)) chosen = &c;
  out.chosen = chosen->name;
  out.enters_engine = true;
  for (const auto& [radius, e] : chosen->held_out_by_radius)
    if (!(e.rms_log < out.forms.front().held_out_by_radius.at(radius).rms_log)) {
      out.enters_engine = false;
      out.notes.push_back(fmt::format("radius {}: {} is not better than the third version on the held-out runs", radius, out.chosen));
    }
  return out;
}

FourthVersion write_fourth_version(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& soft,
                                   const std::vector<ProbeWallForce>& confined, const FittedValue& beta_ss, const std::string& out_dir) {
  const FourthVersion a = analyse_fourth_version(plan, soft, confined, beta_ss);
  const ManyBodyProbe::FourthVersionPlan& f = *plan.fourth;
  nlohmann::json j;
  j["plan"] = plan_path, j["code_version"] = code_version(), j["chosen"] = a.chosen, j["enters_engine"] = a.enters_engine, j["notes"] = a.notes;
  std::string md = fmt::format(
      "# The probe's fourth part: the soft-soft contact under confinement (generated by softpack-coarse probe-report, {})\n\n"
      "Plan: `{}` (`fourth_version`; paper/many-body.md, \"The fourth part's analysis\"). Seeds {}. The force on a soft-particle "
      "pressing the centre while walls confine it, against each soft-soft form in the engine's mean rule. Fitted on {} of every "
      "confined kind with the unconfined soft arrangements; held out: {}. An error is exp(rms ln(pred/meas)) (mean of the logarithm), "
      "over the points whose measured or predicted force is above the floor; ± is the jackknife over the seeds; the third version's "
      "β_ss is its law file's, not fitted here.\n\n"
      "| form | parameter (engine's) | fit runs | unconfined soft | held-out runs |",
      code_version(), plan_path, fmt::join(plan.seeds, ", "), fmt::join(f.fit, ", "), fmt::join(f.held_out, ", "));
  for (const auto& [radius, Rs] : plan.radii) md += fmt::format(" held out, {} |", radius);
  md += "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < plan.radii.size(); ++i) md += "---|";
  md += "\n";
  for (const FourthVersion::Form& c : a.forms) {
    md += fmt::format("| {} | {} {:.3f} ± {:.3f} | {} | {} | {} |", c.name, c.name == "onset-shift" ? "γ" : "β_ss", c.parameter.value, c.parameter.se,
                      error_factor(c.fit), error_factor(c.unconfined), error_factor(c.held_out));
    nlohmann::json cj{{"parameter", {{"value", c.parameter.value}, {"se", c.parameter.se}}},
                      {"fit", probe_error_json(c.fit)},
                      {"unconfined", probe_error_json(c.unconfined)},
                      {"held_out", probe_error_json(c.held_out)}};
    for (const auto& [radius, e] : c.held_out_by_radius) md += fmt::format(" {} |", error_factor(e)), cj["held_out_by_radius"][radius] = probe_error_json(e);
    for (const auto& [name, e] : c.by_arrangement) cj["arrangements"][name] = probe_error_json(e);
    md += "\n";
    j["forms"][c.name] = cj;
  }
  md += "\n| arrangement | role |";
  for (const FourthVersion::Form& c : a.forms) md += fmt::format(" {} |", c.name);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < a.forms.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& [name, e] : a.forms.front().by_arrangement) {
    const std::string arrangement = name.substr(0, name.find(':'));
    const bool held = name.find("+walls-") != std::string::npos && std::find(f.held_out.begin(), f.held_out.end(), arrangement) != f.held_out.end();
    md += fmt::format("| {} | {} |", name, held ? "held out" : "fit");
    for (const FourthVersion::Form& c : a.forms) md += fmt::format(" {} |", error_factor(c.by_arrangement.at(name)));
    md += "\n";
  }
  md += fmt::format("\nChosen by the rule: **{}**; it enters the engine: **{}** (its held-out error below the third version's at each radius).\n",
                    a.chosen, a.enters_engine ? "yes" : "no");
  for (const std::string& n : a.notes) md += fmt::format("\n- {}", n);

  // The curves: each radius, confined arrangement and Δn, the pressing soft-particle's measured
  // force (mean and se over the seeds) and each form's.
  std::string dat = "# the probe's fourth part: radius arrangement delta_n F_mean[N] F_se[N]";
  for (const FourthVersion::Form& c : a.forms) dat += " F_" + c.name;
  dat += "\n";
  const auto X = fit_single_contact(plan, soft, "one:soft");  // the analysis's (one:soft is in the bodies files)
  for (const auto& [radius, Rs] : plan.radii)
    for (const auto& [kind, runs] : plan.confined_groups)
      for (const std::string& run : runs) {
        const std::string name = run + ":" + kind;
        dat += fmt::format("\n\n# {} {}\n", radius, name);
        for (const double dn : plan.delta_n) {
          std::vector<double> F;
          const ProbeWallForce* at = nullptr;
          for (const ProbeWallForce& w : confined)
            if (w.radius == radius && w.arrangement == name && w.wall == 0 && std::abs(w.delta_n[0] - dn) < 1e-9) F.push_back(w.Fn), at = &w;
          if (!at) continue;
          const MeanError m = mean_error(F);
          dat += fmt::format("{} {} {:.4f} {:.6e} {:.6e}", radius, name, dn, m.mean, m.error);
          for (const FourthVersion::Form& c : a.forms) dat += fmt::format(" {:.6e}", law_of(c.name, c.parameter.value, X).predict(*at));
          dat += "\n";
        }
      }
  std::filesystem::create_directories(out_dir);
  write_file_atomically(out_dir + "/fourth-version.md", md + "\n");
  write_file_atomically(out_dir + "/fourth-version.json", j.dump(2) + "\n");
  write_file_atomically(out_dir + "/fourth-version.dat", dat);
  return a;
}

}  // namespace softpack
