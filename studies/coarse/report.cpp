#include "coarse/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

// Mean and standard error over seeds; NaN where not known (no seed, or one for the error).
MeanError seeds_mean_error(const std::vector<double>& v) { return mean_error(v, FewSeeds::not_known); }

// The value of column `get` of a run's rows of `phase` at `strain`, linear between rows; a row
// within `tolerance` of it (a phase's last row, a step short of the grid) stands for it; NaN
// farther outside the phase's strains.
template <class Get>
double at_strain(const CoarseResult& r, int phase, double strain, Get get, double tolerance) {
  if (phase == 2) {  // the shear: rows of phase 2 (and the last before it) by the wall's displacement
    const CurveRow* prev = nullptr;
    for (const CurveRow& row : r.rows) {
      if (row.phase != 2) {
        prev = &row;
        continue;
      }
      const double a = prev ? (prev->phase == 2 ? prev->shear : 0.0) : 0.0, b = row.shear;
      if (prev && (strain - a) * (strain - b) <= 0.0 && a != b) return get(*prev) + (strain - a) / (b - a) * (get(row) - get(*prev));
      if (std::abs(row.shear - strain) <= tolerance) return get(row);
      prev = &row;
    }
    return kNaN;
  }
  const CurveRow* prev = nullptr;
  for (const CurveRow& row : r.rows) {
    if (row.phase != phase && !(phase == -1 && &row == &r.rows.front())) {
      if (phase == -1 && row.phase == 1) prev = &row;  // unloading starts where loading ended
      continue;
    }
    if (prev) {
      const double a = prev->strain, b = row.strain;
      if ((strain - a) * (strain - b) <= 0.0 && a != b) {
        const double t = (strain - a) / (b - a);
        return get(*prev) + t * (get(row) - get(*prev));
      }
    }
    if (row.strain == strain) return get(row);
    prev = &row;
  }
  for (const CurveRow& row : r.rows)
    if (row.phase == phase && std::abs(row.strain - strain) <= tolerance) return get(row);
  return kNaN;
}

// The same values, NaN for NaN.
bool same_values(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])))) return false;
  return true;
}

}  // namespace

CoarseComparison compare_coarse(const std::vector<CoarseResult>& resolved, const std::vector<CoarseResult>& soft, double strain,
                                double unload_strain, double step, double shear, double shear_step) {
  CoarseComparison c;
  const std::vector<CoarseResult>* runs[2] = {&resolved, &soft};
  for (const CoarseResult& r : resolved) c.seeds.push_back(r.seed);
  std::vector<std::pair<double, int>> grid;
  const long n_load = std::lround(strain / step), n_unload = std::lround(unload_strain / step);
  for (long k = 0; k <= n_load; ++k) grid.emplace_back(std::min(strain, static_cast<double>(k) * step), 1);
  for (long k = 1; k <= n_unload; ++k) grid.emplace_back(strain - std::min(unload_strain, static_cast<double>(k) * step), -1);
  const long n_shear = shear_step > 0.0 ? std::lround(shear / shear_step) : 0;
  for (long k = 1; k <= n_shear; ++k) grid.emplace_back(std::min(shear, static_cast<double>(k) * shear_step), 2);
  bool agreeing = true;
  for (const auto& [e, phase] : grid) {
    CoarsePoint p;
    p.strain = phase == 2 ? strain - unload_strain : e, p.phase = phase, p.shear = phase == 2 ? e : 0.0;
    const double tol = phase == 2 ? 0.25 * shear_step : 0.25 * step;
    std::vector<double> diff;
    for (int m = 0; m < 2; ++m) {
      std::vector<double> sigma, K0, fraction, Z, tau;
      for (const CoarseResult& r : *runs[m]) {
        const double s = at_strain(r, phase, e, [](const CurveRow& w) { return w.sigma_top; }, tol);
        const double lat = at_strain(r, phase, e, [](const CurveRow& w) { return w.sigma_lateral; }, tol);
        p.sigma_seed[m].push_back(s);
        if (!std::isfinite(s)) continue;
        sigma.push_back(s);
        if (s > 0.0) K0.push_back(lat / s);
        fraction.push_back(at_strain(r, phase, e, [](const CurveRow& w) { return w.fraction; }, tol));
        Z.push_back(at_strain(r, phase, e, [](const CurveRow& w) { return w.Z; }, tol));
        tau.push_back(at_strain(r, phase, e, [](const CurveRow& w) { return w.tau; }, tol));
      }
      p.sigma[m] = seeds_mean_error(sigma), p.K0[m] = seeds_mean_error(K0), p.fraction[m] = seeds_mean_error(fraction), p.Z[m] = seeds_mean_error(Z);
      p.tau[m] = seeds_mean_error(tau);
    }
    for (std::size_t k = 0; k < resolved.size(); ++k) diff.push_back(p.sigma_seed[1][k] - p.sigma_seed[0][k]);
    p.sigma_difference = seeds_mean_error(diff);
    const double tolerance = 2.0 * std::hypot(p.sigma[0].error, p.sigma[1].error);
    p.agrees = std::abs(p.sigma[1].mean - p.sigma[0].mean) <= tolerance;
    if (phase == 1) {
      agreeing = agreeing && p.agrees;
      if (agreeing) c.agreement_strain = e;
    }
    c.points.push_back(p);
  }
  for (std::size_t k = 0; k < resolved.size(); ++k) {
    c.cpu[0].push_back(resolved[k].cpu_seconds), c.cpu[1].push_back(soft[k].cpu_seconds);
    c.speedup.push_back(resolved[k].cpu_seconds / soft[k].cpu_seconds);
    if (soft[k].beyond_range >= 0) c.beyond_range += soft[k].beyond_range, c.max_dn = std::max(c.max_dn, soft[k].max_dn);  // < 0: not counted (LAMMPS)
  }
  bool counted = !soft.empty();  // every soft run counts its contacts beyond the laws row by row
  double least = std::numeric_limits<double>::infinity();
  for (const CoarseResult& r : soft) {
    const double within = strain_within_laws(r.rows);
    counted = counted && !std::isnan(within), least = std::min(least, within);
  }
  if (counted) c.within_laws_strain = least;
  c.mean_speedup = seeds_mean_error(c.speedup);
  if (!resolved.empty()) c.spheres[0] = resolved[0].spheres, c.spheres[1] = soft[0].spheres, c.bodies = resolved[0].bodies;
  return c;
}

std::optional<PairedShift> paired_shift(const CoarseComparison& base, const CoarseComparison& c, std::string* why) {
  const auto none = [&](const std::string& reason) -> std::optional<PairedShift> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (c.seeds != base.seeds) return none("not the same media seeds");
  if (c.points.size() != base.points.size()) return none("not the same recorded strains");
  if (std::isnan(c.within_laws_strain) || std::isnan(base.within_laws_strain)) return none("a soft run does not count its contacts beyond the laws");
  PairedShift out;
  out.strain = std::min(c.within_laws_strain, base.within_laws_strain);
  if (out.strain < 0.0) return none("a soft run meets a contact beyond its laws from its first row");
  const CoarsePoint* at = nullptr;
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const CoarsePoint &p = c.points[k], &b = base.points[k];
    if (p.phase != b.phase || std::abs(p.strain - b.strain) > 1e-9) return none("not the same recorded strains");
    if (p.phase != 1) continue;
    if (!same_values(p.sigma_seed[0], b.sigma_seed[0])) return none(fmt::format("not the same resolved runs (σzz at strain {:.3f})", p.strain));
    if (std::abs(p.strain - out.strain) <= 1e-9) at = &p;
  }
  if (!at) return none(fmt::format("no loading point at strain {}", out.strain));
  const CoarsePoint& b = base.points[static_cast<std::size_t>(at - c.points.data())];
  std::vector<double> q;
  for (std::size_t s = 0; s < c.seeds.size(); ++s) q.push_back((at->sigma_seed[1][s] - b.sigma_seed[1][s]) / at->sigma_seed[0][s]);
  out.q = seeds_mean_error(q);
  const auto ratio = [](const CoarsePoint& p) {
    const double r = p.sigma[1].mean / p.sigma[0].mean;
    return MeanError{r, std::abs(r) * std::hypot(p.sigma[1].error / p.sigma[1].mean, p.sigma[0].error / p.sigma[0].mean)};
  };
  out.ratio[0] = ratio(b), out.ratio[1] = ratio(*at);
  return out;
}

std::string coarse_pm(const MeanError& m, const char* fmt_value) {
  if (!std::isfinite(m.mean)) return "–";
  const std::string v = fmt::format(fmt::runtime(fmt_value), m.mean);
  return std::isfinite(m.error) ? v + " ± " + fmt::format("{:.2g}", m.error) : v;
}

std::string coarse_run_path(const std::string& dir, CoarseModel model, std::uint64_t seed) {
  return fmt::format("{}/{}/seed-{}.h5", dir, name(model), seed);
}

std::optional<CoarseComparison> coarse_comparison(const CoarseGrainSettings& s, const std::string& dir) {
  std::vector<CoarseResult> resolved, soft;
  for (std::uint64_t seed : s.seeds) {
    const std::string a = coarse_run_path(dir, CoarseModel::resolved, seed), b = coarse_run_path(dir, CoarseModel::soft, seed);
    if (!std::filesystem::exists(a) || !std::filesystem::exists(b)) continue;
    resolved.push_back(read_coarse_result(a));
    soft.push_back(read_coarse_result(b));
  }
  if (resolved.empty()) return std::nullopt;
  return compare_coarse(resolved, soft, s.strain, s.unload_strain, s.record_strain, s.shear, s.record_shear);
}

void write_coarse_report(const CoarseComparison& c, const CoarseGrainSettings& s, const std::string& label, const std::string& out) {
  std::filesystem::create_directories(out);

  std::ostringstream dat;
  dat << "# coarse-grain report: " << label << ", seeds";
  for (auto seed : c.seeds) dat << ' ' << seed;
  dat << "\n# strain phase sigma_res sigma_res_se sigma_soft sigma_soft_se K0_res K0_res_se K0_soft K0_soft_se"
         " fraction_res fraction_soft Z_res Z_res_se Z_soft Z_soft_se diff diff_se agrees tau_res tau_res_se tau_soft tau_soft_se\n"
         "# (the third block, phase 2, is the shear: column 1 is then the top wall's displacement / H0)\n";
  int last_phase = 1;
  for (const CoarsePoint& p : c.points) {
    if (p.phase != last_phase) dat << "\n\n", last_phase = p.phase;
    dat << fmt::format("{:.6f} {} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6f} {:.6f} {:.4f} {:.4f} {:.4f} {:.4f} {:.6e} {:.6e} {} "
                       "{:.6e} {:.6e} {:.6e} {:.6e}\n",
                       p.phase == 2 ? p.shear : p.strain, p.phase, p.sigma[0].mean, p.sigma[0].error, p.sigma[1].mean, p.sigma[1].error, p.K0[0].mean,
                       p.K0[0].error, p.K0[1].mean, p.K0[1].error, p.fraction[0].mean, p.fraction[1].mean, p.Z[0].mean, p.Z[0].error,
                       p.Z[1].mean, p.Z[1].error, p.sigma_difference.mean, p.sigma_difference.error, p.agrees ? 1 : 0,
                       p.tau[0].mean, p.tau[0].error, p.tau[1].mean, p.tau[1].error);
  }
  write_file_atomically((std::filesystem::path(out) / "curves.dat").string(), dat.str());

  std::ostringstream md;
  md << "# Coarse-grain validation: resolved against soft-particles\n\n";
  md << fmt::format("Settings `{}`; seeds", label);
  for (auto seed : c.seeds) md << ' ' << seed;
  md << fmt::format(". Resolved: {} spheres; soft: {} spheres ({} bodies). Code {}.\n\n", c.spheres[0], c.spheres[1], c.bodies,
                    code_version());
  md << "| strain | phase | σzz resolved [Pa] | σzz soft [Pa] | soft − resolved [Pa] | agrees | K0 resolved | K0 soft | φ resolved | φ soft | Z resolved | Z soft |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const long every = std::max(1L, std::lround(0.01 / s.record_strain));
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const CoarsePoint& p = c.points[k];
    if (p.phase == 2) continue;
    if (k % static_cast<std::size_t>(every) != 0 && k + 1 != c.points.size() && c.points[k + 1].phase != 2) continue;
    md << fmt::format("| {:.3f} | {} | {} | {} | {} | {} | {} | {} | {:.4f} | {:.4f} | {} | {} |\n", p.strain,
                      p.phase > 0 ? "load" : "unload", coarse_pm(p.sigma[0]), coarse_pm(p.sigma[1]), coarse_pm(p.sigma_difference), p.agrees ? "yes" : "no",
                      coarse_pm(p.K0[0], "{:.3f}"), coarse_pm(p.K0[1], "{:.3f}"), p.fraction[0].mean, p.fraction[1].mean, coarse_pm(p.Z[0], "{:.2f}"),
                      coarse_pm(p.Z[1], "{:.2f}"));
  }
  if (s.shear > 0.0) {
    md << fmt::format("\nPlaten shear at axial strain {:.3f}: the top wall moved along x by `shear` of the initial height.\n\n",
                      s.strain - s.unload_strain);
    md << "| shear | τ resolved [Pa] | τ soft [Pa] | τ/σzz resolved | τ/σzz soft | σzz resolved [Pa] | σzz soft [Pa] |\n";
    md << "|---|---|---|---|---|---|---|\n";
    for (const CoarsePoint& p : c.points) {
      if (p.phase != 2) continue;
      md << fmt::format("| {:.3f} | {} | {} | {:.3f} | {:.3f} | {} | {} |\n", p.shear, coarse_pm(p.tau[0]), coarse_pm(p.tau[1]),
                        p.tau[0].mean / p.sigma[0].mean, p.tau[1].mean / p.sigma[1].mean, coarse_pm(p.sigma[0]), coarse_pm(p.sigma[1]));
    }
  }
  md << fmt::format("\nAgreement (|soft − resolved| ≤ 2 √(se² + se²) of the two means) at every loading point up to strain **{:.3f}**.\n",
                    c.agreement_strain);
  md << fmt::format("Speed-up (CPU time resolved / soft, per seed): **{}**; CPU [s] resolved", coarse_pm(c.mean_speedup, "{:.1f}"));
  for (double t : c.cpu[0]) md << fmt::format(" {:.1f}", t);
  md << ", soft";
  for (double t : c.cpu[1]) md << fmt::format(" {:.2f}", t);
  md << fmt::format(".\nSoft contacts beyond the laws' measured range: {} evaluations (largest Δn {:.3f}).\n", c.beyond_range, c.max_dn);
  if (!std::isnan(c.within_laws_strain))
    md << (c.within_laws_strain < 0.0 ? std::string("The soft runs meet a contact beyond the laws' range from their first row.\n")
                                      : fmt::format("The soft runs' stress is within the laws' measured range up to loading strain **{:.3f}** "
                                                    "(the last row before any seed's first contact beyond it).\n",
                                                    c.within_laws_strain));
  write_file_atomically((std::filesystem::path(out) / "coarse-grain.md").string(), md.str());

  nlohmann::json j;
  j["settings"] = label;
  j["seeds"] = c.seeds;
  j["agreement_strain"] = c.agreement_strain;
  j["speedup"] = {{"mean", c.mean_speedup.mean}, {"error", std::isfinite(c.mean_speedup.error) ? nlohmann::json(c.mean_speedup.error) : nlohmann::json()}, {"per_seed", c.speedup}};
  j["cpu_seconds"] = {{"resolved", c.cpu[0]}, {"soft", c.cpu[1]}};
  j["spheres"] = {{"resolved", c.spheres[0]}, {"soft", c.spheres[1]}};
  j["bodies"] = c.bodies;
  j["beyond_range"] = c.beyond_range;
  j["max_dn"] = c.max_dn;
  j["within_laws_strain"] = std::isnan(c.within_laws_strain) ? nlohmann::json() : nlohmann::json(c.within_laws_strain);
  j["code_version"] = code_version();
  write_file_atomically((std::filesystem::path(out) / "summary.json").string(), j.dump(1) + "\n");
}

}  // namespace softpack
