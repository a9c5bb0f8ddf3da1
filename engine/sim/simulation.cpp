#include "sim/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "contact/viscous_damping.hpp"
#include "core/parallel.hpp"
#include "forces/contact_walk.hpp"
#include "integrate/velocity_verlet.hpp"
#include "scene/bodies.hpp"
#include "scene/validate.hpp"

namespace softpack {
namespace {

const SceneDef& validated(const SceneDef& scene) {
  validate(scene);
  return scene;
}

// The quench of a free shell, as of a grain: its velocity (spin) is zeroed where it runs against
// its load (torque).
void quench_shells(World& w) {
  for (std::size_t k = 0; k < w.shells.size(); ++k) {
    SphericalShell& s = w.shells[k];
    if (!s.free()) continue;
    if (w.shell_loads[k].force.dot(s.velocity) < 0.0) s.velocity.setZero();
    if (w.shell_loads[k].torque.dot(s.spin) < 0.0) s.spin.setZero();
  }
}

Watchdog::Context watchdog_context(const SceneDef& scene, double dt, const StableLimit& limit) {
  Watchdog::Context c;
  c.dt = dt;
  c.limit = limit;
  for (const PlaneDef& p : scene.planes) c.plane_names.push_back(p.name);
  for (const ShellDef& s : scene.shells) c.shell_names.push_back(s.name);
  c.gravity = scene.effects.gravity;
  return c;
}

}  // namespace

Simulation::Simulation(const SceneDef& scene)
    : scene_(validated(scene)),
      dt_(choose_time_step(scene_)),
      stable_(softpack::stable_limit(scene_)),
      world_(make_world(scene_)),
      forces_(scene_),
      neighbours_(scene_.neighbor, world_, forces_.constants(), scene_.effects.friction, shell_members(scene_.shells, world_.p.body)),
      drivers_(scene_, world_),
      watchdog_(scene_.watchdog, watchdog_context(scene_, dt_, stable_)) {
  for (std::size_t k = 0; k < scene_.drivers.size(); ++k) validate_steps(scene_.drivers[k], dt_, fmt::format("drivers[{}]", k));
  for (const SphericalShell& s : world_.shells) free_shells_ = free_shells_ || s.free();
  rebuild_neighbours();
  compute_forces(0.0);  // F(t0); springs start unstretched
  watchdog_.start(world_, residuals());
}

// ---------------------------------------------------------------------------------------------
// The step

void Simulation::step() {
  const Movers movers = active_ ? active_->movers() : Movers{};
  kick_drift(world_.p, dt_, neighbours_, active_ ? &movers : nullptr);
  if (free_shells_) half_kick_shells(world_.shells, world_.shell_loads, dt_, scene_.effects.rotation);
  if (free_shells_) drift_shells(world_.shells, dt_);
  if (!drivers_.empty()) drivers_.advance(world_, dt_, neighbours_);
  update_neighbours();
  compute_forces(dt_);
  if (active_) wake_now();
  const Movers after_wake = active_ ? active_->movers() : Movers{};  // the spheres that woke move from now on
  half_kick(world_.p, dt_, active_ ? &after_wake : nullptr, quench_);
  if (free_shells_) half_kick_shells(world_.shells, world_.shell_loads, dt_, scene_.effects.rotation);
  if (quench_ && free_shells_) quench_shells(world_);
  if (!drivers_.empty()) {
    watchdog_.add_driver_work(drivers_.work(world_, dt_));
    drivers_.finish(world_);
  }
  world_.time += dt_;
  ++world_.steps;
  if (active_) {
    active_->count_step(world_.p.size());
    if (++since_sleep_check_ >= sleep_interval_) sleep_check();
  }
  if (++since_check_ >= scene_.watchdog.check_interval) check_now();
}

void Simulation::wake_now() { active_->wake(world_, neighbours_.lists(), forces_); }

void Simulation::sleep_check() {
  if (!active_) return;
  since_sleep_check_ = 0;
  active_->sleep(world_, neighbours_.lists(), forces_, neighbours_.x_at_build());
}

void Simulation::set_active_set(const std::optional<ActiveSetDef>& def) {
  if (active_) active_->wake_all(neighbours_.lists());
  active_.reset();
  if (!def) return;
  if (forces_.active() && forces_.model(0).body_state())
    throw InputError(fmt::format("active_set: not available with the normal law '{}', whose force reads every contact of a body "
                                 "(a sleeping body's frozen forces would not follow its awake neighbours); drop one of them",
                                 forces_.model(0).name()));
  validate_active_set(*def, "active_set");
  if (scene_.effects.soft_particles)
    throw InputError("active_set: not available with soft-particle contacts (effects.soft_particles); drop one of them");
  sleep_interval_ = steps_for(def->check_interval);
  since_sleep_check_ = 0;
  active_.emplace(*def, world_.p.size());
}

void Simulation::update_neighbours() {
  if (!neighbours_.need_rebuild(world_)) return;
  if (!Watchdog::positions_finite(world_)) watchdog_.check(world_, residuals());  // the grid must not see NaN or infinity
  rebuild_neighbours();
}

void Simulation::rebuild_neighbours() {
  std::vector<NewContacts> added;
  try {
    added = neighbours_.rebuild(world_);
  } catch (const std::invalid_argument&) {
    watchdog_.check(world_, residuals());  // spheres flung out of any sensible domain: report the blow-up
    throw;
  }
  if (forces_.active()) forces_.set_constants(world_, neighbours_.lists(), added);
  if (active_) active_->rebuild(world_, neighbours_.lists(), forces_);
}

// Gravity (or zero), then every contact's force, family by family through its model's loops.
// Velocities are the half-step velocities v(t + dt/2) of velocity Verlet.
void Simulation::compute_forces(double spring_dt) {
  Particles& p = world_.p;
  const Vec3 g = scene_.effects.gravity.value_or(Vec3::Zero());
  const bool gravity = scene_.effects.gravity.has_value(), rotates = p.rotates();
  parallel::for_each_share(p.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) p.F[i] = gravity ? Vec3(p.m[i] * g) : Vec3::Zero();
    if (rotates) std::fill(p.T.begin() + static_cast<std::ptrdiff_t>(begin), p.T.begin() + static_cast<std::ptrdiff_t>(end), Vec3::Zero());
  });
  for (auto& l : world_.plane_loads) l = WallLoad{};
  for (auto& l : world_.shell_loads) l = WallLoad{};
  if (active_) active_->add_frozen(p);
  forces_.add_contact_forces(world_, neighbours_.lists(), spring_dt);
}

void Simulation::run_steps(long n) {
  for (long s = 0; s < n; ++s) step();
  if (since_check_ > 0) check_now();
}

void Simulation::check_now() {
  since_check_ = 0;
  watchdog_.check(world_, residuals());
}

long Simulation::steps_for(double duration) const {
  validate_steps(duration, dt_, "duration");  // lround is undefined beyond the range of long
  return std::max(1L, std::lround(duration / dt_));
}

void Simulation::add_driver(const DriverDef& driver) {
  validate_steps(driver, dt_, "driver");
  drivers_.add(driver, world_);
  if (active_) wake_now();  // a driven sphere does not sleep
}

void Simulation::run_for(double duration) { run_steps(steps_for(duration)); }

void Simulation::zero_velocities() {
  Particles& p = world_.p;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.is_driven(i)) continue;
    p.v[i].setZero();
    if (p.rotates()) p.w[i].setZero();
  }
  for (SphericalShell& s : world_.shells)
    if (s.free()) s.velocity.setZero(), s.spin.setZero();
}

const WallLoad& Simulation::wall_load(const std::string& name) const {
  for (std::size_t k = 0; k < scene_.planes.size(); ++k)
    if (scene_.planes[k].name == name) return world_.plane_loads[k];
  for (std::size_t k = 0; k < scene_.shells.size(); ++k)
    if (scene_.shells[k].name == name) return world_.shell_loads[k];
  throw InputError(fmt::format("no plane or shell is named '{}'", name));
}

void Simulation::forget_setup_caches() { damping::forget_zeta_cache(); }

Vec3 Simulation::force_between(int from, int on) const {
  Vec3 total = Vec3::Zero();
  if (!forces_.active()) return total;
  const Particles& p = world_.p;
  const BodyTree tree(scene_.shells);  // a body counts the bodies inside it (scene/bodies.hpp)
  for_each_closed_contact(world_, neighbours_.lists(), forces_, [&](const ClosedContact& c) {
    if (c.kind != ClosedContact::Kind::pair) return;
    const int bi = p.body[c.i], bj = p.body[c.j];
    const auto in = [&](int b, int body) { return b == body || tree.within(b, body); };
    if (!((in(bi, from) && in(bj, on)) || (in(bi, on) && in(bj, from)))) return;
    const Vec3 d = p.x[c.i] - p.x[c.j];
    const Vec3 n = d / d.norm();
    Vec3 F = c.Fn() * n;  // on sphere i
    if (c.spring) F -= c.kt() * *c.spring;
    total += in(bi, on) ? F : Vec3(-F);
  });
  return total;
}

}  // namespace softpack
