#include "measure/sweep.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <utility>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/stopwatch.hpp"
#include "core/version.hpp"

namespace softpack {
namespace {

PointResult record_point(const Simulation& sim, const ContactSetup& setup, const RelaxationReport& relax) {
  PointResult r;
  r.force = measured_force(sim, setup);
  if (!setup.first_shell.empty()) r.force_first = sim.wall_load(setup.first_shell).force;
  r.force_between = setup.second_body >= 0 ? sim.force_between(setup.first_body, setup.second_body) : r.force;
  const Measurement m = sim.residuals();
  r.contacts = static_cast<long>(m.contacts);
  r.overlap_max = m.deepest.fraction;
  r.overlap_q99 = sim.overlap_quantile(0.99);
  r.relax_steps = relax.steps;
  r.relax_time = relax.simulated_time;
  r.checks = relax.checks;
  r.awake_fraction = relax.awake_fraction;
  return r;
}

// A point file is reused only when it holds the same configuration (the stage's sections, the
// scene, the packings by content, so the seed), was computed by this release (a change of result
// bits bumps the release: a point of another one may hold other bits), holds the point it is filed
// under, and reads whole, its state included (every dataset is checksummed: a flipped bit is an
// InputError here, not a wrong restart later). Returns what it read, so that nothing is read twice.
std::optional<PointFile> reusable(const std::string& path, const std::string& config, const std::string& release, const PointKey& key) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    PointFile f = read_point_file(path, true);
    if (f.provenance.config != config) return std::nullopt;
    if (const std::string other = release_of(f.provenance.code_version); other != release) {
      fmt::print(stderr, "note: {}: a checkpoint of release {} (this build is {}), the point is computed again\n", path,
                 other.empty() ? "unknown" : other, release);
      return std::nullopt;
    }
    if (const std::string other = point_mismatch(f, key); !other.empty())
      throw InputError(fmt::format("{}: holds {} (a checkpoint filed under another point)", path, other));
    return f;
  } catch (const InputError& e) {
    // Unreadable or misfiled (it cannot be half-written, but may be damaged, foreign or moved): recomputed, said.
    fmt::print(stderr, "warning: checkpoint not used, the point is computed again: {}\n", e.what());
    return std::nullopt;
  }
}

// One chain of points: the states later points start from, and the simulation that runs it.
struct Chain {
  std::vector<SweepPoint> plan;
  std::vector<bool> needed;                          // a later point starts from this one
  std::vector<std::optional<SimulationState>> kept;  // the states of the needed points
  std::vector<bool> computed;                        // computed (not reused) in this run
  std::optional<std::optional<SimulationState>> start;  // the stage's start, once asked
  std::optional<Simulation> sim;
  std::optional<SimulationState> built;  // the scene as built, when one simulation runs the chain
  std::optional<std::size_t> sim_at;     // the point whose end the simulation holds
};

}  // namespace

Vec3 measured_force(const Simulation& sim, const ContactSetup& setup) { return sim.wall_load(setup.second_wall).force; }

std::string point_mismatch(const PointFile& f, const PointKey& key) {
  const PointResult& r = f.result;
  if (f.provenance.stage != key.stage) return fmt::format("a point of the {} stage, not of the {} stage", f.provenance.stage, key.stage);
  if (r.delta_n != key.delta_n || r.alpha_deg != key.alpha_deg || r.ht != key.ht)
    return fmt::format("the point delta_n = {}, alpha = {} deg, ht = {} m, not delta_n = {}, alpha = {} deg, ht = {} m", r.delta_n,
                       r.alpha_deg, r.ht, key.delta_n, key.alpha_deg, key.ht);
  return "";
}

std::vector<PointResult> run_sweep(const SweepContext& c, const SweepStage& stage) {
  std::size_t total = 0;
  for (std::size_t chain = 0; chain < stage.chains(); ++chain) total += stage.points(chain);
  std::vector<PointResult> points;
  points.reserve(total);
  const PointProvenance provenance{stage.name(), scene_name(c.setup.kind), c.config, c.code_version, c.stamp,
                                     parallel::threads_for(c.setup.scene.particles.size())};
  std::size_t computed = 0;
  for (std::size_t chain = 0; chain < stage.chains(); ++chain) {
    Chain ch;
    const std::size_t n = stage.points(chain);
    for (std::size_t k = 0; k < n; ++k) ch.plan.push_back(stage.point(chain, k));
    ch.needed.assign(n, false), ch.kept.resize(n), ch.computed.assign(n, false);
    for (const SweepPoint& p : ch.plan)
      if (p.from) ch.needed.at(*p.from) = true;
    for (std::size_t k = 0; k < n; ++k) {
      const SweepPoint& p = ch.plan[k];
      // 1. Reuse, unless the point it starts from was computed again.
      if (!(p.from && ch.computed[*p.from])) {
        if (std::optional<PointFile> f = reusable(p.path, c.config, release_of(c.code_version), p.key)) {
          points.push_back(std::move(f->result));
          points.back().reused = true;
          if (c.progress) c.progress(stage.name(), points.size() - 1, total, points.back(), true);
          if (ch.needed[k]) ch.kept[k] = std::move(f->state);
          continue;
        }
      }
      // 2. Restore what the point starts from, unless the simulation holds it.
      Stopwatch watch;  // loading: with the restore
      if (stage.simulation_per_point() || !ch.sim) {
        ch.sim.emplace(c.setup.scene);
        ch.sim_at.reset();
        if (!stage.simulation_per_point()) ch.built = ch.sim->state();
      }
      Simulation& sim = *ch.sim;
      long step0 = sim.step_count();
      const bool fresh = sim.step_count() == 0 && !ch.sim_at;
      if (!(p.from && ch.sim_at == p.from)) {
        if (p.from) {
          sim.restore(*ch.kept.at(*p.from));
        } else {
          if (!ch.start) ch.start = stage.start(chain);
          if (*ch.start) sim.restore(**ch.start);
          else if (!fresh) sim.restore(*ch.built);
        }
        if (!stage.counts_steps_before_restore()) step0 = sim.step_count();
      }
      // 3. Load, 4. relax.
      RelaxationReport relax;
      PointTiming timing;
      try {
        stage.load(sim, chain, k, p.from);
        timing.loading = watch.lap();
        relax = softpack::relax(sim, c.settings.relaxation, {}, [&] { return measured_force(sim, c.setup); });
        timing.relaxation = watch.lap();
      } catch (const NumericalError& e) {
        throw NumericalError(p.label + ": " + e.what());  // the watchdog's diagnostic names the point
      }
      // 5. Record, 6. checkpoint, 7. progress.
      PointResult r = record_point(sim, c.setup, relax);
      r.delta_n = p.key.delta_n, r.hn = p.key.delta_n * c.setup.Rs, r.alpha_deg = p.key.alpha_deg, r.ht = p.key.ht;
      r.steps = sim.step_count() - step0;
      r.timing = timing;
      stage.before_checkpoint(sim);
      SimulationState state = sim.state();
      write_point_file(p.path, r, state, provenance);
      ch.computed[k] = true;
      ch.sim_at = k;
      if (ch.needed[k]) ch.kept[k] = std::move(state);
      points.push_back(r);
      if (c.progress) c.progress(stage.name(), points.size() - 1, total, r, false);
      if (c.stop_after && ++computed == c.stop_after && points.size() < total) return {};
    }
  }
  return points;
}

}  // namespace softpack
