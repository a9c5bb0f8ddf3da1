#include "sim/watchdog.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace softpack {
namespace {

std::string vec(const Vec3& v) { return fmt::format("[{:.4g}, {:.4g}, {:.4g}]", v.x(), v.y(), v.z()); }

// Work of gravity since the start: sum m_i g . (x_i - x_i(start)) [J].
double gravity_work(const World& world, const std::optional<Vec3>& g, const std::vector<Vec3>& x_start) {
  if (!g || x_start.empty()) return 0.0;
  const Particles& p = world.p;
  double work = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) work += p.m[i] * g->dot(p.x[i] - x_start[i]);
  return work;
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

}  // namespace

// "step 120, t = 0.0093 s: "
std::string Watchdog::where(const World& world) const {
  return fmt::format("step {}, t = {:.6g} s: ", world.steps, world.time);
}

// "; dt = 7.74e-05 s, stable limit 0.000387 s (Rayleigh time of sphere 0)"
std::string Watchdog::time_step() const {
  return fmt::format("; dt = {:.4g} s, stable limit {:.4g} s (Rayleigh time of sphere {})", context_.dt,
                     context_.limit.t_rayleigh, context_.limit.particle);
}

// "spheres 3 and 7 (r = ...) overlap by ... m, ... of the smaller radius", from the residuals.
std::string Watchdog::overlap_text(const World& world, const Measurement::Deepest& d) const {
  const auto& r = world.p.r;
  if (d.i < 0) return "no contact";
  if (d.j >= 0)
    return fmt::format("spheres {} and {} (r = {:.4g} m and {:.4g} m) overlap by {:.4g} m, {:.3g} of the smaller radius", d.i,
                       d.j, r[d.i], r[d.j], d.overlap, d.fraction);
  const std::string wall = d.plane >= 0 ? fmt::format("plane '{}'", context_.plane_names[d.plane])
                                        : fmt::format("shell '{}'", context_.shell_names[d.shell]);
  return fmt::format("sphere {} (r = {:.4g} m) overlaps {} by {:.4g} m, {:.3g} of its radius", d.i, r[d.i], wall, d.overlap,
                     d.fraction);
}

// Throws the diagnostic of the first sphere with a non-finite value, if there is one;
// `before` tells what the last check saw.
void Watchdog::check_finite(const World& world, const std::string& before) const {
  const Particles& p = world.p;
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
  throw NumericalError(where(world) + fmt::format("sphere {} (r = {:.4g} m) has a non-finite {} ({}); {} of {} spheres are not finite{}",
                                                  i, p.r[i], what, state, count, p.size(), before) +
                       time_step());
}

void Watchdog::start(const World& world, const Measurement& m) {
  started_ = false;
  check(world, m);
}

bool Watchdog::positions_finite(const World& world) {
  double zero = 0.0;
  for (const Vec3& x : world.p.x) zero += 0.0 * x.sum();
  return zero == 0.0;
}

void Watchdog::check(const World& world, const Measurement& m) {
  if (!all_finite(world.p)) {
    // What may have caused it: the largest overlap among finite positions, the last check.
    std::string context = "; largest overlap: " + overlap_text(world, m.deepest);
    if (started_)
      context += fmt::format("; the last check, at step {}, found an energy {:.3g} times its budget and a largest overlap of "
                             "{:.3g} of a radius",
                             last_.step, last_.energy_ratio, last_.fraction);
    check_finite(world, context);
  }
  if (!started_) {
    x_start_.clear();
    if (context_.gravity) x_start_ = world.p.x;
  }
  // The tangential springs are left out: their ½ kt ξ² changes without work when kt follows the
  // overlap (Tsuji's kt ∝ √h, Eq. 8's kt(Δn)), and capped by Coulomb's μ Fn it cannot blow up alone.
  const double E = m.kinetic_energy + (m.elastic_energy - m.spring_energy);
  const double W_gravity = gravity_work(world, context_.gravity, x_start_);
  if (!started_) {
    start_energy_ = E;
    driver_work_ = 0.0;
    budget_ = 0.0;
    started_ = true;
  }
  budget_ = std::max(budget_, start_energy_ + driver_work_ + W_gravity);

  last_ = Last{world.steps, m.deepest.fraction, budget_ > 0.0 ? E / budget_ : 0.0};
  largest_energy_ratio_ = std::max(largest_energy_ratio_, last_.energy_ratio);
  largest_fraction_ = std::max(largest_fraction_, m.deepest.fraction);
  // A blow-up first (its message names the largest overlap too), then the overlap alone. Energies
  // of round-off are no blow-up: while every contact overlaps by less than kRoundOffOverlap of
  // its radius and no sphere moves by more than that fraction of its radius in a step, E and its
  // budget are rounding errors (3e-39 J growing to 1e-34 J on a soft-particle whose grains
  // touch by 1e-13 of a radius and move at 1e-14 m/s) and are not judged.
  const auto round_off = [&] {
    if (!(m.deepest.fraction < kRoundOffOverlap && context_.dt > 0.0)) return false;
    const Particles& p = world.p;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!p.is_driven(i) && p.v[i].norm() * context_.dt >= kRoundOffOverlap * p.r[i]) return false;
    return true;
  };
  if (!(E <= def_.energy_growth * budget_) && E > 0.0 && !round_off()) {
    const Particles& p = world.p;
    std::string hot = "no free sphere moves";
    if (m.hottest >= 0)
      hot = fmt::format("most energetic sphere {} (r = {:.4g} m, |v| = {:.4g} m/s, kinetic energy {:.4g} J)", m.hottest,
                        p.r[m.hottest], p.v[m.hottest].norm(), m.hottest_energy);
    throw NumericalError(
        where(world) +
        fmt::format("energy blow-up: kinetic + normal elastic energy {:.4g} J (kinetic {:.4g} J, normal elastic {:.4g} J; "
                    "the tangential springs, not judged, {:.4g} J) exceeds watchdog.energy_growth = {} times its budget {:.4g} J "
                    "(the largest so far of: energy at the start {:.4g} J + work of the drivers {:.4g} J{}); {}; largest overlap: {}",
                    E, m.kinetic_energy, m.elastic_energy - m.spring_energy, m.spring_energy, def_.energy_growth, budget_,
                    start_energy_, driver_work_,
                    x_start_.empty() ? "" : fmt::format(" + work of gravity, now {:.4g} J", W_gravity), hot,
                    overlap_text(world, m.deepest)) +
        time_step());
  }

  if (m.deepest.fraction > def_.max_overlap_fraction)
    throw NumericalError(where(world) + overlap_text(world, m.deepest) +
                         fmt::format(", above watchdog.max_overlap_fraction = {}", def_.max_overlap_fraction) + time_step());
}

}  // namespace softpack
