// Semantic checks of a scene: ranges, references between its parts and contradictions.
// Each failure throws InputError with the key path ("drivers[1].group.body: ...").
#pragma once
#include <vector>

#include "scene/relaxation_def.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

void validate(const SceneDef& scene);

/// Validates a relaxation protocol (InputError naming relaxation.<key>).
void validate(const RelaxationDef& def);

/// The checks of validate() for `drivers` run in `scene` (Drivers::add: a driver started during a run).
void validate_drivers(const SceneDef& scene, const std::vector<DriverDef>& drivers);

}  // namespace softpack
