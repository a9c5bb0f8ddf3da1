#include "sim/residuals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "forces/contact_walk.hpp"

namespace softpack {
namespace {

// The radius an overlap is measured against: the smaller sphere's (a sphere's own against a
// wall); for a soft-particle's contact its law's R, so that the fraction is its Δn.
double contact_radius(const Particles& p, const ClosedContact& c) { return c.overlap_scale(p); }

}  // namespace

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

Measurement residuals(const World& world, const ContactLists& lists, const ForceField& forces) {
  Measurement m;
  const Particles& p = world.p;
  if (forces.active()) {
    double sum_Fn = 0.0;
    for_each_closed_contact(world, lists, forces, [&](const ClosedContact& c) {
      m.elastic_energy += c.normal_energy();
      if (c.spring) {
        const double spring = c.spring_energy();
        m.elastic_energy += spring;
        m.spring_energy += spring;
      }
      sum_Fn += c.Fn();
      ++m.contacts;
      const double radius = contact_radius(p, c);
      if (!(c.h / radius > m.deepest.fraction)) return;
      m.deepest = {c.h / radius, c.h, c.i, c.j, c.kind == ClosedContact::Kind::plane ? c.wall : -1,
                   c.kind == ClosedContact::Kind::shell ? c.wall : -1};
    });
    m.mean_contact_force = m.contacts ? sum_Fn / static_cast<double>(m.contacts) : 0.0;
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.is_driven(i)) continue;
    const double translation = 0.5 * p.m[i] * p.v[i].squaredNorm();
    const double rotation = p.rotates() && p.inv_I[i] > 0.0 ? 0.5 * p.w[i].squaredNorm() / p.inv_I[i] : 0.0;  // a locked spin stays 0
    m.kinetic_energy += translation;  // two sums, in this order: the recorded residuals keep their bits
    if (p.rotates()) m.kinetic_energy += rotation;
    if (translation + rotation > m.hottest_energy) m.hottest_energy = translation + rotation, m.hottest = static_cast<int>(i);
    m.max_unbalanced_force = std::max(m.max_unbalanced_force, p.F[i].norm());
  }
  for (const SphericalShell& s : world.shells)  // free shells move as bodies of their own
    if (s.free()) m.kinetic_energy += 0.5 * s.mass * (s.velocity.squaredNorm() + 2.0 / 3.0 * s.radius * s.radius * s.spin.squaredNorm());
  return m;
}

double overlap_quantile(const World& world, const ContactLists& lists, const ForceField& forces, double q) {
  if (!forces.active()) return 0.0;
  const Particles& p = world.p;
  std::vector<double> fraction;
  for_each_closed_contact(world, lists, forces, [&](const ClosedContact& c) {
    fraction.push_back(c.h / contact_radius(p, c));
  });
  if (fraction.empty()) return 0.0;
  // The nearest rank: the smallest value at least a fraction q of the contacts do not exceed.
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(fraction.size()))) - 1;
  std::nth_element(fraction.begin(), fraction.begin() + static_cast<std::ptrdiff_t>(rank), fraction.end());
  return fraction[rank];
}

}  // namespace softpack
