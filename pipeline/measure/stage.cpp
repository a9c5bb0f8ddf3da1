#include "measure/stage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/stopwatch.hpp"
#include "core/version.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"
#include "integrate/time_step.hpp"
#include "measure/sweeps.hpp"
#include "scene/validate.hpp"

namespace softpack {
namespace {

// The packing must come from this profile's packing section (same text and, when it records one,
// same stamp: release and imported sources too), else the sweep would silently measure another
// soft-particle.
PackingFile checked_packing(const std::string& path, const std::string& packing_section, const std::string& packing_stamp,
                            const std::string& config_path) {
  PackingFile p = read_packing_file(path);
  if (p.provenance.config != packing_section)
    throw InputError(fmt::format("{}: this packing was made from another packing configuration than the `packing` section of "
                                 "{} ({}; make it again with {} --config {})",
                                 path, config_path, first_difference(p.provenance.config, packing_section, "the packing", "the profile"),
                                 p.imported ? "softpack-import" : "softpack-pack", config_path));
  check_stamp(path, "packing", p.provenance.stamp, packing_stamp, config_path);
  return p;
}

// An imported packing's grains have the density its source file gives: the profile's material
// must be that one, or say that it ignores the file's (the grains' mass sets the relaxation's
// dynamics; a density read and dropped would measure another soft-particle with no word).
void check_imported_density(const std::string& path, const PackingFile& p, double density, const std::string& config_path) {
  if (!p.imported || !std::isfinite(p.imported->density) || std::abs(p.imported->density - density) <= 1e-9 * density) return;
  throw InputError(fmt::format("{}: its grains' density is {:.6g} kg/m^3 (the density column of {}, times packing.import.density_unit), "
                               "not material.density = {:.6g} of {}, which every grain takes: set material.density: {:.6g}, or "
                               "packing.import.density: ignore to take the profile's",
                               path, p.imported->density, p.imported->source_file, density, config_path, p.imported->density));
}

// How a packing is named in the points' configuration: its path, its seed and its identity (the
// SHA-256 of its content), so that a checkpoint measured on another packing of that name is not
// reused.
std::string packing_label(const std::string& path, const PackingFile& p, const std::string& sha256) {
  return fmt::format("{} (seed {}, packing sha256 {})", path, p.provenance.seed, sha256);
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
  // One configuration per result: Make planned this run with the stamp it gives; a profile edited
  // since (even if reverted before the run ends) is refused here, before any point is computed.
  const std::string stamp = profile_stamp(root, o.stage);
  check_planned_stamp(o.config_path, o.stage, o.stamp, stamp);

  SweepContext c;
  c.settings = settings;
  std::string packings, own_packing_sha256;
  if (o.hertz_check) {
    if (kind != ContactScene::soft_solid) throw InputError("--hertz-check: only for the soft-solid scene");
    c.setup = hertz_check_setup(shell_radius(parse_packing(root), parse_seeds(root)), settings.simulation);
    packings = "none: Hertz check, one solid sphere of radius Rs";
  } else {
    if (o.packing.empty()) throw InputError("--packing: required (the packing file of this seed)");
    const std::string packing_stamp = profile_stamp(root, "packing");
    const PackingFile first = checked_packing(o.packing, packing_section, packing_stamp, o.config_path);
    check_imported_density(o.packing, first, settings.simulation.material.density, o.config_path);
    // The seed the results are filed and averaged under is the packing's own.
    if (first.provenance.seed != static_cast<std::uint64_t>(o.seed))
      throw InputError(fmt::format("--seed: {} does not match --packing {}, which was made with seed {}; "
                                   "give the packing of seed {}, or --seed {}",
                                   o.seed, o.packing, first.provenance.seed, o.seed, first.provenance.seed));
    own_packing_sha256 = packing_sha256(first);
    packings = packing_label(o.packing, first, own_packing_sha256);
    if (kind == ContactScene::soft_soft) {
      if (o.second_packing.empty()) throw InputError("--second-packing: required for soft-soft (a packing of another seed)");
      const PackingFile second = checked_packing(o.second_packing, packing_section, packing_stamp, o.config_path);
      check_imported_density(o.second_packing, second, settings.simulation.material.density, o.config_path);
      if (second.provenance.seed == first.provenance.seed)
        throw InputError(fmt::format("--second-packing: {} has the same seed as --packing; soft-soft needs two independent packings",
                                     o.second_packing));
      const std::string second_sha256 = packing_sha256(second);
      if (second_sha256 == own_packing_sha256)
        throw InputError(fmt::format("--second-packing: {} is the same packing as --packing {} (same content, SHA-256 {}) under "
                                     "another seed; soft-soft needs two independent packings",
                                     o.second_packing, o.packing, second_sha256));
      packings += ", " + packing_label(o.second_packing, second, second_sha256);
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
  c.stamp = stamp;
  c.normal_config = config("normal");
  c.checkpoint_dir = o.checkpoints;
  c.code_version = code_version();
  c.stop_after = static_cast<std::size_t>(std::max(0L, o.stop_after));
  c.progress = progress;
  if (o.stage != "normal") {  // the normal states to shear or slide: reused, or computed where missing
    SweepContext normal = c;
    normal.config = c.normal_config;
    normal.stamp = profile_stamp(root, "normal");
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
  write_sweep_results_file(o.out, points, PointProvenance{o.stage, o.scene, c.config, c.code_version, c.stamp, parallel::threads_for(c.setup.scene.particles.size())}, packings,
                           own_packing_sha256, static_cast<std::uint64_t>(o.seed), stage_time);
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
