// The simulation: owns the spheres, walls, contact lists and drivers of one scene and advances
// them with velocity Verlet. One step runs these phases, one function each:
//
//   half_kick           v += F/m dt/2, w += T/I dt/2 (free spheres)
//   drift               x += v dt
//   advance_drivers     kinematic spheres and walls to their prescribed state at t + dt
//   update_neighbours   rebuild the Verlet lists when the skin is used up
//   compute_forces      contact laws (contact/contact_force.hpp), gravity, wall loads
//   half_kick           v += F/m dt/2, w += T/I dt/2
//
// The watchdog (sim/watchdog.hpp) checks the state every scene.watchdog.check_interval steps and
// stops a run gone wrong with a NumericalError; it only reads the state.
//
// Only the declared effects run (scene/scene_def.hpp): the force loop is compiled for each
// combination of friction, damping and rotation, and state of undeclared effects is never
// allocated.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/material.hpp"
#include "core/particles.hpp"
#include "integrate/time_step.hpp"
#include "neighbor/contact_list.hpp"
#include "neighbor/hierarchical_grid.hpp"
#include "scene/scene_def.hpp"
#include "sim/watchdog.hpp"
#include "walls/plane_wall.hpp"
#include "walls/spherical_shell.hpp"

namespace softpack {

/// Force and torque a wall receives from the spheres; the torque is about the wall's
/// reference point (the plane's point, the shell's centre).
struct WallLoad {
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
};

/// Residuals of the current state, used by the relaxation protocols.
struct Measurement {
  double kinetic_energy = 0.0;        ///< free spheres, translation + rotation [J]
  double elastic_energy = 0.0;        ///< Hertz + tangential springs [J]
  double max_unbalanced_force = 0.0;  ///< largest |net force| on a free sphere [N]
  double mean_contact_force = 0.0;    ///< mean Hertz force over closed contacts [N]
  std::size_t contacts = 0;           ///< closed contacts (sphere-sphere and sphere-wall)
  /// Deepest contact relative to its smaller radius (a sphere's own radius against a wall):
  /// spheres i and j, or sphere i and plane `plane` or shell `shell` (j = -1). i = -1: none.
  struct Deepest {
    double fraction = 0.0, overlap = 0.0;  ///< h / radius [-], h [m]
    int i = -1, j = -1, plane = -1, shell = -1;
  } deepest;
  int hottest = -1;             ///< free sphere with the largest kinetic energy (-1: none moves)
  double hottest_energy = 0.0;  ///< its kinetic energy [J]
  /// max unbalanced force / mean contact force (0 for a state with no force at all).
  double force_ratio() const;
  /// kinetic energy / elastic energy (0 when both vanish).
  double energy_ratio() const;
};

/// Everything a run needs to continue bit for bit: the checkpoints of the sweeps.
struct SimulationState {
  double time = 0.0;
  long steps = 0;
  std::vector<Vec3> x, v, w, F, T;  ///< w and T empty without rotation
  std::vector<Vec3> plane_points, shell_centres;
  /// Non-zero tangential springs: sphere pairs (i < j), and per wall (sphere, spring).
  struct PairSpring {
    int i = 0, j = 0;
    Vec3 xi = Vec3::Zero();
  };
  struct WallSpring {
    int i = 0;
    Vec3 xi = Vec3::Zero();
  };
  std::vector<PairSpring> pair_springs;
  std::vector<std::vector<WallSpring>> plane_springs, shell_springs;
};

class Simulation {
 public:
  /// Validates the scene (InputError naming the key on failure), computes the initial forces
  /// and checks the initial state (NumericalError, e.g. for an overlap beyond the watchdog's limit).
  explicit Simulation(const SceneDef& scene);

  void step();
  /// n steps, then a watchdog check: a state a caller sees after run_steps() has been checked.
  void run_steps(long n);
  /// Number of steps that make up `duration` (rounded, at least 1).
  long steps_for(double duration) const;
  void run_for(double duration);
  /// Sets every free sphere's translational and angular velocity to zero.
  void zero_velocities();
  /// Starts a driver now (validated like the scene's drivers).
  void add_driver(const DriverDef& driver);
  /// Stops every driver now: walls stand still, driven spheres stop and become free.
  void release_drivers();
  /// True while a driver with a target (distance, angle, duration) has not reached it.
  bool drivers_moving() const;
  Measurement measure() const;

  /// The state of the spheres, walls and springs (no drivers may be moving).
  SimulationState state() const;
  /// Continues from a state of the same scene; InputError when it does not fit the scene. The
  /// watchdog checks the state and restarts its energy budget from it.
  void restore(const SimulationState& s);
  /// Elastic contact force (Hertz and tangential springs, no damping) that the spheres of body
  /// `from` exert on the spheres of body `on`.
  Vec3 force_between(int from, int on) const;

  double dt() const { return dt_; }
  double time() const { return time_; }
  long step_count() const { return steps_; }
  const StableLimit& stable_limit() const { return stable_; }
  const SceneDef& scene() const { return scene_; }
  const Particles& particles() const { return p_; }
  const std::vector<PlaneWall>& planes() const { return planes_; }
  const std::vector<SphericalShell>& shells() const { return shells_; }
  const std::vector<WallLoad>& plane_loads() const { return plane_loads_; }
  const std::vector<WallLoad>& shell_loads() const { return shell_loads_; }
  /// Load on the plane or shell of that name; throws InputError if there is none.
  const WallLoad& wall_load(const std::string& name) const;
  const PairList& pair_list() const { return pairs_; }
  const std::vector<WallList>& plane_lists() const { return plane_lists_; }
  const std::vector<WallList>& shell_lists() const { return shell_lists_; }
  long neighbour_rebuilds() const { return rebuilds_; }
  const Watchdog& watchdog() const { return watchdog_; }

  /// How far a driver has gone: distance [m] or angle [rad] along its path.
  struct ActiveDriverProgress {
    double progress = 0.0;
    bool reached = false;  ///< target reached during the current step
  };

 private:
  struct ActiveDriver : ActiveDriverProgress {
    DriverDef def;
    std::vector<int> members;  ///< driven spheres (group drivers)
    int plane = -1, shell = -1;
    bool retired = false;
  };

  void half_kick();
  void drift();
  void advance_drivers();
  void finish_drivers();
  void update_neighbours();
  void rebuild_neighbours();
  void compute_forces(double spring_dt);
  void check_now();
  double driver_work() const;
  template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
  void compute_forces_for(double spring_dt);

  ContactCoefficients coefficients(int i, int j) const;
  ContactCoefficients wall_coefficients(int i, int wall_material, double R12) const;
  std::vector<int> members_of(const GroupDef& g) const;
  void activate(ActiveDriver& d);
  ActiveDriver make_driver(const DriverDef& def);

  SceneDef scene_;
  Particles p_;
  std::vector<PlaneWall> planes_;
  std::vector<SphericalShell> shells_;
  std::vector<WallLoad> plane_loads_, shell_loads_;
  std::vector<std::vector<int>> shell_members_;

  // Material pair constants, index a * nmat + b.
  std::size_t nmat_ = 0;
  std::vector<double> D_, Dt_, mu_;
  double alpha_ = 0.0;  ///< damping coefficient alpha(e)

  double dt_ = 0.0, time_ = 0.0;
  long steps_ = 0;
  StableLimit stable_;

  // Neighbour lists.
  HierarchicalGrid grid_;
  double skin_ = 0.0;  ///< [m]
  PairList pairs_;
  std::vector<WallList> plane_lists_, shell_lists_;
  std::vector<Vec3> x_at_build_, plane_at_build_, shell_at_build_;
  /// The two largest squared displacements since the last neighbour build, over the spheres'
  /// current positions (different spheres): a pair's gap has shrunk by at most their roots' sum.
  struct LargestTwo {
    double first = 0.0, second = 0.0;
    void add(double d2) {
      if (d2 > first) second = first, first = d2;
      else if (d2 > second) second = d2;
    }
  } disp2_;
  bool rebuild_requested_ = true;
  long rebuilds_ = 0;

  std::vector<ActiveDriver> drivers_;

  Watchdog watchdog_;
  long since_check_ = 0;  ///< steps since the last watchdog check

  std::vector<int> closed_;                 ///< scratch of the pair forces: touching pairs
  std::vector<std::pair<int, int>> found_;  ///< scratch of rebuild_neighbours: pairs found
  std::vector<std::size_t> first_;          ///< scratch of rebuild_neighbours: counting sort
};

}  // namespace softpack
