// The simulation of one scene: it composes the parts, each in its own folder, and advances them
// with velocity Verlet. The parts, in the direction of their dependencies:
//
//   World       the spheres, walls and clock           state/world.hpp
//   Neighbours  contact detection and the lists        neighbor/neighbours.hpp
//   Drivers     prescribed motion                       drivers/drivers.hpp
//   ForceField  the normal law, effects and loops      forces/force_field.hpp
//   Watchdog    stops a run gone wrong                 sim/watchdog.hpp
//
// One step runs these phases, one function each:
//
//   kick_drift          v += F/m dt/2, w += T/I dt/2, then x += v dt    integrate/velocity_verlet
//                       (free spheres, one pass)
//   advance_drivers     kinematic spheres and walls at t + dt            drivers/drivers
//   update_neighbours   rebuild the Verlet lists when the skin is used up neighbor/neighbours
//   compute_forces      gravity, then the contact law of every contact   forces/force_field
//   (wake)              only with an active set: sleeping spheres whose force grew wake  sim/active_set
//   half_kick           with the quench, only while set_quench(true): v = 0 where F·v < 0
//                       (relaxation), in the same pass
//   finish_drivers      the drivers' work (watchdog budget); drivers that arrived stop
//   (sleep)             with an active set, every check_interval: spheres at rest fall asleep
//
// The watchdog checks the state every scene.watchdog.check_interval steps; it only reads it.
// Only the declared effects run (scene/scene_def.hpp): the force loops are compiled for each
// combination of them, and the state of undeclared effects is never allocated.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "drivers/drivers.hpp"
#include "forces/force_field.hpp"
#include "integrate/time_step.hpp"
#include "neighbor/neighbours.hpp"
#include "scene/scene_def.hpp"
#include "sim/active_set.hpp"
#include "sim/residuals.hpp"
#include "sim/watchdog.hpp"
#include "state/simulation_state.hpp"
#include "state/world.hpp"

namespace softpack {

class Simulation {
 public:
  /// Validates the scene (InputError naming the key on failure), computes the initial forces
  /// and checks the initial state (NumericalError, e.g. for an overlap beyond the watchdog's limit).
  explicit Simulation(const SceneDef& scene);
  Simulation(const Simulation&) = delete;  // the parts refer to the scene and to each other
  Simulation& operator=(const Simulation&) = delete;
  /// Forgets what the construction of scenes remembers across a process (the damping's zeta of
  /// each restitution, contact/viscous_damping.hpp), so that the next one costs what the first of
  /// a process costs (timings that compare runs of one process); the same bits either way.
  static void forget_setup_caches();

  void step();
  /// n steps, then a watchdog check: a state a caller sees after run_steps() has been checked.
  void run_steps(long n);
  /// Number of steps that make up `duration` (rounded, at least 1); InputError beyond
  /// limits::kMaxSteps (scene/limits.hpp; callers that know the duration's key check it first
  /// with validate_steps()).
  long steps_for(double duration) const;
  void run_for(double duration);
  /// Sets every free sphere's translational and angular velocity to zero.
  void zero_velocities();
  /// Turns the per-grain velocity quench of every step on or off (scene/relaxation_def.hpp).
  void set_quench(bool on) { quench_ = on; }
  bool quenching() const { return quench_; }
  /// Turns the active set (sim/active_set.hpp) on with `def` (validated: InputError naming
  /// active_set.<key>), or off with nullopt; either way every sphere is awake afterwards.
  void set_active_set(const std::optional<ActiveSetDef>& def);
  /// The active set, or null when it is off.
  const ActiveSet* active_set() const { return active_ ? &*active_ : nullptr; }
  /// A sleep check now (the paper protocol makes one after each stop); nothing without an active set.
  void sleep_check();
  /// Starts a driver now (validated like the scene's drivers, its steps with validate_steps()).
  void add_driver(const DriverDef& driver);
  /// Stops every driver now: walls stand still, driven spheres stop and become free.
  void release_drivers() { drivers_.release(world_); }
  /// True while a driver with a target (distance, angle, duration) has not reached it.
  bool drivers_moving() const { return drivers_.moving(); }
  /// Residuals of the current state (sim/residuals.hpp).
  Measurement residuals() const { return softpack::residuals(world_, neighbours_.lists(), forces_); }
  double overlap_quantile(double q) const { return softpack::overlap_quantile(world_, neighbours_.lists(), forces_, q); }

  /// The state of the spheres, walls and springs (no drivers may be moving). sim/checkpoint.cpp.
  SimulationState state() const;
  /// Continues from a state of the same scene; InputError when it does not fit the scene. The
  /// watchdog checks the state and restarts its energy budget from it. An active set wakes
  /// every sphere.
  void restore(const SimulationState& s);
  /// Elastic contact force (normal law and tangential springs, no damping) that the spheres of
  /// body `from` exert on the spheres of body `on` (each with the bodies inside it, scene/bodies.hpp).
  Vec3 force_between(int from, int on) const;

  double dt() const { return dt_; }
  double time() const { return world_.time; }
  long step_count() const { return world_.steps; }
  const StableLimit& stable_limit() const { return stable_; }
  const SceneDef& scene() const { return scene_; }
  const World& world() const { return world_; }
  const Particles& particles() const { return world_.p; }
  const std::vector<PlaneWall>& planes() const { return world_.planes; }
  const std::vector<SphericalShell>& shells() const { return world_.shells; }
  const std::vector<WallLoad>& plane_loads() const { return world_.plane_loads; }
  const std::vector<WallLoad>& shell_loads() const { return world_.shell_loads; }
  /// Load on the plane or shell of that name; throws InputError if there is none.
  const WallLoad& wall_load(const std::string& name) const;
  /// The lists of family 0 (the scene's model; neighbor/contact_list.hpp ContactLists).
  const PairList& pair_list() const { return neighbours_.lists().family.at(0).pairs; }
  const std::vector<WallList>& plane_lists() const { return neighbours_.lists().family.at(0).planes; }
  const std::vector<WallList>& shell_lists() const { return neighbours_.lists().family.at(0).shells; }
  /// Every contact list (forces/contact_walk.hpp walks them).
  const ContactLists& contact_lists() const { return neighbours_.lists(); }
  long neighbour_rebuilds() const { return neighbours_.rebuilds(); }
  const ForceField& force_field() const { return forces_; }
  const Watchdog& watchdog() const { return watchdog_; }

 private:
  void update_neighbours();
  void rebuild_neighbours();
  void compute_forces(double spring_dt);
  void check_now();
  void wake_now();

  SceneDef scene_;
  double dt_ = 0.0;
  StableLimit stable_;
  World world_;
  ForceField forces_;
  Neighbours neighbours_;
  Drivers drivers_;
  Watchdog watchdog_;
  long since_check_ = 0;  ///< steps since the last watchdog check
  bool quench_ = false;
  bool free_shells_ = false;  ///< a shell has a mass (walls/spherical_shell.hpp)
  std::optional<ActiveSet> active_;
  long sleep_interval_ = 0;       ///< steps between sleep checks
  long since_sleep_check_ = 0;
};

}  // namespace softpack
