#include "relax/relaxation.hpp"

#include "scene/validate.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace softpack {

RelaxationReport relax(Simulation& sim, const RelaxationDef& def,
                       const std::function<void(const RelaxationCheck&)>& on_check, const std::function<Vec3()>& measured) {
  validate(def);
  // The quench is on for this relaxation only, whatever ends it (an exception of the watchdog).
  struct Quench {
    Simulation& sim;
    bool was;
    ~Quench() { sim.set_quench(was); }
  } quench{sim, sim.quenching()};
  sim.set_quench(std::visit([](const auto& d) { return d.quench; }, def));
  // So is the active set: every grain is awake again when the relaxation ends.
  const std::optional<ActiveSetDef> active = std::visit([](const auto& d) { return d.active_set; }, def);
  struct ActiveSetScope {
    Simulation& sim;
    std::optional<ActiveSetDef> was;
    ~ActiveSetScope() { sim.set_active_set(was); }
  } active_scope{sim, sim.active_set() ? std::optional(sim.active_set()->def()) : std::nullopt};
  if (active) sim.set_active_set(active);
  const double sphere_steps0 = sim.active_set() ? sim.active_set()->sphere_steps() : 0.0;
  const double awake0 = sim.active_set() ? sim.active_set()->awake_sphere_steps() : 0.0;
  const long step0 = sim.step_count();
  const double t0 = sim.time();
  RelaxationReport report;
  const auto record = [&] {
    report.checks.push_back({sim.time() - t0, sim.step_count() - step0, sim.residuals()});
    if (on_check) on_check(report.checks.back());
  };
  if (const auto* p = std::get_if<PaperRelaxationDef>(&def)) {
    if (p->settle && !measured)
      throw InputError("relaxation.settle: needs a measured force (the force on the second body of a sweep); a scene has none");
    Vec3 before = Vec3::Zero();  // the measured force at the previous stop (settle)
    for (int k = 0; k < p->stops; ++k) {
      sim.run_for(p->wait);
      const Vec3 now = p->settle ? measured() : Vec3::Zero();
      sim.zero_velocities();
      sim.sleep_check();
      record();
      if (p->settle && k > 0 && (now - before).norm() <= std::max(p->settle->relative * now.norm(), p->settle->absolute)) break;
      before = now;
    }
    sim.run_for(p->final_wait);
    record();
  } else {
    const auto& c = std::get<ConvergedRelaxationDef>(def);
    report.converged = false;
    while (sim.time() - t0 < c.max_time) {
      sim.run_for(std::min(c.check_interval, c.max_time - (sim.time() - t0)));
      record();
      const Measurement& m = report.checks.back().residuals;
      if (m.force_ratio() < c.force_tolerance && m.energy_ratio() < c.energy_tolerance) {
        report.converged = true;
        break;
      }
      if (c.zero_velocities_at_checks) {
        sim.zero_velocities();
        sim.sleep_check();
      }
    }
  }
  report.steps = sim.step_count() - step0;
  report.simulated_time = sim.time() - t0;
  if (const ActiveSet* a = sim.active_set(); a && a->sphere_steps() > sphere_steps0)
    report.awake_fraction = (a->awake_sphere_steps() - awake0) / (a->sphere_steps() - sphere_steps0);
  return report;
}

}  // namespace softpack
