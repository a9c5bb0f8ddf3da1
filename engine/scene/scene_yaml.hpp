// Reads a scene from YAML (the format is documented in docs/scene-format.md and exercised by
// experiments/scenes/*.yaml). Syntax, types and unknown keys are checked here with file, line
// and column; ranges and cross-references by validate(), whose messages are placed in the file
// by their key.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"
#include "scene/relaxation_def.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

/// What softpack-run does with a scene: run for a while (drivers move), then relax.
struct RunDef {
  std::optional<double> duration;
  std::optional<RelaxationDef> relaxation;
};

struct SceneFile {
  SceneDef scene;
  RunDef run;
  ConfigNode root;  ///< the document, to place later errors in it (ConfigNode::locate)
};

/// Parses and validates a scene document. Soft-particle laws are not read here (the engine
/// reads no JSON): effects.soft_particles holds the law file's path (SoftParticlesDef::law_file)
/// and empty laws, which a Simulation refuses until the program has read them
/// (formats/scene_laws.hpp load_scene_laws).
SceneFile parse_scene(const ConfigNode& root);
SceneFile load_scene_file(const std::string& path);

// The readers of the scene's parts, shared with the profiles (measure/settings.cpp): types and
// keys only; the ranges are validate()'s (scene/validate.hpp).
/// `also`: keys the caller reads itself besides E, nu, mu, density (the profile's `wall`).
Material parse_material(const ConfigNode& node, const std::string& name, const std::vector<std::string>& also = {});
/// `also`: keys the caller reads itself (a scene file's `soft_particles`).
EffectsDef parse_effects(const ConfigNode& node, const std::vector<std::string>& also = {});
IntegrationDef parse_integration(const ConfigNode& node);
NeighborDef parse_neighbor(const ConfigNode& node);
ShellContactRadius parse_contact_radius(const ConfigNode& node);
RelaxationDef parse_relaxation(const ConfigNode& node);
/// The optional `watchdog` map of a scene or a profile: every key optional, defaults in
/// WatchdogDef (scene/scene_def.hpp).
WatchdogDef parse_watchdog(const ConfigNode& node);

}  // namespace softpack
