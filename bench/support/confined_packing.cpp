#include "support/confined_packing.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "neighbor/spatial_order.hpp"
#include "support/scenes.hpp"

namespace softpack::bench {

std::vector<Sphere> read_spheres(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<Sphere> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Sphere sp;
    if (!(s >> sp.x.x() >> sp.x.y() >> sp.x.z() >> sp.r)) throw std::runtime_error(path + ": bad line: " + line);
    out.push_back(sp);
  }
  return out;
}

void write_spheres(const std::string& path, const std::vector<Sphere>& spheres) {
  std::string text = "# x y z r [m], softpack benchmark packing\n";
  for (const auto& s : spheres) text += fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}\n", s.x.x(), s.x.y(), s.x.z(), s.r);
  write_file_atomically(path, text);
}

SceneDef bench_scene(const std::vector<Sphere>& spheres, const BenchParameters& p, bool friction) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = friction;
  s.effects.rotation = friction;
  s.effects.restitution = p.restitution;
  s.integration.safety = p.safety;
  s.neighbor.skin = p.skin;
  s.neighbor.level_ratio = p.level_ratio;
  std::vector<Vec3> x;
  for (const auto& sp : spheres) x.push_back(sp.x);
  for (const std::int32_t k : spatial_order(x)) {  // in spatial order, as LAMMPS sorts its atoms
    const Sphere& sp = spheres[static_cast<std::size_t>(k)];
    ParticleDef d;
    d.x = sp.x;
    d.r = sp.r;
    d.body = 0;
    s.particles.push_back(d);
  }
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), p.Rs, 0, ShellContactRadius::concave, std::nullopt}};
  return s;
}

std::vector<Sphere> confined_packing(int n, const BenchParameters& p, const std::string& cache) {
  if (!cache.empty() && std::filesystem::exists(cache)) return read_spheres(cache);
  testing::Random rng(20261122);
  SceneDef s = testing::basic_scene();
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.restitution = p.restitution;
  // Place the spheres at a quarter of the nominal size, then grow them all by the same factor
  // until the solid fraction is reached (the polydispersity is kept; the final sizes are
  // printed by softpack-bench-scene).
  const double start = 0.25;
  s.particles = testing::random_spheres_in_shell(rng, n, p.Rs, start * p.r_max / p.polydispersity, start * p.r_max,
                                                 p.exponent, 1000, 0);
  s.shells = {ShellDef{"shell", 0, Vec3::Zero(), p.Rs, 0, ShellContactRadius::concave, std::nullopt}};
  testing::compress(s, p.Rs, p.solid_fraction, 0.03);
  std::vector<Sphere> out;
  for (const auto& d : s.particles) out.push_back({d.x, d.r});
  if (!cache.empty()) write_spheres(cache, out);
  return out;
}

}  // namespace softpack::bench
