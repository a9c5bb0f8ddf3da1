// softpack-coarse's resolved-cost subcommand (issue 35, docs/nested.md), apart from softpack_coarse.cpp:
//
//   softpack-coarse estimate --config C --medium M --soft S.h5 --measured R.h5 ... --out F.json
//       the resolved model's cost of medium M from its spheres and step, the soft run S's simulated
//       time and the CPU time per sphere-step of the resolved runs R (coarse/resolved_estimate.hpp),
//       and, with the settings' plan.levels_added, the same medium that many levels deeper.
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "apps/coarse_medium_cli.hpp"
#include "coarse/medium_file.hpp"
#include "coarse/resolved_estimate.hpp"
#include "coarse/result_file.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace softpack::apps::coarse_app {

struct EstimateCommand {
  CLI::App* cmd = nullptr;
  std::string config, medium, soft, out;
  std::vector<std::string> measured;
  bool quiet = false;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("estimate",
                             "the resolved model's cost from the medium, its soft run and resolved runs of other media (coarse/resolved_estimate.hpp)");
    cmd->add_option("--config", config, "settings of the medium, e.g. experiments/three-decades.yaml")->required();
    cmd->add_option("--medium", medium, "medium file (softpack-coarse medium)")->required();
    cmd->add_option("--soft", soft, "the medium's soft run (softpack-coarse run --model soft)")->required();
    cmd->add_option("--measured", measured, "resolved runs whose CPU time per sphere-step is taken")->required();
    cmd->add_option("--out", out, "the estimate (JSON)")->required();
    cmd->add_flag("--quiet", quiet, "no summary line");
  }

  /// Runs it when given; false when not.
  bool run() const {
    if (!*cmd) return false;
    const CoarseGrainSettings s = read_coarse_grain_settings(config);
    const MediumFile mf = read_medium_file(medium);
    const Medium m = medium_with_contents(s, config, mf, medium, fmt::format("softpack-coarse estimate seed {}", mf.seed), quiet);
    const CoarseResult soft_run = read_coarse_result(soft);
    std::vector<CoarseResult> runs;
    for (const std::string& p : measured) runs.push_back(read_coarse_result(p));
    const ResolvedEstimate e = estimate_resolved(s, m, soft_run, runs);
    write_file_atomically(out, resolved_estimate_json(e, config, medium, soft_run, runs));
    if (!quiet)
      fmt::print(stderr,
                 "softpack-coarse estimate seed {}: resolved {:.4g} spheres, {:.3g} steps of {:.3g} s, {:.3g} CPU s at {:.3g} s per "
                 "sphere-step; soft {:.3g} CPU s: {:.3g} times -> {}\n",
                 mf.seed, e.spheres, e.steps, e.dt, e.cpu, e.cpu_per_sphere_step, e.soft_cpu, e.speed_up(), out);
    if (!quiet && e.deeper.levels_added > 0)
      fmt::print(stderr, "softpack-coarse estimate seed {}: planned {} levels deeper: {:.4g} spheres, {:.3g} steps, {:.3g} CPU s: {:.3g} times\n",
                 mf.seed, e.deeper.levels_added, e.deeper.spheres, e.deeper.steps, e.deeper.cpu, e.deeper.cpu / e.soft_cpu);
    return true;
  }
};

}  // namespace softpack::apps::coarse_app
