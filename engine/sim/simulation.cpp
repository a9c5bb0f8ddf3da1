#include "sim/simulation.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "contact/contact_force.hpp"
#include "contact/hertz_normal.hpp"
#include "contact/viscous_damping.hpp"
#include "core/error.hpp"
#include "scene/validate.hpp"
#include "sim/pair_forces.hpp"
#include "sim/shell_forces.hpp"

namespace softpack {

double Measurement::force_ratio() const {
  if (max_unbalanced_force == 0.0) return 0.0;
  if (mean_contact_force == 0.0) return std::numeric_limits<double>::infinity();
  return max_unbalanced_force / mean_contact_force;
}

double Measurement::energy_ratio() const {
  if (kinetic_energy == 0.0) return 0.0;
  if (elastic_energy == 0.0) return std::numeric_limits<double>::infinity();
  return kinetic_energy / elastic_energy;
}

Simulation::Simulation(const SceneDef& scene) : scene_(scene) {
  validate(scene_);
  watchdog_ = Watchdog(scene_.watchdog);
  const EffectsDef& fx = scene_.effects;

  nmat_ = scene_.materials.size();
  D_.resize(nmat_ * nmat_);
  Dt_.resize(nmat_ * nmat_);
  mu_.resize(nmat_ * nmat_);
  for (std::size_t a = 0; a < nmat_; ++a)
    for (std::size_t b = 0; b < nmat_; ++b) {
      D_[a * nmat_ + b] = hertz_D(scene_.materials[a], scene_.materials[b]);
      Dt_[a * nmat_ + b] = tsuji_Dt(scene_.materials[a], scene_.materials[b]);
      mu_[a * nmat_ + b] = contact_mu(scene_.materials[a], scene_.materials[b]);
    }
  if (fx.damping()) alpha_ = damping::alpha_from_restitution(*fx.restitution);

  const std::size_t n = scene_.particles.size();
  p_.x.resize(n);
  p_.v.resize(n);
  p_.F.assign(n, Vec3::Zero());
  p_.r.resize(n);
  p_.m.resize(n);
  p_.inv_m.resize(n);
  p_.body.resize(n);
  p_.material.resize(n);
  if (fx.rotation) {
    p_.w.resize(n);
    p_.T.assign(n, Vec3::Zero());
    p_.inv_I.resize(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const ParticleDef& d = scene_.particles[i];
    const double rho = scene_.materials[d.material].density;
    p_.x[i] = d.x;
    p_.v[i] = d.v;
    p_.r[i] = d.r;
    p_.m[i] = rho * 4.0 / 3.0 * std::numbers::pi * d.r * d.r * d.r;
    p_.inv_m[i] = 1.0 / p_.m[i];
    p_.body[i] = d.body;
    p_.material[i] = d.material;
    if (fx.rotation) {
      p_.w[i] = d.w;
      p_.inv_I[i] = 1.0 / (0.4 * p_.m[i] * d.r * d.r);  // solid sphere, I = 2/5 m r^2
    }
  }

  for (const PlaneDef& d : scene_.planes)
    planes_.push_back(PlaneWall{d.point, d.normal.normalized(), Vec3::Zero(), d.material});
  for (const ShellDef& d : scene_.shells) {
    shells_.push_back(SphericalShell{d.centre, d.radius, d.body, Vec3::Zero(), Vec3::Zero(), d.material, d.contact_radius});
    std::vector<int> members;
    for (std::size_t i = 0; i < n; ++i)
      if (p_.body[i] == d.body) members.push_back(static_cast<int>(i));
    shell_members_.push_back(std::move(members));
  }
  plane_loads_.resize(planes_.size());
  shell_loads_.resize(shells_.size());
  plane_lists_.resize(planes_.size());
  shell_lists_.resize(shells_.size());

  stable_ = softpack::stable_limit(scene_);
  dt_ = choose_time_step(scene_);
  double r_min = std::numeric_limits<double>::max();
  for (double r : p_.r) r_min = std::min(r_min, r);
  skin_ = scene_.neighbor.skin * r_min;

  if (!scene_.drivers.empty()) p_.driven.assign(n, 0);
  for (const DriverDef& d : scene_.drivers) {
    drivers_.push_back(make_driver(d));
  }

  rebuild_neighbours();
  compute_forces(0.0);  // F(t0); springs start unstretched
  watchdog_.start(*this);
}

// ---------------------------------------------------------------------------------------------
// Contact constants

ContactCoefficients Simulation::coefficients(int i, int j) const {
  const std::size_t mm = static_cast<std::size_t>(p_.material[i]) * nmat_ + p_.material[j];
  const double R12 = hertz::reduced_radius(p_.r[i], p_.r[j]);
  ContactCoefficients k;
  k.kn = hertz::stiffness(R12, D_[mm]);
  k.kt0 = tsuji::stiffness_factor(R12, Dt_[mm]);
  k.mu = mu_[mm];
  const double m12 = p_.m[i] * p_.m[j] / (p_.m[i] + p_.m[j]);
  k.gamma0 = damping::gamma_factor(alpha_, m12, k.kn);
  // Inertia of the sliding-rolling mode: 1/mt = 1/mi + ri^2/Ii + 1/mj + rj^2/Ij.
  double inv_mt = p_.inv_m[i] + p_.inv_m[j];
  if (p_.rotates()) inv_mt += p_.r[i] * p_.r[i] * p_.inv_I[i] + p_.r[j] * p_.r[j] * p_.inv_I[j];
  k.gamma_t0 = scene_.effects.tangential_damping_ratio * damping::gamma_factor(alpha_, 1.0 / inv_mt, k.kt0);
  return k;
}

ContactCoefficients Simulation::wall_coefficients(int i, int wall_material, double R12) const {
  const std::size_t mm = static_cast<std::size_t>(p_.material[i]) * nmat_ + wall_material;
  ContactCoefficients k;
  k.kn = hertz::stiffness(R12, D_[mm]);
  k.kt0 = tsuji::stiffness_factor(R12, Dt_[mm]);
  k.mu = mu_[mm];
  k.gamma0 = damping::gamma_factor(alpha_, p_.m[i], k.kn);  // a wall has infinite mass
  double inv_mt = p_.inv_m[i];
  if (p_.rotates()) inv_mt += p_.r[i] * p_.r[i] * p_.inv_I[i];
  k.gamma_t0 = scene_.effects.tangential_damping_ratio * damping::gamma_factor(alpha_, 1.0 / inv_mt, k.kt0);
  return k;
}

// ---------------------------------------------------------------------------------------------
// Drivers

std::vector<int> Simulation::members_of(const GroupDef& g) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (g.kind == GroupDef::Kind::all || p_.body[i] == g.body) out.push_back(static_cast<int>(i));
  return out;
}

Simulation::ActiveDriver Simulation::make_driver(const DriverDef& def) {
  ActiveDriver d;
  d.def = def;
  activate(d);
  return d;
}

void Simulation::activate(ActiveDriver& d) {
  std::visit(
      [&](const auto& def) {
        using D = std::decay_t<decltype(def)>;
        if constexpr (std::is_same_v<D, MoveWallDef>) {
          for (std::size_t k = 0; k < scene_.planes.size(); ++k)
            if (scene_.planes[k].name == def.wall) d.plane = static_cast<int>(k);
          for (std::size_t k = 0; k < scene_.shells.size(); ++k)
            if (scene_.shells[k].name == def.wall) d.shell = static_cast<int>(k);
        } else {
          if constexpr (std::is_same_v<D, RotateGroupDef>)
            if (def.with_shell)
              for (std::size_t k = 0; k < scene_.shells.size(); ++k)
                if (scene_.shells[k].body == def.group.body) d.shell = static_cast<int>(k);
          d.members = members_of(def.group);
          for (int i : d.members) {
            p_.driven[i] = 1;
            p_.v[i].setZero();
            if (p_.rotates()) p_.w[i].setZero();
          }
        }
      },
      d.def);
}

void Simulation::add_driver(const DriverDef& driver) {
  SceneDef probe = scene_;
  probe.drivers.clear();
  for (const ActiveDriver& d : drivers_)
    if (!d.retired) probe.drivers.push_back(d.def);
  probe.drivers.push_back(driver);
  validate(probe);
  scene_.drivers.push_back(driver);
  if (p_.driven.empty()) p_.driven.assign(p_.size(), 0);
  drivers_.push_back(make_driver(driver));
}

void Simulation::release_drivers() {
  for (ActiveDriver& d : drivers_) {
    if (d.retired) continue;
    d.retired = true;
    if (d.plane >= 0) planes_[d.plane].velocity.setZero();
    if (d.shell >= 0) shells_[d.shell].velocity.setZero(), shells_[d.shell].spin.setZero();
    for (int i : d.members) {
      p_.driven[i] = 0;
      p_.v[i].setZero();
      if (p_.rotates()) p_.w[i].setZero();
    }
  }
}

bool Simulation::drivers_moving() const {
  for (const ActiveDriver& d : drivers_)
    if (!d.retired && !std::holds_alternative<HoldGroupDef>(d.def)) return true;
  return false;
}

// Advances a driver's progress by one step of length `step` towards `total`; returns the
// increment, which is shortened on the last step so the driver lands exactly on its target.
double advance_progress(Simulation::ActiveDriverProgress& d, double step, double total) {
  const double remaining = total - d.progress;
  if (remaining <= step) {
    d.progress = total;
    d.reached = true;
    return remaining;
  }
  d.progress += step;
  return step;
}

// Moves kinematic spheres and walls by one step. Each driver advances by its rate times dt,
// clipped so that it lands exactly on its target; the velocity it reports for this step is
// the distance moved over dt.
void Simulation::advance_drivers() {
  for (ActiveDriver& d : drivers_) {
    if (d.retired) continue;
    std::visit(
        [&](const auto& def) {
          using D = std::decay_t<decltype(def)>;
          if constexpr (std::is_same_v<D, MoveWallDef> || std::is_same_v<D, TranslateGroupDef>) {
            const double speed = def.velocity.norm();
            const Vec3 dir = def.velocity / speed;
            const double total = def.distance ? *def.distance : *def.duration * speed;
            const double ds = advance_progress(d, speed * dt_, total);
            const Vec3 u = dir * (ds / dt_);
            if constexpr (std::is_same_v<D, MoveWallDef>) {
              if (d.plane >= 0) {
                planes_[d.plane].point += dir * ds;
                planes_[d.plane].velocity = u;
              } else {
                shells_[d.shell].centre += dir * ds;
                shells_[d.shell].velocity = u;
              }
            } else {
              for (int i : d.members) {
                p_.x[i] += dir * ds;
                p_.v[i] = u;
              }
            }
          } else if constexpr (std::is_same_v<D, RotateGroupDef>) {
            const double rate = std::abs(def.rate);
            const double total = def.angle ? *def.angle : *def.duration * rate;
            const double dtheta = advance_progress(d, rate * dt_, total);
            // Exact rotation of the positions; the velocities are those velocity Verlet would
            // give for this step: the chord velocity (x_new - x_old)/dt and the spin
            // 2 tan(dtheta/2)/dt, for which the contact-point velocity of two spheres of the
            // group vanishes exactly in the half-step frame, whatever the axis (the identity
            // (R - 1) d = 2 tan(dtheta/2) axis x (R + 1) d / 2): the spring is carried unchanged.
            const Vec3 axis = def.axis.normalized() * (def.rate > 0 ? 1.0 : -1.0);
            const Eigen::Matrix3d R = Eigen::AngleAxisd(dtheta, axis).toRotationMatrix();
            const Vec3 Omega = axis * (2.0 * std::tan(0.5 * dtheta) / dt_);
            for (int i : d.members) {
              const Vec3 x_new = def.centre + R * (p_.x[i] - def.centre);
              p_.v[i] = (x_new - p_.x[i]) / dt_;
              p_.x[i] = x_new;
              if (p_.rotates()) p_.w[i] = Omega;
            }
            if (d.shell >= 0) shells_[d.shell].spin = Omega;
          }
          // HoldGroupDef: the spheres stay where they are, at rest.
        },
        d.def);
    for (int i : d.members) disp2_.add((p_.x[i] - x_at_build_[i]).squaredNorm());
  }
}

// Drivers that reached their target stop: walls stand still, groups stop and are released
// (free from the next step on) or held in place.
void Simulation::finish_drivers() {
  for (ActiveDriver& d : drivers_) {
    if (d.retired || !d.reached) continue;
    d.retired = true;
    if (d.plane >= 0) planes_[d.plane].velocity.setZero();
    if (d.shell >= 0) shells_[d.shell].velocity.setZero(), shells_[d.shell].spin.setZero();
    AfterDrive after = AfterDrive::release;
    if (const auto* r = std::get_if<RotateGroupDef>(&d.def)) after = r->after;
    if (const auto* t = std::get_if<TranslateGroupDef>(&d.def)) after = t->after;
    for (int i : d.members) {
      p_.v[i].setZero();
      if (p_.rotates()) p_.w[i].setZero();
      if (after == AfterDrive::release) p_.driven[i] = 0;
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

// ---------------------------------------------------------------------------------------------
// Neighbour lists

void Simulation::update_neighbours() {
  // A pair's gap shrinks by at most the sum of both displacements since the last build, at most
  // the two largest; a wall gap by the sphere's plus the wall's: rebuild before either can
  // exceed the skin.
  double wall_disp = 0.0;
  for (std::size_t k = 0; k < planes_.size(); ++k)
    wall_disp = std::max(wall_disp, (planes_[k].point - plane_at_build_[k]).norm());
  for (std::size_t k = 0; k < shells_.size(); ++k)
    wall_disp = std::max(wall_disp, (shells_[k].centre - shell_at_build_[k]).norm());
  const double disp = std::sqrt(disp2_.first);
  if (rebuild_requested_ || disp + std::sqrt(disp2_.second) >= skin_ || disp + wall_disp >= skin_) {
    watchdog_.check_positions(*this);  // the grid must not see NaN or infinity
    rebuild_neighbours();
  }
}

void Simulation::rebuild_neighbours() {
  const bool friction = scene_.effects.friction;
  const std::size_t n = p_.size();
  if (scene_.effects.normal) {
    // Pairs as (i, j) with i < j, sorted: a counting sort by i, then each sphere's few
    // partners sorted by j.
    try {
      grid_.build(p_.x, p_.r, skin_, scene_.neighbor.level_ratio);
    } catch (const std::invalid_argument&) {
      watchdog_.check(*this);  // spheres flung out of any sensible domain: report the blow-up
      throw;
    }
    found_.clear();
    first_.assign(n + 1, 0);
    grid_.for_each_pair([&](int i, int j) {
      const auto [a, b] = std::minmax(i, j);
      found_.emplace_back(a, b);
      ++first_[static_cast<std::size_t>(a) + 1];
    });
    for (std::size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
    std::vector<PairEntry> fresh(found_.size());
    for (const auto& [a, b] : found_) fresh[first_[a]++] = PairEntry{a, b, p_.r[a] + p_.r[b]};
    for (std::size_t i = 0, begin = 0; i < n; begin = first_[i++])
      std::sort(fresh.begin() + static_cast<std::ptrdiff_t>(begin), fresh.begin() + static_cast<std::ptrdiff_t>(first_[i]),
                [](const PairEntry& a, const PairEntry& b) { return a.j < b.j; });
    for (std::size_t k : pairs_.replace(std::move(fresh), friction))
      pairs_.k[k] = coefficients(pairs_.pairs[k].i, pairs_.pairs[k].j);

    for (std::size_t w = 0; w < planes_.size(); ++w) {
      std::vector<WallEntry> list;
      for (std::size_t i = 0; i < n; ++i)
        if (planes_[w].distance(p_.x[i]) - p_.r[i] < skin_) list.push_back({static_cast<int>(i), {}});
      WallList& wl = plane_lists_[w];
      for (std::size_t k : wl.replace(std::move(list), friction))
        wl.entries[k].k = wall_coefficients(wl.entries[k].i, planes_[w].material, p_.r[wl.entries[k].i]);
    }
    for (std::size_t w = 0; w < shells_.size(); ++w) {
      const SphericalShell& s = shells_[w];
      std::vector<WallEntry> list;
      for (int i : shell_members_[w])
        if (s.radius - (p_.x[i] - s.centre).norm() - p_.r[i] < skin_) list.push_back({i, {}});
      WallList& wl = shell_lists_[w];
      for (std::size_t k : wl.replace(std::move(list), friction)) {
        const int i = wl.entries[k].i;
        const double R12 = s.contact_radius == ShellContactRadius::concave
                               ? hertz::reduced_radius_concave(p_.r[i], s.radius)
                               : p_.r[i];
        wl.entries[k].k = wall_coefficients(i, s.material, R12);
      }
    }
  }
  x_at_build_ = p_.x;
  plane_at_build_.clear();
  for (const auto& pl : planes_) plane_at_build_.push_back(pl.point);
  shell_at_build_.clear();
  for (const auto& s : shells_) shell_at_build_.push_back(s.centre);
  disp2_ = {};
  rebuild_requested_ = false;
  ++rebuilds_;
}

// ---------------------------------------------------------------------------------------------
// Forces

void Simulation::compute_forces(double spring_dt) {
  const EffectsDef& fx = scene_.effects;
  const bool sync = scene_.integration.history_update == HistoryUpdate::synchronized;
  const int key = (fx.friction ? 8 : 0) | (sync ? 4 : 0) | (fx.damping() ? 2 : 0) | (fx.rotation ? 1 : 0);
  switch (key & (fx.friction ? 15 : 3)) {  // the history update only matters with friction
    case 0: compute_forces_for<false, false, false, false>(spring_dt); break;
    case 2: compute_forces_for<false, true, false, false>(spring_dt); break;
    case 8: compute_forces_for<true, false, false, false>(spring_dt); break;
    case 9: compute_forces_for<true, false, true, false>(spring_dt); break;
    case 10: compute_forces_for<true, true, false, false>(spring_dt); break;
    case 11: compute_forces_for<true, true, true, false>(spring_dt); break;
    case 12: compute_forces_for<true, false, false, true>(spring_dt); break;
    case 13: compute_forces_for<true, false, true, true>(spring_dt); break;
    case 14: compute_forces_for<true, true, false, true>(spring_dt); break;
    case 15: compute_forces_for<true, true, true, true>(spring_dt); break;
    default: throw std::logic_error("rotation without friction is rejected by validate()");
  }
}

template <bool Friction, bool Damping, bool Rotation, bool Synchronized>
void Simulation::compute_forces_for(double spring_dt) {
  const std::size_t n = p_.size();
  const EffectsDef& fx = scene_.effects;
  if (fx.gravity) {
    const Vec3 g = *fx.gravity;
    for (std::size_t i = 0; i < n; ++i) p_.F[i] = p_.m[i] * g;
  } else {
    std::fill(p_.F.begin(), p_.F.end(), Vec3::Zero());
  }
  if constexpr (Rotation) std::fill(p_.T.begin(), p_.T.end(), Vec3::Zero());
  for (auto& l : plane_loads_) l = WallLoad{};
  for (auto& l : shell_loads_) l = WallLoad{};
  if (!fx.normal) return;

  const Vec3* const x = p_.x.data();
  const double* const r = p_.r.data();
  // Velocities are the half-step velocities v(t + dt/2) of velocity Verlet.
  const Vec3* const v = p_.v.data();
  const Vec3* w = nullptr;
  if constexpr (Rotation) w = p_.w.data();
  const double half_dt = 0.5 * spring_dt;
  Vec3* const F = p_.F.data();
  Vec3* const T = Rotation ? p_.T.data() : nullptr;
  Vec3 no_spring = Vec3::Zero();

  // Sphere-sphere contacts: the vectorised loop of sim/pair_forces.cpp (same arithmetic as
  // contact_force(), used below for the walls).
  accumulate_pair_forces(pairs_, PairForceArrays{x, v, w, r, F, T},
                         PairForceEffects{Friction, Damping, Rotation, Synchronized}, spring_dt, closed_);

  // Sphere-wall contacts: body 1 is the sphere, body 2 the wall.
  // `n_half` and `h_half` are the contact normal and overlap at t + dt/2, `wall_velocity_half`
  // the wall's velocity at the half-step contact point (they differ for a turning shell).
  const auto wall_contact = [&](WallList& list, std::size_t k, int i, const Vec3& nrm, double h, const Vec3& n_half,
                                double h_half, const Vec3& wall_velocity, const Vec3& wall_velocity_half, const Vec3& ref,
                                WallLoad& load) {
    Vec3 vc = v[i] - wall_velocity;
    const double ai = r[i] - 0.5 * h;
    if constexpr (Rotation) vc -= (ai * w[i]).cross(nrm);
    Vec3& spring = Friction ? list.spring[k] : no_spring;
    if constexpr (Friction) {
      if constexpr (Synchronized) {
        Vec3 vc_half = v[i] - wall_velocity_half;
        if constexpr (Rotation) vc_half -= ((r[i] - 0.5 * h_half) * w[i]).cross(n_half);
        advance_spring(spring, n_half, vc_half, nrm, spring_dt);
      } else {
        advance_spring(spring, nrm, vc, nrm, spring_dt);
      }
    }
    const ContactForce cf = contact_force<Friction, Damping>(nrm, h, vc, list.entries[k].k, spring);
    F[i] += cf.F;
    if constexpr (Rotation) T[i] -= ai * nrm.cross(cf.Ft);
    load.force -= cf.F;
    load.torque += (x[i] - ai * nrm - ref).cross(-cf.F);
  };
  for (std::size_t w_ = 0; w_ < planes_.size(); ++w_) {
    const PlaneWall& pl = planes_[w_];
    WallList& list = plane_lists_[w_];
    for (std::size_t k = 0; k < list.entries.size(); ++k) {
      const int i = list.entries[k].i;
      const double h = pl.overlap(x[i], r[i]);
      if (h <= 0.0) {
        if constexpr (Friction) list.spring[k].setZero();
        continue;
      }
      const double h_half = h + half_dt * (v[i] - pl.velocity).dot(pl.normal);
      wall_contact(list, k, i, pl.normal, h, pl.normal, h_half, pl.velocity, pl.velocity, pl.point, plane_loads_[w_]);
    }
  }
  // Sphere-shell contacts: the vectorised loop of sim/shell_forces.cpp (same arithmetic as
  // wall_contact() above with the shell's geometry; a turning shell moves its surface with it).
  for (std::size_t w_ = 0; w_ < shells_.size(); ++w_)
    accumulate_shell_forces(shell_lists_[w_], shells_[w_], PairForceArrays{x, v, w, r, F, T},
                            PairForceEffects{Friction, Damping, Rotation, Synchronized}, spring_dt,
                            shell_loads_[w_].force, shell_loads_[w_].torque);
}

// ---------------------------------------------------------------------------------------------
// Integration

// Half kicks: v += F/m dt/2 and w += T/I dt/2 for every free sphere.
void Simulation::half_kick() {
  const std::size_t n = p_.size();
  const double half = 0.5 * dt_;
  const std::uint8_t* const driven = p_.driven.empty() ? nullptr : p_.driven.data();
  Vec3* const v = p_.v.data();
  const Vec3* const F = p_.F.data();
  const double* const inv_m = p_.inv_m.data();
  for (std::size_t i = 0; i < n; ++i)
    if (!driven || !driven[i]) v[i] += (half * inv_m[i]) * F[i];
  if (p_.rotates()) {
    Vec3* const w = p_.w.data();
    const Vec3* const T = p_.T.data();
    const double* const inv_I = p_.inv_I.data();
    for (std::size_t i = 0; i < n; ++i)
      if (!driven || !driven[i]) w[i] += (half * inv_I[i]) * T[i];
  }
}

// Drift: x += v dt for every free sphere, noting the two largest displacements since the last
// neighbour build (driven spheres are added by advance_drivers()).
void Simulation::drift() {
  const std::size_t n = p_.size();
  const std::uint8_t* const driven = p_.driven.empty() ? nullptr : p_.driven.data();
  Vec3* const x = p_.x.data();
  const Vec3* const v = p_.v.data();
  const Vec3* const x0 = x_at_build_.data();
  LargestTwo disp2;
  for (std::size_t i = 0; i < n; ++i) {
    if (driven && driven[i]) continue;
    x[i] += dt_ * v[i];
    disp2.add((x[i] - x0[i]).squaredNorm());
  }
  disp2_ = disp2;
}

void Simulation::step() {
  half_kick();
  drift();
  if (!drivers_.empty()) advance_drivers();
  update_neighbours();
  compute_forces(dt_);
  half_kick();
  if (!drivers_.empty()) {
    watchdog_.add_driver_work(driver_work());
    finish_drivers();
  }
  time_ += dt_;
  ++steps_;
  if (++since_check_ >= scene_.watchdog.check_interval) check_now();
}

void Simulation::run_steps(long n) {
  for (long s = 0; s < n; ++s) step();
  if (since_check_ > 0) check_now();
}

void Simulation::check_now() {
  since_check_ = 0;
  watchdog_.check(*this);
}

// Positive work each driver did on the spheres during the step just made, for the watchdog's
// energy budget: the force at the end of the step times the step's motion (a driven sphere's
// velocity and spin are its displacement and turn over dt; walls receive -F from the spheres).
double Simulation::driver_work() const {
  double total = 0.0;
  for (const ActiveDriver& d : drivers_) {
    if (d.retired || std::holds_alternative<HoldGroupDef>(d.def)) continue;
    double work = 0.0;
    if (std::holds_alternative<MoveWallDef>(d.def)) {
      if (d.plane >= 0) work -= plane_loads_[d.plane].force.dot(planes_[d.plane].velocity);
      else work -= shell_loads_[d.shell].force.dot(shells_[d.shell].velocity);
    } else {
      for (int i : d.members) {
        work -= p_.F[i].dot(p_.v[i]);
        if (p_.rotates()) work -= p_.T[i].dot(p_.w[i]);
      }
      if (d.shell >= 0) work -= shell_loads_[d.shell].torque.dot(shells_[d.shell].spin);  // turned with its spheres
    }
    total += std::max(0.0, work * dt_);
  }
  return total;
}

long Simulation::steps_for(double duration) const {
  return std::max(1L, std::lround(duration / dt_));
}

void Simulation::run_for(double duration) { run_steps(steps_for(duration)); }

void Simulation::zero_velocities() {
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.is_driven(i)) continue;
    p_.v[i].setZero();
    if (p_.rotates()) p_.w[i].setZero();
  }
}

const WallLoad& Simulation::wall_load(const std::string& name) const {
  for (std::size_t k = 0; k < scene_.planes.size(); ++k)
    if (scene_.planes[k].name == name) return plane_loads_[k];
  for (std::size_t k = 0; k < scene_.shells.size(); ++k)
    if (scene_.shells[k].name == name) return shell_loads_[k];
  throw InputError(fmt::format("no plane or shell is named '{}'", name));
}

// ---------------------------------------------------------------------------------------------
// State

SimulationState Simulation::state() const {
  if (drivers_moving()) throw std::logic_error("Simulation::state: a driver is still moving");
  SimulationState s;
  s.time = time_;
  s.steps = steps_;
  s.x = p_.x, s.v = p_.v, s.w = p_.w, s.F = p_.F, s.T = p_.T;
  for (const auto& pl : planes_) s.plane_points.push_back(pl.point);
  for (const auto& sh : shells_) s.shell_centres.push_back(sh.centre);
  for (std::size_t k = 0; k < pairs_.spring.size(); ++k)
    if (pairs_.spring[k] != Vec3::Zero()) s.pair_springs.push_back({pairs_.pairs[k].i, pairs_.pairs[k].j, pairs_.spring[k]});
  const auto wall_springs = [](const std::vector<WallList>& lists) {
    std::vector<std::vector<SimulationState::WallSpring>> out;
    for (const WallList& l : lists) {
      out.emplace_back();
      for (std::size_t k = 0; k < l.spring.size(); ++k)
        if (l.spring[k] != Vec3::Zero()) out.back().push_back({l.entries[k].i, l.spring[k]});
    }
    return out;
  };
  s.plane_springs = wall_springs(plane_lists_);
  s.shell_springs = wall_springs(shell_lists_);
  return s;
}

void Simulation::restore(const SimulationState& s) {
  const std::size_t n = p_.size();
  if (s.x.size() != n || s.v.size() != n || s.F.size() != n || s.w.size() != p_.w.size() || s.T.size() != p_.T.size() ||
      s.plane_points.size() != planes_.size() || s.shell_centres.size() != shells_.size())
    throw InputError(fmt::format("the saved state does not fit this scene ({} spheres saved, {} in the scene)", s.x.size(), n));
  time_ = s.time;
  steps_ = s.steps;
  p_.x = s.x, p_.v = s.v, p_.w = s.w, p_.F = s.F, p_.T = s.T;
  for (std::size_t k = 0; k < planes_.size(); ++k) planes_[k].point = s.plane_points[k];
  for (std::size_t k = 0; k < shells_.size(); ++k) shells_[k].centre = s.shell_centres[k];
  rebuild_neighbours();
  // Install the springs; a saved spring whose pair is not listed cannot be: it was touching.
  if (scene_.effects.friction) {
    std::fill(pairs_.spring.begin(), pairs_.spring.end(), Vec3::Zero());
    for (auto* lists : {&plane_lists_, &shell_lists_})
      for (WallList& l : *lists) std::fill(l.spring.begin(), l.spring.end(), Vec3::Zero());
    std::size_t a = 0;
    for (const auto& sp : s.pair_springs) {
      while (a < pairs_.pairs.size() && std::pair(pairs_.pairs[a].i, pairs_.pairs[a].j) < std::pair(sp.i, sp.j)) ++a;
      if (a == pairs_.pairs.size() || pairs_.pairs[a].i != sp.i || pairs_.pairs[a].j != sp.j)
        throw InputError(fmt::format("the saved state has a spring for spheres {} and {}, which are apart", sp.i, sp.j));
      pairs_.spring[a] = sp.xi;
    }
    const auto install = [](std::vector<WallList>& lists, const std::vector<std::vector<SimulationState::WallSpring>>& saved) {
      for (std::size_t w = 0; w < lists.size() && w < saved.size(); ++w) {
        std::size_t a = 0;
        for (const auto& sp : saved[w]) {
          while (a < lists[w].entries.size() && lists[w].entries[a].i < sp.i) ++a;
          if (a == lists[w].entries.size() || lists[w].entries[a].i != sp.i)
            throw InputError(fmt::format("the saved state has a wall spring for sphere {}, which is off the wall", sp.i));
          lists[w].spring[a] = sp.xi;
        }
      }
    };
    install(plane_lists_, s.plane_springs);
    install(shell_lists_, s.shell_springs);
  }
  watchdog_.start(*this);
  since_check_ = 0;
}

Vec3 Simulation::force_between(int from, int on) const {
  Vec3 total = Vec3::Zero();
  const bool friction = scene_.effects.friction;
  for (std::size_t k = 0; k < pairs_.pairs.size(); ++k) {
    const PairEntry& e = pairs_.pairs[k];
    const int bi = p_.body[e.i], bj = p_.body[e.j];
    if (!((bi == from && bj == on) || (bi == on && bj == from))) continue;
    const Vec3 d = p_.x[e.i] - p_.x[e.j];
    const double dist = d.norm(), h = e.r_sum - dist;
    if (h <= 0.0) continue;
    const Vec3 n = d / dist;
    const ContactCoefficients& c = pairs_.k[k];
    Vec3 F = hertz::force(c.kn, h) * n;  // on sphere i
    if (friction) F -= c.kt0 * std::sqrt(h) * pairs_.spring[k];
    total += bi == on ? F : Vec3(-F);
  }
  return total;
}

// ---------------------------------------------------------------------------------------------
// Residuals

Measurement Simulation::measure() const {
  Measurement m;
  double sum_Fn = 0.0;
  const auto add_contact = [&](const ContactCoefficients& k, double h, const Vec3* spring) {
    m.elastic_energy += hertz::energy(k.kn, h);
    if (spring) m.elastic_energy += tsuji::energy(k.kt0 * std::sqrt(h), *spring);
    sum_Fn += hertz::force(k.kn, h);
    ++m.contacts;
  };
  const auto deepest = [&](double h, double radius, Measurement::Deepest site) {
    if (!(h / radius > m.deepest.fraction)) return;
    site.fraction = h / radius, site.overlap = h;
    m.deepest = site;
  };
  const bool friction = scene_.effects.friction;
  for (std::size_t k = 0; k < pairs_.pairs.size(); ++k) {
    const PairEntry& e = pairs_.pairs[k];
    const double h = e.r_sum - (p_.x[e.i] - p_.x[e.j]).norm();
    if (!(h > 0.0)) continue;
    add_contact(pairs_.k[k], h, friction ? &pairs_.spring[k] : nullptr);
    deepest(h, std::min(p_.r[e.i], p_.r[e.j]), {0.0, 0.0, e.i, e.j, -1, -1});
  }
  for (std::size_t w = 0; w < planes_.size(); ++w)
    for (std::size_t k = 0; k < plane_lists_[w].entries.size(); ++k) {
      const WallEntry& e = plane_lists_[w].entries[k];
      const double h = planes_[w].overlap(p_.x[e.i], p_.r[e.i]);
      if (!(h > 0.0)) continue;
      add_contact(e.k, h, friction ? &plane_lists_[w].spring[k] : nullptr);
      deepest(h, p_.r[e.i], {0.0, 0.0, e.i, -1, static_cast<int>(w), -1});
    }
  for (std::size_t w = 0; w < shells_.size(); ++w)
    for (std::size_t k = 0; k < shell_lists_[w].entries.size(); ++k) {
      const WallEntry& e = shell_lists_[w].entries[k];
      const double h = shells_[w].overlap(p_.x[e.i], p_.r[e.i]);
      if (!(h > 0.0)) continue;
      add_contact(e.k, h, friction ? &shell_lists_[w].spring[k] : nullptr);
      deepest(h, p_.r[e.i], {0.0, 0.0, e.i, -1, -1, static_cast<int>(w)});
    }
  m.mean_contact_force = m.contacts ? sum_Fn / static_cast<double>(m.contacts) : 0.0;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.is_driven(i)) continue;
    const double translation = 0.5 * p_.m[i] * p_.v[i].squaredNorm();
    const double rotation = p_.rotates() ? 0.5 * p_.w[i].squaredNorm() / p_.inv_I[i] : 0.0;
    m.kinetic_energy += translation;  // two sums, in this order: the recorded residuals keep their bits
    if (p_.rotates()) m.kinetic_energy += rotation;
    if (translation + rotation > m.hottest_energy) m.hottest_energy = translation + rotation, m.hottest = static_cast<int>(i);
    m.max_unbalanced_force = std::max(m.max_unbalanced_force, p_.F[i].norm());
  }
  return m;
}

}  // namespace softpack
