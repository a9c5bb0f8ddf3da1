#include "sim/watchdog.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/hertz_normal.hpp"
#include "contact/tsuji_tangential.hpp"
#include "core/error.hpp"
#include "sim/simulation.hpp"

namespace softpack {
namespace {

std::string vec(const Vec3& v) { return fmt::format("[{:.4g}, {:.4g}, {:.4g}]", v.x(), v.y(), v.z()); }

// "step 120, t = 0.0093 s: "
std::string where(const Simulation& sim) { return fmt::format("step {}, t = {:.6g} s: ", sim.step_count(), sim.time()); }

// "; dt = 7.74e-05 s, stable limit 0.000387 s (Rayleigh time of sphere 0)"
std::string time_step(const Simulation& sim) {
  return fmt::format("; dt = {:.4g} s, stable limit {:.4g} s (Rayleigh time of sphere {})", sim.dt(),
                     sim.stable_limit().t_rayleigh, sim.stable_limit().particle);
}

/// One pass over the state: energies, the largest overlap and the most energetic sphere.
struct Scan {
  double kinetic = 0.0, elastic = 0.0, gravity_work = 0.0;
  // Largest overlap fraction: spheres i and j, or sphere i against `wall` (j < 0).
  double fraction = 0.0, overlap = 0.0;
  int i = -1, j = -1;
  std::string wall;
  // Free sphere with the largest kinetic energy.
  int hot = -1;
  double hot_energy = 0.0;

  double energy() const { return kinetic + elastic; }
  std::string overlap_text(const Simulation& sim) const {
    const auto& r = sim.particles().r;
    if (i < 0) return "no contact";
    if (j >= 0)
      return fmt::format("spheres {} and {} (r = {:.4g} m and {:.4g} m) overlap by {:.4g} m, {:.3g} of the smaller radius", i,
                         j, r[i], r[j], overlap, fraction);
    return fmt::format("sphere {} (r = {:.4g} m) overlaps {} by {:.4g} m, {:.3g} of its radius", i, r[i], wall, overlap,
                       fraction);
  }
};

Scan scan(const Simulation& sim, const std::vector<Vec3>& x_start) {
  Scan s;
  const Particles& p = sim.particles();
  const bool friction = sim.scene().effects.friction;
  const auto note = [&](double h, double fraction, int i, int j, const std::string* wall) {
    if (!(fraction > s.fraction)) return;
    s.fraction = fraction, s.overlap = h, s.i = i, s.j = j;
    if (wall) s.wall = *wall;
  };
  const PairList& pairs = sim.pair_list();
  for (std::size_t k = 0; k < pairs.pairs.size(); ++k) {
    const PairEntry& e = pairs.pairs[k];
    const double d2 = (p.x[e.i] - p.x[e.j]).squaredNorm();
    if (!(d2 < e.r_sum * e.r_sum)) continue;  // apart: no square root (about half the list)
    const double h = e.r_sum - std::sqrt(d2);
    const ContactCoefficients& c = pairs.k[k];
    s.elastic += hertz::energy(c.kn, h);
    if (friction) s.elastic += tsuji::energy(c.kt0 * std::sqrt(h), pairs.spring[k]);
    note(h, h / std::min(p.r[e.i], p.r[e.j]), e.i, e.j, nullptr);
  }
  const auto walls = [&](const auto& geometry, const std::vector<WallList>& lists, const char* kind, const auto& names) {
    for (std::size_t w = 0; w < lists.size(); ++w) {
      const WallList& l = lists[w];
      const std::string name = fmt::format("{} '{}'", kind, names[w].name);
      for (std::size_t k = 0; k < l.entries.size(); ++k) {
        const int i = l.entries[k].i;
        const double h = geometry[w].overlap(p.x[i], p.r[i]);
        if (!(h > 0.0)) continue;
        const ContactCoefficients& c = l.entries[k].k;
        s.elastic += hertz::energy(c.kn, h);
        if (friction) s.elastic += tsuji::energy(c.kt0 * std::sqrt(h), l.spring[k]);
        note(h, h / p.r[i], i, -1, &name);
      }
    }
  };
  walls(sim.planes(), sim.plane_lists(), "plane", sim.scene().planes);
  walls(sim.shells(), sim.shell_lists(), "shell", sim.scene().shells);

  const auto& g = sim.scene().effects.gravity;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (g && !x_start.empty()) s.gravity_work += p.m[i] * g->dot(p.x[i] - x_start[i]);
    if (p.is_driven(i)) continue;
    double e = 0.5 * p.m[i] * p.v[i].squaredNorm();
    if (p.rotates()) e += 0.5 * p.w[i].squaredNorm() / p.inv_I[i];
    s.kinetic += e;
    if (e > s.hot_energy) s.hot_energy = e, s.hot = static_cast<int>(i);
  }
  return s;
}

// False when a position, velocity, force (spin, torque) is not finite. One multiply-add per
// sphere: 0 * sum is 0 for finite values and NaN for NaN or infinity (no fast-math in this
// build). A sum of huge finite values may overflow: check_finite() then finds nothing.
bool all_finite(const Particles& p) {
  double zero = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) zero += 0.0 * (p.x[i].sum() + p.v[i].sum() + p.F[i].sum());
  if (p.rotates())
    for (std::size_t i = 0; i < p.size(); ++i) zero += 0.0 * (p.w[i].sum() + p.T[i].sum());
  return zero == 0.0;
}

bool finite(const Particles& p, std::size_t i) {
  return p.x[i].allFinite() && p.v[i].allFinite() && p.F[i].allFinite() &&
         (!p.rotates() || (p.w[i].allFinite() && p.T[i].allFinite()));
}

// Throws the diagnostic of the first sphere with a non-finite value, if there is one;
// `before` tells what the last check saw.
void check_finite(const Simulation& sim, const std::string& before) {
  const Particles& p = sim.particles();
  std::size_t first = p.size(), count = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!finite(p, i)) {
      if (count++ == 0) first = i;
    }
  if (count == 0) return;
  const std::size_t i = first;
  std::string what;
  const auto add = [&](const char* name, const Vec3& v) {
    if (!v.allFinite()) what += (what.empty() ? "" : ", ") + std::string(name);
  };
  add("position", p.x[i]);
  add("velocity", p.v[i]);
  add("force", p.F[i]);
  if (p.rotates()) add("angular velocity", p.w[i]), add("torque", p.T[i]);
  std::string state = fmt::format("x = {}, v = {}, F = {}", vec(p.x[i]), vec(p.v[i]), vec(p.F[i]));
  if (p.rotates()) state += fmt::format(", w = {}, T = {}", vec(p.w[i]), vec(p.T[i]));
  throw NumericalError(where(sim) + fmt::format("sphere {} (r = {:.4g} m) has a non-finite {} ({}); {} of {} spheres are not finite{}",
                                                i, p.r[i], what, state, count, p.size(), before) +
                       time_step(sim));
}

}  // namespace

void Watchdog::start(const Simulation& sim) {
  started_ = false;
  check(sim);
}

void Watchdog::check_positions(const Simulation& sim) {
  double zero = 0.0;
  for (const Vec3& x : sim.particles().x) zero += 0.0 * x.sum();
  if (!(zero == 0.0)) check(sim);
}

void Watchdog::check(const Simulation& sim) {
  if (!all_finite(sim.particles())) {
    // What may have caused it: the largest overlap among finite positions, the last check.
    std::string context = "; largest overlap: " + scan(sim, {}).overlap_text(sim);
    if (started_)
      context += fmt::format("; the last check, at step {}, found an energy {:.3g} times its budget and a largest overlap of "
                             "{:.3g} of a radius",
                             last_.step, last_.energy_ratio, last_.fraction);
    check_finite(sim, context);
  }
  if (!started_) {
    x_start_.clear();
    if (sim.scene().effects.gravity) x_start_ = sim.particles().x;
  }
  const Scan s = scan(sim, x_start_);
  if (!started_) {
    start_energy_ = s.energy();
    driver_work_ = 0.0;
    budget_ = 0.0;
    started_ = true;
  }
  budget_ = std::max(budget_, start_energy_ + driver_work_ + s.gravity_work);

  const double E = s.energy();
  last_ = Last{sim.step_count(), s.fraction, budget_ > 0.0 ? E / budget_ : 0.0};
  largest_energy_ratio_ = std::max(largest_energy_ratio_, last_.energy_ratio);
  largest_fraction_ = std::max(largest_fraction_, s.fraction);
  // A blow-up first (its message names the largest overlap too), then the overlap alone.
  if (!(E <= def_.energy_growth * budget_) && E > 0.0) {
    const Particles& p = sim.particles();
    std::string hot = "no free sphere moves";
    if (s.hot >= 0)
      hot = fmt::format("most energetic sphere {} (r = {:.4g} m, |v| = {:.4g} m/s, kinetic energy {:.4g} J)", s.hot, p.r[s.hot],
                        p.v[s.hot].norm(), s.hot_energy);
    throw NumericalError(
        where(sim) +
        fmt::format("energy blow-up: kinetic + elastic energy {:.4g} J (kinetic {:.4g} J, elastic {:.4g} J) exceeds "
                    "watchdog.energy_growth = {} times its budget {:.4g} J (the largest so far of: energy at the start "
                    "{:.4g} J + work of the drivers {:.4g} J{}); {}; largest overlap: {}",
                    E, s.kinetic, s.elastic, def_.energy_growth, budget_, start_energy_, driver_work_,
                    x_start_.empty() ? "" : fmt::format(" + work of gravity, now {:.4g} J", s.gravity_work), hot,
                    s.overlap_text(sim)) +
        time_step(sim));
  }

  if (s.fraction > def_.max_overlap_fraction)
    throw NumericalError(where(sim) + s.overlap_text(sim) +
                         fmt::format(", above watchdog.max_overlap_fraction = {}", def_.max_overlap_fraction) + time_step(sim));
}

}  // namespace softpack
