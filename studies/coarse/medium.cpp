#include "coarse/medium.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/error.hpp"
#include "core/random.hpp"
#include "measure/content_scene.hpp"
#include "packing/power_law.hpp"

namespace softpack {
namespace {

double ball(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// ∫ r^3 r^-b dr from lo to hi (up to the constant of P(r)).
double volume_moment(double lo, double hi, double b) {
  if (std::abs(b - 4.0) < 1e-12) return std::log(hi / lo);
  return (std::pow(hi, 4.0 - b) - std::pow(lo, 4.0 - b)) / (4.0 - b);
}

}  // namespace

std::uint64_t site_seed(std::uint64_t seed, std::size_t k) { return seed * 1000 + k; }

double packing_mass(const Packing& p, double density) {
  double m = 0.0;
  for (double r : p.radii) m += density * ball(r);
  return m;
}

Medium build_medium(const CoarseGrainSettings& s, std::uint64_t seed, const MediumProgress& progress) {
  Medium m;
  m.Rs = s.packing.Rs;
  Random rng(seed);
  const power_law::Law first{s.r_min_over_Rs * m.Rs, s.decade * s.r_min_over_Rs * m.Rs, s.exponent};
  for (long k = 0; k < s.grains; ++k) {
    m.grain_r.push_back(power_law::sample(first, rng));
    m.grains_volume += ball(m.grain_r.back());
  }
  // The second decade (and with nested soft-particles the `levels` - 1 below it): the packing's
  // own range, the same P(r) continued below the first decade down to the last level's grains.
  const double r2_max = s.packing.r_max, r2_min = s.packing.r_max / std::pow(s.packing.polydispersity, s.levels);
  m.target_volume = m.grains_volume * volume_moment(r2_min, r2_max, s.exponent) / volume_moment(first.r_min, first.r_max, s.exponent);
  m.levels = s.levels;
  // Nested, sampled: a site's site weighs the sample's mean (the same seeds as the sites' own).
  const bool sampled = s.levels > 1 && s.content_sample > 0;
  if (sampled)
    m.content_mean = sample_contents(s.packing, s.levels - 1, seed, static_cast<std::size_t>(s.content_sample), [&](std::size_t k, std::size_t n) {
      if (progress) progress("sample", k, n);
    });
  // As many packings as bring the solid volume nearest to the target (one at least).
  while (true) {
    const std::size_t k = m.packings.size();
    LevelPacking p = generate_level(s.packing, s.levels - 1, site_seed(seed, k));
    std::vector<SiteContent> inside;
    if (!sampled) inside = generate_contents(s.packing, s.levels - 1, site_seed(seed, k), p.sites.size());
    double v = std::accumulate(p.grains.radii.begin(), p.grains.radii.end(), 0.0, [](double a, double r) { return a + ball(r); });
    for (const SiteContent& c : inside) v += c.solid_volume();
    if (sampled) v += static_cast<double>(p.sites.size()) * m.content_mean.volume;
    if (k > 0 && std::abs(m.packings_volume + v - m.target_volume) >= std::abs(m.packings_volume - m.target_volume)) break;
    m.packings.push_back(std::move(p.grains));
    m.packing_seeds.push_back(site_seed(seed, k));
    if (s.levels > 1) {
      m.inner_radius = p.site_radius;
      m.inner_sites.push_back(std::move(p.sites));
      if (!sampled) m.contents.push_back(std::move(inside));
    }
    m.packings_volume += v;
    if (progress) progress("site", k + 1, static_cast<std::size_t>(std::ceil(m.target_volume / (m.packings_volume / static_cast<double>(k + 1)))));
  }
  m.sites.resize(m.packings.size());

  // Random placement, largest first: bodies are the grains (their radius) and the sites (Rs).
  struct Body {
    double r;
    std::size_t index;  // grain index, or grains + site index
  };
  std::vector<Body> bodies;
  double volume = 0.0;
  for (std::size_t k = 0; k < m.grain_r.size(); ++k) bodies.push_back({m.grain_r[k], k}), volume += ball(m.grain_r[k]);
  for (std::size_t k = 0; k < m.sites.size(); ++k) bodies.push_back({m.Rs, m.grain_r.size() + k}), volume += ball(m.Rs);
  std::stable_sort(bodies.begin(), bodies.end(), [](const Body& a, const Body& b) { return a.r > b.r; });
  m.L = std::cbrt(volume / (s.initial_fraction * s.aspect));
  m.H = s.aspect * m.L;
  std::vector<Vec3> placed_x;
  std::vector<double> placed_r;
  m.grain_x.resize(m.grain_r.size());
  for (const Body& b : bodies) {
    if (2.0 * b.r >= m.L)
      throw InputError(fmt::format("medium.initial_fraction: a body of radius {:.4g} m is wider than the box ({:.4g} m); "
                                   "lower initial_fraction or add grains",
                                   b.r, m.L));
    bool done = false;
    for (long t = 0; t < s.placement_trials && !done; ++t) {
      const Vec3 x(rng.uniform(b.r, m.L - b.r), rng.uniform(b.r, m.L - b.r), rng.uniform(b.r, m.H - b.r));
      done = true;
      for (std::size_t j = 0; j < placed_x.size() && done; ++j) done = (x - placed_x[j]).norm() >= b.r + placed_r[j];
      if (!done) continue;
      placed_x.push_back(x), placed_r.push_back(b.r);
      if (b.index < m.grain_r.size()) m.grain_x[b.index] = x;
      else m.sites[b.index - m.grain_r.size()] = x;
    }
    if (!done)
      throw InputError(fmt::format("medium.initial_fraction: {} (a body of radius {:.4g} m found no place in {} trials); lower "
                                   "initial_fraction or raise placement_trials",
                                   s.initial_fraction, b.r, s.placement_trials));
  }
  return m;
}

void medium_contents(const CoarseGrainSettings& s, Medium& m, const std::function<void(std::size_t, std::size_t)>& progress) {
  if (m.levels != s.levels)
    throw InputError(fmt::format("the medium's sites have {} levels and the settings' packing {} (soft_particle.profile's "
                                 "packing.levels): make the medium again",
                                 m.levels, s.levels));
  if (m.content_mean.sample != static_cast<std::size_t>(s.content_sample))
    throw InputError(fmt::format("the medium's contents were {} and the settings' medium.content_sample is {}: make the medium again",
                                 m.content_mean.sample > 0 ? fmt::format("sampled {} per level", m.content_mean.sample) : "made",
                                 s.content_sample));
  m.contents.clear();
  if (m.levels == 1 || m.content_mean.sample > 0) return;
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    m.contents.push_back(generate_contents(s.packing, s.levels - 1, m.packing_seeds[k], m.inner_sites[k].size()));
    if (progress) progress(k + 1, m.sites.size());
  }
}

SiteInside site_inside(const Medium& m, std::size_t k) {
  SiteInside in;
  if (m.levels == 1) return in;
  if (m.content_mean.sample > 0) {
    const auto n = static_cast<double>(m.inner_sites.at(k).size());
    const ContentMean& c = m.content_mean;
    return {n * c.volume, n * c.volume_error, n * c.shells_volume, n * c.shells_volume_error, n * c.grains, n * c.grains_error,
            n > 0.0 ? c.smallest_radius : in.smallest_radius};
  }
  if (m.contents.size() != m.sites.size())
    throw InputError(fmt::format("a medium of nested soft-particles ({} levels): its sites' contents are neither made (medium_contents, "
                                 "as softpack-coarse run and estimate do) nor sampled (medium.content_sample)",
                                 m.levels));
  const auto smallest = [&](auto& self, const SiteContent& c) -> void {
    for (double r : c.level.grains.radii) in.smallest_radius = std::min(in.smallest_radius, r);
    for (const SiteContent& sub : c.sites) self(self, sub);
  };
  for (const SiteContent& c : m.contents[k]) {
    smallest(smallest, c);
    in.volume += c.solid_volume();
    in.shells_volume += content_shells_mass(c, 1.0, 1.0);  // unit density and fraction: the shells' volume
    in.grains += static_cast<double>(c.grains());
  }
  return in;
}

SceneDef engine_scene(const CoarseGrainSettings& s) {
  const SimulationSettings& sim = s.simulation;
  SceneDef scene;
  scene.materials = {sim.material, sim.wall_material};
  scene.effects = sim.effects;
  scene.integration = sim.integration;
  scene.neighbor = sim.neighbor;
  scene.watchdog.max_overlap_fraction = s.max_overlap_fraction;
  return scene;
}

SceneDef medium_scene(const CoarseGrainSettings& s, const Medium& m, CoarseModel model, const SoftParticleLaws& laws) {
  const SimulationSettings& sim = s.simulation;
  SceneDef scene = engine_scene(s);
  constexpr int kGrain = 0, kWall = 1;
  for (std::size_t k = 0; k < m.grain_x.size(); ++k) {
    ParticleDef p;
    p.x = m.grain_x[k], p.r = m.grain_r[k], p.material = kGrain;
    scene.particles.push_back(p);
  }
  if (model == CoarseModel::resolved && m.content_mean.sample > 0)
    throw InputError(fmt::format("a medium whose sites' contents are sampled (medium.content_sample {}) has no resolved model: "
                                 "its contents are weighed, not made; allowed: the soft model, or a medium without content_sample",
                                 m.content_mean.sample));
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const Packing& pk = m.packings[k];
    // Every grain inside the site, at every level, and (nested) the free shells of its sites.
    double grains_mass = packing_mass(pk, sim.material.density), inner_shells = 0.0;
    if (m.levels > 1) {
      const SiteInside in = site_inside(m, k);
      grains_mass += sim.material.density * in.volume;
      inner_shells = s.shell_mass_fraction * sim.material.density * in.shells_volume;
    }
    if (model == CoarseModel::resolved) {
      for (std::size_t i = 0; i < pk.centres.size(); ++i) {
        ParticleDef p;
        p.x = m.sites[k] + pk.centres[i], p.r = pk.radii[i], p.material = kGrain, p.body = static_cast<int>(k);
        scene.particles.push_back(p);
      }
      scene.shells.push_back(ShellDef{fmt::format("site{}", k), static_cast<int>(k), m.sites[k], m.Rs, kWall, sim.shell_contact_radius,
                                      s.shell_mass_fraction * grains_mass});
    } else {
      ParticleDef p;
      p.x = m.sites[k], p.r = m.Rs, p.material = kGrain, p.soft = true, p.spin_locked = s.spin_locked;
      p.mass = (1.0 + s.shell_mass_fraction) * grains_mass;
      if (m.levels > 1) *p.mass += inner_shells;
      scene.particles.push_back(p);
    }
  }
  // Nested: each site's sites resolved inside its shell, after every site's own grains and
  // shell (so that shell k is site k's, and a site's spheres are its grains then its contents').
  if (model == CoarseModel::resolved && m.levels > 1) {
    int next_body = static_cast<int>(m.sites.size());
    const ContentPlacement place{kGrain, kWall, sim.material.density, sim.shell_contact_radius, s.shell_mass_fraction};
    for (std::size_t k = 0; k < m.sites.size(); ++k)
      add_contents(scene, m.contents[k], m.inner_sites[k], m.inner_radius, static_cast<int>(k), m.sites[k], 1.0, place, next_body);
  }
  if (model == CoarseModel::soft) scene.effects.soft_particles = SoftParticlesDef{laws, s.grain_contact, s.beyond_range};
  const auto plane = [&](const char* name, const Vec3& point, const Vec3& normal) {
    scene.planes.push_back(PlaneDef{name, point, normal, kWall});
  };
  plane("bottom", Vec3::Zero(), Vec3::UnitZ());
  plane("top", Vec3(0, 0, m.H), -Vec3::UnitZ());
  plane("x0", Vec3::Zero(), Vec3::UnitX());
  plane("x1", Vec3(m.L, 0, 0), -Vec3::UnitX());
  plane("y0", Vec3::Zero(), Vec3::UnitY());
  plane("y1", Vec3(0, m.L, 0), -Vec3::UnitY());
  return scene;
}

std::vector<int> sphere_bodies(const Medium& m, CoarseModel model) {
  std::vector<int> out;
  const int grains = static_cast<int>(m.grain_x.size());
  for (int k = 0; k < grains; ++k) out.push_back(k);
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const std::size_t n = model == CoarseModel::resolved ? m.packings[k].centres.size() : 1;
    out.insert(out.end(), n, grains + static_cast<int>(k));
  }
  if (model == CoarseModel::resolved && m.levels > 1) {  // the sites' contents, site by site (medium_scene)
    if (m.contents.size() != m.sites.size())
      throw InputError("sphere_bodies: the medium's sites' contents are not made (medium_contents; a sampled medium has no resolved model)");
    for (std::size_t k = 0; k < m.sites.size(); ++k)
      for (const SiteContent& c : m.contents[k]) out.insert(out.end(), c.grains(), grains + static_cast<int>(k));
  }
  return out;
}

}  // namespace softpack
