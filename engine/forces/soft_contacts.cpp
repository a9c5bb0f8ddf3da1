#include "forces/soft_contacts.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace softpack {

SoftContacts::SoftContacts(const SceneDef& scene) : def_(std::make_unique<SoftParticlesDef>(*scene.effects.soft_particles)) {
  const EffectsDef& e = scene.effects;
  fx_.friction = e.friction;
  fx_.damping = e.damping();
  if (e.damping()) fx_.zeta = linear_damping_ratio(*e.restitution);
  fx_.tangential_ratio = e.tangential_damping_ratio;
  rotation_ = e.rotation;
  synchronized_ = e.friction && scene.integration.history_update == HistoryUpdate::synchronized;
}

namespace {

// 1/mt of a sphere: 1/m + r^2/I with rotation (the sliding-rolling mode), 1/m without.
double inv_mt(const Particles& p, std::size_t i) { return p.inv_m[i] + (p.rotates() ? p.r[i] * p.r[i] * p.inv_I[i] : 0.0); }

}  // namespace

void SoftContacts::set_constants(const World& world, SoftLists& lists) const {
  const Particles& p = world.p;
  const SoftParticleLaws& laws = def_->laws;
  lists.pair_k.resize(lists.pairs.size());
  for (std::size_t k = 0; k < lists.pairs.size(); ++k) {
    auto i = static_cast<std::size_t>(lists.pairs.i[k]), j = static_cast<std::size_t>(lists.pairs.j[k]);
    const bool both = p.is_soft(i) && p.is_soft(j);
    if (!p.is_soft(i)) std::swap(i, j);  // R1 is a soft-particle's
    const double m12 = p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
    lists.pair_k[k] = soft_contact_constants(laws, both ? SoftContactKind::soft : SoftContactKind::grain, def_->grain_contact, p.r[i],
                                             p.r[j], m12, 1.0 / (inv_mt(p, i) + inv_mt(p, j)));
  }
  lists.plane_k.resize(lists.planes.size());
  for (std::size_t w = 0; w < lists.planes.size(); ++w) {
    const WallList& l = lists.planes[w];
    lists.plane_k[w].resize(l.size());
    for (std::size_t k = 0; k < l.size(); ++k) {
      const auto i = static_cast<std::size_t>(l.i[k]);
      lists.plane_k[w][k] = soft_contact_constants(laws, SoftContactKind::wall, def_->grain_contact, p.r[i], 0.0, p.m[i], 1.0 / inv_mt(p, i));
    }
  }
}

void SoftContacts::count(double dn, int i, int j, int plane, const SoftContactConstants& k) {
  if (dn > stats_.max_dn) stats_.max_dn = dn, stats_.i = i, stats_.j = j, stats_.plane = plane;
  const SoftPowerLaw& law = k.law->normal;
  if (!(dn > law.dn_max)) return;
  ++stats_.beyond_range;
  if (def_->beyond_range == SoftParticlesDef::BeyondRange::stop)
    throw NumericalError(fmt::format(
        "soft-particle contact of sphere {} with {} at dn = {:.4g}, beyond the range its law was measured on ({:.4g} to {:.4g}, {}); "
        "effects.soft_particles.beyond_range is 'stop'",
        i, j >= 0 ? fmt::format("sphere {}", j) : fmt::format("plane {}", plane), dn, law.dn_min, law.dn_max, def_->laws.source));
}

void SoftContacts::add_forces(World& world, SoftLists& lists, double dt) {
  Particles& p = world.p;
  const auto spring_of = [&](std::vector<Vec3>& springs, std::size_t k) { return fx_.friction ? v3(springs[k]) : V3<double>{}; };
  // Sphere pairs: d = xi - xj, h = Ri + Rj - |d|, n = d/|d| (forces/pair_contacts.hpp).
  PairList& pairs = lists.pairs;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int i = pairs.i[k], j = pairs.j[k];
    const Vec3 d = p.x[i] - p.x[j];
    const double dist = d.norm(), h = pairs.r_sum[k] - dist;
    if (!(h > 0.0)) {
      if (fx_.friction) pairs.spring[k].setZero();
      continue;
    }
    ContactGeometry<double> g;
    g.n = v3(d / dist);
    g.h = h;
    const Vec3 vij = p.v[i] - p.v[j];
    const double ai = p.r[i] - 0.5 * h, aj = p.r[j] - 0.5 * h;
    Vec3 vc = vij;
    if (rotation_) vc -= (ai * p.w[i] + aj * p.w[j]).cross(vec3(g.n));
    g.vc = v3(vc);
    g.n_frame = g.n, g.vc_frame = g.vc;
    if (synchronized_) {
      const Vec3 d_half = d - 0.5 * dt * vij;
      const double dist_half = d_half.norm();
      g.n_frame = v3(d_half / dist_half);
      Vec3 vc_half = vij;
      if (rotation_) {
        const double h_half = pairs.r_sum[k] - dist_half;
        vc_half -= ((p.r[i] - 0.5 * h_half) * p.w[i] + (p.r[j] - 0.5 * h_half) * p.w[j]).cross(d_half / dist_half);
      }
      g.vc_frame = v3(vc_half);
    }
    V3<double> xi = spring_of(pairs.spring, k);
    double dn = 0.0;
    const ContactForce<double> f = soft_contact_force(g, lists.pair_k[k], fx_, xi, dt, dn);
    count(dn, i, j, -1, lists.pair_k[k]);
    const Vec3 F = vec3(f.F);
    p.F[i] += F;
    p.F[j] -= F;
    if (rotation_) {
      const Vec3 t = vec3(g.n).cross(vec3(f.Ft));
      p.T[i] -= ai * t;
      p.T[j] -= aj * t;
    }
    if (fx_.friction) pairs.spring[k] = vec3(xi);
  }
  // Planes: h = r - (x - p).N, n = N (forces/wall_contacts.hpp).
  for (std::size_t w = 0; w < lists.planes.size(); ++w) {
    WallList& l = lists.planes[w];
    const PlaneWall& wall = world.planes[w];
    WallLoad& load = world.plane_loads[w];
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int i = l.i[k];
      const double h = p.r[i] - (p.x[i] - wall.point).dot(wall.normal);
      if (!(h > 0.0)) {
        if (fx_.friction) l.spring[k].setZero();
        continue;
      }
      ContactGeometry<double> g;
      g.n = v3(wall.normal);
      g.h = h;
      const double ai = p.r[i] - 0.5 * h;
      Vec3 vc = p.v[i] - wall.velocity;
      if (rotation_) vc -= (ai * p.w[i]).cross(wall.normal);
      g.vc = v3(vc);
      g.n_frame = g.n, g.vc_frame = g.vc;
      if (synchronized_) {
        Vec3 vc_half = p.v[i] - wall.velocity;
        if (rotation_) {
          const double h_half = h + 0.5 * dt * (p.v[i] - wall.velocity).dot(wall.normal);
          vc_half -= ((p.r[i] - 0.5 * h_half) * p.w[i]).cross(wall.normal);
        }
        g.vc_frame = v3(vc_half);
      }
      V3<double> xi = spring_of(l.spring, k);
      double dn = 0.0;
      const ContactForce<double> f = soft_contact_force(g, lists.plane_k[w][k], fx_, xi, dt, dn);
      count(dn, i, -1, static_cast<int>(w), lists.plane_k[w][k]);
      const Vec3 F = vec3(f.F);
      p.F[i] += F;
      if (rotation_) p.T[i] -= ai * wall.normal.cross(vec3(f.Ft));
      load.force -= F;
      load.torque += (p.x[i] - ai * wall.normal - wall.point).cross(-F);
      if (fx_.friction) l.spring[k] = vec3(xi);
    }
  }
}

}  // namespace softpack
