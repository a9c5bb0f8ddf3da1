#include "report/stage_timing.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "core/error.hpp"
#include "formats/average_file.hpp"
#include "formats/fit_file.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"

namespace softpack {
namespace {

// The row of `stage` and `scene`, made when first asked for (rows keep the order of first use).
StageTiming& row(ProfileTiming& t, const std::string& stage, const std::string& scene) {
  for (auto& s : t.stages)
    if (s.stage == stage && s.scene == scene) return s;
  StageTiming& s = t.stages.emplace_back();
  s.stage = stage, s.scene = scene;
  return s;
}

bool exists(const std::string& path) { return std::filesystem::exists(path); }

void add_sweeps(ProfileTiming& t, const std::string& stage, const std::vector<std::string>& paths) {
  for (const auto& path : paths) {
    if (!exists(path)) {
      // The scene from the file name (<scene>-seed-<seed>.h5), so that the row is the right one.
      const std::string name = std::filesystem::path(path).filename().string();
      const std::string scene = name.rfind("soft-solid", 0) == 0 ? "soft-solid" : name.rfind("soft-soft", 0) == 0 ? "soft-soft" : "";
      row(t, stage, scene).missing.push_back(path);
      continue;
    }
    const SweepResults r = read_sweep_results_file(path, stage);
    if (!r.has_timing) throw InputError(fmt::format("{}: /timing: none (a results file of a release before 0.4.0)", path));
    StageTiming& s = row(t, stage, r.provenance.scene);
    ++s.files;
    for (std::size_t k = 0; k < r.delta_n.size(); ++k) {
      ++s.points;
      s.reused += r.reused[k] != 0;
      const Elapsed loading{r.phase_wall[0][k], r.phase_cpu[0][k]}, relaxation{r.phase_wall[1][k], r.phase_cpu[1][k]},
          output{r.phase_wall[2][k], r.phase_cpu[2][k]};
      s.phases.loading += loading, s.phases.relaxation += relaxation, s.phases.output += output;
      s.cost += loading + relaxation + output;
    }
    s.process += Elapsed{r.total_seconds, r.total_cpu_seconds};
  }
}

// A stage whose cost is its processes' time: `read` gives the Elapsed a file records.
template <class Read>
void add_processes(ProfileTiming& t, const std::string& stage, const std::vector<std::string>& paths, Read&& read) {
  if (paths.empty()) return;
  StageTiming& s = row(t, stage, "");
  for (const auto& path : paths) {
    if (!exists(path)) {
      s.missing.push_back(path);
      continue;
    }
    const Elapsed e = read(path);
    ++s.files;
    s.process += e;
    s.cost += e;
  }
}

}  // namespace

Elapsed ProfileTiming::total() const {
  Elapsed e;
  for (const auto& s : stages) e += s.cost;
  return e;
}

bool ProfileTiming::complete() const {
  for (const auto& s : stages)
    if (!s.missing.empty()) return false;
  return true;
}

ProfileTiming collect_timing(const TimingInputs& in) {
  ProfileTiming t;
  add_processes(t, "packing", in.packings, [](const std::string& p) {
    const PackingProvenance v = read_packing_file(p).provenance;
    return Elapsed{v.seconds, v.cpu_seconds};
  });
  add_sweeps(t, "normal", in.normal);
  add_sweeps(t, "tangential", in.tangential);
  add_processes(t, "average", in.averages, [](const std::string& p) {
    const AverageFile a = read_average_file(p);
    if (!a.time) throw InputError(fmt::format("{}: /provenance: no seconds and cpu_seconds (an average file older than 0.4.0)", p));
    return *a.time;
  });
  add_processes(t, "fit", in.fits, [](const std::string& p) {
    const FitEstimates f = read_fit_file(p);
    if (!f.time) throw InputError(fmt::format("{}: provenance: no seconds and cpu_seconds (a fit file older than 0.4.0)", p));
    return *f.time;
  });
  return t;
}

std::string timing_table(const ProfileTiming& t, const std::string& title) {
  const Elapsed total = t.total();
  const auto share = [&](double cpu) { return total.cpu > 0 ? fmt::format("{:.1f}%", 100.0 * cpu / total.cpu) : "-"; };
  std::string s = fmt::format("{}\n\n", title);
  s += "| stage | scene | files | points (reused) | wall [s] | CPU [s] | share of CPU | loading CPU [s] | relaxation CPU [s] | "
       "output CPU [s] | CPU per point [s] | processes wall / CPU [s] |\n";
  s += "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : t.stages) {
    const bool sweep = r.stage == "normal" || r.stage == "tangential";
    const std::string files = r.missing.empty() ? fmt::format("{}", r.files) : fmt::format("{} ({} missing)", r.files, r.missing.size());
    if (sweep)
      s += fmt::format("| {} | {} | {} | {} ({}) | {:.1f} | {:.1f} | {} | {:.1f} | {:.1f} | {:.2f} | {:.3f} | {:.1f} / {:.1f} |\n",
                       r.stage, r.scene, files, r.points, r.reused, r.cost.wall, r.cost.cpu, share(r.cost.cpu),
                       r.phases.loading.cpu, r.phases.relaxation.cpu, r.phases.output.cpu,
                       r.points ? r.cost.cpu / static_cast<double>(r.points) : 0.0, r.process.wall, r.process.cpu);
    else
      s += fmt::format("| {} | | {} | | {:.2f} | {:.2f} | {} | | | | | {:.2f} / {:.2f} |\n", r.stage, files, r.cost.wall, r.cost.cpu,
                       share(r.cost.cpu), r.process.wall, r.process.cpu);
  }
  s += fmt::format("| **total** | | | | {:.1f} | {:.1f} ({:.2f} CPU-minutes) | 100% | | | | | |\n", total.wall, total.cpu,
                   total.cpu / 60.0);
  s += "\nSweeps: the sum over their points of what each point recorded, whichever run computed it (reused: taken from a\n"
       "checkpoint by the last run); the other stages: their processes. Wall-clock times add up the stages as if run one\n"
       "after the other.\n";
  if (!t.complete()) {
    s += "\nMissing (not run yet):\n";
    for (const auto& r : t.stages)
      for (const auto& m : r.missing) s += "  " + m + "\n";
  }
  return s;
}

std::string timing_json(const ProfileTiming& t) {
  using nlohmann::json;
  const auto elapsed = [](const Elapsed& e) { return json{{"wall", e.wall}, {"cpu", e.cpu}}; };
  json stages = json::array();
  for (const auto& r : t.stages)
    stages.push_back({{"stage", r.stage},
                      {"scene", r.scene},
                      {"files", r.files},
                      {"missing", r.missing},
                      {"points", r.points},
                      {"reused", r.reused},
                      {"cost", elapsed(r.cost)},
                      {"loading", elapsed(r.phases.loading)},
                      {"relaxation", elapsed(r.phases.relaxation)},
                      {"output", elapsed(r.phases.output)},
                      {"process", elapsed(r.process)}});
  return json{{"stages", stages}, {"total", elapsed(t.total())}, {"complete", t.complete()}}.dump(2) + "\n";
}

}  // namespace softpack
