// The rules of the relaxation protocols and of the active set (scene/relaxation_def.hpp,
// scene/active_set_def.hpp): the part of scene/validate.hpp that concerns bringing a scene to rest.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/validate.hpp"
#include "scene/validate_detail.hpp"

namespace softpack {
namespace {

using limits::number_text;
using validation::check;
using validation::fail;

}  // namespace

void validate_active_set(const ActiveSetDef& a, const std::string& key) {
  const auto non_negative = [&](double v, const char* name, const char* unit) {
    if (!(v >= 0.0 && std::isfinite(v))) fail(key + "." + name, fmt::format("{}{} is not allowed; allowed: >= 0", v, unit));
  };
  non_negative(a.sleep_force, "sleep_force", "");
  non_negative(a.sleep_speed, "sleep_speed", " m/s");
  if (!(a.wake_force > 0.0 && std::isfinite(a.wake_force)))
    fail(key + ".wake_force", fmt::format("{} is not allowed; allowed: > 0 (a fraction of the sphere's own contact forces)", a.wake_force));
  if (!(a.wake_force >= a.sleep_force))
    fail(key + ".wake_force",
         fmt::format("{} is below sleep_force = {}: a grain put to sleep would wake at once; allowed: wake_force >= sleep_force",
                     number_text(a.wake_force), number_text(a.sleep_force)));
  if (!(a.check_interval > 0.0 && std::isfinite(a.check_interval)))
    fail(key + ".check_interval", fmt::format("{} s is not allowed; allowed: > 0", a.check_interval));
}

void validate(const RelaxationDef& def, const std::string& key) {
  const auto positive = [&](double v, const char* name) {
    if (!(v > 0.0 && std::isfinite(v))) fail(key + "." + name, fmt::format("{} is not allowed; allowed: > 0", v));
  };
  if (const auto& a = std::visit([](const auto& d) { return d.active_set; }, def)) validate_active_set(*a, key + ".active_set");
  if (const auto* p = std::get_if<PaperRelaxationDef>(&def)) {
    check(key + ".stops", p->stops, limits::kStops);
    if (const auto& st = p->settle) {
      for (const auto& [v, name] : {std::pair{st->relative, "settle.relative"}, {st->absolute, "settle.absolute"}})
        if (!(v >= 0.0 && std::isfinite(v))) fail(key + "." + name, fmt::format("{} is not allowed; allowed: >= 0", v));
      if (st->relative == 0.0 && st->absolute == 0.0)
        fail(key + ".settle", "relative and absolute are both 0, so the stops would never end early; allowed: at least one > 0");
    }
    if (p->stops > 0) positive(p->wait, "wait");
    positive(p->final_wait, "final_wait");
  } else {
    const auto& c = std::get<ConvergedRelaxationDef>(def);
    positive(c.force_tolerance, "force_tolerance");
    positive(c.energy_tolerance, "energy_tolerance");
    positive(c.check_interval, "check_interval");
    positive(c.max_time, "max_time");
    if (!(c.max_time / c.check_interval <= limits::kMaxChecks))
      fail(key + ".check_interval",
           fmt::format("{} s is not allowed; max_time / check_interval = {} checks; allowed: at most {} checks (check_interval >= "
                       "{} s), each a row of the relaxation's table",
                       number_text(c.check_interval), number_text(std::ceil(c.max_time / c.check_interval)),
                       number_text(limits::kMaxChecks), limits::approx_text(c.max_time / limits::kMaxChecks)));
  }
}

void validate_steps(const RelaxationDef& def, double dt, const std::string& key) {
  if (const auto& a = std::visit([](const auto& d) { return d.active_set; }, def))
    validate_steps(a->check_interval, dt, key + ".active_set.check_interval");
  if (const auto* p = std::get_if<PaperRelaxationDef>(&def)) {
    const auto steps = [&](double t) { return std::max(1.0, std::round(t / dt)); };  // Simulation::steps_for
    const double total = p->stops * steps(p->wait) + steps(p->final_wait);
    if (total <= limits::kMaxSteps) return;
    const bool waits = p->stops > 0 && p->stops * p->wait >= p->final_wait;
    fail(key + (waits ? ".wait" : ".final_wait"),
         fmt::format("the protocol ({} stops after {} s each, then {} s) is {} time steps of dt = {} s; allowed: at most {} "
                     "steps",
                     p->stops, number_text(p->wait), number_text(p->final_wait), limits::approx_text(total),
                     limits::approx_text(dt), number_text(limits::kMaxSteps)));
  }
  const auto& c = std::get<ConvergedRelaxationDef>(def);
  validate_steps(c.max_time, dt, key + ".max_time");
}

}  // namespace softpack
