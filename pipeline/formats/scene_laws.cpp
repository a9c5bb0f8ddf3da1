#include "formats/scene_laws.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "scene/validate.hpp"

namespace softpack {

void load_scene_laws(SceneFile& file) {
  if (!file.scene.effects.soft_particles || file.scene.effects.soft_particles->law_file.empty()) return;
  SoftParticlesDef& def = *file.scene.effects.soft_particles;
  const std::string key = "effects.soft_particles.laws";
  try {
    std::error_code ec;
    if (!std::filesystem::exists(def.law_file, ec) && !ec)  // other failures: read_law_file's message
      throw InputError(fmt::format("{}: '{}' does not exist; allowed: a law file (JSON, \"format\": \"softpack-laws\"), its "
                                   "path absolute or relative to the scene file's folder",
                                   key, def.law_file));
    try {
      def.laws = soft_particle_laws(read_law_file(def.law_file), def.law_file);
    } catch (const InputError& e) {
      throw InputError(key + ": " + e.what());
    }
    validate_soft_particles(file.scene);
  } catch (const InputError& e) {
    throw file.root.locate(e);
  }
}

}  // namespace softpack
