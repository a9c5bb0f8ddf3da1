#include "forces/force_field.hpp"

#include "contact/hertz_normal.hpp"
#include "contact/tsuji_tangential.hpp"
#include "contact/viscous_damping.hpp"

namespace softpack {

ForceField::ForceField(const SceneDef& scene) {
  const EffectsDef& e = scene.effects;
  fx_ = Effects{e.friction, e.damping(), e.rotation, scene.integration.history_update == HistoryUpdate::synchronized};
  if (e.normal.empty()) return;
  law_ = &normal_law(e.normal);
  if (e.soft_particles) soft_.emplace(scene);
  loops_ = law_->loops(fx_);
  if (e.damping()) zeta_ = law_->damping_coefficient(*e.restitution);
  tangential_ratio_ = e.tangential_damping_ratio;
  materials_ = scene.materials.size();
  D_.resize(materials_ * materials_);
  Dt_.resize(materials_ * materials_);
  mu_.resize(materials_ * materials_);
  for (std::size_t a = 0; a < materials_; ++a)
    for (std::size_t b = 0; b < materials_; ++b) {
      D_[a * materials_ + b] = hertz_D(scene.materials[a], scene.materials[b]);
      Dt_[a * materials_ + b] = tsuji_Dt(scene.materials[a], scene.materials[b]);
      mu_[a * materials_ + b] = contact_mu(scene.materials[a], scene.materials[b]);
    }
}

void ForceField::add_contact_forces(World& world, ContactLists& lists, double spring_dt) {
  if (loops_) loops_->run(world, lists, spring_dt, closed_);
  if (soft_ && lists.soft) soft_->add_forces(world, *lists.soft, spring_dt);
}

void ForceField::add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T) {
  if (loops_) loops_->add_pair_forces(world, pairs, mask, sign, F, T, closed_);
}

// The constants of a contact of materials `mm` with reduced radius R12, reduced mass m12 (a
// sphere's mass against a wall, which has infinite mass) and the inverse mass of the
// sliding-rolling mode, 1/mt = sum over the spheres of 1/m + r^2/I (1/m without rotation).
ContactConstants<double> ForceField::constants(std::size_t mm, double R12, double m12, double inv_mt) const {
  ContactConstants<double> k{};
  k.kn = law_->stiffness(R12, D_[mm]);
  k.kt0 = tsuji::stiffness_factor(R12, Dt_[mm]);
  k.mu = mu_[mm];
  k.gamma0 = damping::gamma_factor(zeta_, m12, k.kn);
  k.gamma_t0 = tangential_ratio_ * damping::gamma_factor(zeta_, 1.0 / inv_mt, k.kt0);
  return k;
}

ContactConstants<double> ForceField::pair_constants(const Particles& p, int i, int j) const {
  double inv_mt = p.inv_m[i] + p.inv_m[j];
  if (p.rotates()) inv_mt += p.r[i] * p.r[i] * p.inv_I[i] + p.r[j] * p.r[j] * p.inv_I[j];
  return constants(static_cast<std::size_t>(p.material[i]) * materials_ + p.material[j], hertz::reduced_radius(p.r[i], p.r[j]),
                   p.m[i] * p.m[j] / (p.m[i] + p.m[j]), inv_mt);
}

ContactConstants<double> ForceField::wall_constants(const Particles& p, int i, int wall_material, double R12) const {
  double inv_mt = p.inv_m[i];
  if (p.rotates()) inv_mt += p.r[i] * p.r[i] * p.inv_I[i];
  return constants(static_cast<std::size_t>(p.material[i]) * materials_ + wall_material, R12, p.m[i], inv_mt);
}

void ForceField::set_constants(const World& world, ContactLists& lists, const NewContacts& added) const {
  const Particles& p = world.p;
  for (std::size_t k : added.pairs) lists.pairs.k.set(k, pair_constants(p, lists.pairs.i[k], lists.pairs.j[k]));
  for (std::size_t w = 0; w < added.planes.size(); ++w) {
    WallList& l = lists.planes[w];
    for (std::size_t k : added.planes[w]) l.k.set(k, wall_constants(p, l.i[k], world.planes[w].material, p.r[l.i[k]]));
  }
  for (std::size_t w = 0; w < added.shells.size(); ++w) {
    WallList& l = lists.shells[w];
    for (std::size_t k : added.shells[w]) {
      const int i = l.i[k];
      const SphericalShell& shell = world.shells[w];
      const double R12 =
          shell.contact_radius == ShellContactRadius::concave ? hertz::reduced_radius_concave(p.r[i], shell.radius) : p.r[i];
      l.k.set(k, wall_constants(p, i, shell.material, R12));
    }
  }
  if (soft_ && added.soft) soft_->set_constants(world, *lists.soft);
}

}  // namespace softpack
