#include "drivers/drivers.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "scene/bodies.hpp"
#include "scene/validate.hpp"

namespace softpack {
namespace {

// A body's group: its spheres and those of the bodies inside it (scene/bodies.hpp).
std::vector<int> members_of(const Particles& p, const GroupDef& g, const BodyTree& tree) {
  std::vector<int> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (g.kind == GroupDef::Kind::all || p.body[i] == g.body || tree.within(p.body[i], g.body)) out.push_back(static_cast<int>(i));
  return out;
}

// Advances a driver's progress by one step of length `step` towards `total`; returns the
// increment, which is shortened on the last step so the driver lands exactly on its target.
double advance_progress(Drivers::Progress& d, double step, double total) {
  const double remaining = total - d.progress;
  if (remaining <= step) {
    d.progress = total;
    d.reached = true;
    return remaining;
  }
  d.progress += step;
  return step;
}

}  // namespace

Drivers::Drivers(const SceneDef& scene, World& world) : scene_(&scene) {
  if (!scene.drivers.empty()) world.p.driven.assign(world.p.size(), 0);
  for (const DriverDef& d : scene.drivers) active_.push_back(start(d, world));
}

Drivers::Active Drivers::start(const DriverDef& def, World& world) const {
  Active d;
  d.def = def;
  Particles& p = world.p;
  std::visit(
      [&](const auto& dd) {
        using D = std::decay_t<decltype(dd)>;
        if constexpr (std::is_same_v<D, MoveWallDef>) {
          for (std::size_t k = 0; k < scene_->planes.size(); ++k)
            if (scene_->planes[k].name == dd.wall) d.plane = static_cast<int>(k);
          for (std::size_t k = 0; k < scene_->shells.size(); ++k)
            if (scene_->shells[k].name == dd.wall) d.shell = static_cast<int>(k);
        } else {
          if constexpr (std::is_same_v<D, RotateGroupDef>)
            if (dd.with_shell)
              for (std::size_t k = 0; k < scene_->shells.size(); ++k)
                if (scene_->shells[k].body == dd.group.body) d.shell = static_cast<int>(k);
          d.members = members_of(p, dd.group, BodyTree(scene_->shells));
          for (int i : d.members) {
            p.driven[i] = 1;
            p.v[i].setZero();
            if (p.rotates()) p.w[i].setZero();
          }
        }
      },
      def);
  return d;
}

void Drivers::add(const DriverDef& driver, World& world) {
  std::vector<DriverDef> defs;
  for (const Active& d : active_)
    if (!d.retired) defs.push_back(d.def);
  defs.push_back(driver);
  validate_drivers(*scene_, defs);
  if (world.p.driven.empty()) world.p.driven.assign(world.p.size(), 0);
  active_.push_back(start(driver, world));
}

void Drivers::release(World& world) {
  Particles& p = world.p;
  for (Active& d : active_) {
    if (d.retired) continue;
    d.retired = true;
    if (d.plane >= 0) world.planes[d.plane].velocity.setZero();
    if (d.shell >= 0) world.shells[d.shell].velocity.setZero(), world.shells[d.shell].spin.setZero();
    for (int i : d.members) {
      p.driven[i] = 0;
      p.v[i].setZero();
      if (p.rotates()) p.w[i].setZero();
    }
  }
}

bool Drivers::moving() const {
  for (const Active& d : active_)
    if (!d.retired && !std::holds_alternative<HoldGroupDef>(d.def)) return true;
  return false;
}

void Drivers::advance(World& world, double dt, Neighbours& neighbours) {
  Particles& p = world.p;
  for (Active& d : active_) {
    if (d.retired) continue;
    std::visit(
        [&](const auto& def) {
          using D = std::decay_t<decltype(def)>;
          if constexpr (std::is_same_v<D, MoveWallDef> || std::is_same_v<D, TranslateGroupDef>) {
            const double speed = def.velocity.norm();
            const Vec3 dir = def.velocity / speed;
            const double total = def.distance ? *def.distance : *def.duration * speed;
            const double ds = advance_progress(d, speed * dt, total);
            const Vec3 u = dir * (ds / dt);
            if constexpr (std::is_same_v<D, MoveWallDef>) {
              if (d.plane >= 0) {
                world.planes[d.plane].point += dir * ds;
                world.planes[d.plane].velocity = u;
              } else {
                world.shells[d.shell].centre += dir * ds;
                world.shells[d.shell].velocity = u;
              }
            } else {
              for (int i : d.members) {
                p.x[i] += dir * ds;
                p.v[i] = u;
              }
            }
          } else if constexpr (std::is_same_v<D, RotateGroupDef>) {
            const double rate = std::abs(def.rate);
            const double total = def.angle ? *def.angle : *def.duration * rate;
            const double dtheta = advance_progress(d, rate * dt, total);
            // Exact rotation of the positions; the velocities are those velocity Verlet would
            // give for this step: the chord velocity (x_new - x_old)/dt and the spin
            // 2 tan(dtheta/2)/dt, for which the contact-point velocity of two spheres of the
            // group vanishes exactly in the half-step frame, whatever the axis (the identity
            // (R - 1) d = 2 tan(dtheta/2) axis x (R + 1) d / 2): the spring is carried unchanged.
            const Vec3 axis = def.axis.normalized() * (def.rate > 0 ? 1.0 : -1.0);
            const Eigen::Matrix3d R = Eigen::AngleAxisd(dtheta, axis).toRotationMatrix();
            const Vec3 Omega = axis * (2.0 * std::tan(0.5 * dtheta) / dt);
            for (int i : d.members) {
              const Vec3 x_new = def.centre + R * (p.x[i] - def.centre);
              p.v[i] = (x_new - p.x[i]) / dt;
              p.x[i] = x_new;
              if (p.rotates() && p.inv_I[i] > 0.0) p.w[i] = Omega;  // a locked spin stays 0 (it is carried round, not turned)
            }
            if (d.shell >= 0) {  // the shell turns with its spheres (about its own centre: its centre stays, exactly)
              SphericalShell& shell = world.shells[d.shell];
              const Vec3 c_new = def.centre + R * (shell.centre - def.centre);
              shell.velocity = (c_new - shell.centre) / dt;
              shell.centre = c_new;
              shell.spin = Omega;
            }
          }
          // HoldGroupDef: the spheres stay where they are, at rest.
        },
        d.def);
    for (int i : d.members) neighbours.moved().add((p.x[i] - neighbours.x_at_build()[i]).squaredNorm());
  }
}

void Drivers::finish(World& world) {
  Particles& p = world.p;
  for (Active& d : active_) {
    if (d.retired || !d.reached) continue;
    d.retired = true;
    if (d.plane >= 0) world.planes[d.plane].velocity.setZero();
    if (d.shell >= 0) world.shells[d.shell].velocity.setZero(), world.shells[d.shell].spin.setZero();
    AfterDrive after = AfterDrive::release;
    if (const auto* r = std::get_if<RotateGroupDef>(&d.def)) after = r->after;
    if (const auto* t = std::get_if<TranslateGroupDef>(&d.def)) after = t->after;
    for (int i : d.members) {
      p.v[i].setZero();
      if (p.rotates()) p.w[i].setZero();
      if (after == AfterDrive::release) p.driven[i] = 0;
    }
    if (after == AfterDrive::hold) {
      HoldGroupDef hold;
      if (const auto* r = std::get_if<RotateGroupDef>(&d.def)) hold.group = r->group;
      if (const auto* t = std::get_if<TranslateGroupDef>(&d.def)) hold.group = t->group;
      d.def = hold;
      d.retired = false;
      d.reached = false;
    }
  }
}

double Drivers::work(const World& world, double dt) const {
  const Particles& p = world.p;
  double total = 0.0;
  for (const Active& d : active_) {
    if (d.retired || std::holds_alternative<HoldGroupDef>(d.def)) continue;
    double w = 0.0;
    if (std::holds_alternative<MoveWallDef>(d.def)) {
      if (d.plane >= 0) w -= world.plane_loads[d.plane].force.dot(world.planes[d.plane].velocity);
      else w -= world.shell_loads[d.shell].force.dot(world.shells[d.shell].velocity);
    } else {
      for (int i : d.members) {
        w -= p.F[i].dot(p.v[i]);
        if (p.rotates()) w -= p.T[i].dot(p.w[i]);
      }
      if (d.shell >= 0) {  // turned with its spheres (and carried on the arc about another point)
        const SphericalShell& shell = world.shells[d.shell];
        w -= world.shell_loads[d.shell].force.dot(shell.velocity) + world.shell_loads[d.shell].torque.dot(shell.spin);
      }
    }
    total += std::max(0.0, w * dt);
  }
  return total;
}

}  // namespace softpack
