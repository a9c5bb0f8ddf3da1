#include "measure/stage.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "config/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/version.hpp"
#include "formats/sweep_file.hpp"
#include "integrate/time_step.hpp"
#include "measure/sweeps.hpp"
#include "scene/validate.hpp"

namespace softpack {
namespace {

// The first line where two section texts differ, as "'<packing line>' in the packing, '<profile
// line>' in the profile" ("(none)" past the end of one).
std::string first_difference(const std::string& packing, const std::string& profile) {
  std::size_t a = 0, b = 0;
  while (a < packing.size() || b < profile.size()) {
    const std::size_t ea = std::min(packing.find('\n', a), packing.size()), eb = std::min(profile.find('\n', b), profile.size());
    const std::string la = a < packing.size() ? packing.substr(a, ea - a) : "(none)";
    const std::string lb = b < profile.size() ? profile.substr(b, eb - b) : "(none)";
    if (la != lb) {
      const auto trim = [](std::string s) { return s.erase(0, std::min(s.find_first_not_of(' '), s.size())); };
      return fmt::format("'{}' in the packing, '{}' in the profile", trim(la), trim(lb));
    }
    a = ea + 1, b = eb + 1;
  }
  return "";
}

// The packing must come from this profile's packing section (same text), else the sweep
// would silently measure another soft-particle.
PackingFile checked_packing(const std::string& path, const std::string& packing_section, const std::string& config_path) {
  PackingFile p = read_packing_file(path);
  if (p.provenance.config != packing_section)
    throw InputError(fmt::format("{}: this packing was made from another packing configuration than the `packing` section of "
                                 "{} ({}; make it again with {} --config {})",
                                 path, config_path, first_difference(p.provenance.config, packing_section),
                                 p.imported ? "softpack-import" : "softpack-pack", config_path));
  return p;
}

// How a packing is named in the points' configuration: its path and seed, and for an imported
// one the SHA-256 of its source, so that a checkpoint measured on an older source is not reused.
std::string packing_label(const std::string& path, const PackingFile& p) {
  return p.imported ? fmt::format("{} (seed {}, source sha256 {})", path, p.provenance.seed, p.imported->source_sha256)
                    : fmt::format("{} (seed {})", path, p.provenance.seed);
}

StageSummary run(const StageOptions& o, const StageProgress& progress) {
  const Stopwatch watch;
  if (o.seed < 0) throw InputError(fmt::format("--seed: {} is not allowed; allowed: a seed >= 0", o.seed));
  const ConfigNode root = ConfigNode::load_file(o.config_path);
  MeasurementSettings settings;
  try {
    settings = parse_measurement(root);
  } catch (const InputError& e) {
    throw in_file(o.config_path, e);
  }
  if (o.stage == "tangential" && !settings.has_tangential)
    throw InputError(fmt::format("{}: no `tangential` section: this profile is normal-only (make packings normal)", o.config_path));
  if (o.stage == "sliding" && !settings.has_sliding)
    throw InputError(fmt::format("{}: no `sliding` section: this profile has no sliding measurement", o.config_path));
  const ContactScene kind = parse_contact_scene(o.scene);
  const std::string packing_section = section_text(root, "packing");

  SweepContext c;
  c.settings = settings;
  std::string packings;
  if (o.hertz_check) {
    if (kind != ContactScene::soft_solid) throw InputError("--hertz-check: only for the soft-solid scene");
    c.setup = hertz_check_setup(shell_radius(parse_packing(root), parse_seeds(root)), settings.simulation);
    packings = "none: Hertz check, one solid sphere of radius Rs";
  } else {
    if (o.packing.empty()) throw InputError("--packing: required (the packing file of this seed)");
    const PackingFile first = checked_packing(o.packing, packing_section, o.config_path);
    // The seed the results are filed and averaged under is the packing's own.
    if (first.provenance.seed != static_cast<std::uint64_t>(o.seed))
      throw InputError(fmt::format("--seed: {} does not match --packing {}, which was made with seed {}; "
                                   "give the packing of seed {}, or --seed {}",
                                   o.seed, o.packing, first.provenance.seed, o.seed, first.provenance.seed));
    packings = packing_label(o.packing, first);
    if (kind == ContactScene::soft_soft) {
      if (o.second_packing.empty()) throw InputError("--second-packing: required for soft-soft (a packing of another seed)");
      const PackingFile second = checked_packing(o.second_packing, packing_section, o.config_path);
      if (second.provenance.seed == first.provenance.seed)
        throw InputError(fmt::format("--second-packing: {} has the same seed as --packing; soft-soft needs two independent packings",
                                     o.second_packing));
      packings += ", " + packing_label(o.second_packing, second);
      c.setup = soft_soft_setup(first, second, settings.simulation, settings.normal.second_radius_ratio);
    } else {
      c.setup = soft_solid_setup(first, settings.simulation);
    }
  }
  c.setup.scene.watchdog = settings.watchdog;  // when to stop a run gone wrong; changes no result
  // The rules that need the time step, before the first point: the scene's own (validate()), then
  // the steps of the relaxation, of each approach and of each rotation, named by the profile's keys.
  validate(c.setup.scene);
  try {
    validate_sweep_steps(settings, c.setup.Rs, choose_time_step(c.setup.scene));
  } catch (const InputError& e) {
    throw root.locate(e);
  }
  // What every point depends on: the sections read, the scene and the packings used.
  const auto config = [&](const std::string& stage) {
    return "# stage: " + stage + ", scene: " + o.scene + (o.hertz_check ? " (Hertz check)" : "") + "\n# packings: " + packings +
           "\n" + stage_text(root, stage);
  };
  c.config = config(o.stage);
  c.checkpoint_dir = o.checkpoints;
  c.code_version = code_version();
  c.stop_after = static_cast<std::size_t>(std::max(0L, o.stop_after));
  c.progress = progress;
  if (o.stage != "normal") {  // the normal states to shear or slide: reused, or computed where missing
    SweepContext normal = c;
    normal.config = config("normal");
    normal.checkpoint_dir = o.normal_checkpoints;
    normal.stop_after = 0;
    run_normal_sweep(normal);
  }
  const std::vector<PointResult> points = o.stage == "normal"       ? run_normal_sweep(c)
                                         : o.stage == "tangential" ? run_tangential_sweep(c, o.normal_checkpoints)
                                                                   : run_sliding_sweep(c, o.normal_checkpoints);
  if (points.empty()) return StageSummary{0, 0.0, true};  // stopped on purpose (tests)
  // The stage's wall-clock time since it began, and its process's CPU time (with its start-up).
  const Elapsed stage_time{watch.elapsed().wall, process_cpu_seconds()};
  write_sweep_results_file(o.out, points, PointProvenance{o.stage, o.scene, c.config, c.code_version}, packings,
                           static_cast<std::uint64_t>(o.seed), stage_time);
  return StageSummary{points.size(), stage_time.wall, false};
}

}  // namespace

StageSummary run_stage(const StageOptions& o, const StageProgress& progress) {
  try {
    return run(o, progress);
  } catch (const NumericalError& e) {
    throw NumericalError(fmt::format("{} seed {}, {}", o.scene, o.seed, e.what()));
  }
}

}  // namespace softpack
