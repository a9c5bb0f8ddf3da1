#include "support/scenes.hpp"

#include "packing/power_law.hpp"
#include "relax/relaxation.hpp"
#include "sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>


namespace softpack::testing {

Material paper_grain() { return Material{"grain", 5.0e5, 0.3, 0.3, 2500.0}; }
Material stiff_grain() { return Material{"stiff", 2.0e6, 0.25, 0.5, 7800.0}; }

SceneDef basic_scene() {
  SceneDef s;
  s.materials = {paper_grain()};
  s.effects.normal = "hertz";
  s.integration.safety = 0.2;
  s.neighbor = NeighborDef{0.2, 2.0};
  return s;
}

double power_law_radius(Random& rng, double r_min, double r_max, double b) {
  return power_law::sample(power_law::Law{r_min, r_max, b}, rng);
}

std::vector<ParticleDef> random_cloud(Random& rng, int n, double half, double r_min, double r_max, double b) {
  std::vector<ParticleDef> out(n);
  for (auto& p : out) {
    p.r = r_min == r_max ? r_min : power_law_radius(rng, r_min, r_max, b);
    p.x = rng.in_box(half);
  }
  return out;
}

std::vector<ParticleDef> random_spheres_in_shell(Random& rng, int n, double Rs, double r_min, double r_max,
                                                 double b, int trials, int body) {
  // n radii, sorted descending, inserted largest first; a sphere that finds no free place in
  // `trials` attempts is dropped. Overlaps are checked against the spheres already placed in
  // the 27 cells (of size 2 r_max) around the candidate.
  std::vector<double> radii;
  for (int k = 0; k < n; ++k) radii.push_back(power_law_radius(rng, r_min, r_max, b));
  std::sort(radii.rbegin(), radii.rend());
  const double cell = 2.0 * r_max;
  const auto key = [&](const Vec3& x, int dx, int dy, int dz) {
    const auto c = [&](double v, int d) { return static_cast<std::int64_t>(std::floor(v / cell)) + d + (1 << 20); };
    return (c(x.x(), dx) << 42) | (c(x.y(), dy) << 21) | c(x.z(), dz);
  };
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  std::vector<ParticleDef> placed;
  for (double r : radii) {
    for (int t = 0; t < trials; ++t) {
      const Vec3 x = rng.in_ball(Rs - r);
      bool free = true;
      for (int dx = -1; dx <= 1 && free; ++dx)
        for (int dy = -1; dy <= 1 && free; ++dy)
          for (int dz = -1; dz <= 1 && free; ++dz) {
            const auto it = cells.find(key(x, dx, dy, dz));
            if (it == cells.end()) continue;
            for (int q : it->second)
              if ((placed[q].x - x).squaredNorm() < (placed[q].r + r) * (placed[q].r + r)) {
                free = false;
                break;
              }
          }
      if (free) {
        ParticleDef p;
        p.x = x;
        p.r = r;
        p.body = body;
        cells[key(x, 0, 0, 0)].push_back(static_cast<int>(placed.size()));
        placed.push_back(p);
        break;
      }
    }
  }
  return placed;
}

double solid_fraction(const std::vector<ParticleDef>& particles, double R) {
  double v = 0.0;
  for (const auto& p : particles) v += std::pow(p.r, 3);
  return v / std::pow(R, 3);
}

void compress(SceneDef& scene, double R, double fraction, double growth) {
  SceneDef s = scene;
  if (!s.effects.damping()) s.effects.restitution = 0.3;
  for (double phi = solid_fraction(s.particles, R); phi < fraction * (1.0 - 1e-9); phi = solid_fraction(s.particles, R)) {
    const double factor = std::min(1.0 + growth, std::cbrt(fraction / phi));
    for (auto& p : s.particles) p.r *= factor;
    Simulation sim(s);
    relax(sim, PaperRelaxationDef{3, 0.01, 0.01});
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      s.particles[i].x = sim.particles().x[i];
      s.particles[i].v = Vec3::Zero();
      s.particles[i].w = Vec3::Zero();
    }
  }
  for (std::size_t i = 0; i < s.particles.size(); ++i) scene.particles[i] = s.particles[i];
}

}  // namespace softpack::testing
