// A scene as plain data (Box2D style): what the simulation contains and which effects it runs.
// Files are parsed into this at the executable boundary (scene/scene_yaml.hpp); the engine
// validates it (scene/validate.hpp) and runs exactly the declared effects.
//
// Every numeric parameter must be set by the caller: there are no hidden defaults here. The
// values used by the project live in experiments/*.yaml.
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "contact/soft_particle_law.hpp"
#include "core/material.hpp"
#include "core/types.hpp"
#include "walls/spherical_shell.hpp"

namespace softpack {

struct ParticleDef {
  Vec3 x = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  Vec3 w = Vec3::Zero();
  double r = 0.0;
  int material = 0;
  int body = kNoBody;
  /// A soft-particle (effects.soft_particles): one rigid sphere with the measured contact laws.
  bool soft = false;
  /// Its mass [kg] when set (a soft-particle weighs its grains, not a full sphere); otherwise
  /// 4/3 pi r^3 rho.
  std::optional<double> mass;
  /// Its spin held at zero (effects.rotation; I taken infinite): an infinite resistance to rolling
  /// and torsion, as a bound (paper/many-body.md), not a law. Scene key `rotation: locked`.
  bool spin_locked = false;
};

struct ShellDef {
  std::string name;
  int body = kNoBody;
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
  int material = 0;
  ShellContactRadius contact_radius = ShellContactRadius::concave;
  /// A free shell's mass [kg] (walls/spherical_shell.hpp): it moves under its grains' load.
  /// Unset: kinematic, it stands still unless a driver moves it.
  std::optional<double> mass;
  /// The body whose shell encloses this one (scene/bodies.hpp: nested soft-particles, resolved);
  /// kNoBody: none.
  int parent = kNoBody;
};

struct PlaneDef {
  std::string name;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int material = 0;
};

/// Soft-particle contacts (contact/soft_particle_law.hpp): spheres with `soft` meet walls,
/// solid spheres and each other through the laws measured on soft-particles.
struct SoftParticlesDef {
  SoftParticleLaws laws;  ///< formats/law_file.hpp soft_particle_laws() makes it from a law file
  GrainContactRule grain_contact = GrainContactRule::wall;
  enum class BeyondRange { report, stop } beyond_range = BeyondRange::report;
  /// The law file a scene file names (effects.soft_particles.laws), relative paths taken from the
  /// scene file's folder; empty for a scene built in code. The engine reads no JSON: its reader
  /// leaves `laws` empty and the program fills them (formats/scene_laws.hpp load_scene_laws); a
  /// Simulation refuses soft-particles without laws (scene/validate.hpp). Its initializer keeps
  /// the three-member aggregate initializations of the code free of -Wmissing-field-initializers.
  std::string law_file{};
};

/// Effects a scene may declare. An undeclared effect costs nothing and allocates nothing.
struct EffectsDef {
  std::string normal;     ///< the normal law, by name (forces/contact_models.cpp: hertz, Eq. 3-6); empty: none
  bool friction = false;  ///< Tsuji tangential spring with Coulomb limit, Eq. 5-6
  bool rotation = false;  ///< angular velocities and torques
  std::optional<double> restitution;             ///< damping declared: normal restitution e
  double tangential_damping_ratio = 1.0;  ///< scales the tangential damping (contact/viscous_damping.hpp)
  std::optional<Vec3> gravity;                   ///< [m/s^2]
  std::optional<SoftParticlesDef> soft_particles;  ///< spheres with the soft-particle laws
  bool damping() const { return restitution.has_value(); }
};

/// Which spheres a driver moves.
struct GroupDef {
  enum class Kind { all, body } kind = Kind::all;
  int body = kNoBody;
};

/// What a driver does once it has reached its target.
enum class AfterDrive { release, hold };

/// Prescribed translation of a wall or shell at constant velocity, for a distance or a time.
struct MoveWallDef {
  std::string wall;
  Vec3 velocity = Vec3::Zero();
  std::optional<double> distance;  ///< stop after this path length [m]
  std::optional<double> duration;  ///< or after this time [s]
};

/// Slow rigid rotation of a group about a point and an axis (the tangential measurement).
/// Every sphere of the group is moved kinematically: x -> c + R(theta)(x - c), and spins with
/// the group's angular velocity.
struct RotateGroupDef {
  GroupDef group;
  Vec3 centre = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double rate = 0.0;               ///< angular speed [rad/s], sign gives the sense
  std::optional<double> angle;     ///< stop after this angle [rad]
  std::optional<double> duration;  ///< or after this time [s]
  AfterDrive after = AfterDrive::release;
  /// Turn the body's shell with its spheres (a rigid rotation of the whole soft-particle, no
  /// slip at the shell); needs a body group. About the shell's own centre the shell only spins;
  /// about another point its centre also moves on the arc (the sliding stage's orbit of the
  /// second soft-particle about the first).
  bool with_shell = false;
};

/// Rigid translation of a group at constant velocity.
struct TranslateGroupDef {
  GroupDef group;
  Vec3 velocity = Vec3::Zero();
  std::optional<double> distance;
  std::optional<double> duration;
  AfterDrive after = AfterDrive::release;
};

/// Keep a group fixed in space for the whole run.
struct HoldGroupDef {
  GroupDef group;
};

using DriverDef = std::variant<MoveWallDef, RotateGroupDef, TranslateGroupDef, HoldGroupDef>;

/// How the tangential spring is carried from step to step. Velocity Verlet evaluates forces at
/// positions x(t+dt) with velocities v(t+dt/2). `standard` (LAMMPS's default) rotates the spring
/// into the tangent plane at t+dt and adds the half-step relative velocity there: the spring's
/// frame and its increment are half a step apart, which makes small grains between large ones
/// stick or creep at size ratios above ~3 (Vyas et al., Comput. Phys. Commun. 310, 109524
/// (2025)). `synchronized` (their fix, LAMMPS's `synchronized_verlet`) rotates the spring into
/// the tangent plane at t+dt/2, where the half-step velocity lives, adds the increment there,
/// then rotates it into the plane at t+dt for the force.
enum class HistoryUpdate { synchronized, standard };

struct IntegrationDef {
  std::optional<double> dt;         ///< fixed time step [s], refused above the stable limit
  std::optional<double> safety;     ///< or dt = safety * Rayleigh time of the smallest sphere
  HistoryUpdate history_update = HistoryUpdate::synchronized;
};

struct NeighborDef {
  double skin = 0.0;         ///< Verlet skin as a fraction of the smallest radius
  double level_ratio = 0.0;  ///< cell size ratio between levels of the hierarchical grid (> 1)
};

/// Thresholds of the watchdog (sim/watchdog.hpp), which stops a run that has gone wrong with a
/// NumericalError; it never changes a result. Unlike the physics, these have defaults: the
/// values below, documented in docs/scene-format.md (scene key `watchdog`) and docs/measurement.md
/// (profile section `watchdog`).
struct WatchdogDef {
  static constexpr double kMaxOverlapFraction = 1.0;
  static constexpr double kEnergyGrowth = 10.0;
  static constexpr long kCheckInterval = 100;

  /// Largest overlap allowed, as a fraction of the smaller radius of the pair (of the sphere's
  /// radius against a wall). +infinity switches the criterion off (from C++ only).
  double max_overlap_fraction = kMaxOverlapFraction;
  /// The run stops when kinetic + elastic energy exceeds this factor times its budget: the
  /// largest energy the run has been given so far (initial energy + positive work of the
  /// drivers + work of gravity). > 1.
  double energy_growth = kEnergyGrowth;
  /// Steps between two full checks (also done at construction, restore, and the end of each
  /// run_steps()). >= 1.
  long check_interval = kCheckInterval;
};

struct SceneDef {
  std::vector<Material> materials;
  EffectsDef effects;
  std::vector<ParticleDef> particles;
  std::vector<ShellDef> shells;
  std::vector<PlaneDef> planes;
  std::vector<DriverDef> drivers;
  IntegrationDef integration;
  NeighborDef neighbor;
  WatchdogDef watchdog;

  int material_index(const std::string& name) const;  ///< -1 if absent
};

}  // namespace softpack
