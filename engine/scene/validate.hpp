// Semantic checks of a scene: ranges, references between its parts and contradictions. This is
// the one owner of every range rule of a scene's parameters: the YAML readers check only types
// and keys, then locate these messages in the file by their key path (ConfigNode::locate).
// Each failure throws InputError with the key path ("drivers[1].group.body: ...").
#pragma once
#include <string>
#include <vector>

#include "scene/relaxation_def.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

/// Whether a scene's soft-particle laws must be there. A scene file's reader (scene/scene_yaml.hpp)
/// checks its scene before the program has read the law file it names (SoftParticlesDef::law_file,
/// formats/scene_laws.hpp load_scene_laws, which then checks the rest): `pending` skips the rules
/// that need the laws while they are empty. Everything else, Simulation first, uses `loaded`, so
/// that no scene runs soft-particles without laws.
enum class SoftLaws { loaded, pending };

void validate(const SceneDef& scene, SoftLaws laws = SoftLaws::loaded);

/// The checks of each part, for a part held elsewhere (a profile's sections): `key` is the part's
/// key path, which the messages name ("simulation.effects.damping.restitution: ...").
void validate_material(const Material& m, const std::string& key);
/// Soft-particle contacts: the laws the scene's contacts need, the radii they were measured at
/// (scene/validate_soft.cpp).
void validate_soft_particles(const SceneDef& scene, SoftLaws laws = SoftLaws::loaded);
/// Why a soft-particle of radius r cannot run on `law` (named `law_key`) of `laws`, or "": r must be
/// the reference radius R0 without a radius scaling, within the measured radii with one (the
/// scaling of the tangential law too with friction). Also the LAMMPS pair style's rule.
std::string soft_radius_refusal(const SoftParticleLaws& laws, const SoftSceneLaw& law, const std::string& law_key, double r, bool friction);
void validate_effects(const EffectsDef& e, const std::vector<Material>& materials, const std::string& key = "effects");
void validate_integration(const IntegrationDef& in, const std::string& key = "integration");
void validate_neighbor(const NeighborDef& nb, const std::string& key = "neighbor");
void validate_watchdog(const WatchdogDef& wd, const std::string& key = "watchdog");
/// An active set (InputError naming <key>.<name>).
void validate_active_set(const ActiveSetDef& def, const std::string& key);
/// A relaxation protocol (InputError naming <key>.<name>).
void validate(const RelaxationDef& def, const std::string& key = "relaxation");

/// The checks of validate() for `drivers` run in `scene` (Drivers::add: a driver started during a run).
void validate_drivers(const SceneDef& scene, const std::vector<DriverDef>& drivers);

// The rules that need the time step dt, checked where it is known (sim/simulation.cpp, the
// executables, measure/stage.cpp): a duration may ask for at most limits::kMaxSteps steps, a
// driven rotation may turn at most limits::kMaxRotationPerStep per step. InputError names `key`.
/// `seconds` of simulated time (run.duration; `what` describes it in the message, default
/// "<seconds> s").
void validate_steps(double seconds, double dt, const std::string& key, const std::string& what = "");
/// A relaxation: its waits (paper: stops x wait + final_wait) or its max_time (converged).
void validate_steps(const RelaxationDef& def, double dt, const std::string& key = "relaxation");
/// A driver: its way to its target (distance / speed, angle / rate, or duration) and its rotation per step.
void validate_steps(const DriverDef& driver, double dt, const std::string& key);

}  // namespace softpack
