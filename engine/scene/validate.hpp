// Semantic checks of a scene: ranges, references between its parts and contradictions.
// Each failure throws InputError with the key path ("drivers[1].group.body: ...").
#pragma once
#include "scene/scene_def.hpp"

namespace softpack {

void validate(const SceneDef& scene);

}  // namespace softpack
