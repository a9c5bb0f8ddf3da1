#include "support/confined_packing.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "core/random.hpp"
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

SceneDef bench_scene(const std::vector<Sphere>& spheres, const BenchParameters& p, bool friction, bool spatial) {
  SceneDef s = testing::basic_scene();
  s.effects.friction = friction;
  s.effects.rotation = friction;
  s.effects.restitution = p.restitution;
  s.integration.safety = p.safety;
  s.neighbor.skin = p.skin;
  s.neighbor.level_ratio = p.level_ratio;
  std::vector<Vec3> x;
  for (const auto& sp : spheres) x.push_back(sp.x);
  std::vector<std::int32_t> order(spheres.size());
  std::iota(order.begin(), order.end(), 0);
  if (spatial) order = spatial_order(x);  // as LAMMPS sorts its atoms
  for (const std::int32_t k : order) {
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

Lattice lattice_cube(long n, double r, double overlap) {
  Lattice out;
  out.r = r, out.overlap = overlap;
  const double a = std::sqrt(2.0) * (2.0 - overlap) * r;  // cubic cell; nearest neighbours at a / sqrt(2)
  // Sites a/2 (i, j, k) with i + j + k even, 0 <= i, j, k <= m: about (m + 1)^3 / 2 of them.
  const int m = std::max(1, static_cast<int>(std::lround(std::cbrt(2.0 * static_cast<double>(n)) - 1.0)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m; ++j)
      for (int k = 0; k <= m; ++k)
        if ((i + j + k) % 2 == 0) out.spheres.push_back({0.5 * a * Vec3(i, j, k), r});
  out.side = 0.5 * a * m;
  Random rng(20261204);
  for (std::size_t k = out.spheres.size(); k > 1; --k)
    std::swap(out.spheres[k - 1], out.spheres[static_cast<std::size_t>(rng.uniform() * static_cast<double>(k))]);
  return out;
}

SceneDef lattice_scene(const Lattice& lattice, const BenchParameters& p, bool friction, bool spatial) {
  SceneDef s = bench_scene(lattice.spheres, p, friction, spatial);
  s.shells.clear();
  // A face sphere misses four neighbours, whose normal forces would sum to 4 cos 45 deg = 2^(3/2)
  // times one along the face's normal; the plane's contact (R12 = r, a pair's r/2) gives that at
  // an overlap 2^(2/3) times a pair's (Hertz: Fn ~ sqrt(R12) h^(3/2)).
  const double h = lattice.overlap * lattice.r, gap = lattice.r - std::cbrt(4.0) * h;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 e = Vec3::Unit(axis);
    s.planes.push_back(PlaneDef{fmt::format("low{}", axis), -gap * e, e, 0});
    s.planes.push_back(PlaneDef{fmt::format("high{}", axis), (lattice.side + gap) * e, -e, 0});
  }
  return s;
}

}  // namespace softpack::bench
