#include "measure/sweeps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "profile/profile.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"

namespace softpack {
namespace {

// The measured force: the load on the second body's wall or shell, what holds it in place.
Vec3 measured_force(const Simulation& sim, const ContactSetup& setup) { return sim.wall_load(setup.second_wall).force; }

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

// Moves the second body by `distance` along `direction` (a unit vector) at `speed`, rigidly: its
// shell and, for soft-soft, its spheres, released when it arrives.
void move_second_body(Simulation& sim, const ContactSetup& setup, const Vec3& direction, double distance, double speed) {
  if (distance <= 0.0) return;
  const Vec3 velocity = speed * direction;
  sim.add_driver(MoveWallDef{setup.second_wall, velocity, distance, std::nullopt});
  if (setup.second_body >= 0) {
    TranslateGroupDef t;
    t.group = GroupDef{GroupDef::Kind::body, setup.second_body};
    t.velocity = velocity;
    t.distance = distance;
    t.after = AfterDrive::release;
    sim.add_driver(t);
  }
  while (sim.drivers_moving()) sim.step();
}

// The sliding stage's move by `dht` at `speed`, parallel to the contact: the wall along +y; the
// second soft-particle (shell and spheres, rigidly) on an orbit about the first's centre by the
// angle dht / Rs, so that its centre keeps its distance and the contact its depth hn (a
// translation would open the contact as it slides).
void slide_second_body(Simulation& sim, const ContactSetup& setup, double dht, double speed) {
  if (dht <= 0.0) return;
  if (setup.second_body < 0) return move_second_body(sim, setup, Vec3(0, 1, 0), dht, speed);
  RotateGroupDef orbit;
  orbit.group = GroupDef{GroupDef::Kind::body, setup.second_body};
  orbit.centre = Vec3::Zero();  // the first shell's centre
  orbit.axis = Vec3::UnitZ();
  orbit.rate = speed / setup.Rs;
  orbit.angle = dht / setup.Rs;
  orbit.after = AfterDrive::release;
  orbit.with_shell = true;
  sim.add_driver(orbit);
  while (sim.drivers_moving()) sim.step();
}

// The normal approach: along -x by `distance`.
void approach(Simulation& sim, const ContactSetup& setup, double distance, double speed) {
  move_second_body(sim, setup, Vec3(-1, 0, 0), distance, speed);
}

// Runs fn(); when the watchdog stops the run, its diagnostic names the point.
template <class Fn>
void at_point(const std::string& point, Fn&& fn) {
  try {
    fn();
  } catch (const NumericalError& e) {
    throw NumericalError(point + ": " + e.what());
  }
}

// The sliding stage's alpha: soft-soft, the orbit's angle, by which the contact's frame has turned
// about +z; soft-solid, 0.
double sliding_alpha_deg(const SweepContext& c, double ht) {
  return c.setup.second_body >= 0 ? ht / c.setup.Rs * 180.0 / std::numbers::pi : 0.0;
}

// Which point a point file must hold to be taken as point k of a sweep: its stage and its place
// on the grid (the values the sweep records with it, bit for bit).
struct PointKey {
  const char* stage;
  double delta_n, alpha_deg, ht;
};

// "" when the point file holds the point `key`, else what it holds instead.
std::string other_point(const PointFile& f, const PointKey& key) {
  const PointResult& r = f.result;
  if (f.provenance.stage != key.stage) return fmt::format("a point of the {} stage, not of the {} stage", f.provenance.stage, key.stage);
  if (r.delta_n != key.delta_n || r.alpha_deg != key.alpha_deg || r.ht != key.ht)
    return fmt::format("the point delta_n = {}, alpha = {} deg, ht = {} m, not delta_n = {}, alpha = {} deg, ht = {} m", r.delta_n,
                       r.alpha_deg, r.ht, key.delta_n, key.alpha_deg, key.ht);
  return "";
}

// A point file is reused only when it holds the same configuration (the stage's sections, the
// scene, the packings by content, so the seed), the point it is filed under, and reads whole,
// its state included (every dataset is checksummed: a flipped bit is an InputError here, not a
// wrong restart later). Returns what it read, so that nothing is read twice.
std::optional<PointFile> reusable(const std::string& path, const std::string& config, const PointKey& key) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    PointFile f = read_point_file(path, true);
    if (f.provenance.config != config) return std::nullopt;
    if (const std::string other = other_point(f, key); !other.empty())
      throw InputError(fmt::format("{}: holds {} (a checkpoint filed under another point)", path, other));
    return f;
  } catch (const InputError& e) {
    // Unreadable or misfiled (it cannot be half-written, but may be damaged, foreign or moved): recomputed, said.
    fmt::print(stderr, "warning: checkpoint not used, the point is computed again: {}\n", e.what());
    return std::nullopt;
  }
}

PointProvenance provenance(const SweepContext& c, const char* stage) {
  return PointProvenance{stage, scene_name(c.setup.kind), c.config, c.code_version, c.stamp};
}

// The normal state at delta_n (a point of the normal grid), from the normal stage's point files:
// InputError unless the file is that point of this configuration (stage, scene, packings, sections).
SimulationState normal_state(const SweepContext& c, const std::string& normal_dir, double delta_n) {
  const auto& grid = c.settings.normal.delta_n;
  const std::size_t k = static_cast<std::size_t>(std::find(grid.begin(), grid.end(), delta_n) - grid.begin());
  const std::string path = normal_point_path(normal_dir, k);
  if (!std::filesystem::exists(path))
    throw InputError(fmt::format("{}: missing normal state for delta_n = {} (run the normal stage of this scene and seed first)",
                                 path, delta_n));
  PointFile f = read_point_file(path, true);
  if (f.provenance.config != c.normal_config)
    throw InputError(fmt::format("{}: this normal state was computed with another configuration than this sweep's ({}); "
                                 "run the normal stage of this profile, scene and seed again",
                                 path, first_difference(f.provenance.config, c.normal_config, "the state", "this sweep")));
  if (const std::string other = other_point(f, PointKey{"normal", delta_n, 0.0, 0.0}); !other.empty())
    throw InputError(fmt::format("{}: filed as the normal state of delta_n = {}, it holds {}; run the normal stage again", path,
                                 delta_n, other));
  return std::move(f.state);
}

}  // namespace

std::string normal_point_path(const std::string& dir, std::size_t k) {
  return (std::filesystem::path(dir) / fmt::format("point-{:03d}.h5", k)).string();
}

std::string tangential_point_path(const std::string& dir, std::size_t hn_index, std::size_t alpha_index) {
  return (std::filesystem::path(dir) / fmt::format("point-{:03d}-{:03d}.h5", hn_index, alpha_index)).string();
}

std::string sliding_point_path(const std::string& dir, std::size_t hn_index, std::size_t ht_index) {
  return tangential_point_path(dir, hn_index, ht_index);
}


std::vector<PointResult> run_sliding_sweep(const SweepContext& c, const std::string& normal_dir) {
  const auto& hn_grid = c.settings.sliding.delta_n;
  const auto& ht_grid = c.settings.sliding.ht_over_Rs;
  const std::size_t total = hn_grid.size() * ht_grid.size();
  std::vector<PointResult> points;
  std::size_t computed = 0;
  for (std::size_t a = 0; a < hn_grid.size(); ++a) {
    // Each point continues from the previous one: reuse the finished ones in order, keeping the
    // last state, then compute the rest in one simulation.
    std::size_t done = 0;
    SimulationState last;
    while (done < ht_grid.size()) {
      std::optional<PointFile> f = reusable(sliding_point_path(c.checkpoint_dir, a, done), c.config,
                                            PointKey{"sliding", hn_grid[a], sliding_alpha_deg(c, ht_grid[done] * c.setup.Rs),
                                                     ht_grid[done] * c.setup.Rs});
      if (!f) break;
      points.push_back(f->result);
      points.back().reused = true;
      if (c.progress) c.progress("sliding", points.size() - 1, total, points.back(), true);
      last = std::move(f->state);
      ++done;
    }
    if (done == ht_grid.size()) continue;
    Simulation sim(c.setup.scene);
    sim.restore(done == 0 ? normal_state(c, normal_dir, hn_grid[a]) : last);
    double ht_now = done == 0 ? 0.0 : ht_grid[done - 1] * c.setup.Rs;
    for (std::size_t b = done; b < ht_grid.size(); ++b) {
      Stopwatch watch;
      const long step0 = sim.step_count();
      const double ht = ht_grid[b] * c.setup.Rs;
      RelaxationReport relax;
      PointTiming timing;
      at_point(fmt::format("sliding point {}/{} (delta_n = {}, ht/Rs = {})", points.size() + 1, total, hn_grid[a], ht_grid[b]),
               [&] {
                 slide_second_body(sim, c.setup, ht - ht_now, c.settings.sliding.speed);
                 timing.loading = watch.lap();
                 relax = softpack::relax(sim, c.settings.relaxation, {}, [&] { return measured_force(sim, c.setup); });
                 timing.relaxation = watch.lap();
               });
      ht_now = ht;
      PointResult r = record_point(sim, c.setup, relax);
      r.delta_n = hn_grid[a];
      r.hn = hn_grid[a] * c.setup.Rs;
      r.ht = ht;
      r.alpha_deg = sliding_alpha_deg(c, ht);
      r.steps = sim.step_count() - step0;
      r.timing = timing;
      write_point_file(sliding_point_path(c.checkpoint_dir, a, b), r, sim.state(), provenance(c, "sliding"));
      points.push_back(r);
      if (c.progress) c.progress("sliding", points.size() - 1, total, r, false);
      if (c.stop_after && ++computed == c.stop_after && points.size() < total) return {};
    }
  }
  return points;
}

std::vector<PointResult> run_normal_sweep(const SweepContext& c) {
  const auto& grid = c.settings.normal.delta_n;
  std::vector<PointResult> points(grid.size());
  std::size_t done = 0;  // points 0..done-1 are reusable
  SimulationState undeformed, last;  // the states of points 0 and done-1, when done > 0
  while (done < grid.size()) {
    std::optional<PointFile> f =
        reusable(normal_point_path(c.checkpoint_dir, done), c.config, PointKey{"normal", grid[done], 0.0, 0.0});
    if (!f) break;
    points[done] = f->result;
    points[done].reused = true;
    if (c.progress) c.progress("normal", done, grid.size(), points[done], true);
    (done == 0 ? undeformed : last) = std::move(f->state);
    ++done;
  }
  if (done == grid.size()) return points;

  Simulation sim(c.setup.scene);
  // The direct path starts every point from the undeformed state: point 0's when the grid starts
  // at 0 (relaxed there), else the scene as built (the bodies in contact, not yet relaxed).
  const bool direct = !c.settings.normal.incremental, zero_first = grid.front() == 0.0;
  const SimulationState built = direct && !zero_first ? sim.state() : SimulationState{};
  double hn_now = 0.0;
  if (done > 0) {
    // Continue from the last finished state (incremental) or the undeformed one (direct).
    const std::size_t from = c.settings.normal.incremental ? done - 1 : 0;
    sim.restore(from == 0 ? undeformed : last);
    hn_now = grid[from] * c.setup.Rs;
  }
  const SimulationState undeformed_if_direct = (direct && zero_first && done > 0) ? undeformed : SimulationState{};
  std::size_t computed = 0;
  for (std::size_t k = done; k < grid.size(); ++k) {
    Stopwatch watch;
    // Before the restore: a direct-path point's `steps` counts from the previous point's end (a
    // known error of that diagnostic column, kept until the next release bump changes result bits;
    // a grid that does not start at 0, new, counts from the restored state).
    long step0 = sim.step_count();
    const double hn = grid[k] * c.setup.Rs;
    if (direct && !zero_first && (k > 0 || done > 0)) {
      sim.restore(built);
      step0 = sim.step_count();
      hn_now = 0.0;
    } else if (direct && k > 0) {
      sim.restore(k == done && done > 0 ? undeformed_if_direct : read_point_file(normal_point_path(c.checkpoint_dir, 0), true).state);
      hn_now = 0.0;
    }
    RelaxationReport relax;
    PointTiming timing;
    at_point(fmt::format("normal point {}/{} (delta_n = {})", k + 1, grid.size(), grid[k]), [&] {
      approach(sim, c.setup, hn - hn_now, c.settings.normal.speed);
      timing.loading = watch.lap();  // with the restore of the undeformed state (direct path)
      relax = softpack::relax(sim, c.settings.relaxation, {}, [&] { return measured_force(sim, c.setup); });
      timing.relaxation = watch.lap();
    });
    hn_now = hn;
    PointResult r = record_point(sim, c.setup, relax);
    r.delta_n = grid[k];
    r.hn = hn;
    r.steps = sim.step_count() - step0;
    r.timing = timing;
    write_point_file(normal_point_path(c.checkpoint_dir, k), r, sim.state(), provenance(c, "normal"));
    points[k] = r;
    if (c.progress) c.progress("normal", k, grid.size(), r, false);
    if (c.stop_after && ++computed == c.stop_after && k + 1 < grid.size()) return {};
  }
  return points;
}

std::vector<PointResult> run_tangential_sweep(const SweepContext& c, const std::string& normal_dir) {
  const auto& hn_grid = c.settings.tangential.delta_n;
  const auto& alphas = c.settings.tangential.alpha_deg;
  const std::size_t total = hn_grid.size() * alphas.size();
  std::vector<PointResult> points;
  std::size_t computed = 0;
  for (std::size_t a = 0; a < hn_grid.size(); ++a) {
    std::optional<SimulationState> state;  // the normal state, read when a point has to be computed
    for (std::size_t b = 0; b < alphas.size(); ++b) {
      const std::string path = tangential_point_path(c.checkpoint_dir, a, b);
      const double ht = std::numbers::pi * c.setup.Rs * alphas[b] / 180.0;
      if (const std::optional<PointFile> f = reusable(path, c.config, PointKey{"tangential", hn_grid[a], alphas[b], ht})) {
        points.push_back(f->result);
        points.back().reused = true;
        if (c.progress) c.progress("tangential", points.size() - 1, total, points.back(), true);
        continue;
      }
      Stopwatch watch;  // loading: reading and restoring the normal state, then the rotation
      if (!state) state = normal_state(c, normal_dir, hn_grid[a]);
      Simulation sim(c.setup.scene);
      sim.restore(*state);
      const long step0 = sim.step_count();
      const double alpha = alphas[b] * std::numbers::pi / 180.0;
      RelaxationReport relax;
      PointTiming timing;
      const std::string point =
          fmt::format("tangential point {}/{} (delta_n = {}, alpha = {} deg)", points.size() + 1, total, hn_grid[a], alphas[b]);
      at_point(point, [&] {
        if (alpha != 0.0) {
          RotateGroupDef rot;
          rot.group = GroupDef{GroupDef::Kind::body, c.setup.first_body};
          rot.centre = Vec3::Zero();  // the first shell's centre
          rot.axis = Vec3::UnitZ();
          rot.rate = std::copysign(c.settings.tangential.rate, alpha);
          rot.angle = std::abs(alpha);
          rot.after = c.settings.tangential.after == AfterRotation::hold ? AfterDrive::hold : AfterDrive::release;
          rot.with_shell = !c.setup.first_shell.empty();
          sim.add_driver(rot);
          while (sim.drivers_moving()) sim.step();
        }
        timing.loading = watch.lap();
        relax = softpack::relax(sim, c.settings.relaxation, {}, [&] { return measured_force(sim, c.setup); });
        timing.relaxation = watch.lap();
      });
      PointResult r = record_point(sim, c.setup, relax);
      r.delta_n = hn_grid[a];
      r.hn = hn_grid[a] * c.setup.Rs;
      r.alpha_deg = alphas[b];
      r.ht = ht;
      r.steps = sim.step_count() - step0;
      r.timing = timing;
      sim.release_drivers();
      write_point_file(path, r, sim.state(), provenance(c, "tangential"));
      points.push_back(r);
      if (c.progress) c.progress("tangential", points.size() - 1, total, r, false);
      if (c.stop_after && ++computed == c.stop_after && points.size() < total) return {};
    }
  }
  return points;
}

}  // namespace softpack
