// The registry of normal laws (forces/normal_law.hpp) and the laws the engine registers: one
// line each, below.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <deque>
#include <mutex>
#include <stdexcept>

#include "contact/hertz_normal.hpp"
#include "core/error.hpp"
#include "core/suggest.hpp"
#include "forces/compile_loops.hpp"

namespace softpack {
namespace {

struct Registry {
  std::mutex mutex;
  std::deque<NormalLaw> laws;  // a deque: references stay valid while laws are added

  Registry() {
    laws.push_back(make_normal_law<HertzNormal>());  // effects.normal: hertz (paper Eq. 3)
  }
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

const NormalLaw& normal_law(const std::string& name) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const NormalLaw& law : r.laws)
    if (law.name == name) return law;
  std::vector<std::string> names;
  for (const NormalLaw& law : r.laws) names.push_back(law.name);
  const std::string close = closest_match(name, names);
  throw InputError(fmt::format("effects.normal: '{}' is not a normal law of this engine{}; allowed: {}", name,
                               close.empty() ? "" : fmt::format(" (did you mean '{}'?)", close), fmt::join(names, ", ")));
}

void add_normal_law(NormalLaw law) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const NormalLaw& l : r.laws)
    if (l.name == law.name) throw std::invalid_argument("a normal law named '" + law.name + "' is registered already");
  r.laws.push_back(std::move(law));
}

}  // namespace softpack
