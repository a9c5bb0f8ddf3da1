#include "scene/validate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "core/error.hpp"
#include "scene/bodies.hpp"
#include "scene/limits.hpp"
#include "scene/validate_detail.hpp"

namespace softpack {
namespace {

using limits::number_text;
using validation::check;
using validation::fail;

bool finite(const Vec3& v) { return v.allFinite(); }

// A point: finite, each coordinate within limits::kCoordinate.
void check_point(const std::string& key, const Vec3& x) {
  if (!finite(x)) fail(key, "must be finite");
  for (int k = 0; k < 3; ++k)
    if (!limits::kCoordinate.contains(x[k]))
      fail(key, fmt::format("{} m (its {} coordinate) is not allowed; allowed: {}", number_text(x[k]), "xyz"[k],
                            limits::text(limits::kCoordinate)));
}

// Why a direction (normalised by the engine) is refused, "" when it is not: it must be finite,
// of a length neither 0 nor infinite once squared (the engine's norm); [1e300, 1e300, 0] was
// called non-finite, which none of its numbers is.
std::string direction_refusal(const Vec3& v) {
  if (!v.allFinite()) return "must be a finite, non-zero vector";
  const double n = v.norm();
  if (n == 0.0) return "must be a non-zero vector (its length is 0)";
  if (!std::isfinite(n))
    return fmt::format("[{}, {}, {}] is too long: its length overflows a double; allowed: components of at most 1e150 in "
                       "magnitude (only the direction counts: scale it down)",
                       number_text(v.x()), number_text(v.y()), number_text(v.z()));
  return "";
}

// The contact grid numbers its cells with 21 bits along each axis (neighbor/hierarchical_grid.hpp):
// the spheres, as the grid sees them (centres +- radii), must span fewer than limits::kGridCells
// cells of its finest level, 2 r_min + skin r_min.
void check_grid_span(const SceneDef& s) {
  double r_min = s.particles[0].r;
  Vec3 lo = s.particles[0].x, hi = lo;
  for (const ParticleDef& p : s.particles) {
    r_min = std::min(r_min, p.r);
    lo = lo.cwiseMin(p.x - Vec3::Constant(p.r));
    hi = hi.cwiseMax(p.x + Vec3::Constant(p.r));
  }
  const double cell = 2.0 * r_min + s.neighbor.skin * r_min;
  const Vec3 extent = hi - lo;
  int axis = 0;
  extent.maxCoeff(&axis);
  if (extent[axis] * (1.0 / cell) >= limits::kGridCells)
    fail("particles", fmt::format("the spheres span {} m along {}, {} cells of the contact grid's finest level "
                                  "(2 r_min + skin r_min = {} m); allowed: fewer than {} cells (2^21 - 1), a span below "
                                  "{} m for these radii",
                                  number_text(extent[axis]), "xyz"[axis], number_text(std::floor(extent[axis] / cell)),
                                  number_text(cell), number_text(limits::kGridCells), limits::approx_text(limits::kGridCells * cell)));
}

// Two spheres with the same centre have no contact normal (d / |d| is 0/0): refused here, by
// sorting the centres (O(N log N)), instead of turning into NaN forces at the first step.
void check_distinct_centres(const SceneDef& s) {
  std::vector<std::size_t> order(s.particles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto key = [&](std::size_t i) {
    const Vec3& x = s.particles[i].x;
    return std::array<double, 3>{x.x(), x.y(), x.z()};
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t i = order[k - 1], j = order[k];
    if (key(i) == key(j)) {
      const Vec3& x = s.particles[i].x;
      fail(fmt::format("particles[{}]", std::max(i, j)),
           fmt::format("its centre [{}, {}, {}] m is that of particles[{}]; spheres with coincident centres have no "
                       "contact normal (move one of them)",
                       x.x(), x.y(), x.z(), std::min(i, j)));
    }
  }
}

void check_materials(const SceneDef& s) {
  if (s.materials.empty()) fail("materials", "at least one material is required");
  std::set<std::string> names;
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    const Material& m = s.materials[k];
    const std::string key = fmt::format("materials.{}", m.name.empty() ? std::to_string(k) : m.name);
    if (!names.insert(m.name).second) fail(key, "material defined twice");
    validate_material(m, key);
  }
}

void check_material_ref(const SceneDef& s, int m, const std::string& key) {
  if (m < 0 || m >= static_cast<int>(s.materials.size()))
    fail(key, fmt::format("material index {} does not exist ({} materials)", m, s.materials.size()));
}

std::set<int> bodies_of(const SceneDef& s) {
  std::set<int> b;
  for (const auto& p : s.particles)
    if (p.body != kNoBody) b.insert(p.body);
  return b;
}

std::string list_bodies(const std::set<int>& bodies) {
  if (bodies.empty()) return "no sphere belongs to a body";
  std::string out = "bodies present:";
  for (int b : bodies) out += fmt::format(" {}", b);
  return out;
}

void check_group(const SceneDef& s, const GroupDef& g, const std::string& key) {
  if (g.kind == GroupDef::Kind::all) return;
  const auto bodies = bodies_of(s);
  if (!bodies.contains(g.body))
    fail(key + ".body", fmt::format("body {} does not exist ({})", g.body, list_bodies(bodies)));
}

// Bodies inside bodies (scene/bodies.hpp): a parent is another shell's body, no body encloses
// itself, and a shell and every sphere of the bodies inside it lie within each enclosing shell.
void check_shell_parents(const SceneDef& s) {
  if (std::none_of(s.shells.begin(), s.shells.end(), [](const ShellDef& sh) { return sh.parent != kNoBody; })) return;
  std::map<int, std::size_t> shell_of;
  for (std::size_t k = 0; k < s.shells.size(); ++k) shell_of.emplace(s.shells[k].body, k);
  for (std::size_t k = 0; k < s.shells.size(); ++k) {
    const ShellDef& sh = s.shells[k];
    if (sh.parent == kNoBody) continue;
    const std::string key = fmt::format("shells[{}].parent", k);
    const auto up = shell_of.find(sh.parent);
    if (sh.parent == sh.body || up == shell_of.end())
      fail(key, fmt::format("{} is not allowed; allowed: the body of another shell, whose shell encloses this one", sh.parent));
    std::set<int> seen{sh.body};
    for (int b = sh.parent; b != kNoBody; b = s.shells[shell_of.at(b)].parent)
      if (!seen.insert(b).second || !shell_of.contains(b)) fail(key, fmt::format("body {} encloses itself through its parents", sh.body));
    const ShellDef& outer = s.shells[up->second];
    if ((sh.centre - outer.centre).norm() >= outer.radius)
      fail(fmt::format("shells[{}].centre", k), fmt::format("lies outside shell '{}' of its parent body {}", outer.name, sh.parent));
  }
  std::vector<int> bodies;
  for (const ParticleDef& p : s.particles) bodies.push_back(p.body);
  const auto members = shell_members(s.shells, bodies);
  for (std::size_t k = 0; k < s.shells.size(); ++k)
    for (int i : members[k])
      if ((s.particles[static_cast<std::size_t>(i)].x - s.shells[k].centre).norm() >= s.shells[k].radius)
        fail(fmt::format("particles[{}]", i), fmt::format("its centre lies outside shell '{}', which encloses its body {}", s.shells[k].name,
                                                        s.particles[static_cast<std::size_t>(i)].body));
}

bool wall_exists(const SceneDef& s, const std::string& name) {
  for (const auto& p : s.planes)
    if (p.name == name) return true;
  for (const auto& sh : s.shells)
    if (sh.name == name) return true;
  return false;
}

void check_stop(const std::optional<double>& a, const char* a_name, const std::optional<double>& b,
                const char* b_name, const std::string& key) {
  if (a && b) fail(key, fmt::format("give '{}' or '{}', not both", a_name, b_name));
  if (!a && !b) fail(key, fmt::format("one of '{}' or '{}' is required", a_name, b_name));
  const double v = a ? *a : *b;
  if (!(v > 0.0 && std::isfinite(v)))
    fail(key + "." + (a ? a_name : b_name), fmt::format("{} is not allowed; allowed: > 0", v));
}

void check_drivers(const SceneDef& s, const std::vector<DriverDef>& drivers) {
  std::set<int> driven_bodies;
  bool all_driven = false;
  std::set<std::string> driven_walls;
  auto claim = [&](const GroupDef& g, const std::string& key) {
    const bool clash = all_driven || (g.kind == GroupDef::Kind::all && !driven_bodies.empty()) ||
                       (g.kind == GroupDef::Kind::body && driven_bodies.contains(g.body));
    if (clash) fail(key, "these spheres are already moved by an earlier driver");
    if (g.kind == GroupDef::Kind::all) all_driven = true;
    else driven_bodies.insert(g.body);
  };
  for (std::size_t k = 0; k < drivers.size(); ++k) {
    const std::string key = fmt::format("drivers[{}]", k);
    std::visit(
        [&](const auto& d) {
          using D = std::decay_t<decltype(d)>;
          if constexpr (std::is_same_v<D, MoveWallDef>) {
            if (!wall_exists(s, d.wall))
              fail(key + ".wall", fmt::format("no plane or shell is named '{}'", d.wall));
            for (const auto& sh : s.shells)
              if (sh.name == d.wall && sh.mass)
                fail(key + ".wall", fmt::format("shell '{}' is free (it has a mass): it moves under its grains' load, not a driver", d.wall));
            if (!driven_walls.insert(d.wall).second)
              fail(key + ".wall", fmt::format("wall '{}' is already moved by an earlier driver", d.wall));
            if (!finite(d.velocity) || d.velocity.norm() == 0.0)
              fail(key + ".velocity", "must be a finite, non-zero vector");
            check(key + ".velocity", d.velocity.stableNorm(), limits::kDriveSpeed);
            check_stop(d.distance, "distance", d.duration, "duration", key);
          } else if constexpr (std::is_same_v<D, RotateGroupDef>) {
            check_group(s, d.group, key + ".group");
            claim(d.group, key + ".group");
            if (const std::string why = direction_refusal(d.axis); !why.empty()) fail(key + ".axis", why);
            check_point(key + ".centre", d.centre);
            if (!(std::isfinite(d.rate) && d.rate != 0.0)) fail(key + ".rate", "must be finite and non-zero");
            check(key + ".rate", std::abs(d.rate), limits::kRate);
            check_stop(d.angle, "angle", d.duration, "duration", key);
            if (d.with_shell) {
              const ShellDef* shell = nullptr;
              for (const auto& sh : s.shells)
                if (d.group.kind == GroupDef::Kind::body && sh.body == d.group.body) shell = &sh;
              if (!shell) fail(key + ".with_shell", "needs a group that is a body with a shell");
              if (shell->mass) fail(key + ".with_shell", fmt::format("shell '{}' is free (it has a mass): a driver cannot turn it", shell->name));
            }
          } else if constexpr (std::is_same_v<D, TranslateGroupDef>) {
            check_group(s, d.group, key + ".group");
            claim(d.group, key + ".group");
            if (!finite(d.velocity) || d.velocity.norm() == 0.0)
              fail(key + ".velocity", "must be a finite, non-zero vector");
            check(key + ".velocity", d.velocity.stableNorm(), limits::kDriveSpeed);
            check_stop(d.distance, "distance", d.duration, "duration", key);
          } else {
            check_group(s, d.group, key + ".group");
            claim(d.group, key + ".group");
          }
        },
        drivers[k]);
  }
}

}  // namespace

void validate(const SceneDef& s, SoftLaws laws) {
  check_materials(s);
  if (s.particles.empty()) fail("particles", "the scene has no spheres");
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const auto& p = s.particles[i];
    const std::string key = fmt::format("particles[{}]", i);
    check(key + ".r", p.r, limits::kRadius);
    if (!finite(p.x) || !finite(p.v) || !finite(p.w)) fail(key, "position and velocities must be finite");
    check_point(key + ".x", p.x);
    check(key + ".v", p.v.stableNorm(), limits::kSpeed);
    check(key + ".w", p.w.stableNorm() * p.r, limits::kSurfaceSpeed);
    if (p.spin_locked && !s.effects.rotation) fail(key + ".rotation", "locked needs effects.rotation (without it no sphere spins)");
    if (p.spin_locked && p.w != Vec3::Zero()) fail(key + ".w", "a sphere whose rotation is locked cannot spin: remove w or rotation: locked");
    if (p.body < kNoBody) fail(key + ".body", fmt::format("{} is not allowed; allowed: a body id >= 0, or none", p.body));
    check_material_ref(s, p.material, key + ".material");
  }
  check_distinct_centres(s);

  validate_effects(s.effects, s.materials);
  validate_soft_particles(s, laws);

  std::set<std::string> wall_names;
  std::set<int> shell_bodies;
  for (std::size_t k = 0; k < s.planes.size(); ++k) {
    const auto& pl = s.planes[k];
    const std::string key = fmt::format("planes[{}]", k);
    if (pl.name.empty() || !wall_names.insert(pl.name).second) fail(key + ".name", fmt::format("'{}' is empty or not unique", pl.name));
    check_point(key + ".point", pl.point);
    if (const std::string why = direction_refusal(pl.normal); !why.empty()) fail(key + ".normal", why);
    check_material_ref(s, pl.material, key + ".material");
  }
  for (std::size_t k = 0; k < s.shells.size(); ++k) {
    const auto& sh = s.shells[k];
    const std::string key = fmt::format("shells[{}]", k);
    if (sh.name.empty() || !wall_names.insert(sh.name).second) fail(key + ".name", fmt::format("'{}' is empty or not unique", sh.name));
    check(key + ".radius", sh.radius, limits::kShellRadius);
    if (sh.mass) check(key + ".mass", *sh.mass, limits::kMass);
    if (sh.body < 0) fail(key + ".body", "a shell confines the spheres of one body: give a body id >= 0");
    if (!shell_bodies.insert(sh.body).second) fail(key + ".body", fmt::format("body {} already has a shell", sh.body));
    check_point(key + ".centre", sh.centre);
    check_material_ref(s, sh.material, key + ".material");
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const auto& p = s.particles[i];
      if (p.body != sh.body) continue;
      if ((p.x - sh.centre).norm() >= sh.radius)
        fail(fmt::format("particles[{}]", i), fmt::format("its centre lies outside shell '{}' of its body {}", sh.name, sh.body));
      if (p.r >= sh.radius) fail(fmt::format("particles[{}].r", i), fmt::format("not smaller than the radius of shell '{}'", sh.name));
    }
  }
  check_shell_parents(s);

  validate_integration(s.integration);
  validate_neighbor(s.neighbor);
  if (!s.effects.normal.empty()) check_grid_span(s);  // the grid is built for the contact law only
  check_drivers(s, s.drivers);

  validate_watchdog(s.watchdog);
}

void validate_material(const Material& m, const std::string& key) {
  check(key + ".E", m.E, limits::kModulus);
  check(key + ".nu", m.nu, limits::kPoisson);
  check(key + ".mu", m.mu, limits::kFriction);
  check(key + ".density", m.density, limits::kDensity);
}

void validate_effects(const EffectsDef& e, const std::vector<Material>& materials, const std::string& key) {
  if (e.friction && e.normal.empty()) fail(key + ".friction", "friction needs the normal law (declare effects.normal)");
  if (e.damping() && e.normal.empty()) fail(key + ".damping", "damping needs the normal law (declare effects.normal)");
  if (e.rotation && !e.friction)
    fail(key + ".rotation", "rotation without friction: nothing produces a torque (declare effects.friction or drop rotation)");
  if (e.friction) {
    bool any_mu = false;
    for (const auto& m : materials) any_mu = any_mu || m.mu > 0.0;
    if (!any_mu) fail(key + ".friction", "friction declared but every material has mu = 0");
  }
  if (e.damping()) check(key + ".damping.restitution", *e.restitution, limits::kRestitution);
  check(key + ".damping.tangential_ratio", e.tangential_damping_ratio, limits::kTangentialRatio);
  if (e.gravity && !finite(*e.gravity)) fail(key + ".gravity", "must be finite");
  if (e.gravity) check(key + ".gravity", e.gravity->stableNorm(), limits::kGravity);
}

void validate_integration(const IntegrationDef& in, const std::string& key) {
  if (in.dt && in.safety) fail(key, "give 'dt' or 'safety', not both");
  if (!in.dt && !in.safety) fail(key, "one of 'dt' or 'safety' is required");
  // dt <= the stable limit: integrate/time_step.cpp; the steps it makes of a duration: validate_steps().
  if (in.dt && !(*in.dt > 0.0 && std::isfinite(*in.dt))) fail(key + ".dt", fmt::format("{} s is not allowed; allowed: dt > 0", *in.dt));
  if (in.safety) check(key + ".safety", *in.safety, limits::kSafety);
}

void validate_neighbor(const NeighborDef& nb, const std::string& key) {
  check(key + ".skin", nb.skin, limits::kSkin);  // a fraction of the smallest radius
  check(key + ".level_ratio", nb.level_ratio, limits::kLevelRatio);
}

void validate_watchdog(const WatchdogDef& wd, const std::string& key) {
  if (!(wd.max_overlap_fraction > 0.0))
    fail(key + ".max_overlap_fraction",
         fmt::format("{} is not allowed; allowed: > 0 (overlap / smaller radius)", wd.max_overlap_fraction));
  if (!(wd.energy_growth > 1.0))
    fail(key + ".energy_growth", fmt::format("{} is not allowed; allowed: > 1", wd.energy_growth));
  check(key + ".check_interval", static_cast<double>(wd.check_interval), limits::kCheckInterval);
}

void validate_drivers(const SceneDef& scene, const std::vector<DriverDef>& drivers) { check_drivers(scene, drivers); }

void validate_steps(double seconds, double dt, const std::string& key, const std::string& what) {
  const double steps = seconds / dt;
  if (steps <= limits::kMaxSteps) return;
  fail(key, fmt::format("{} is {} time steps of dt = {} s; allowed: at most {} steps ({} s of simulated time)",
                        what.empty() ? number_text(seconds) + " s" : what, limits::approx_text(steps),
                        limits::approx_text(dt), number_text(limits::kMaxSteps), limits::approx_text(limits::kMaxSteps * dt)));
}

void validate_steps(const DriverDef& driver, double dt, const std::string& key) {
  std::visit(
      [&](const auto& d) {
        using D = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<D, MoveWallDef> || std::is_same_v<D, TranslateGroupDef>) {
          const double speed = d.velocity.norm();
          if (!(speed > 0.0)) return;  // validate_drivers() refuses it
          if (d.distance)
            validate_steps(*d.distance / speed, dt, key + ".distance",
                           fmt::format("{} m at {} m/s", number_text(*d.distance), number_text(speed)));
          else
            validate_steps(*d.duration, dt, key + ".duration");
        } else if constexpr (std::is_same_v<D, RotateGroupDef>) {
          const double rate = std::abs(d.rate);
          if (!(rate > 0.0)) return;  // validate_drivers() refuses it
          if (!(rate * dt <= limits::kMaxRotationPerStep))
            fail(key + ".rate", fmt::format("{} rad/s turns the group by {} rad in a time step of dt = {} s; allowed: at most "
                                            "{} rad per step (|rate| <= {} rad/s)",
                                            number_text(d.rate), limits::approx_text(rate * dt), limits::approx_text(dt),
                                            number_text(limits::kMaxRotationPerStep),
                                            limits::approx_text(limits::kMaxRotationPerStep / dt)));
          if (d.angle)
            validate_steps(*d.angle / rate, dt, key + ".angle",
                           fmt::format("{} rad at {} rad/s", number_text(*d.angle), number_text(rate)));
          else
            validate_steps(*d.duration, dt, key + ".duration");
        }
      },
      driver);
}

int SceneDef::material_index(const std::string& name) const {
  for (std::size_t k = 0; k < materials.size(); ++k)
    if (materials[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace softpack
