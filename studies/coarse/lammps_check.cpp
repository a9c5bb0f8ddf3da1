#include "coarse/lammps_check.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {

namespace {

std::pair<double, double> strain_range(const ConfigNode& n) {
  const std::vector<ConfigNode> items = n.items();
  if (items.size() != 2) n.fail("give two strains, [from, to]");
  const double lo = items[0].number(), hi = items[1].number();
  if (!(lo >= 0.0 && hi > lo && hi < 1.0)) n.fail(fmt::format("[{}, {}] is not allowed; allowed: 0 <= from < to < 1", lo, hi));
  return {lo, hi};
}

bool in_range(double strain, double lo, double hi) { return strain >= lo - 1e-9 && strain <= hi + 1e-9; }

// |difference| / (bound sqrt(se0² + se1²)): <= 1 agrees.
double excess(const MeanError& a, const MeanError& b, double bound) {
  const double limit = bound * std::hypot(a.error, b.error), diff = std::abs(b.mean - a.mean);
  return limit > 0.0 ? diff / limit : (diff > 0.0 ? INFINITY : 0.0);
}

// The runs of `engine` (softpack or lammps) in `dir`, one per seed; `how`: the make goal that runs them.
std::vector<CoarseResult> runs_of(const std::string& dir, const std::vector<std::uint64_t>& seeds, const std::string& engine, const std::string& how) {
  std::vector<CoarseResult> out;
  for (const std::uint64_t seed : seeds) {
    const std::string path = fmt::format("{}/seed-{}.h5", dir, seed);
    if (!std::filesystem::exists(path)) throw InputError(fmt::format("{}: no such run ({})", path, how));
    out.push_back(read_coarse_result(path));
    if (out.back().engine != engine || out.back().model != "soft")
      throw InputError(fmt::format("{}: a run of the {} model by {}, where the check reads the soft model's by {}", path, out.back().model,
                                   out.back().engine, engine));
  }
  return out;
}

double seconds_of(const std::vector<CoarseResult>& runs) {
  double s = 0.0;
  for (const CoarseResult& r : runs) s += r.seconds;
  return s;
}

}  // namespace

LammpsCheckPlan read_lammps_check_plan(const std::string& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  root.allow_only({"lammps_check"});
  const ConfigNode c = root.at("lammps_check");
  c.allow_only({"study", "settings", "seeds", "ranks", "strain_range", "k0_strain_range", "bound_in_standard_errors"});
  LammpsCheckPlan p;
  p.study = c.at("study").string();
  for (const ConfigNode& s : c.at("settings").items()) p.settings.push_back(s.string());
  for (const ConfigNode& s : c.at("seeds").items()) {
    const long seed = s.integer();
    if (seed < 0) s.fail(fmt::format("{} is not allowed; allowed: a seed >= 0", seed));
    p.seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  for (const ConfigNode& r : c.at("ranks").items()) {
    const long n = r.integer();
    if (n < 1 || n > 4096) r.fail(fmt::format("{} is not allowed; allowed: 1 to 4096 ranks", n));
    p.ranks.push_back(static_cast<int>(n));
  }
  if (p.settings.empty() || p.seeds.size() < 2 || p.ranks.empty()) c.fail("give settings, at least two seeds (a spread) and ranks");
  std::tie(p.strain_lo, p.strain_hi) = strain_range(c.at("strain_range"));
  std::tie(p.k0_lo, p.k0_hi) = strain_range(c.at("k0_strain_range"));
  p.bound = c.at("bound_in_standard_errors").number();
  if (!(p.bound > 0.0 && p.bound <= 10.0)) c.at("bound_in_standard_errors").fail(fmt::format("{} is not allowed; allowed: 0 < bound <= 10", p.bound));
  return p;
}

LammpsVerdict judge_lammps(const CoarseComparison& c, const LammpsCheckPlan& plan, const std::string& setting, int ranks, double end_strain) {
  LammpsVerdict v;
  v.setting = setting, v.ranks = ranks;
  for (const CoarsePoint& p : c.points) {
    if (p.phase == 2) {
      v.tau[0] = p.tau[0], v.tau[1] = p.tau[1];  // the last point of the shear
      continue;
    }
    if (p.phase == 1 && std::abs(p.strain - end_strain) < 1e-9)
      v.end_sigma[0] = p.sigma[0], v.end_sigma[1] = p.sigma[1], v.end_K0[0] = p.K0[0], v.end_K0[1] = p.K0[1], v.end_ratio = p.sigma[1].mean / p.sigma[0].mean,
      v.end_difference = p.sigma_difference;
    if (in_range(p.strain, plan.strain_lo, plan.strain_hi)) {
      const double e = excess(p.sigma[0], p.sigma[1], plan.bound);
      ++v.sigma_points;
      v.sigma_agreeing += e <= 1.0;
      if (v.sigma_points == 1 || e > v.worst_excess) v.worst_excess = e, v.worst_strain = p.strain, v.worst_ratio = p.sigma[1].mean / p.sigma[0].mean;
    }
    if (p.phase == 1 && in_range(p.strain, plan.k0_lo, plan.k0_hi)) {
      const double e = excess(p.K0[0], p.K0[1], plan.bound);
      ++v.k0_points;
      v.k0_agreeing += e <= 1.0;  // an undefined K0 (NaN) does not agree
      if (v.k0_points == 1 || !(e <= v.k0_worst_excess)) v.k0_worst_excess = e, v.k0_worst_strain = p.strain;
    }
  }
  return v;
}

std::vector<LammpsVerdict> write_lammps_check(const LammpsCheckPlan& plan, const std::string& plan_path, const std::string& out_dir) {
  std::vector<LammpsVerdict> out;
  std::string md = fmt::format(
      "# The soft-particle medium in LAMMPS against softpack's engine (generated by softpack-coarse lammps-check, {})\n\n"
      "Rule (`{}`, written before the runs): LAMMPS's mean σzz over the media seeds {} within {} √(se_LAMMPS² + se_engine²) of the engine's at "
      "every loading and unloading point of strain {} to {}, and K0 likewise at every loading point of strain {} to {}. The media and the "
      "engine's soft runs are `{}`'s; LAMMPS runs the input `softpack-coarse export --lammps` writes (docs/lammps.md).\n\n"
      "| setting | ranks | σzz points within | worst (strain, excess, LAMMPS / engine) | K0 points within | K0 worst (strain, excess) "
      "| σzz end of loading, engine [Pa] | LAMMPS [Pa] | paired difference [Pa] | K0 there, engine | LAMMPS | τ end of shear, engine [Pa] | LAMMPS [Pa] | accepted |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      code_version(), plan_path, fmt::join(plan.seeds, ", "), plan.bound, plan.strain_lo, plan.strain_hi, plan.k0_lo, plan.k0_hi, plan.study);
  nlohmann::json j{{"plan", plan_path}, {"code_version", code_version()}, {"seeds", plan.seeds}};
  std::string ranks_md, time_md;
  for (const std::string& setting : plan.settings) {
    const CoarseGrainSettings s = read_coarse_grain_settings(fmt::format("{}/profiles/{}.yaml", plan.study, setting));
    const auto compare = [&](const std::vector<CoarseResult>& a, const std::vector<CoarseResult>& b) {
      return compare_coarse(a, b, s.strain, s.unload_strain, s.record_strain, s.shear, s.record_shear);
    };
    const std::vector<CoarseResult> engine = runs_of(fmt::format("{}/{}/soft", plan.study, setting), plan.seeds, "softpack", "the study's make goal");
    std::vector<std::vector<CoarseResult>> lammps;
    for (const int ranks : plan.ranks) {
      lammps.push_back(runs_of(fmt::format("{}/{}/np{}", out_dir, setting, ranks), plan.seeds, "lammps", "make lammps-check"));
      LammpsVerdict v = judge_lammps(compare(engine, lammps.back()), plan, setting, ranks, s.strain);
      v.seconds[0] = seconds_of(engine), v.seconds[1] = seconds_of(lammps.back());
      out.push_back(v);
      md += fmt::format("| {} | {} | {} of {} | {:.3f}, {:.2f}, {:.3f} | {} of {} | {:.3f}, {:.2f} | {} | {} | {} | {} | {} | {} | {} | **{}** |\n", setting, ranks,
                        v.sigma_agreeing, v.sigma_points, v.worst_strain, v.worst_excess, v.worst_ratio, v.k0_agreeing, v.k0_points, v.k0_worst_strain,
                        v.k0_worst_excess, coarse_pm(v.end_sigma[0]), coarse_pm(v.end_sigma[1]), coarse_pm(v.end_difference), coarse_pm(v.end_K0[0], "{:.3f}"),
                        coarse_pm(v.end_K0[1], "{:.3f}"), coarse_pm(v.tau[0]), coarse_pm(v.tau[1]), v.accepted() ? "yes" : "no");
      time_md += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.2f} |\n", setting, ranks, v.seconds[0], v.seconds[1], v.seconds[1] / v.seconds[0]);
      j["settings"][setting][std::to_string(ranks)] = {
          {"sigma_points", v.sigma_points}, {"sigma_agreeing", v.sigma_agreeing}, {"worst_strain", v.worst_strain}, {"worst_excess", v.worst_excess},
          {"worst_ratio", v.worst_ratio},   {"k0_points", v.k0_points},           {"k0_agreeing", v.k0_agreeing},   {"end_ratio", v.end_ratio},
          {"accepted", v.accepted()},       {"engine_seconds", v.seconds[0]},      {"lammps_seconds", v.seconds[1]}};
    }
    for (std::size_t k = 1; k < lammps.size(); ++k) {  // more ranks against the first count, by the same rule
      const LammpsVerdict v = judge_lammps(compare(lammps[0], lammps[k]), plan, setting, plan.ranks[k], s.strain);
      ranks_md += fmt::format("| {} | {} against {} | {} of {} | {:.3f}, {:.2f} | {} of {} |\n", setting, plan.ranks[k], plan.ranks[0], v.sigma_agreeing,
                              v.sigma_points, v.worst_strain, v.worst_excess, v.k0_agreeing, v.k0_points);
    }
  }
  if (!ranks_md.empty())
    md += "\n## More ranks against the first count (reported outside the rule)\n\nThe same comparison and bound, LAMMPS's runs on more ranks "
          "against its runs on the first count: the sums' order changes with the ranks, so the runs part like any two runs of a granular medium.\n\n"
          "| setting | ranks | σzz points within | worst (strain, excess) | K0 points within |\n|---|---|---|---|---|\n" + ranks_md;
  md += "\n## Time (the runs' own, summed over the seeds; not a benchmark: `make bench` is)\n\n"
        "| setting | ranks | engine [s] | LAMMPS [s] | LAMMPS / engine |\n|---|---|---|---|---|\n" + time_md;
  std::filesystem::create_directories(out_dir + "/report");
  write_file_atomically(out_dir + "/report/check.md", md);
  write_file_atomically(out_dir + "/report/check.json", j.dump(2) + "\n");
  return out;
}

}  // namespace softpack
