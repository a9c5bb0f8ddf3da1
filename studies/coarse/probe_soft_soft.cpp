#include "coarse/probe_soft_soft.hpp"

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

// The engine's parameter in [0, 10] (the plans); the probe's centre carries all the others, which
// the mean rule halves, so the law below takes half of it.
constexpr double kParameterMax = 10.0, kMeanRule = 0.5;

// The form's law with its engine parameters (a stress form on its β_ss's volumetric-union law).
ProbeLaw law_of(const SoftSoftVersion::Form& f, const std::map<std::string, fit::PowerLawFit>& X) {
  ProbeLaw law{f.base, kMeanRule * (f.stress.empty() ? f.parameter.value : f.beta_ss.value), X};
  if (!f.stress.empty()) law.stress = kMeanRule * f.parameter.value, law.stress_form = ProbeLaw::stress_form_of(f.stress);
  law.count_predicted_force = true;
  return law;
}

// The form's engine parameters fitted on `fit` of `points` (X fitted again on them): {its
// parameter, β_ss} (β_ss the form's own unless joint).
std::pair<double, double> fit_form(const ManyBodyProbe& plan, SoftSoftVersion::Form f, const std::vector<ProbeWallForce>& points,
                                   const std::vector<std::string>& fit, bool joint) {
  f.parameter = {};
  const auto X = fit_single_contact(plan, points, "one:soft");
  if (f.stress.empty() || !joint) {
    const ProbeLaw law = law_of(f, X);
    const double p = fit_parameter(law, kMeanRule * kParameterMax, points, fit, plan, f.stress.empty() ? &ProbeLaw::parameter : &ProbeLaw::stress);
    return {p / kMeanRule, f.beta_ss.value};
  }
  // β_ss and κ together: for each β_ss the best κ (its error a smooth function of each); the
  // force is the law's alone plus κ times its term, each computed once per β_ss
  std::vector<ProbeWallForce> in_fit;
  for (const ProbeWallForce& w : points)
    if (listed(fit, w.arrangement)) in_fit.push_back(w);
  ProbeLaw law = law_of(f, X);
  std::vector<double> alone(in_fit.size()), term(in_fit.size());
  const auto kappa_at = [&](double beta) {
    law.parameter = kMeanRule * beta, law.stress = 1.0;
    for (std::size_t i = 0; i < in_fit.size(); ++i) alone[i] = law.predict_alone(in_fit[i]), term[i] = law.predict(in_fit[i]) - alone[i];
    const auto error = [&](double k) { return probe_error(law, in_fit, {}, plan, [&](std::size_t i) { return alone[i] + k * term[i]; }).rms_log; };
    const double k = least_of(error, kMeanRule * kParameterMax, 100);
    return std::pair{k, error(k)};
  };
  const double beta = least_of([&](double b) { return kappa_at(b).second; }, kParameterMax, 50);
  return {kappa_at(beta).first / kMeanRule, beta};
}

}  // namespace

std::vector<std::string> reported_runs(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part) {
  std::vector<std::string> out;
  for (const std::string& kind : plan.confined_kinds(true))
    for (const std::string& r : plan.bodies(kind))
      if (!listed(part.fit, r) && !listed(part.held_out, r)) out.push_back(r);
  return out;
}

const SoftSoftVersion::Form& SoftSoftVersion::form(const std::string& name) const {
  for (const Form& f : forms)
    if (f.name == name) return f;
  throw InputError(fmt::format("no soft-soft form '{}' in the analysis", name));
}

SoftSoftVersion analyse_soft_soft(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::vector<ProbeWallForce>& soft,
                                  const std::vector<ProbeWallForce>& confined, const SoftSoftVersion::Form& baseline) {
  // The points: every contact of the soft arrangements (each a soft-soft one), the first contact
  // of the confined runs (the others are walls).
  std::vector<ProbeWallForce> points = soft;
  for (const ProbeWallForce& w : confined)
    if (w.wall == 0) points.push_back(w);
  std::vector<std::string> unconfined;
  for (const std::string& a : plan.bodies("soft"))
    if (a != "one:soft") unconfined.push_back(a);
  std::vector<std::string> fit = part.fit;
  fit.insert(fit.end(), unconfined.begin(), unconfined.end());
  const std::vector<std::string> reported = reported_runs(plan, part);
  const auto X = fit_single_contact(plan, points, "one:soft");

  SoftSoftVersion out;
  std::vector<SoftSoftVersion::Form> forms{baseline};
  for (const std::string& name : part.forms) {
    SoftSoftVersion::Form f;
    f.name = name;
    if (name.rfind("stress", 0) == 0)  // on the baseline's law: its β_ss (a stress baseline's own, else its parameter)
      f.stress = name, f.base = baseline.base, f.beta_ss = baseline.stress.empty() ? baseline.parameter : baseline.beta_ss;
    else
      f.base = name;
    forms.push_back(f);
  }
  for (SoftSoftVersion::Form& c : forms) {
    c.held_out_by_radius.clear(), c.by_arrangement.clear();  // a baseline from an earlier part has that part's
    if (&c != &forms.front()) {
      const bool joint = part.joint_beta_ss && !c.stress.empty();
      const auto [value, beta] = fit_form(plan, c, points, fit, joint);
      c.parameter.value = value;
      std::vector<double> theta, theta_beta;  // the jackknife over the seeds, both parameters from the same fits
      for (const std::uint64_t seed : plan.seeds) {
        std::vector<ProbeWallForce> rest;
        for (const ProbeWallForce& w : points)
          if (w.seed != seed) rest.push_back(w);
        const auto [v, b] = fit_form(plan, c, rest, fit, joint);
        theta.push_back(v), theta_beta.push_back(b);
      }
      c.parameter.se = jackknife_error(theta);
      if (joint) c.beta_ss = {beta, jackknife_error(theta_beta)};
      if (c.parameter.value > 0.999 * kParameterMax) out.notes.push_back(fmt::format("{}: its parameter at the end of its range [0, {}]", c.name, kParameterMax));
      if (joint && beta > 0.999 * kParameterMax) out.notes.push_back(fmt::format("{}: its β_ss at the end of its range [0, {}]", c.name, kParameterMax));
    }
    const ProbeLaw law = law_of(c, X);
    c.fit = probe_error(law, points, fit, plan), c.held_out = probe_error(law, points, part.held_out, plan);
    c.unconfined = probe_error(law, points, unconfined, plan);
    for (const auto& [radius, Rs] : plan.radii) {
      std::vector<ProbeWallForce> of_radius;
      for (const ProbeWallForce& w : points)
        if (w.radius == radius) of_radius.push_back(w);
      c.held_out_by_radius[radius] = probe_error(law, of_radius, part.held_out, plan);
    }
    for (const std::string& a : fit) c.by_arrangement[a] = probe_error(law, points, {a}, plan);
    for (const std::string& a : part.held_out) c.by_arrangement[a] = probe_error(law, points, {a}, plan);
    for (const std::string& a : reported) c.by_arrangement[a] = probe_error(law, points, {a}, plan);
  }
  out.forms = forms;
  // The rule: the least held-out error among the plan's forms; into the engine only if below the
  // baseline's at each radius.
  const SoftSoftVersion::Form* chosen = nullptr;
  for (const SoftSoftVersion::Form& c : out.forms)
    if (&c != &out.forms.front() && (!chosen || c.held_out.rms_log < chosen->held_out.rms_log)) chosen = &c;
  out.chosen = chosen->name;
  out.enters_engine = true;
  for (const auto& [radius, e] : chosen->held_out_by_radius)
    if (!(e.points > 0 && e.rms_log < out.forms.front().held_out_by_radius.at(radius).rms_log)) {
      out.enters_engine = false;
      out.notes.push_back(fmt::format("radius {}: {} is not better than {} on the held-out runs{}", radius, out.chosen, out.forms.front().name,
                                      e.points > 0 ? "" : " (it has none)"));
    }
  return out;
}

SoftSoftVersion write_soft_soft(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::string& plan_path,
                                const std::vector<ProbeWallForce>& soft, const std::vector<ProbeWallForce>& confined,
                                const SoftSoftVersion::Form& baseline, const std::string& title, const std::string& out_dir, const std::string& name) {
  const SoftSoftVersion a = analyse_soft_soft(plan, part, soft, confined, baseline);
  const std::vector<std::string> reported = reported_runs(plan, part);
  nlohmann::json j;
  j["plan"] = plan_path, j["code_version"] = code_version(), j["chosen"] = a.chosen, j["enters_engine"] = a.enters_engine, j["notes"] = a.notes;
  const auto symbol = [](const SoftSoftVersion::Form& c) { return !c.stress.empty() ? "κ" : c.base == "onset-shift" ? "γ" : "β_ss"; };
  std::string md = fmt::format(
      "# {} (generated by softpack-coarse probe-report, {})\n\n"
      "Plan: `{}` (paper/many-body.md). Seeds {}. The force on a soft-particle pressing the centre while walls confine it, against "
      "each soft-soft form in the engine's mean rule. Fitted on {} with the unconfined soft arrangements; held out: {}. An error is "
      "exp(rms ln(pred/meas)) (mean of the logarithm), over the points whose measured or predicted force is above the floor; ± is the "
      "jackknife over the seeds; {}'s parameter is its law file's, not fitted here{}.\n\n"
      "| form | parameter (engine's) | fit runs | unconfined soft | held-out runs |",
      title, code_version(), plan_path, fmt::join(plan.seeds, ", "), fmt::join(part.fit, ", "), fmt::join(part.held_out, ", "), baseline.name,
      std::any_of(a.forms.begin(), a.forms.end(), [](const auto& c) { return !c.stress.empty(); })
          ? (part.joint_beta_ss ? "; each stress form's β_ss (in brackets) is fitted with its κ" : "; stress is on its force")
          : "");
  for (const auto& [radius, Rs] : plan.radii) md += fmt::format(" held out, {} |", radius);
  md += "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < plan.radii.size(); ++i) md += "---|";
  md += "\n";
  for (const SoftSoftVersion::Form& c : a.forms) {
    const std::string beneath = c.stress.empty() ? "" : fmt::format(" (β_ss {:.3f} ± {:.3f})", c.beta_ss.value, c.beta_ss.se);
    md += fmt::format("| {} | {} {:.3f} ± {:.3f}{} | {} | {} | {} |", c.name, symbol(c), c.parameter.value, c.parameter.se, beneath, error_factor(c.fit),
                      error_factor(c.unconfined), error_factor(c.held_out));
    nlohmann::json cj{{"base", c.base},
                      {"parameter", {{"value", c.parameter.value}, {"se", c.parameter.se}}},
                      {"fit", probe_error_json(c.fit)},
                      {"unconfined", probe_error_json(c.unconfined)},
                      {"held_out", probe_error_json(c.held_out)}};
    if (!c.stress.empty()) cj["stress"] = c.stress, cj["beta_ss"] = {{"value", c.beta_ss.value}, {"se", c.beta_ss.se}};
    for (const auto& [radius, e] : c.held_out_by_radius) md += fmt::format(" {} |", error_factor(e)), cj["held_out_by_radius"][radius] = probe_error_json(e);
    for (const auto& [arrangement, e] : c.by_arrangement) cj["arrangements"][arrangement] = probe_error_json(e);
    md += "\n";
    j["forms"][c.name] = cj;
  }
  md += "\n| arrangement | role |";
  for (const SoftSoftVersion::Form& c : a.forms) md += fmt::format(" {} |", c.name);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < a.forms.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& [arrangement, e] : a.forms.front().by_arrangement) {
    md += fmt::format("| {} | {} |", arrangement, listed(part.held_out, arrangement) ? "held out" : listed(part.fit, arrangement) || !listed(reported, arrangement) ? "fit" : "reported");
    for (const SoftSoftVersion::Form& c : a.forms) md += fmt::format(" {} |", error_factor(c.by_arrangement.at(arrangement)));
    md += "\n";
  }
  md += fmt::format("\nChosen by the rule: **{}**; it enters the engine: **{}** (its held-out error below {}'s at each radius).\n", a.chosen,
                    a.enters_engine ? "yes" : "no", baseline.name);
  for (const std::string& n : a.notes) md += fmt::format("\n- {}", n);

  // The curves: each confined run of the part (confined's order), the pressing soft-particle's force.
  const auto X = fit_single_contact(plan, soft, "one:soft");  // the analysis's (one:soft is in the bodies files)
  std::vector<std::string> drawn, form_names;
  for (const std::string& kind : plan.confined_kinds(true))
    for (const std::string& r : plan.bodies(kind)) drawn.push_back(r);
  for (const SoftSoftVersion::Form& c : a.forms) form_names.push_back(c.name);
  write_confined_curves(plan, confined, drawn, form_names, [&](std::size_t f, const ProbeWallForce& w) { return law_of(a.forms[f], X).predict(w); },
                        title, out_dir, name);
  write_file_atomically(out_dir + "/" + name + ".md", md + "\n");
  write_file_atomically(out_dir + "/" + name + ".json", j.dump(2) + "\n");
  return a;
}

}  // namespace softpack
