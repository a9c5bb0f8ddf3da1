#include "coarse/multi_contact.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "coarse/medium.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "packing/generator.hpp"
#include "relax/relaxation.hpp"

namespace softpack {
namespace {

constexpr const char* kAllowed = "one, opposite, orthogonal, triangle, tetrahedral, square, pyramid, cube, opposite-half, orthogonal-half, random-N (N = 2 to 6)";

// random-N: N unit vectors, uniform on the sphere, each at least 60 degrees from the others
// (drawn one after the other, all again after 1 000 refusals of one), turned so that the first is +z.
std::vector<ProbeWall> random_walls(int n, std::uint64_t seed) {
  Random rng(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(n));
  const double cos_min = std::cos(std::numbers::pi / 3.0);
  const auto direction = [&] {
    for (;;) {
      const Vec3 v = rng.in_ball(1.0);
      if (v.norm() > 1e-3) return Vec3(v.normalized());
    }
  };
  std::vector<Vec3> u;
  while (u.size() < static_cast<std::size_t>(n)) {
    u.assign(1, direction());
    for (int refused = 0; u.size() < static_cast<std::size_t>(n) && refused < 1000;) {
      const Vec3 v = direction();
      bool apart = true;
      for (const Vec3& e : u) apart = apart && e.dot(v) <= cos_min;
      if (apart) u.push_back(v), refused = 0;
      else ++refused;
    }
  }
  const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(u[0], Vec3::UnitZ()).toRotationMatrix();
  std::vector<ProbeWall> walls;
  for (const Vec3& e : u) walls.push_back({(turn * e).normalized(), 1.0});
  walls[0].u = Vec3::UnitZ();  // exactly
  return walls;
}

}  // namespace

ProbeArrangement builtin_arrangement(const std::string& name, std::uint64_t seed) {
  const Vec3 z = Vec3::UnitZ(), x = Vec3::UnitX(), y = Vec3::UnitY();
  const double s3 = std::sqrt(3.0) / 2.0;
  ProbeArrangement a{name, {}};
  auto& w = a.walls;
  if (name == "one") w = {{z, 1.0}};
  else if (name == "opposite") w = {{z, 1.0}, {-z, 1.0}};
  else if (name == "orthogonal") w = {{z, 1.0}, {x, 1.0}};
  else if (name == "triangle") w = {{z, 1.0}, {Vec3(s3, 0.0, -0.5), 1.0}, {Vec3(-s3, 0.0, -0.5), 1.0}};
  else if (name == "tetrahedral") {
    const double c = -1.0 / 3.0, r = std::sqrt(8.0) / 3.0;
    w = {{z, 1.0}, {Vec3(r, 0.0, c), 1.0}, {Vec3(-r / 2.0, r * s3, c), 1.0}, {Vec3(-r / 2.0, -r * s3, c), 1.0}};
  } else if (name == "square") w = {{z, 1.0}, {x, 1.0}, {-z, 1.0}, {-x, 1.0}};
  else if (name == "pyramid") w = {{z, 1.0}, {-z, 1.0}, {x, 1.0}, {-x, 1.0}, {y, 1.0}};
  else if (name == "cube") w = {{z, 1.0}, {-z, 1.0}, {x, 1.0}, {-x, 1.0}, {y, 1.0}, {-y, 1.0}};
  else if (name == "opposite-half") w = {{z, 1.0}, {-z, 0.5}};
  else if (name == "orthogonal-half") w = {{z, 1.0}, {x, 0.5}};
  else if (name.starts_with("random-") && name.size() == 8 && name[7] >= '2' && name[7] <= '6') w = random_walls(name[7] - '0', seed);
  else throw InputError(fmt::format("arrangement '{}' is not allowed; allowed: {}", name, kAllowed));
  return a;
}

std::vector<MultiContactPoint> measure_multi_contact(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                                     const std::vector<ProbeArrangement>& arrangements,
                                                     const std::vector<double>& delta_n,
                                                     const std::function<void(const MultiContactPoint&)>& progress) {
  for (std::size_t k = 0; k < delta_n.size(); ++k)
    if (!(delta_n[k] > 0.0 && delta_n[k] < 1.0) || (k > 0 && !(delta_n[k] > delta_n[k - 1])))
      throw InputError(fmt::format("delta_n: {} (value {}) is not allowed; allowed: increasing values in (0, 1)", delta_n[k], k + 1));
  const Packing packing = generate_packing(s.packing, packing_seed);
  const double Rs = s.packing.Rs;
  const SimulationSettings& sim = s.simulation;
  std::vector<MultiContactPoint> out;
  for (const ProbeArrangement& a : arrangements) {
    SceneDef scene = engine_scene(s);
    for (std::size_t i = 0; i < packing.radii.size(); ++i) {
      ParticleDef p;
      p.x = packing.centres[i], p.r = packing.radii[i], p.body = 0;
      scene.particles.push_back(p);
    }
    scene.shells.push_back(ShellDef{"shell", 0, Vec3::Zero(), Rs, 1, sim.shell_contact_radius, std::nullopt});
    const std::size_t n = a.walls.size();
    for (std::size_t k = 0; k < n; ++k)  // each wall touching the shell from outside, its normal towards the centre
      scene.planes.push_back(PlaneDef{fmt::format("wall{}", k), Rs * a.walls[k].u, -a.walls[k].u, 1});
    Simulation simulation(scene);
    double at = 0.0;
    for (const double dn : delta_n) try {
      bool moved = false;
      for (std::size_t k = 0; k < n; ++k) {
        const double step = a.walls[k].w * (dn - at) * Rs;
        if (!(step > 0.0)) continue;
        simulation.add_driver(MoveWallDef{fmt::format("wall{}", k), -s.normal_speed * a.walls[k].u, step, std::nullopt});
        moved = true;
      }
      if (moved) {
        while (simulation.drivers_moving()) simulation.run_steps(100);
        simulation.release_drivers();
      }
      at = dn;
      relax(simulation, s.relaxation, {}, [&] { return -simulation.plane_loads()[0].force; });
      MultiContactPoint p{a.name, dn, {}, {}};
      for (std::size_t k = 0; k < n; ++k) p.Fn.push_back(simulation.plane_loads()[k].force.dot(a.walls[k].u));
      out.push_back(p);
      if (progress) progress(out.back());
    } catch (const NumericalError& e) {
      out.push_back({a.name, dn, {}, e.what()});
      if (progress) progress(out.back());
      break;
    }
  }
  return out;
}

}  // namespace softpack
