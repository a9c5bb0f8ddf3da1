#include "coarse/probe_second.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

LogRatio log_ratio(const std::vector<double>& ratios) {
  std::vector<double> logs;
  for (const double x : ratios) logs.push_back(std::log(x));
  const MeanError m = mean_error(logs);
  return {m.mean, m.error, ratios.size()};
}

bool same(double a, double b) { return std::abs(a - b) < 1e-9; }

// The force of the first contact of arrangement `name` at Δn of one radius and seed (NaN if absent).
double first_force(const std::vector<ProbeWallForce>& f, const std::string& radius, const std::string& name, std::uint64_t seed, double dn) {
  for (const ProbeWallForce& w : f)
    if (w.wall == 0 && w.seed == seed && w.radius == radius && w.arrangement == name && same(w.delta_n[0], dn)) return w.Fn;
  return std::nan("");
}

// One seed's shear chain at one Δn: kt [N/m], the sliding ratio at the largest ht, Fn at ht = 0.
struct Chain {
  double kt = std::nan(""), mu = std::nan(""), Fn0 = std::nan("");
};
Chain chain(std::vector<ShearRow> rows, double Rs, double ht_window, double ht_last) {
  std::sort(rows.begin(), rows.end(), [](const ShearRow& a, const ShearRow& b) { return a.ht < b.ht; });
  Chain c;
  if (rows.empty() || rows.front().ht != 0.0) return c;
  const ShearRow& zero = rows.front();
  c.Fn0 = zero.Fn;
  double num = 0.0, den = 0.0;
  for (const ShearRow& r : rows)
    if (r.ht > 0.0 && r.ht <= ht_window * (1.0 + 1e-12)) num += (r.Ft - zero.Ft) * r.ht * Rs, den += r.ht * Rs * r.ht * Rs;
  if (den > 0.0) c.kt = num / den;
  if (same(rows.back().ht, ht_last) && rows.back().Fn > 0.0) c.mu = rows.back().Ft / rows.back().Fn;
  return c;
}

std::string ratio_text(const LogRatio& r) {
  if (r.seeds == 0) return "–";
  if (r.seeds == 1) return fmt::format("{:.3f} (one seed)", std::exp(r.mean));  // no spread to judge it by
  return fmt::format("{:.3f} ({:+.3f} ± {:.3f}){}", std::exp(r.mean), r.mean, r.se, r.within() ? "" : " *");
}
nlohmann::json ratio_json(const LogRatio& r) { return {{"ratio", std::exp(r.mean)}, {"mean_log", r.mean}, {"se_log", r.se}, {"seeds", r.seeds}, {"within", r.within()}}; }

}  // namespace

std::string error_factor(const ProbeError& e) { return e.points ? fmt::format("{:.2f} ({:+.2f})", std::exp(e.rms_log), e.mean_log) : "–"; }
nlohmann::json probe_error_json(const ProbeError& e) { return {{"rms_log", e.rms_log}, {"mean_log", e.mean_log}, {"points", e.points}}; }

std::vector<ShearRow> read_shear_file(const std::string& path, const std::string& radius, std::uint64_t seed) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the shear file (make many-body-probe writes it)", path));
  std::vector<ShearRow> out;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    ShearRow r{radius, {}, seed, 0.0, 0.0, 0.0, 0.0};
    if (!(s >> r.arrangement >> r.delta_n >> r.ht >> r.Fn >> r.Ft) || !std::isfinite(r.Fn) || !std::isfinite(r.Ft))
      throw InputError(fmt::format("{}:{}: expected 'arrangement delta_n ht/Rs Fn Ft' with finite forces", path, line_no));
    out.push_back(r);
  }
  return out;
}

SecondPart analyse_second_part(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& bodies,
                               const std::vector<ShearRow>& shear, double beta) {
  SecondPart out;
  out.beta_walls = beta;
  const auto F1_walls = fit_single_contact(plan, walls);
  for (const auto& [kind, arrangements] : plan.body_groups) {
    const std::string one = kind == "wall" ? "one" : "one:" + kind;
    const std::vector<ProbeWallForce>& ones = kind == "wall" ? walls : bodies;
    // 1. the single contact over the wall's, per seed, where both are above the walls' floor
    for (const auto& [radius, Rs] : plan.radii) {
      if (kind == "wall") break;  // its single contact is the walls' own
      const double floor = plan.force_floor * fit::evaluate(F1_walls.at(radius), plan.delta_n.back());
      for (const double dn : plan.delta_n) {
        std::vector<double> r;
        for (const std::uint64_t seed : plan.seeds) {
          const double Fk = first_force(bodies, radius, one, seed, dn), Fw = first_force(walls, radius, "one", seed, dn);
          if (Fk > floor && Fw > floor) r.push_back(Fk / Fw);
        }
        out.single[kind][radius][dn] = log_ratio(r);
      }
    }
    // 2. several contacts: the kind's own F1, the walls' β
    SecondPart::KindErrors& k = out.kinds[kind];
    std::map<std::string, fit::PowerLawFit> F1;
    try {
      F1 = fit_single_contact(plan, ones, one);
    } catch (const InputError& e) {
      out.notes.push_back(fmt::format("{}: no F1, so no errors: {}", kind, e.what()));
      continue;
    }
    std::vector<std::string> several;
    for (const std::string& a : arrangements)
      if (a != "one") several.push_back(a + ":" + kind);
    const ProbeLaw pairwise{"pairwise", 0.0, F1}, volumetric{"volumetric", beta, F1}, engine{"volumetric", 0.5 * beta, F1};
    k.carries_over = true;
    for (const std::string& a : several) {
      k.pairwise[a] = probe_error(pairwise, bodies, {a}, plan);
      k.volumetric[a] = probe_error(volumetric, bodies, {a}, plan);
      if (kind == "soft") k.engine[a] = probe_error(engine, bodies, {a}, plan);
      if (!(k.volumetric[a].rms_log < k.pairwise[a].rms_log)) k.carries_over = false;
    }
    k.beta = fit_parameter(ProbeLaw{"volumetric", 0.0, F1}, 3.0, bodies, several, plan);
    std::vector<ProbeWallForce> with_ones = bodies;  // the wall kind's single contact is in `walls`
    if (kind == "wall") with_ones.insert(with_ones.end(), walls.begin(), walls.end());
    k.beta_se = jackknife_parameter("volumetric", 3.0, with_ones, several, plan, one);
  }
  // 3. the confined shear over `one`'s
  for (const auto& [radius, Rs] : plan.radii)
    for (const double dn : plan.shear_delta_n) {
      std::map<std::string, std::map<std::uint64_t, Chain>> chains;
      for (const std::string& a : plan.shear_arrangements)
        for (const std::uint64_t seed : plan.seeds) {
          std::vector<ShearRow> rows;
          for (const ShearRow& r : shear)
            if (r.radius == radius && r.arrangement == a && r.seed == seed && same(r.delta_n, dn)) rows.push_back(r);
          chains[a][seed] = chain(rows, Rs, plan.shear_ht[1], plan.shear_ht.back());
        }
      for (const std::string& a : plan.shear_arrangements) {
        SecondPart::Shear& s = out.shear[radius][a][dn];
        std::vector<double> kt, mu, Fn;
        double n = 0.0;
        for (const std::uint64_t seed : plan.seeds) {
          const Chain &c = chains[a][seed], &o = chains["one"][seed];
          if (c.kt > 0.0 && o.kt > 0.0) kt.push_back(c.kt / o.kt);
          else if (a != "one")
            out.notes.push_back(fmt::format("{} {} at Δn {}, seed {}: kt {:.4g} N/m, one's {:.4g}: no kt ratio", radius, a, dn, seed, c.kt, o.kt));
          if (c.mu > 0.0 && o.mu > 0.0) mu.push_back(c.mu / o.mu);
          if (c.Fn0 > 0.0 && o.Fn0 > 0.0) Fn.push_back(c.Fn0 / o.Fn0);
          if (std::isfinite(c.kt) && std::isfinite(c.mu) && std::isfinite(o.kt) && std::isfinite(o.mu))
            s.kt_mean += c.kt, s.mu_mean += c.mu, s.kt_one += o.kt, s.mu_one += o.mu, n += 1.0;
        }
        if (n > 0.0) s.kt_mean /= n, s.mu_mean /= n, s.kt_one /= n, s.mu_one /= n;
        s.kt = log_ratio(kt), s.mu = log_ratio(mu), s.Fn = log_ratio(Fn);
      }
    }
  return out;
}

std::vector<ProbeWallForce> read_bodies_files(const ManyBodyProbe& plan, const std::string& probe_dir, const std::vector<std::string>& kinds) {
  std::vector<ProbeWallForce> bodies;
  for (const auto& [radius, Rs] : plan.radii)
    for (const std::uint64_t seed : plan.seeds)
      for (const std::string& kind : kinds) {
        const auto b = read_probe_file(fmt::format("{}/{}/bodies-{}-{}.dat", probe_dir, radius, kind, seed), radius, seed);
        bodies.insert(bodies.end(), b.begin(), b.end());
      }
  return bodies;
}

std::vector<ShearRow> read_shear_files(const ManyBodyProbe& plan, const std::string& probe_dir) {
  std::vector<ShearRow> shear;
  for (const auto& [radius, Rs] : plan.radii)
    for (const std::uint64_t seed : plan.seeds) {
      const auto s = read_shear_file(fmt::format("{}/{}/shear-{}.dat", probe_dir, radius, seed), radius, seed);
      shear.insert(shear.end(), s.begin(), s.end());
    }
  return shear;
}

SecondPart write_second_part(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& walls,
                             const std::vector<ProbeWallForce>& bodies, const std::vector<ShearRow>& shear, double beta,
                             const std::string& out_dir) {
  const SecondPart a = analyse_second_part(plan, walls, bodies, shear, beta);
  nlohmann::json j;
  j["plan"] = plan_path, j["code_version"] = code_version(), j["beta_walls"] = beta, j["notes"] = a.notes;
  std::string md = fmt::format(
      "# The many-body probe's second part (generated by softpack-coarse probe-report, {})\n\n"
      "Plan: `{}` (`bodies`, `shear`; paper/many-body.md, \"The probe's second part\"). Seeds {}; {} body forces, {} shear points.\n"
      "A ratio is the geometric mean over the seeds of the per-seed ratio, with the mean ± standard error of its logarithm in "
      "brackets; * marks a ratio further than 2 standard errors from 1 (a ratio of one seed is not judged). An error is as in probe.md: exp(rms ln(pred/meas)) "
      "(mean of the logarithm).\n\n",
      code_version(), plan_path, fmt::join(plan.seeds, ", "), bodies.size(), shear.size());
  md += "## 1. One contact: the body's force over the wall's at the same Δn\n\n";
  for (const auto& [radius, Rs] : plan.radii) {
    md += fmt::format("Radius {} (Rs = {} m):\n\n| Δn |", radius, Rs);
    std::vector<std::string> kinds;  // the plan's order, the walls' own kind left out
    for (const auto& [kind, arrangements] : plan.body_groups)
      if (a.single.count(kind)) kinds.push_back(kind);
    for (const std::string& kind : kinds) md += fmt::format(" {} |", kind);
    md += "\n|---|";
    for (std::size_t i = 0; i < kinds.size(); ++i) md += "---|";
    md += "\n";
    for (const double dn : plan.delta_n) {
      md += fmt::format("| {} |", dn);
      for (const std::string& kind : kinds) {
        const LogRatio& r = a.single.at(kind).at(radius).at(dn);
        md += fmt::format(" {} |", ratio_text(r));
        j["single"][kind][radius][fmt::format("{}", dn)] = ratio_json(r);
      }
      md += "\n";
    }
    md += "\n";
  }
  md += fmt::format("## 2. Several contacts: errors with each kind's own single-contact F1 (walls' β = {:.3f})\n\n", beta);
  md += "| arrangement | pairwise | volumetric, walls' β | engine (soft: β/2) |\n|---|---|---|---|\n";
  for (const auto& [kind, k] : a.kinds) {
    for (const auto& [name, e] : k.pairwise) {
      md += fmt::format("| {} | {} | {} | {} |\n", name, error_factor(e), error_factor(k.volumetric.at(name)),
                        k.engine.count(name) ? error_factor(k.engine.at(name)) : std::string("as volumetric"));
      j["bodies"][kind]["arrangements"][name] = {{"pairwise", probe_error_json(e)}, {"volumetric", probe_error_json(k.volumetric.at(name))}};
      if (k.engine.count(name)) j["bodies"][kind]["arrangements"][name]["engine"] = probe_error_json(k.engine.at(name));
    }
    j["bodies"][kind]["beta_refit"] = k.beta, j["bodies"][kind]["beta_refit_se"] = k.beta_se, j["bodies"][kind]["carries_over"] = k.carries_over;
  }
  md += "\n| kind | β refitted on its arrangements (diagnosis) | volumetric carries over |\n|---|---|---|\n";
  for (const auto& [kind, k] : a.kinds) md += fmt::format("| {} | {:.3f} ± {:.3f} | {} |\n", kind, k.beta, k.beta_se, k.carries_over ? "yes" : "no");
  md += "\n## 3. Shear under confinement, over the arrangement `one` at the same Δn\n\n"
        "kt: slope of Ft − Ft(0) over the plan's first two ht (ht ≤ " + fmt::format("{}", plan.shear_ht[1]) + " Rs); μ: Ft / Fn at the largest ht; Fn: the first wall's at ht = 0. The engine "
        "predicts kt and μ ratios of 1.\n\n"
        "| radius | arrangement | Δn | Fn / Fn_one | kt [N/m] | kt / kt_one | μ | μ / μ_one |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& [radius, by_a] : a.shear)
    for (const std::string& name : plan.shear_arrangements)
      for (const auto& [dn, s] : by_a.at(name)) {
        md += fmt::format("| {} | {} | {} | {} | {:.4g} | {} | {:.3f} | {} |\n", radius, name, dn, ratio_text(s.Fn), s.kt_mean,
                          name == "one" ? std::string("1") : ratio_text(s.kt), s.mu_mean, name == "one" ? std::string("1") : ratio_text(s.mu));
        j["shear"][radius][name][fmt::format("{}", dn)] = {{"Fn", ratio_json(s.Fn)}, {"kt", ratio_json(s.kt)}, {"mu", ratio_json(s.mu)},
                                                          {"kt_mean", s.kt_mean}, {"mu_mean", s.mu_mean}, {"kt_one", s.kt_one}, {"mu_one", s.mu_one}};
      }
  for (const std::string& n : a.notes) md += fmt::format("\n- {}", n);
  std::filesystem::create_directories(out_dir);
  write_file_atomically(out_dir + "/second-part.md", md + "\n");
  write_file_atomically(out_dir + "/second-part.json", j.dump(2) + "\n");
  return a;
}

}  // namespace softpack
