// The watchdog: stops a run that has left the physical regime, with a diagnostic, before it
// writes wrong results. It reads the world and its residuals (sim/residuals.hpp) and changes
// nothing, so it changes no result. Criteria (thresholds in WatchdogDef, scene/scene_def.hpp;
// docs/physics.md §13):
//
//   non-finite  a position, velocity, force (angular velocity, torque) is NaN or infinite;
//   energy      E > energy_growth * B, with E the kinetic (free spheres) + normal elastic (contacts)
//               energy and B its budget: the largest value so far of E_0 + W_drivers + W_gravity.
//               The tangential springs' ½ kt ξ² is not in E: it changes without work when kt
//               follows the overlap, and Coulomb's limit μ Fn bounds it by the normal state.
//               E_0 is E when the budget started (construction, restore), W_drivers the positive
//               work of each driver since then, summed step by step, and W_gravity =
//               sum m_i g . (x_i - x_i(start)). Damping only removes energy, so a sound run keeps
//               E <= B up to the integration error; a blow-up multiplies E by orders of magnitude
//               within a few steps;
//   overlap     h / min(r_i, r_j) > max_overlap_fraction for a sphere pair, h / r for a sphere
//               on a plane or shell.
//
// checked in this order; the first that fails is reported.
//
// The simulation runs the full check every check_interval steps, at construction and restore
// (the states it is given), at the end of every run_steps() (what a caller writes after a run has
// been checked), and before a neighbour rebuild sees a non-finite position.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "integrate/time_step.hpp"
#include "scene/scene_def.hpp"
#include "sim/residuals.hpp"
#include "state/world.hpp"

namespace softpack {

class Watchdog {
 public:
  /// What the diagnostics name: the time step and its limit, the walls, gravity.
  struct Context {
    double dt = 0.0;
    StableLimit limit;
    std::vector<std::string> plane_names, shell_names;
    std::optional<Vec3> gravity;
  };

  /// Overlaps below this fraction of the radius are of rounding size: a state whose contacts all
  /// stay below it, and whose spheres move by less than it per step, is not judged by the energy
  /// criterion.
  static constexpr double kRoundOffOverlap = 1e-9;

  Watchdog() = default;
  Watchdog(const WatchdogDef& def, Context context) : def_(def), context_(std::move(context)) {}

  const WatchdogDef& def() const { return def_; }

  /// Checks the state and starts the energy budget from it (construction, restore).
  void start(const World& world, const Measurement& m);
  /// Adds the positive work the drivers did on the spheres during one step [J].
  void add_driver_work(double work) { driver_work_ += work; }
  /// Checks the current state and its residuals; throws NumericalError with the diagnostic.
  void check(const World& world, const Measurement& m);
  /// Only the positions (cheap): a neighbour rebuild must not see NaN or infinity.
  static bool positions_finite(const World& world);

  /// Energy budget B of the last check [J].
  double budget() const { return budget_; }
  /// Largest overlap fraction and largest E / B met at the checks so far: how close a run came
  /// to the thresholds (tests, choice of the thresholds).
  double largest_overlap_fraction() const { return largest_fraction_; }
  double largest_energy_ratio() const { return largest_energy_ratio_; }

 private:
  std::string where(const World& world) const;
  std::string time_step() const;
  std::string overlap_text(const World& world, const Measurement::Deepest& d) const;
  void check_finite(const World& world, const std::string& before) const;

  WatchdogDef def_;
  Context context_;
  bool started_ = false;
  double start_energy_ = 0.0;   ///< E_0 [J]
  double driver_work_ = 0.0;    ///< W_drivers since the start [J]
  double budget_ = 0.0;         ///< B [J]
  std::vector<Vec3> x_start_;   ///< positions at the start (with gravity only)
  double largest_fraction_ = 0.0, largest_energy_ratio_ = 0.0;
  struct Last {
    long step = 0;
    double fraction = 0.0, energy_ratio = 0.0;
  } last_;  ///< what the last check found, for the diagnostic of a non-finite value
};

}  // namespace softpack
