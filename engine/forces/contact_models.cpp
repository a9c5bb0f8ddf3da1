// The registry of contact models (forces/contact_models.hpp) and the models the engine
// registers: one line each, below.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <deque>
#include <mutex>
#include <stdexcept>

#include "contact/hertz_normal.hpp"
#include "contact/soft_particle_law.hpp"
#include "contact/tsuji_model.hpp"
#include "core/error.hpp"
#include "core/suggest.hpp"
#include "forces/compile_loops.hpp"

namespace softpack {
namespace {

struct Registry {
  std::mutex mutex;
  std::deque<ContactModelType> models;  // a deque: references stay valid while models are added

  Registry() {
    models.push_back(make_contact_model<TsujiModel<HertzNormal>>());  // effects.normal: hertz (paper Eq. 3-6)
    models.push_back(make_contact_model<SoftParticleModel>(false));    // the spheres marked soft (Eq. 7-8)
    models.push_back(make_contact_model<SoftManyBodyModel>(false));    // the same, a law file with many_body (issue 33)
  }
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

const ContactModelType& contact_model(const std::string& name, bool of_scene) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const ContactModelType& m : r.models)
    if (m.name == name && (m.of_scene || !of_scene)) return m;
  std::vector<std::string> names;
  for (const ContactModelType& m : r.models)
    if (m.of_scene) names.push_back(m.name);
  const std::string close = closest_match(name, names);
  throw InputError(fmt::format("effects.normal: '{}' is not a contact model of this engine{}; allowed: {}", name,
                               close.empty() ? "" : fmt::format(" (did you mean '{}'?)", close), fmt::join(names, ", ")));
}

void add_contact_model(ContactModelType model) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const ContactModelType& m : r.models)
    if (m.name == model.name) throw std::invalid_argument("a contact model named '" + model.name + "' is registered already");
  r.models.push_back(std::move(model));
}

}  // namespace softpack
