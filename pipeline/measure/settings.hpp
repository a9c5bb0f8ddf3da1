// Settings of the contact-law measurement (paper §4), read from a profile's `material`,
// `simulation`, `relaxation`, `normal` and `tangential` sections. `material`, `simulation`,
// `relaxation` and `watchdog` are parts of a scene and are read and validated as a scene's are
// (scene/scene_yaml.hpp, scene/validate.hpp); `normal` and `tangential` are the sweeps' own.
// Every value is named in the profile; the choices the paper leaves open are justified in
// docs/measurement.md. The optional `watchdog` section sets when a run that has gone wrong stops
// (sim/watchdog.hpp); it changes no result and is not part of the configuration recorded with
// the points.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"
#include "core/material.hpp"
#include "relax/relaxation.hpp"
#include "scene/scene_def.hpp"
#include "walls/spherical_shell.hpp"

namespace softpack {

/// The two contacts of the paper: a soft-particle against a plane wall (a solid sphere of
/// infinite radius), and two soft-particles of equal size.
enum class ContactScene { soft_solid, soft_soft };
ContactScene parse_contact_scene(const std::string& name);  ///< "soft-solid" | "soft-soft"
std::string scene_name(ContactScene s);

/// How the sites of a packing of nested soft-particles (packing.levels > 1, packing/nested.hpp)
/// are held in the measurement scenes: the profile's `content` section (docs/nested.md).
///   soft:     each site one soft-particle of the soft-particle's body, following the law file
///             of the level below (`laws`), of its content's mass and (1 + shell_mass_fraction);
///   resolved: each site's content, down to the last level, in a free shell (its grains' mass
///             times shell_mass_fraction) whose parent is the enclosing body.
enum class ContentForm { soft, resolved };
struct ContentSettings {
  ContentForm form = ContentForm::soft;
  std::string laws;  ///< soft: the law file's path (read when a scene is built: it may be made after the profile is read)
  /// soft, optional: a law file whose many-body law (`many_body`, dimensionless) the sites follow
  /// on top of `laws`' pairwise laws; empty: the pairwise laws alone.
  std::string many_body;
  GrainContactRule grain_contact = GrainContactRule::wall;  ///< soft: a grain against a site
  double shell_mass_fraction = 0.0;
};

/// Engine settings of the measurement scenes: the profile's `material` and `simulation`
/// sections, in the scene format's own terms (docs/scene-format.md), read by its own readers,
/// and the `content` section (absent: a packing without levels).
struct SimulationSettings {
  Material material;       ///< of the grains (and of the shells and the wall unless `material.wall`)
  Material wall_material;  ///< of the shells and the plane wall: `material.wall`, each key left out the grains'
  EffectsDef effects;
  IntegrationDef integration;
  NeighborDef neighbor;
  ShellContactRadius shell_contact_radius = ShellContactRadius::concave;  ///< `shells: {contact_radius}`
  std::optional<ContentSettings> content;
};

/// How the first soft-particle is turned for the tangential measurement.
enum class AfterRotation { release, hold };

struct NormalSettings {
  std::vector<ContactScene> scenes;
  std::vector<double> delta_n;  ///< hn / Rs, increasing, >= 0 (the first point approaches from contact)
  double speed = 0.0;           ///< approach speed of the second body [m/s]
  bool incremental = true;      ///< from the previous point (else from the undeformed state)
  /// soft-soft: the second soft-particle is its packing scaled by this ratio (radius Rs2 = ratio
  /// Rs, the self-similar soft-particle of that radius); 1: two of equal size (the paper's).
  double second_radius_ratio = 1.0;
};

struct TangentialSettings {
  std::vector<double> delta_n;    ///< hn / Rs of the normal states to shear (a subset of normal)
  std::vector<double> alpha_deg;  ///< rotation angles [degrees], ht = pi Rs alpha / 180
  double rate = 0.0;              ///< angular speed of the rotation [rad/s]
  AfterRotation after = AfterRotation::release;
};

/// The sliding measurement (issue 16, the soft-particle's friction coefficient): from the saved
/// normal state at each of `delta_n`, the second body is moved along +y, parallel to the contact,
/// through each ht = ht_over_Rs Rs in turn (each point from the previous one, as a shear test),
/// at `speed`, then the scene relaxes; the contact slides where Ft / Fn stops growing.
struct SlidingSettings {
  std::vector<double> delta_n;     ///< hn / Rs of the normal states to slide (a subset of normal)
  std::vector<double> ht_over_Rs;  ///< tangential displacement of the second body / Rs, increasing, > 0
  double speed = 0.0;              ///< its speed [m/s]
};

struct MeasurementSettings {
  SimulationSettings simulation;
  RelaxationDef relaxation;
  NormalSettings normal;
  TangentialSettings tangential;
  bool has_tangential = true;  ///< false: a normal-only profile (no `tangential` section)
  SlidingSettings sliding;
  bool has_sliding = false;  ///< the optional `sliding` section is there
  WatchdogDef watchdog;  ///< `watchdog` section (optional; defaults of WatchdogDef)
};

/// Reads and validates the sections; InputError names file, key and allowed values.
MeasurementSettings parse_measurement(const ConfigNode& root);

/// The rules of the sweeps that need the time step dt of the measurement scene (soft-particles
/// of shell radius Rs), checked before the first point (measure/stage.cpp): the relaxation, the
/// longest approach of a normal point (normal.speed), the largest rotation of a tangential
/// one (tangential.rate) and the longest move of a sliding one (sliding.speed) each take at most limits::kMaxSteps steps, and the rotation turns at
/// most limits::kMaxRotationPerStep per step (scene/limits.hpp). InputError names the key.
void validate_sweep_steps(const MeasurementSettings& m, double Rs, double dt);

}  // namespace softpack
