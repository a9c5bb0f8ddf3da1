#include "measure/sweeps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "core/error.hpp"
#include "core/version.hpp"
#include "profile/profile.hpp"

namespace softpack {
namespace {

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

// Turns `body` (its spheres, and its shell when `with_shell`) rigidly about +z through the first
// shell's centre (the origin) by `angle` [rad] at `rate` [rad/s] (its sign: the sense), then lets
// it go or holds it.
void turn_body(Simulation& sim, int body, double angle, double rate, AfterDrive after, bool with_shell) {
  RotateGroupDef rot;
  rot.group = GroupDef{GroupDef::Kind::body, body};
  rot.centre = Vec3::Zero();
  rot.axis = Vec3::UnitZ();
  rot.rate = rate;
  rot.angle = angle;
  rot.after = after;
  rot.with_shell = with_shell;
  sim.add_driver(rot);
  while (sim.drivers_moving()) sim.step();
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
  if (const std::string release = release_of(f.provenance.code_version); release != release_of(c.code_version))
    throw InputError(fmt::format("{}: this normal state was computed by release {}, this build is {} (a release changes result "
                                 "bits); run the normal stage of this profile, scene and seed again",
                                 path, release.empty() ? "unknown" : release, release_of(c.code_version)));
  if (const std::string other = point_mismatch(f, PointKey{"normal", delta_n, 0.0, 0.0}); !other.empty())
    throw InputError(fmt::format("{}: filed as the normal state of delta_n = {}, it holds {}; run the normal stage again", path,
                                 delta_n, other));
  return std::move(f.state);
}

// Normal (paper §4): the second body approaches along -x to each hn = delta_n Rs of the grid,
// from the previous point (incremental) or from the undeformed state (direct: point 0's when
// the grid starts at 0, relaxed there; else the scene as built).
class NormalStage final : public SweepStage {
 public:
  explicit NormalStage(const SweepContext& c) : c_(c), grid_(c.settings.normal.delta_n) {}
  const char* name() const override { return "normal"; }
  std::size_t chains() const override { return 1; }
  std::size_t points(std::size_t) const override { return grid_.size(); }
  SweepPoint point(std::size_t, std::size_t k) const override {
    std::optional<std::size_t> from;
    if (k > 0 && c_.settings.normal.incremental) from = k - 1;
    if (k > 0 && !c_.settings.normal.incremental && zero_first()) from = 0;
    return {normal_point_path(c_.checkpoint_dir, k), PointKey{"normal", grid_[k], 0.0, 0.0},
            fmt::format("normal point {}/{} (delta_n = {})", k + 1, grid_.size(), grid_[k]), from};
  }
  std::optional<SimulationState> start(std::size_t) const override { return std::nullopt; }
  void load(Simulation& sim, std::size_t, std::size_t k, std::optional<std::size_t> from) const override {
    const double hn_from = from ? grid_[*from] * c_.setup.Rs : 0.0;
    move_second_body(sim, c_.setup, Vec3(-1, 0, 0), grid_[k] * c_.setup.Rs - hn_from, c_.settings.normal.speed);
  }
  bool counts_steps_before_restore() const override { return !c_.settings.normal.incremental && zero_first(); }

 private:
  bool zero_first() const { return grid_.front() == 0.0; }
  const SweepContext& c_;
  const std::vector<double>& grid_;
};

// Tangential (paper §4): from the normal state at each Δn of the grid, the first soft-particle
// (its spheres and its shell) is turned rigidly about +z through its centre by each alpha, then
// released (or held) and relaxed; ht = π Rs alpha / 180.
class TangentialStage final : public SweepStage {
 public:
  TangentialStage(const SweepContext& c, std::string normal_dir) : c_(c), normal_dir_(std::move(normal_dir)) {}
  const char* name() const override { return "tangential"; }
  std::size_t chains() const override { return t().delta_n.size(); }
  std::size_t points(std::size_t) const override { return t().alpha_deg.size(); }
  SweepPoint point(std::size_t a, std::size_t b) const override {
    const double alpha = t().alpha_deg[b], ht = std::numbers::pi * c_.setup.Rs * alpha / 180.0;
    const std::size_t index = a * points(a) + b + 1, total = chains() * points(a);
    return {tangential_point_path(c_.checkpoint_dir, a, b), PointKey{"tangential", t().delta_n[a], alpha, ht},
            fmt::format("tangential point {}/{} (delta_n = {}, alpha = {} deg)", index, total, t().delta_n[a], alpha),
            std::nullopt};
  }
  std::optional<SimulationState> start(std::size_t a) const override { return normal_state(c_, normal_dir_, t().delta_n[a]); }
  bool simulation_per_point() const override { return true; }
  void load(Simulation& sim, std::size_t, std::size_t b, std::optional<std::size_t>) const override {
    const double alpha = t().alpha_deg[b] * std::numbers::pi / 180.0;
    if (alpha == 0.0) return;
    turn_body(sim, c_.setup.first_body, std::abs(alpha), std::copysign(t().rate, alpha),
              t().after == AfterRotation::hold ? AfterDrive::hold : AfterDrive::release, !c_.setup.first_shell.empty());
  }
  // A rotation held (tangential.after: hold) lets go before the state is saved.
  void before_checkpoint(Simulation& sim) const override { sim.release_drivers(); }

 private:
  const TangentialSettings& t() const { return c_.settings.tangential; }
  const SweepContext& c_;
  std::string normal_dir_;
};

// Sliding (issue 16): from the normal state at each Δn of the grid, the second body is moved
// parallel to the contact to each ht = ht_over_Rs Rs in turn, each point from the previous one:
// the wall along +y; the second soft-particle (shell and spheres, rigidly) on an orbit about the
// first's centre by the angle ht / Rs, so that its centre keeps its distance and the contact its
// depth hn (a translation would open the contact as it slides), recorded as alpha_deg.
class SlidingStage final : public SweepStage {
 public:
  SlidingStage(const SweepContext& c, std::string normal_dir) : c_(c), normal_dir_(std::move(normal_dir)) {}
  const char* name() const override { return "sliding"; }
  std::size_t chains() const override { return s().delta_n.size(); }
  std::size_t points(std::size_t) const override { return s().ht_over_Rs.size(); }
  SweepPoint point(std::size_t a, std::size_t b) const override {
    const std::size_t index = a * points(a) + b + 1, total = chains() * points(a);
    return {sliding_point_path(c_.checkpoint_dir, a, b), PointKey{"sliding", s().delta_n[a], alpha_deg(ht(b)), ht(b)},
            fmt::format("sliding point {}/{} (delta_n = {}, ht/Rs = {})", index, total, s().delta_n[a], s().ht_over_Rs[b]),
            b > 0 ? std::optional<std::size_t>(b - 1) : std::nullopt};
  }
  std::optional<SimulationState> start(std::size_t a) const override { return normal_state(c_, normal_dir_, s().delta_n[a]); }
  void load(Simulation& sim, std::size_t, std::size_t b, std::optional<std::size_t> from) const override {
    const double dht = ht(b) - (from ? ht(*from) : 0.0);
    if (dht <= 0.0) return;
    if (c_.setup.second_body < 0) return move_second_body(sim, c_.setup, Vec3(0, 1, 0), dht, s().speed);
    turn_body(sim, c_.setup.second_body, dht / c_.setup.Rs, s().speed / c_.setup.Rs, AfterDrive::release, true);  // an orbit
  }

 private:
  const SlidingSettings& s() const { return c_.settings.sliding; }
  double ht(std::size_t b) const { return s().ht_over_Rs[b] * c_.setup.Rs; }
  // Soft-soft: the orbit's angle, by which the contact's frame has turned about +z; soft-solid: 0.
  double alpha_deg(double ht) const { return c_.setup.second_body >= 0 ? ht / c_.setup.Rs * 180.0 / std::numbers::pi : 0.0; }
  const SweepContext& c_;
  std::string normal_dir_;
};

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

std::vector<PointResult> run_normal_sweep(const SweepContext& c) { return run_sweep(c, NormalStage(c)); }

std::vector<PointResult> run_tangential_sweep(const SweepContext& c, const std::string& normal_dir) {
  return run_sweep(c, TangentialStage(c, normal_dir));
}

std::vector<PointResult> run_sliding_sweep(const SweepContext& c, const std::string& normal_dir) {
  return run_sweep(c, SlidingStage(c, normal_dir));
}

}  // namespace softpack
