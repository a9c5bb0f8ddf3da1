#include "coarse/probe_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"

namespace softpack {

ProbeWallForce probe_point(const ProbeArrangement& a, const std::string& radius, std::uint64_t seed, const std::vector<double>& delta_n,
                           std::size_t wall, double Fn) {
  ProbeWallForce p{radius, a.name, seed, delta_n, wall, Fn, a.body, 0.0};
  std::vector<Vec3> u;
  for (std::size_t k = 0; k < delta_n.size(); ++k) u.push_back(a.walls.at(k).u);
  p.E_union = cap_union_volume(u, delta_n);
  return p;
}

void set_other_contacts(ProbeWallForce* row, std::size_t n, const ProbeArrangement& a) {
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) total += row[k].Fn;
  for (std::size_t k = 0; k < n; ++k) {
    row[k].others_Fn = total - row[k].Fn, row[k].others_along = 0.0;
    for (std::size_t l = 0; l < n; ++l)
      if (l != k) {
        const double c = a.walls.at(l).u.dot(a.walls.at(k).u);
        row[k].others_along += row[l].Fn * c * c;
      }
  }
}

std::vector<ProbeWallForce> read_probe_file(const std::string& path, const std::string& radius, std::uint64_t seed) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the probe file (make many-body-probe writes it)", path));
  std::vector<ProbeWallForce> out;
  std::string arrangement;
  std::vector<double> w;
  ProbeArrangement geometry;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto fail = [&](const std::string& what) { return InputError(fmt::format("{}:{}: {}", path, line_no, what)); };
    if (line.rfind("# arrangement ", 0) == 0) {
      const auto colon = line.find(": ", 14);  // the name may hold ':' (NAME:BODY), not ": "
      if (colon == std::string::npos) throw fail("an arrangement line without ': '");
      arrangement = line.substr(14, colon - 14);
      w.clear();
      for (auto at = line.find(" w=", colon); at != std::string::npos; at = line.find(" w=", at + 3)) w.push_back(std::stod(line.substr(at + 3)));
      if (w.empty()) throw fail("an arrangement without walls");
      try {
        geometry = builtin_arrangement(arrangement, seed);
      } catch (const InputError& e) {
        throw fail(e.what());
      }
      if (geometry.walls.size() != w.size()) throw fail(fmt::format("{} walls, the arrangement has {}", w.size(), geometry.walls.size()));
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    if (arrangement.empty()) throw fail("a row before any '# arrangement' line");
    std::istringstream s(line);
    std::size_t n = 0;
    double dn = 0.0;
    if (!(s >> n >> dn) || n != w.size()) throw fail(fmt::format("expected '{} delta_n' and {} forces", w.size(), w.size()));
    std::vector<double> delta_n;  // with +walls-D the other contacts' walls stand at D (their w_k D)
    for (const double wk : w) delta_n.push_back(wk * (delta_n.empty() || !(geometry.body.walls_at > 0.0) ? dn : geometry.body.walls_at));
    for (std::size_t k = 0; k < n; ++k) {
      double F = 0.0;
      if (!(s >> F) || !std::isfinite(F)) throw fail(fmt::format("wall {}: no finite force", k + 1));
      out.push_back(k == 0 ? probe_point(geometry, radius, seed, delta_n, k, F) : out.back());
      out.back().wall = k, out.back().Fn = F;
    }
    set_other_contacts(out.data() + (out.size() - n), n, geometry);
  }
  return out;
}

double ProbeLaw::predict(const ProbeWallForce& w) const {
  const double F = predict_alone(w);
  if (!(stress > 0.0)) return F;
  // p π Rs² over κ: mean Σ F_l / 4; along the line 3 Σ F_l (u_l·u_k)² / 4; across it
  // 3 Σ F_l (1 − (u_l·u_k)²) / 8 (own contact excluded: each sum is over the others)
  const double p_area = stress_form == StressForm::normal    ? 3.0 * w.others_along / 4.0
                        : stress_form == StressForm::lateral ? 3.0 * (w.others_Fn - w.others_along) / 8.0
                                                             : w.others_Fn / 4.0;
  return F + stress * std::max(0.0, p_area) * cap_area(w.delta_n[w.wall]);
}

ProbeLaw::StressForm ProbeLaw::stress_form_of(const std::string& name) {
  if (name == "stress") return StressForm::mean;
  if (name == "stress-normal") return StressForm::normal;
  if (name == "stress-lateral") return StressForm::lateral;
  throw InputError(fmt::format("'{}' is not a stress form; allowed: stress, stress-normal, stress-lateral", name));
}

double ProbeLaw::predict_alone(const ProbeWallForce& w) const {
  const fit::PowerLawFit& f1 = F1.at(w.radius);
  const double dk = w.delta_n[w.wall];
  const double x = w.body.radius_ratio, g = w.body.kind == PressingBody::Kind::grain && grain_exponent != 0.0 ? std::pow(x / (1.0 + x), grain_exponent) : 1.0;
  if (name == "pairwise") return g * fit::evaluate(f1, dk);
  const double vk = cap_volume(dk);
  if (!(vk > 0.0)) return 0.0;
  double others = 0.0;  // the others' caps: summed (as the engine's body pass sums them), or their union's share
  if (name == "volumetric-union" || name == "onset-shift") others = std::max(0.0, w.E_union - vk);
  else
    for (std::size_t l = 0; l < w.delta_n.size(); ++l)
      if (l != w.wall) others += cap_volume(w.delta_n[l]);
  if (name == "ratio") return g * fit::evaluate(f1, dk) * std::pow((vk + others) / vk, parameter);
  if (name == "onset-shift") {  // the pressure at the depth dk + γ others times the contact's own base
    const double star = dk + parameter * others;
    return star > dk && star < 2.0 ? g * fit::evaluate(f1, star) * cap_area(dk) / cap_area(star) : g * fit::evaluate(f1, dk);
  }
  return many_body_force([&](double d) { return fit::evaluate(f1, d); }, g, dk, others, parameter);  // volumetric: the engine's law
}

namespace {

// The floor of each radius: force_floor x F1 at the plan's largest Δn.
double floor_of(const ProbeLaw& law, const std::string& radius, const ManyBodyProbe& plan) {
  return plan.force_floor * fit::evaluate(law.F1.at(radius), plan.delta_n.back());
}

}  // namespace

std::map<std::string, fit::PowerLawFit> fit_single_contact(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls,
                                                           const std::string& one) {
  std::map<std::string, fit::PowerLawFit> out;
  for (const auto& [radius, Rs] : plan.radii) {
    std::vector<double> dn, mean, se;
    for (const double d : plan.delta_n) {
      std::vector<double> F;
      for (const ProbeWallForce& w : walls)
        if (w.radius == radius && w.arrangement == one && std::abs(w.delta_n[0] - d) < 1e-9) F.push_back(w.Fn);
      if (F.empty()) continue;
      const MeanError m = mean_error(F);
      dn.push_back(d), mean.push_back(m.mean), se.push_back(m.error);
    }
    fit::FitOptions o;
    o.weighting = fit::FitOptions::Weighting::relative;
    o.onset_force = plan.force_floor;
    try {
      out[radius] = fit::fit_normal_law(dn, mean, se, o);
    } catch (const InputError& e) {
      throw InputError(fmt::format("radius {}: the single contact ('{}') cannot be fitted: {}", radius, one, e.what()));
    }
  }
  return out;
}

namespace {

std::size_t parameters(const std::string& name) { return name == "pairwise" ? 0 : 1; }

}  // namespace

double fit_parameter(ProbeLaw law, double hi, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                     const ManyBodyProbe& plan, double ProbeLaw::*field) {
  const auto error = [&](double x) {
    law.*field = x;
    return probe_error(law, walls, arrangements, plan).rms_log;
  };
  double best = 0.0, best_e = error(0.0);
  for (int i = 1; i <= 1000; ++i) {
    const double x = hi * i / 1000.0, e = error(x);
    if (e < best_e) best = x, best_e = e;
  }
  double a = std::max(0.0, best - hi / 1000.0), b = std::min(hi, best + hi / 1000.0);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 60; ++i) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    (error(x1) < error(x2) ? b : a) = (error(x1) < error(x2) ? x2 : x1);
  }
  const double x = 0.5 * (a + b);
  return error(x) < best_e ? x : best;
}

double jackknife_over_seeds(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls,
                            const std::function<double(const std::vector<ProbeWallForce>&)>& fit) {
  std::vector<double> theta;
  for (const std::uint64_t seed : plan.seeds) {
    std::vector<ProbeWallForce> rest;
    for (const ProbeWallForce& w : walls)
      if (w.seed != seed) rest.push_back(w);
    theta.push_back(fit(rest));
  }
  return jackknife_error(theta);
}

double jackknife_parameter(const std::string& name, double hi, const std::vector<ProbeWallForce>& walls,
                           const std::vector<std::string>& arrangements, const ManyBodyProbe& plan, const std::string& one) {
  return jackknife_over_seeds(plan, walls, [&](const std::vector<ProbeWallForce>& rest) {  // F1 and the parameter again
    return fit_parameter(ProbeLaw{name, 0.0, fit_single_contact(plan, rest, one)}, hi, rest, arrangements, plan);
  });
}

ProbeError probe_error(const ProbeLaw& law, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                       const ManyBodyProbe& plan) {
  return probe_error(law, walls, arrangements, plan, [&](std::size_t i) { return law.predict(walls[i]); });
}

ProbeError probe_error(const ProbeLaw& law, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                       const ManyBodyProbe& plan, const std::function<double(std::size_t)>& predict) {
  ProbeError e;
  double sum = 0.0, sum2 = 0.0;
  std::map<std::string, double> floors;
  for (const auto& [radius, f] : law.F1) floors[radius] = floor_of(law, radius, plan);
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const ProbeWallForce& w = walls[i];
    if (!arrangements.empty() && std::find(arrangements.begin(), arrangements.end(), w.arrangement) == arrangements.end()) continue;
    const double floor = floors.at(w.radius);
    const double predicted = law.count_predicted_force || w.Fn > floor ? predict(i) : 0.0;
    if (!(w.Fn > floor) && !(law.count_predicted_force && predicted > floor)) continue;
    const double r = std::log(std::max(predicted, floor) / std::max(w.Fn, floor));
    sum += r, sum2 += r * r, ++e.points;
  }
  if (e.points > 0) e.mean_log = sum / static_cast<double>(e.points), e.rms_log = std::sqrt(sum2 / static_cast<double>(e.points));
  return e;
}

ProbeAnalysis analyse_probe(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls) {
  ProbeAnalysis out;
  const auto F1 = fit_single_contact(plan, walls);
  const std::vector<std::string> all = plan.arrangements();
  for (const std::string& name : plan.candidates) {
    ProbeCandidate c;
    c.law = ProbeLaw{name, 0.0, F1};
    const double hi = name == "volumetric" ? 1.5 : 3.0;
    if (parameters(name) > 0) {
      c.law.parameter = fit_parameter(c.law, hi, walls, plan.fit, plan);
      c.parameter_error = jackknife_parameter(name, hi, walls, plan.fit, plan);
    }
    c.fit = probe_error(c.law, walls, plan.fit, plan);
    c.held_out = probe_error(c.law, walls, plan.held_out, plan);
    for (const std::string& a : all) c.by_arrangement[a] = probe_error(c.law, walls, {a}, plan);
    for (const auto& [radius, Rs] : plan.radii) {
      std::vector<ProbeWallForce> of_radius;
      for (const ProbeWallForce& w : walls)
        if (w.radius == radius) of_radius.push_back(w);
      c.by_radius[radius] = probe_error(c.law, of_radius, plan.held_out, plan);
    }
    out.candidates.push_back(c);
  }
  // The rule: the least held-out error; fewer parameters win within tie_factor of it.
  double least = 0.0;
  for (const ProbeCandidate& c : out.candidates) least = (&c == &out.candidates[0] || c.held_out.rms_log < least) ? c.held_out.rms_log : least;
  const ProbeCandidate* chosen = nullptr;
  for (const ProbeCandidate& c : out.candidates) {
    if (!(c.held_out.rms_log <= plan.tie_factor * least)) continue;
    if (!chosen || parameters(c.law.name) < parameters(chosen->law.name) ||
        (parameters(c.law.name) == parameters(chosen->law.name) && c.held_out.rms_log < chosen->held_out.rms_log))
      chosen = &c;
  }
  out.chosen = chosen->law.name;
  const ProbeCandidate* pairwise = nullptr;
  for (const ProbeCandidate& c : out.candidates)
    if (c.law.name == "pairwise") pairwise = &c;
  out.enters_engine = chosen->law.name != "pairwise" && pairwise != nullptr;
  if (!pairwise) out.notes.push_back("pairwise is not among the candidates: the engine condition cannot be judged");
  std::set<std::string> several;
  for (const ProbeWallForce& w : walls)
    if (w.delta_n.size() >= 2) several.insert(w.arrangement);
  for (const std::string& a : plan.held_out)
    if (pairwise && several.count(a) && !(chosen->by_arrangement.at(a).rms_log < pairwise->by_arrangement.at(a).rms_log)) {
      out.enters_engine = false;
      out.notes.push_back(fmt::format("held-out {}: {} is not better than pairwise", a, out.chosen));
    }
  return out;
}

}  // namespace softpack
