// The skeleton every sweep runs on (issue 30): normal, tangential and sliding supply only their
// loading; reusing finished points, restoring what a point starts from, relaxing, recording,
// checkpointing and progress are written once, here.
//
// A sweep's points form chains (normal: one; tangential and sliding: one per Δn of their grid),
// visited in order. Point k of a chain starts from the chain's start state (the scene as built,
// or a normal state) or from the state of an earlier point of its chain, as its stage says:
//
//   1. reuse: a point whose checkpoint holds the same configuration and the same point is taken
//      as it is, unless the point it starts from was computed again in this run;
//   2. restore: a point that does not continue the simulation of the point before it gets the
//      state it starts from (kept in memory when its point was reused or computed in this run);
//   3. load: the stage moves the bodies from the start's place to the point's;
//   4. relax with the profile's protocol; 5. record the point; 6. checkpoint it (atomically);
//   7. report progress.
//
// Every point is a pure function of its start state, so a sweep started again recomputes nothing
// finished and gives the same bits as an uninterrupted one.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "formats/sweep_file.hpp"
#include "measure/contact_scenes.hpp"
#include "measure/settings.hpp"
#include "sim/simulation.hpp"

namespace softpack {

struct SweepContext {
  ContactSetup setup;
  MeasurementSettings settings;
  std::string config;          ///< configuration text recorded with (and checked against) each point
  std::string stamp;           ///< the stage's configuration stamp, recorded with each point
  /// Tangential and sliding sweeps: the configuration the normal states they start from must
  /// record (the normal stage's `config`); a state filed under another point, stage, seed or
  /// configuration is refused.
  std::string normal_config;
  std::string checkpoint_dir;  ///< point files of this stage
  std::string code_version;
  /// Progress: the stage of the point ("normal", "tangential"), its index, the number of points,
  /// the point just finished (or reused).
  std::function<void(const std::string& stage, std::size_t, std::size_t, const PointResult&, bool reused)> progress;
  std::size_t stop_after = 0;  ///< for tests: stop after computing this many new points (0: never)
};

/// Which point a point file must hold to be taken as a point of a sweep: its stage and its place
/// on the grid, the values the sweep records with it (hn = delta_n Rs).
struct PointKey {
  const char* stage;
  double delta_n, alpha_deg, ht;
};

/// "" when the point file holds the point `key`, else what it holds instead.
std::string point_mismatch(const PointFile& f, const PointKey& key);

/// One point of a stage's grid.
struct SweepPoint {
  std::string path;                 ///< its checkpoint file
  PointKey key;                     ///< what that file must hold
  std::string label;                ///< names the point in the watchdog's messages
  std::optional<std::size_t> from;  ///< the earlier point of its chain it starts from; none: the chain's start
};

/// What a stage supplies to the skeleton: its grid, where each point starts, and its loading.
class SweepStage {
 public:
  virtual ~SweepStage() = default;
  virtual const char* name() const = 0;
  virtual std::size_t chains() const = 0;
  virtual std::size_t points(std::size_t chain) const = 0;
  virtual SweepPoint point(std::size_t chain, std::size_t k) const = 0;
  /// The state a chain starts from; none: the scene as built.
  virtual std::optional<SimulationState> start(std::size_t chain) const = 0;
  /// One simulation per point (a fresh one restored to the point's start) instead of one per
  /// chain that runs on from point to point.
  virtual bool simulation_per_point() const { return false; }
  /// Moves the bodies from the place of point `from` (none: the chain's start) to point k's.
  virtual void load(Simulation& sim, std::size_t chain, std::size_t k, std::optional<std::size_t> from) const = 0;
  /// What the stage does to the simulation after recording a point, before saving its state.
  virtual void before_checkpoint(Simulation&) const {}
  /// A point's `steps` counted from the simulation's count before its restore, not after (the
  /// normal direct path from 0 since release 0.1.0: a known error of that diagnostic column,
  /// kept until the next release that changes result bits).
  virtual bool counts_steps_before_restore() const { return false; }
};

/// Runs `stage` point by point as the skeleton above says. Returns every point in order, or
/// nothing when `c.stop_after` stopped it early.
std::vector<PointResult> run_sweep(const SweepContext& c, const SweepStage& stage);

/// The force the sweeps record: the load on the second body's wall or shell, what holds it in place.
Vec3 measured_force(const Simulation& sim, const ContactSetup& setup);

}  // namespace softpack
