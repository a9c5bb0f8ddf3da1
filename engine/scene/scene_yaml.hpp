// Reads a scene from YAML (the format is documented in docs/scene-format.md and exercised by
// experiments/scenes/*.yaml). Syntax, types and unknown keys are checked here with file, line
// and column; ranges and cross-references by validate().
#pragma once
#include <optional>
#include <string>

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
};

/// Parses and validates a scene document.
SceneFile parse_scene(const ConfigNode& root);
SceneFile load_scene_file(const std::string& path);

RelaxationDef parse_relaxation(const ConfigNode& node);

/// The optional `watchdog` map of a scene or a profile: every key optional, defaults in
/// WatchdogDef (scene/scene_def.hpp).
WatchdogDef parse_watchdog(const ConfigNode& node);

}  // namespace softpack
