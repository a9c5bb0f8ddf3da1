// Kinematic drivers (scene/scene_def.hpp DriverDef): walls and groups of spheres whose motion is
// prescribed, step by step, instead of integrated. A driver advances by its rate times dt,
// clipped so that it lands exactly on its target (distance, angle or duration), then stops: walls
// stand still, groups stop and are released (free from the next step on) or held in place.
#pragma once
#include <string>
#include <vector>

#include "neighbor/neighbours.hpp"
#include "scene/scene_def.hpp"
#include "state/world.hpp"

namespace softpack {

class Drivers {
 public:
  /// The scene's drivers, started now (their spheres are marked driven and stopped).
  Drivers(const SceneDef& scene, World& world);

  bool empty() const { return active_.empty(); }
  /// Starts a driver now; InputError (validated with the scene's rules) when it does not fit.
  void add(const DriverDef& driver, World& world);
  /// Moves the kinematic spheres and walls to their state at t + dt; each driven sphere's
  /// displacement since the last neighbour build goes to `neighbours.moved()`.
  void advance(World& world, double dt, Neighbours& neighbours);
  /// Positive work the drivers did on the spheres during the step just made [J] (the watchdog's
  /// energy budget): the force at the end of the step times the step's motion.
  double work(const World& world, double dt) const;
  /// Drivers that reached their target stop (after the step's forces).
  void finish(World& world);
  /// Stops every driver now: walls stand still, driven spheres stop and become free.
  void release(World& world);
  /// True while a driver with a target has not reached it.
  bool moving() const;

  /// How far a driver has gone: distance [m] or angle [rad] along its path.
  struct Progress {
    double progress = 0.0;
    bool reached = false;  ///< target reached during the current step
  };

 private:
  struct Active : Progress {
    DriverDef def;
    std::vector<int> members;  ///< driven spheres (group drivers)
    int plane = -1, shell = -1;
    bool retired = false;
  };
  Active start(const DriverDef& def, World& world) const;

  const SceneDef* scene_;  ///< the scene the drivers move (owned by the simulation)
  std::vector<Active> active_;
};

}  // namespace softpack
