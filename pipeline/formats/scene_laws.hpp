// The laws of a scene file's soft-particles (scene/scene_yaml.hpp reads the scene, the engine
// reads no JSON): the law file it names, read with formats/law_file.hpp.
#pragma once
#include "scene/scene_yaml.hpp"

namespace softpack {

/// The laws of a scene file's soft-particles: reads the law file it names
/// (effects.soft_particles.laws, SoftParticlesDef::law_file) into SoftParticlesDef::laws, then
/// checks the rules that need them (scene/validate.hpp). The engine reads no JSON, so every
/// program that runs a scene file calls this before it builds the Simulation, which refuses
/// soft-particles without laws; nothing to do in a scene without soft-particles or without a law
/// file (its laws given in code). InputError placed at the key in the scene file: a law file that
/// does not exist or cannot be read, a bad one (read_law_file's field and rule), laws that do not
/// cover the scene (its contacts, its radii).
void load_scene_laws(SceneFile& file);

}  // namespace softpack
