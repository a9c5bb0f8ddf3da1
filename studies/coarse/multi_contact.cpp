#include "coarse/multi_contact.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "coarse/medium.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "packing/generator.hpp"
#include "relax/relaxation.hpp"

namespace softpack {
namespace {

constexpr const char* kAllowed = "one, opposite, orthogonal, triangle, tetrahedral, square, pyramid, cube, opposite-half, orthogonal-half, random-N (N = 2 to 12)";

// random-N: N unit vectors, uniform on the sphere, each at least 60 degrees from the others (40
// above six: twelve caps of 60 degrees leave no room to draw them at random)
// (drawn one after the other, all again after 1 000 refusals of one), turned so that the first is +z.
std::vector<ProbeWall> random_walls(int n, std::uint64_t seed) {
  Random rng(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(n));
  const double cos_min = std::cos(std::numbers::pi / (n <= 6 ? 3.0 : 4.5));
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

// N of "random-N" (2 <= N <= 12, no leading zero), else 0.
int random_count(const std::string& name) {
  if (!name.starts_with("random-") || name.size() < 8 || name.size() > 9 || name[7] == '0') return 0;
  int n = 0;
  for (std::size_t i = 7; i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9') return 0;
    n = 10 * n + (name[i] - '0');
  }
  return n >= 2 && n <= 12 ? n : 0;
}

}  // namespace

std::string PressingBody::name() const {
  const std::string confined = walls_at > 0.0 ? fmt::format("+walls-{}", walls_at) : "";
  if (kind == Kind::grain) return fmt::format("grain-{}", radius_ratio) + confined;
  return (kind == Kind::soft ? "soft" : "wall") + confined;
}

PressingBody parse_pressing_body(const std::string& full_name) {
  const std::size_t plus = full_name.find("+walls-");
  const std::string name = full_name.substr(0, plus);
  if (plus != std::string::npos) {
    std::size_t used = 0;
    double d = 0.0;
    try {
      d = std::stod(full_name.substr(plus + 7), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != full_name.size() - plus - 7 || !(d > 0.0 && d <= 0.5))
      throw InputError(fmt::format("pressing body '{}' is not allowed; allowed: wall, soft or grain-X followed by +walls-D, D in (0, 0.5] "
                                   "(the other contacts' walls' Δn)",
                                   full_name));
    PressingBody b = parse_pressing_body(name);
    b.walls_at = d;
    return b;
  }
  if (name == "wall") return {};
  if (name == "soft") return {PressingBody::Kind::soft, 1.0};
  if (name.starts_with("grain-")) {
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(name.substr(6), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == name.size() - 6 && x >= 0.05 && x <= 20.0) return {PressingBody::Kind::grain, x};
  }
  throw InputError(fmt::format("pressing body '{}' is not allowed; allowed: wall, soft, grain-X (X: the grain's radius over Rs, 0.05 to 20)", name));
}

ProbeArrangement builtin_arrangement(const std::string& full_name, std::uint64_t seed) {
  const Vec3 z = Vec3::UnitZ(), x = Vec3::UnitX(), y = Vec3::UnitY();
  const double s3 = std::sqrt(3.0) / 2.0;
  const std::size_t colon = full_name.find(':');
  const std::string name = full_name.substr(0, colon);
  ProbeArrangement a{full_name, {}, colon == std::string::npos ? PressingBody{} : parse_pressing_body(full_name.substr(colon + 1))};
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
  else if (const int n = random_count(name); n > 0) w = random_walls(n, seed);
  else throw InputError(fmt::format("arrangement '{}' is not allowed; allowed: {}, each alone or as NAME:BODY (BODY: wall, soft, grain-X)", full_name, kAllowed));
  if (a.body.walls_at > 0.0 && w.size() < 2)
    throw InputError(fmt::format("arrangement '{}' is not allowed: +walls-D needs walls besides the first contact (two contacts or more)", full_name));
  // A plane is unbounded: a confining wall nearer than 90 degrees to the first contact would cut
  // the body pressing there (a soft-particle or grain standing outside the shell along +z).
  if (a.body.walls_at > 0.0 && random_count(name) > 0)
    throw InputError(fmt::format("arrangement '{}' is not allowed: random-N draws its walls 60 (or 40) degrees apart, so a confining wall may "
                                 "cut the body pressing at the first contact; +walls-D needs every wall at 90 degrees or more from it",
                                 full_name));
  for (std::size_t k = 1; a.body.walls_at > 0.0 && k < w.size(); ++k)
    if (w[k].u.dot(w[0].u) > 1e-12)
      throw InputError(fmt::format("arrangement '{}' is not allowed: its wall {} stands less than 90 degrees from the first contact and would cut "
                                   "the body pressing there",
                                   full_name, k + 1));
  return a;
}

namespace {

void check_increasing(const std::vector<double>& v, const char* key, double hi) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!(v[k] > 0.0 && v[k] < hi) || (k > 0 && !(v[k] > v[k - 1])))
      throw InputError(fmt::format("{}: {} (value {}) is not allowed; allowed: increasing values in (0, {})", key, v[k], k + 1, hi));
}

// One arrangement's scene: the soft-particle (body 0, its shell "shell") and contact k's body
// (k + 1): a plane "wallK", a held grain, or a soft-particle in its shell "softK".
class Probe {
 public:
  Probe(const CoarseGrainSettings& s, const Packing& packing, std::uint64_t packing_seed, const ProbeArrangement& a)
      : s_(s), a_(a), Rs_(s.packing.Rs), simulation_(scene(s, packing, packing_seed, a)) {}

  Simulation& simulation() { return simulation_; }

  // Moves contact k in by w_k (to - from) Rs, all at once, at the approach speed; grains are held
  // where they arrive, walls and shells stand. With walls_at, only the first contact moves (the
  // others are confine()'s).
  void press(double from, double to) { move(from, to, false); }
  // With walls_at: the walls of the contacts but the first moved in to Δn = walls_at, relaxed.
  void confine() {
    if (!(a_.body.walls_at > 0.0)) return;
    move(0.0, a_.body.walls_at, true);
    relax_here(1);  // settled on a confining wall's force (the first contact's is still 0)
  }
  // The force on contact k's body along u_k.
  double Fn(std::size_t k) const { return load(k).dot(a_.walls[k].u); }
  Vec3 load(std::size_t k) const {
    if (a_.body.kind_at(k) == PressingBody::Kind::grain) return simulation_.force_between(0, static_cast<int>(k) + 1);
    return simulation_.wall_load(body_name(k)).force;  // its plane or its soft-particle's shell
  }
  void relax_here(std::size_t k = 0) { relax(simulation_, s_.relaxation, {}, [&] { return Vec3(-load(k)); }); }

 private:
  // Moves the contacts by w_k (to - from) Rs: the first one's body (confining: the others').
  void move(double from, double to, bool confining) {
    simulation_.release_drivers();
    bool moved = false;
    for (std::size_t k = 0; k < a_.walls.size(); ++k) {
      if (a_.body.walls_at > 0.0 && (k == 0) == confining) continue;
      const double step = a_.walls[k].w * (to - from) * Rs_;
      if (!(step > 0.0)) continue;
      const Vec3 v = -s_.normal_speed * a_.walls[k].u;
      const int body = static_cast<int>(k) + 1;
      const PressingBody::Kind kind = a_.body.kind_at(k);
      if (kind != PressingBody::Kind::grain) simulation_.add_driver(MoveWallDef{body_name(k), v, step, std::nullopt});
      if (kind != PressingBody::Kind::wall)
        simulation_.add_driver(TranslateGroupDef{GroupDef{GroupDef::Kind::body, body}, v, step, std::nullopt,
                                                 kind == PressingBody::Kind::grain ? AfterDrive::hold : AfterDrive::release});
      moved = true;
    }
    while (moved && simulation_.drivers_moving()) simulation_.run_steps(100);
  }
  std::string body_name(std::size_t k) const { return body_name(a_.body, k); }
  // The plane or shell of contact k (none for a grain, which is its body k + 1).
  static std::string body_name(const PressingBody& b, std::size_t k) { return (b.kind_at(k) == PressingBody::Kind::soft ? "soft" : "wall") + std::to_string(k); }
  static void add_packing(SceneDef& scene, const Packing& p, const Vec3& at, int body) {
    for (std::size_t i = 0; i < p.radii.size(); ++i) {
      ParticleDef d;
      d.x = at + p.centres[i], d.r = p.radii[i], d.body = body;
      scene.particles.push_back(d);
    }
  }
  static SceneDef scene(const CoarseGrainSettings& s, const Packing& packing, std::uint64_t seed, const ProbeArrangement& a) {
    const double Rs = s.packing.Rs;
    const ShellContactRadius contact = s.simulation.shell_contact_radius;
    SceneDef scene = engine_scene(s);
    add_packing(scene, packing, Vec3::Zero(), 0);
    scene.shells.push_back(ShellDef{"shell", 0, Vec3::Zero(), Rs, 1, contact, std::nullopt});
    for (std::size_t k = 0; k < a.walls.size(); ++k) {  // each touching the shell from outside
      const Vec3 u = a.walls[k].u;
      const int body = static_cast<int>(k) + 1;
      if (a.body.kind_at(k) == PressingBody::Kind::wall) {
        scene.planes.push_back(PlaneDef{body_name(a.body, k), Rs * u, -u, 1});
      } else if (a.body.kind_at(k) == PressingBody::Kind::grain) {
        ParticleDef g;
        g.x = (1.0 + a.body.radius_ratio) * Rs * u, g.r = a.body.radius_ratio * Rs, g.body = body;
        scene.particles.push_back(g);
      } else {
        add_packing(scene, generate_packing(s.packing, 1000 * seed + k), 2.0 * Rs * u, body);
        scene.shells.push_back(ShellDef{body_name(a.body, k), body, 2.0 * Rs * u, Rs, 1, contact, std::nullopt});
      }
    }
    return scene;
  }
  const CoarseGrainSettings& s_;
  const ProbeArrangement& a_;
  double Rs_;
  Simulation simulation_;
};

}  // namespace

std::vector<MultiContactPoint> measure_multi_contact(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                                     const std::vector<ProbeArrangement>& arrangements,
                                                     const std::vector<double>& delta_n,
                                                     const std::function<void(const MultiContactPoint&)>& progress) {
  check_increasing(delta_n, "delta_n", 1.0);
  const Packing packing = generate_packing(s.packing, packing_seed);
  std::vector<MultiContactPoint> out;
  for (const ProbeArrangement& a : arrangements) {
    Probe probe(s, packing, packing_seed, a);
    try {
      probe.confine();
    } catch (const NumericalError& e) {
      out.push_back({a.name, delta_n.front(), {}, fmt::format("confining walls: {}", e.what())});
      if (progress) progress(out.back());
      continue;
    }
    double at = 0.0;
    for (const double dn : delta_n) try {
      probe.press(at, dn);
      at = dn;
      probe.relax_here();
      MultiContactPoint p{a.name, dn, {}, {}};
      for (std::size_t k = 0; k < a.walls.size(); ++k) p.Fn.push_back(probe.Fn(k));
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

std::vector<ShearPoint> measure_confined_shear(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                               const std::vector<ProbeArrangement>& arrangements, const std::vector<double>& delta_n,
                                               const std::vector<double>& ht_over_Rs, const std::function<void(const ShearPoint&)>& progress) {
  check_increasing(delta_n, "delta_n", 1.0);
  check_increasing(ht_over_Rs, "ht_over_Rs", 1.0);
  const Packing packing = generate_packing(s.packing, packing_seed);
  std::vector<ShearPoint> out;
  const auto record = [&](ShearPoint p) {
    out.push_back(std::move(p));
    if (progress) progress(out.back());
  };
  for (const ProbeArrangement& a : arrangements) {
    if (a.body.kind != PressingBody::Kind::wall) throw InputError(fmt::format("confined shear: arrangement '{}' is not allowed; allowed: walls only", a.name));
    Probe probe(s, packing, packing_seed, a);
    Simulation& sim = probe.simulation();
    double at = 0.0;
    for (const double dn : delta_n) {
      try {
        probe.press(at, dn);
        at = dn;
        probe.relax_here();
      } catch (const NumericalError& e) {
        record({a.name, dn, 0.0, 0.0, 0.0, e.what()});
        break;
      }
      const auto point = [&](double ht) {
        const Vec3 F = probe.load(0);
        return ShearPoint{a.name, dn, ht, F.z(), -F.x(), {}};
      };
      record(point(0.0));
      const SimulationState pressed = sim.state();
      double slid = 0.0;
      for (const double ht : ht_over_Rs) try {
        sim.release_drivers();
        sim.add_driver(MoveWallDef{"wall0", s.normal_speed * Vec3::UnitX(), (ht - slid) * s.packing.Rs, std::nullopt});
        while (sim.drivers_moving()) sim.run_steps(100);
        slid = ht;
        probe.relax_here();
        record(point(ht));
      } catch (const NumericalError& e) {
        record({a.name, dn, ht, 0.0, 0.0, e.what()});
        break;
      }
      sim.release_drivers();
      sim.restore(pressed);
    }
  }
  return out;
}

void write_multi_contact(const std::string& out, const std::string& source, std::uint64_t seed, const std::vector<ProbeArrangement>& arrangements,
                         const std::vector<MultiContactPoint>& points, double cpu_seconds, const std::string& stamp) {
  std::string text = stamp + fmt::format(
      "# softpack-coarse multi-contact: {}, packing seed {}, {}, {:.1f} CPU-s\n"
      "# one block per arrangement; wall k along u_k (from the centre), moved in by w_k delta_n Rs\n"
      "# walls delta_n Fn_1 ... Fn_walls [N]\n",
      source, seed, code_version(), cpu_seconds);
  for (const ProbeArrangement& a : arrangements) {
    text += fmt::format("\n# arrangement {}:", a.name);
    for (const ProbeWall& w : a.walls) text += fmt::format(" u=({:.6f} {:.6f} {:.6f}) w={}", w.u.x() + 0.0, w.u.y() + 0.0, w.u.z() + 0.0, w.w);  // + 0.0: no -0
    text += "\n";
    for (const MultiContactPoint& p : points) {
      if (p.arrangement != a.name) continue;
      if (!p.failed.empty()) {
        text += fmt::format("# delta_n {:.4f} not measured (nor the larger): {}\n", p.delta_n, p.failed);
        continue;
      }
      text += fmt::format("{} {:.4f}", p.Fn.size(), p.delta_n);
      for (const double F : p.Fn) text += fmt::format(" {:.6e}", F + 0.0);
      text += "\n";
    }
  }
  write_file_atomically(out, text);
}

void write_confined_shear(const std::string& out, const std::string& source, std::uint64_t seed, const std::vector<ShearPoint>& sheared, double cpu_seconds,
                          const std::string& stamp) {
  std::string text = stamp + fmt::format(
      "# softpack-coarse multi-contact: {}, packing seed {}, {}, {:.1f} CPU-s\n"
      "# the confined shear: the first wall (+z) slid along +x by ht, each from the previous; Fn along +z, Ft along -x, on it\n"
      "# arrangement delta_n ht/Rs Fn Ft [N]\n",
      source, seed, code_version(), cpu_seconds);
  for (const ShearPoint& p : sheared) {
    if (!p.failed.empty()) text += fmt::format("# {} {:.4f} {} not measured (nor the larger ht): {}\n", p.arrangement, p.delta_n, p.ht, p.failed);
    else text += fmt::format("{} {:.4f} {} {:.6e} {:.6e}\n", p.arrangement, p.delta_n, p.ht, p.Fn + 0.0, p.Ft + 0.0);
  }
  write_file_atomically(out, text);
}

}  // namespace softpack
