#include "coarse/speed.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "coarse/compression.hpp"
#include "coarse/medium.hpp"
#include "coarse/medium_file.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"
#include "coarse/report.hpp"

namespace softpack {
namespace {

struct Model {
  CoarseGrainSettings settings;
  SoftParticleLaws laws;
  SceneDef scene;
};

Model model_of(const std::string& config, const Medium& m, CoarseModel model) {
  Model r{read_coarse_grain_settings(config), {}, {}};
  r.laws = read_soft_particle_laws("coarse_grain.soft_particle", r.settings.laws, r.settings.many_body);
  r.scene = medium_scene(r.settings, m, model, r.laws);
  return r;
}

}  // namespace

SpeedSeed write_speed_seed(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& dir, int version, std::uint64_t seed, int repeats,
                           const SpeedProgress& progress) {
  if (repeats < 1) throw InputError(fmt::format("speed: --repeats {} is not allowed; allowed: 1 or more", repeats));
  const std::vector<std::uint64_t>& seeds = plan.media_seeds_of(version);
  const auto at = std::find(seeds.begin(), seeds.end(), seed);
  if (at == seeds.end())
    throw InputError(fmt::format("speed: --seed {} is not one of {}'s validation.{} ({})", seed, plan_path, media_seeds_key(version), fmt::join(seeds, " ")));
  const bool resolved_first = (at - seeds.begin()) % 2 == 0;
  const std::string pairwise_config = dir + "/profiles/reference.yaml", many_body_config = dir + "/profiles/many-body.yaml", out_dir = dir + "/speed";
  const std::string path = fmt::format("{}/reference/media/seed-{}.h5", dir, seed);
  const MediumFile mf = read_medium_file(path);
  const Medium& m = mf.medium;
  const Model resolved = model_of(pairwise_config, m, CoarseModel::resolved), pairwise = model_of(pairwise_config, m, CoarseModel::soft),
              many_body = model_of(many_body_config, m, CoarseModel::soft);
  for (const auto& [config, s] : {std::pair{pairwise_config, &resolved.settings}, std::pair{many_body_config, &many_body.settings}})
    if (mf.settings != s->medium_text) throw InputError(fmt::format("{}: made with other settings than {}", path, config));
  if (!many_body.laws.many_body) throw InputError(fmt::format("{}: its law file {} has no many_body law", many_body_config, many_body.settings.laws));
  if (pairwise.laws.many_body) throw InputError(fmt::format("{}: its law file {} has a many_body law; the pairwise settings are wanted", pairwise_config, pairwise.settings.laws));
  SpeedSeed r;
  r.seed = seed, r.resolved_first = resolved_first, r.repeats = repeats;
  r.pairwise = r.many_body = std::numeric_limits<double>::infinity();
  const auto run = [&](const Model& x, CoarseModel model, const std::string& name, int k) {
    Simulation::forget_setup_caches();  // each run pays the grains' damping setup, as a process of its own does
    const CompressionRun c = run_compression(x.scene, m, model, x.settings, [&](double done, double total, const CurveRow&) {
      if (progress) progress(name, k, done, total);
    });
    return std::pair{c.time.cpu, c.steps};
  };
  const auto resolved_run = [&] { std::tie(r.resolved, r.steps_resolved) = run(resolved, CoarseModel::resolved, "resolved", 0); };
  if (resolved_first) resolved_run();
  for (int k = 0; k < repeats; ++k) {
    const auto [p, ps] = run(pairwise, CoarseModel::soft, "pairwise", k);
    const auto [b, bs] = run(many_body, CoarseModel::soft, "many-body", k);
    r.pairwise = std::min(r.pairwise, p), r.many_body = std::min(r.many_body, b), r.steps_pairwise = ps, r.steps_many_body = bs;
  }
  if (!resolved_first) resolved_run();
  std::filesystem::create_directories(out_dir);
  write_file_atomically(
      fmt::format("{}/seed-{}.dat", out_dir, seed),
      fmt::format("# the speed-up side by side (softpack-coarse speed, {}): medium {}, resolved and pairwise soft {}, many-body soft {}, "
                  "{} thread(s), the soft runs the least of {}, resolved {}\n"
                  "# seed cpu_resolved[s] cpu_pairwise[s] cpu_many_body[s] steps_resolved steps_pairwise steps_many_body\n"
                  "{} {:.4f} {:.4f} {:.4f} {} {} {}\n",
                  code_version(), path, pairwise_config, many_body_config, parallel::threads(), repeats, resolved_first ? "first" : "last", seed, r.resolved,
                  r.pairwise, r.many_body, r.steps_resolved, r.steps_pairwise, r.steps_many_body));
  return r;
}

void write_speed_report(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& dir, int version) {
  const std::vector<std::uint64_t>& seeds = plan.media_seeds_of(version);
  const std::string out_dir = dir + "/speed";
  std::vector<SpeedSeed> rows;
  std::string heads;
  for (const std::uint64_t seed : seeds) {
    const std::string path = fmt::format("{}/seed-{}.dat", out_dir, seed);
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("{}: cannot read it (make many-body-speed writes it)", path));
    SpeedSeed r;
    bool read = false;
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      if (line_no == 1) heads += fmt::format("- seed {}: {}\n", seed, line.substr(std::min(line.size(), line.find('('))));
      if (line.empty() || line[0] == '#') continue;
      std::istringstream s(line);
      if (!(s >> r.seed >> r.resolved >> r.pairwise >> r.many_body >> r.steps_resolved >> r.steps_pairwise >> r.steps_many_body) || r.seed != seed)
        throw InputError(fmt::format("{}:{}: expected 'seed cpu_resolved cpu_pairwise cpu_many_body steps_resolved steps_pairwise steps_many_body' of seed {}",
                                     path, line_no, seed));
      read = true;
    }
    if (!read) throw InputError(fmt::format("{}: no row (rerun make many-body-speed)", path));
    rows.push_back(r);
  }
  std::vector<double> pair, many, cost;
  std::string table;
  for (const SpeedSeed& r : rows) {
    pair.push_back(r.resolved / r.pairwise), many.push_back(r.resolved / r.many_body), cost.push_back(r.many_body / r.pairwise);
    table += fmt::format("| {} | {:.1f} | {:.3f} | {:.3f} | {:.0f} | {:.0f} | {:.2f} |\n", r.seed, r.resolved, r.pairwise, r.many_body, pair.back(), many.back(),
                         cost.back());
  }
  const auto pm = [](const std::vector<double>& x) {
    const MeanError e = mean_error(x, FewSeeds::not_known);
    return coarse_pm(e);
  };
  const std::string md = fmt::format(
      "# The speed-up side by side (generated by softpack-coarse speed --report, {})\n\n"
      "The media of the law's version {} (seeds {} of `{}`), each compressed, unloaded and sheared three ways in one process, one after "
      "the other (coarse/speed.hpp): resolved, soft with the pairwise laws, soft with the many-body laws. CPU time of each "
      "simulation, the grains' damping setup included in each (as a process of its own pays it); the soft models' the least of their interleaved repeats. Speed-up: resolved / soft, per seed; the mean over "
      "the seeds ± its standard error. Each seed's file: `seed-S.dat`.\n\n{}\n"
      "| seed | resolved [s] | pairwise soft [s] | many-body soft [s] | speed-up pairwise | speed-up many-body | many-body / pairwise |\n"
      "|---|---|---|---|---|---|---|\n{}| mean | | | | {} | {} | {} |\n",
      code_version(), version, fmt::join(seeds, ", "), plan_path, heads, table, pm(pair), pm(many), pm(cost));
  write_file_atomically(out_dir + "/speed.md", md);
}

}  // namespace softpack
