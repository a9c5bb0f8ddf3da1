#include "coarse/probe_body.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <tuple>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace body_part {  // a name of its own: the unity build puts it beside probe_soft_soft.cpp
namespace {

constexpr double kParameterMax = 10.0;  // every parameter in [0, 10] (the plan)
constexpr const char* kBodies[] = {"grain", "wall"};

// The body's β and κ in a form.
const BodyVersion::BodyLaw& law_in(const BodyVersion::Form& f, const ProbeWallForce& w) { return f.body.at(body_of(w.body)); }

// The law without the stress term for body b, its β, on X1 (its floors and counting rule too).
ProbeLaw base_law(const FifthBodyLaw& fifth, const std::map<std::string, fit::PowerLawFit>& X1, double beta) {
  ProbeLaw law{fifth.form, beta, X1, fifth.grain_exponent};
  law.count_predicted_force = true;
  return law;
}

// The stress term over κ: g p π R² a(Δn) with p = Σ_{l≠k} F_l / (4π R²).
double term(const ProbeWallForce& w, double grain_exponent) {
  const double x = w.body.radius_ratio;
  const double g = w.body.kind == PressingBody::Kind::grain ? std::pow(x / (1.0 + x), grain_exponent) : 1.0;
  return g * std::max(0.0, w.others_Fn) / 4.0 * cap_area(w.delta_n[w.wall]);
}

double predict(const BodyVersion::Form& f, const FifthBodyLaw& fifth, const std::map<std::string, fit::PowerLawFit>& X1, const ProbeWallForce& w) {
  const BodyVersion::BodyLaw& b = law_in(f, w);
  return base_law(fifth, X1, b.beta.value).predict_alone(w) + b.kappa.value * term(w, fifth.grain_exponent);
}

ProbeError error_of(const BodyVersion::Form& f, const FifthBodyLaw& fifth, const std::map<std::string, fit::PowerLawFit>& X1,
                    const std::vector<ProbeWallForce>& points, const std::vector<std::string>& runs, const ManyBodyProbe& plan) {
  return probe_error(base_law(fifth, X1, 0.0), points, runs, plan, [&](std::size_t i) { return predict(f, fifth, X1, points[i]); });
}

// {β_b, κ_b} of form `name` for body b, fitted on its runs of `fit` in `points` (X1 fitted again
// on their `one`): union-refit β (κ 0), stress κ (β the fifth's), stress-joint both (for each β
// the best κ). The error is not smooth (the floors clip it): stress-joint's coarser search of β
// is kept only where it fits better than union-refit's β with κ 0, so it never fits worse.
std::pair<double, double> fit_body(const ManyBodyProbe& plan, const std::string& name, const std::string& body, const FifthBodyLaw& fifth,
                                   const std::vector<ProbeWallForce>& points, const std::vector<std::string>& fit) {
  const auto X1 = fit_single_contact(plan, points);
  std::vector<ProbeWallForce> in_fit;
  for (const ProbeWallForce& w : points)
    if (listed(fit, w.arrangement) && body_of(w.body) == body) in_fit.push_back(w);
  if (in_fit.empty()) throw InputError(fmt::format("seventh_version: no fit run with a {} at the first contact; the {}'s β and κ cannot be fitted", body, body));
  const double beta_fifth = body == "grain" ? fifth.beta_grain : fifth.beta_wall;
  std::vector<double> alone(in_fit.size()), t(in_fit.size());
  for (std::size_t i = 0; i < in_fit.size(); ++i) t[i] = term(in_fit[i], fifth.grain_exponent);
  const auto at_beta = [&](double beta) {
    const ProbeLaw law = base_law(fifth, X1, beta);
    for (std::size_t i = 0; i < in_fit.size(); ++i) alone[i] = law.predict_alone(in_fit[i]);
    return law;
  };
  const auto error = [&](const ProbeLaw& law, double kappa) {
    return probe_error(law, in_fit, {}, plan, [&](std::size_t i) { return alone[i] + kappa * t[i]; }).rms_log;
  };
  const auto union_refit = [&] { return least_of([&](double beta) { return error(at_beta(beta), 0.0); }, kParameterMax, 1000); };
  if (name == "union-refit") return {union_refit(), 0.0};
  const auto kappa_at = [&](double beta) {
    const ProbeLaw law = at_beta(beta);
    const double k = least_of([&](double kappa) { return error(law, kappa); }, kParameterMax, 100);
    return std::pair{k, error(law, k)};
  };
  if (name == "stress") return {beta_fifth, kappa_at(beta_fifth).first};
  const double beta = least_of([&](double b) { return kappa_at(b).second; }, kParameterMax, 50), beta_u = union_refit();
  const auto [kappa, e] = kappa_at(beta);
  if (error(at_beta(beta_u), 0.0) <= e) return {beta_u, 0.0};
  return {beta, kappa};
}

}  // namespace
}  // namespace body_part

using body_part::kBodies;
using body_part::error_of;
using body_part::fit_body;
using body_part::predict;

std::string body_of(const PressingBody& b) { return b.kind == PressingBody::Kind::grain ? "grain" : "wall"; }

const BodyVersion::Form& BodyVersion::form(const std::string& name) const {
  for (const Form& f : forms)
    if (f.name == name) return f;
  throw InputError(fmt::format("no form '{}' in the seventh part's analysis", name));
}

BodyVersion analyse_body_version(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::vector<ProbeWallForce>& walls,
                                 const std::vector<ProbeWallForce>& confined, const FifthBodyLaw& fifth, const std::vector<ProbeWallForce>& grains) {
  // The points: the first part's single contact (X1), the first contact of the confined runs
  // (the others are walls).
  std::vector<ProbeWallForce> points;
  for (const ProbeWallForce& w : walls)
    if (w.arrangement == "one") points.push_back(w);
  for (const ProbeWallForce& w : confined)
    if (w.wall == 0 && w.body.kind != PressingBody::Kind::soft) points.push_back(w);
  const auto X1 = fit_single_contact(plan, points);

  BodyVersion out;
  BodyVersion::Form base{"fifth", {}, {}, {}, {}, {}};
  base.body["grain"].beta.value = fifth.beta_grain, base.body["wall"].beta.value = fifth.beta_wall;
  out.forms.push_back(base);
  for (const std::string& name : part.forms) {
    BodyVersion::Form f{name, base.body, {}, {}, {}, {}};
    for (const char* body : kBodies) {
      const auto [beta, kappa] = fit_body(plan, name, body, fifth, points, part.fit);
      std::vector<double> beta_j, kappa_j;  // the jackknife over the seeds, both from the same fits
      for (const std::uint64_t seed : plan.seeds) {
        std::vector<ProbeWallForce> rest;
        for (const ProbeWallForce& w : points)
          if (w.seed != seed) rest.push_back(w);
        const auto [b, k] = fit_body(plan, name, body, fifth, rest, part.fit);
        beta_j.push_back(b), kappa_j.push_back(k);
      }
      BodyVersion::BodyLaw& l = f.body[body];
      if (name != "stress") l.beta = {beta, jackknife_error(beta_j)};
      if (name != "union-refit") l.kappa = {kappa, jackknife_error(kappa_j)};
      for (const auto& [what, v] : {std::pair{"β", beta}, std::pair{"κ", kappa}})
        if (v > 0.999 * kParameterMax) out.notes.push_back(fmt::format("{}: the {}'s {} at the end of its range [0, {}]", name, body, what, kParameterMax));
    }
    out.forms.push_back(f);
  }
  for (BodyVersion::Form& c : out.forms) {
    c.fit = error_of(c, fifth, X1, points, part.fit, plan), c.held_out = error_of(c, fifth, X1, points, part.held_out, plan);
    for (const auto& [radius, Rs] : plan.radii) {
      std::vector<ProbeWallForce> of_radius;
      for (const ProbeWallForce& w : points)
        if (w.radius == radius) of_radius.push_back(w);
      c.held_out_by_radius[radius] = error_of(c, fifth, X1, of_radius, part.held_out, plan);
    }
    for (const std::string& a : part.fit) c.by_arrangement[a] = error_of(c, fifth, X1, points, {a}, plan);
    for (const std::string& a : part.held_out) c.by_arrangement[a] = error_of(c, fifth, X1, points, {a}, plan);
  }
  // The rule: the least held-out error among the plan's forms; into the engine only if below
  // fifth's at each radius.
  const BodyVersion::Form* chosen = nullptr;
  for (const BodyVersion::Form& c : out.forms)
    if (&c != &out.forms.front() && (!chosen || c.held_out.rms_log < chosen->held_out.rms_log)) chosen = &c;
  if (!chosen) throw InputError("seventh_version: no form to judge");
  out.chosen = chosen->name;
  out.enters_engine = true;
  for (const auto& [radius, e] : chosen->held_out_by_radius)
    if (!(e.points > 0 && e.rms_log < out.forms.front().held_out_by_radius.at(radius).rms_log)) {
      out.enters_engine = false;
      out.notes.push_back(fmt::format("radius {}: {} is not better than fifth on the held-out runs{}", radius, out.chosen, e.points > 0 ? "" : " (it has none)"));
    }
  // Reported: fifth and the chosen form where every contact moves at once (the first part's walls'
  // arrangements, the second part's grains'), their single contacts left out.
  std::vector<std::string> wall_runs, grain_runs;
  for (const std::string& a : plan.arrangements())
    if (a != "one") wall_runs.push_back(a);
  for (const ProbeWallForce& w : grains)
    if (w.body.kind == PressingBody::Kind::grain && w.arrangement.rfind("one:", 0) != 0 && !listed(grain_runs, w.arrangement)) grain_runs.push_back(w.arrangement);
  for (const auto& [what, from, runs] : {std::tuple{"walls", &walls, &wall_runs}, std::tuple{"grains", &grains, &grain_runs}})
    if (!runs->empty())
      out.earlier[what] = {error_of(out.forms.front(), fifth, X1, *from, *runs, plan), error_of(*chosen, fifth, X1, *from, *runs, plan)};
  // What the fifth version gives of the shallow contacts, kind by kind.
  for (const auto& [radius, Rs] : plan.radii)
    for (const std::string& kind : plan.confined_kinds(false))
      for (const double dn : plan.delta_n_of(kind)) {
        if (!(dn < 0.1 - 1e-9)) continue;  // the plan's "below 0.1"
        BodyVersion::Shallow s{radius, kind, dn, 0, 0, 0.0, 0.0};
        for (const ProbeWallForce& w : points)
          if (w.radius == radius && w.body.name() == kind && std::abs(w.delta_n[0] - dn) < 1e-9) {
            ++s.points, s.pushed += w.Fn > 0.0 ? 1 : 0;
            s.measured += w.Fn, s.fifth += predict(out.forms.front(), fifth, X1, w);
          }
        if (s.points == 0) continue;
        s.measured /= static_cast<double>(s.points), s.fifth /= static_cast<double>(s.points);
        out.shallow.push_back(s);
      }
  return out;
}

BodyVersion write_body_version(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::string& plan_path,
                               const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& confined, const FifthBodyLaw& fifth,
                               const std::vector<ProbeWallForce>& grains, const std::string& out_dir, const std::string& name) {
  const BodyVersion a = analyse_body_version(plan, part, walls, confined, fifth, grains);
  const std::string title = "The probe's seventh part: a grain or a wall pressing a confined soft-particle";
  nlohmann::json j;
  j["plan"] = plan_path, j["code_version"] = code_version(), j["chosen"] = a.chosen, j["enters_engine"] = a.enters_engine, j["notes"] = a.notes;
  j["fifth"] = {{"form", fifth.form}, {"beta_wall", fifth.beta_wall}, {"beta_grain", fifth.beta_grain}, {"grain_exponent", fifth.grain_exponent}};
  std::string md = fmt::format(
      "# {} (generated by softpack-coarse probe-report, {})\n\n"
      "Plan: `{}` (`seventh_version`; paper/many-body.md, \"Next: a grain or a wall pressing a confined soft-particle\"). Seeds {}. "
      "The force on a grain or a wall at the first contact of a soft-particle that walls at Δn = D already press, against each form "
      "(`studies/coarse/probe_body.hpp`). Fitted on {}; held out: {}. The grains (every grain-X) share one β and one κ, the wall has "
      "its own. An error is exp(rms ln(pred/meas)) (mean of the logarithm), over the points whose measured or predicted force is "
      "above the floor; ± is the jackknife over the seeds; fifth's parameters are the fifth version's (grain exponent p = {:.3f}), "
      "not fitted here.\n\n"
      "| form | grains: β, κ | wall: β, κ | fit runs | held-out runs |",
      title, code_version(), plan_path, fmt::join(plan.seeds, ", "), fmt::join(part.fit, ", "), fmt::join(part.held_out, ", "), fifth.grain_exponent);
  for (const auto& [radius, Rs] : plan.radii) md += fmt::format(" held out, {} |", radius);
  md += "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < plan.radii.size(); ++i) md += "---|";
  md += "\n";
  for (const BodyVersion::Form& c : a.forms) {
    md += fmt::format("| {} |", c.name);
    nlohmann::json cj{{"fit", probe_error_json(c.fit)}, {"held_out", probe_error_json(c.held_out)}};
    for (const char* body : kBodies) {
      const BodyVersion::BodyLaw& l = c.body.at(body);
      md += fmt::format(" {:.3f} ± {:.3f}, {:.3f} ± {:.3f} |", l.beta.value, l.beta.se, l.kappa.value, l.kappa.se);
      cj["bodies"][body] = {{"beta", {{"value", l.beta.value}, {"se", l.beta.se}}}, {"kappa", {{"value", l.kappa.value}, {"se", l.kappa.se}}}};
    }
    md += fmt::format(" {} | {} |", error_factor(c.fit), error_factor(c.held_out));
    for (const auto& [radius, e] : c.held_out_by_radius) md += fmt::format(" {} |", error_factor(e)), cj["held_out_by_radius"][radius] = probe_error_json(e);
    for (const auto& [arrangement, e] : c.by_arrangement) cj["arrangements"][arrangement] = probe_error_json(e);
    md += "\n";
    j["forms"][c.name] = cj;
  }
  md += "\n| run | role |";
  for (const BodyVersion::Form& c : a.forms) md += fmt::format(" {} |", c.name);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < a.forms.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& [arrangement, e] : a.forms.front().by_arrangement) {
    md += fmt::format("| {} | {} |", arrangement, listed(part.held_out, arrangement) ? "held out" : "fit");
    for (const BodyVersion::Form& c : a.forms) md += fmt::format(" {} |", error_factor(c.by_arrangement.at(arrangement)));
    md += "\n";
  }
  md += fmt::format("\nChosen by the rule: **{}**; it enters the engine: **{}** (its held-out error below fifth's at each radius).\n", a.chosen,
                    a.enters_engine ? "yes" : "no");
  for (const std::string& n : a.notes) md += fmt::format("\n- {}", n);
  if (!a.earlier.empty()) {
    md += fmt::format("\n\nReported, not in the rule: fifth and {} on the earlier parts' runs, where every contact moves at once (the "
                      "first part's walls' arrangements, the second part's grains'; the single contacts left out), with this part's error.\n\n"
                      "| runs | fifth | {} |\n|---|---|---|\n",
                      a.chosen, a.chosen);
    for (const auto& [what, e] : a.earlier) {
      md += fmt::format("| {} | {} | {} |\n", what, error_factor(e.first), error_factor(e.second));
      j["earlier"][what] = {{"fifth", probe_error_json(e.first)}, {a.chosen, probe_error_json(e.second)}};
    }
  }
  md += "\n\n## What the fifth version gives of a shallow contact under confinement\n\n"
        "Each kind at each Δn below 0.1 of its grid, over its arrangements and seeds: the first contacts, those with a measured force "
        "above 0, the mean measured force and the fifth version's mean prediction (the law file's, without any stress term on grains "
        "and walls), and their ratio.\n\n"
        "| radius | kind | Δn | contacts | pushed | measured [N] | fifth [N] | fifth / measured |\n|---|---|---|---|---|---|---|---|\n";
  for (const BodyVersion::Shallow& s : a.shallow) {
    md += fmt::format("| {} | {} | {:.3f} | {} | {} | {:.4g} | {:.4g} | {} |\n", s.radius, s.kind, s.delta_n, s.points, s.pushed, s.measured, s.fifth,
                      s.measured > 0.0 ? fmt::format("{:.3f}", s.fifth / s.measured) : "–");
    j["shallow"].push_back({{"radius", s.radius}, {"kind", s.kind}, {"delta_n", s.delta_n}, {"points", s.points}, {"pushed", s.pushed},
                            {"measured", s.measured}, {"fifth", s.fifth}});
  }

  // The curves: each run of the part, the first body's force.
  std::vector<ProbeWallForce> points;
  for (const ProbeWallForce& w : walls)
    if (w.arrangement == "one") points.push_back(w);
  const auto X1 = fit_single_contact(plan, points);
  std::vector<std::string> drawn = part.fit, form_names;
  drawn.insert(drawn.end(), part.held_out.begin(), part.held_out.end());
  for (const BodyVersion::Form& c : a.forms) form_names.push_back(c.name);
  write_confined_curves(plan, confined, drawn, form_names, [&](std::size_t f, const ProbeWallForce& w) { return predict(a.forms[f], fifth, X1, w); },
                        title, out_dir, name, "grain or wall");
  write_file_atomically(out_dir + "/" + name + ".md", md);
  write_file_atomically(out_dir + "/" + name + ".json", j.dump(2) + "\n");
  return a;
}

}  // namespace softpack
