#include "forces/force_field.hpp"

#include <fmt/format.h>

#include "contact/hertz_normal.hpp"
#include "core/error.hpp"

namespace softpack {

ForceField::ForceField(const SceneDef& scene) {
  const EffectsDef& e = scene.effects;
  fx_ = Effects{e.friction, e.damping(), e.rotation, scene.integration.history_update == HistoryUpdate::synchronized};
  if (e.normal.empty()) return;
  materials_ = scene.materials.size();
  ContactSetting setting;
  setting.materials = scene.materials;
  setting.restitution = e.restitution;
  setting.tangential_ratio = e.tangential_damping_ratio;
  models_.push_back(contact_model(e.normal).make(setting, fx_));
  if (e.soft_particles) {
    setting.soft_laws = &e.soft_particles->laws;
    setting.grain_rule = e.soft_particles->grain_contact;
    setting.stop_beyond_range = e.soft_particles->beyond_range == SoftParticlesDef::BeyondRange::stop;
    const auto& many_body = e.soft_particles->laws.many_body;
    if (many_body && many_body->grain_exponent != 0.0 && setting.grain_rule == GrainContactRule::reduced_radius)
      throw InputError(fmt::format("effects.soft_particles.grain_contact: 'reduced-radius' is not allowed with the law file {}, whose many_body has a "
                                   "grain factor (measured at Δn = h / Rs); allowed: wall",
                                   e.soft_particles->laws.source));
    // the pairwise laws, or with a law file's many-body law its model and per-body pass
    models_.push_back(contact_model(e.soft_particles->laws.many_body ? "soft-particle-many-body" : "soft-particle", false).make(setting, fx_));
  }
}

std::vector<std::size_t> ForceField::constants() const {
  std::vector<std::size_t> n;
  for (const auto& m : models_) n.push_back(m->constants());
  return n;
}

RangeStats ForceField::range() const {
  RangeStats all;
  for (const auto& m : models_) {
    const RangeStats& r = m->range();
    all.beyond_range += r.beyond_range;
    if (r.max_dn > all.max_dn) all.max_dn = r.max_dn, all.i = r.i, all.j = r.j, all.plane = r.plane;
  }
  return all;
}

void ForceField::add_contact_forces(World& world, ContactLists& lists, double spring_dt) {
  for (std::size_t f = 0; f < models_.size(); ++f) models_[f]->run(world, lists.family[f], spring_dt, closed_);
}

void ForceField::add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T) {
  if (active()) models_[0]->add_pair_forces(world, pairs, mask, sign, F, T, closed_);
}

namespace {

// 1/mt of the sliding-rolling mode of sphere i: 1/m + r^2/I (1/m without rotation).
double inv_m_and_I(const Particles& p, int i) { return p.inv_m[i] + (p.rotates() ? p.r[i] * p.r[i] * p.inv_I[i] : 0.0); }

// Sphere pair (i, j): reduced radius and mass, and 1/mt = the sum over both spheres of 1/m + r^2/I
// (the two masses first, then the two rotations: the order the archived results were made in).
ContactPartners pair_partners(const Particles& p, std::size_t materials, int i, int j) {
  ContactPartners b;
  b.kind = ContactPartners::Kind::pair;
  b.R1 = p.r[i], b.R2 = p.r[j];
  b.R12 = hertz::reduced_radius(p.r[i], p.r[j]);
  b.m12 = p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
  b.inv_mt = p.inv_m[i] + p.inv_m[j];
  if (p.rotates()) b.inv_mt += p.r[i] * p.r[i] * p.inv_I[i] + p.r[j] * p.r[j] * p.inv_I[j];
  b.materials = static_cast<std::size_t>(p.material[i]) * materials + static_cast<std::size_t>(p.material[j]);
  b.soft1 = p.family_of(static_cast<std::size_t>(i)) == kSoftParticleFamily;
  b.soft2 = p.family_of(static_cast<std::size_t>(j)) == kSoftParticleFamily;
  return b;
}

// Sphere i against a wall of material `wall_material` (infinite mass and radius), reduced radius R12.
ContactPartners wall_partners(const Particles& p, std::size_t materials, int i, ContactPartners::Kind kind, int wall_material, double R12) {
  ContactPartners b;
  b.kind = kind;
  b.R1 = p.r[i], b.R12 = R12;
  b.m12 = p.m[i];
  b.inv_mt = inv_m_and_I(p, i);
  b.materials = static_cast<std::size_t>(p.material[i]) * materials + static_cast<std::size_t>(wall_material);
  b.soft1 = p.family_of(static_cast<std::size_t>(i)) == kSoftParticleFamily;
  return b;
}

}  // namespace

void ForceField::set_constants(const World& world, ContactLists& lists, const std::vector<NewContacts>& added) const {
  const Particles& p = world.p;
  for (std::size_t f = 0; f < added.size(); ++f) {
    const SceneModel& model = *models_[f];
    ContactFamily& l = lists.family[f];
    for (std::size_t k : added[f].pairs) model.set(l.pairs.k, k, pair_partners(p, materials_, l.pairs.i[k], l.pairs.j[k]));
    for (std::size_t w = 0; w < added[f].planes.size(); ++w) {
      WallList& wl = l.planes[w];
      for (std::size_t k : added[f].planes[w])
        model.set(wl.k, k, wall_partners(p, materials_, wl.i[k], ContactPartners::Kind::plane, world.planes[w].material, p.r[wl.i[k]]));
    }
    for (std::size_t w = 0; w < added[f].shells.size(); ++w) {
      WallList& wl = l.shells[w];
      const SphericalShell& shell = world.shells[w];
      for (std::size_t k : added[f].shells[w]) {
        const int i = wl.i[k];
        const double R12 =
            shell.contact_radius == ShellContactRadius::concave ? hertz::reduced_radius_concave(p.r[i], shell.radius) : p.r[i];
        model.set(wl.k, k, wall_partners(p, materials_, i, ContactPartners::Kind::shell, shell.material, R12));
      }
    }
  }
}

}  // namespace softpack
