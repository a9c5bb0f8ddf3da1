#include "relax/relaxation_def.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace softpack {
namespace {

void require_positive(double v, const char* key) {
  if (!(v > 0.0 && std::isfinite(v))) throw InputError(fmt::format("relaxation.{}: {} is not allowed; allowed: > 0", key, v));
}

}  // namespace

void validate(const RelaxationDef& def) {
  if (const auto* p = std::get_if<PaperRelaxationDef>(&def)) {
    if (p->stops < 0) throw InputError(fmt::format("relaxation.stops: {} is not allowed; allowed: >= 0", p->stops));
    if (p->stops > 0) require_positive(p->wait, "wait");
    require_positive(p->final_wait, "final_wait");
  } else {
    const auto& c = std::get<ConvergedRelaxationDef>(def);
    require_positive(c.force_tolerance, "force_tolerance");
    require_positive(c.energy_tolerance, "energy_tolerance");
    require_positive(c.check_interval, "check_interval");
    require_positive(c.max_time, "max_time");
  }
}

}  // namespace softpack
