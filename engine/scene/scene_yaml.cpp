#include "scene/scene_yaml.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.hpp"
#include "scene/validate.hpp"

namespace softpack {
namespace {

int material_ref(const SceneDef& s, const ConfigNode& n) {
  const std::string name = n.string();
  const int k = s.material_index(name);
  if (k < 0) {
    std::vector<std::string> names;
    for (const auto& m : s.materials) names.push_back(m.name);
    n.choice(names);  // fails with the list of materials and a suggestion
  }
  return k;
}

int body_id(const ConfigNode& n) {
  const long b = n.integer();
  if (b < 0) n.fail("allowed: a body id >= 0");
  return static_cast<int>(b);
}

GroupDef parse_group(const ConfigNode& n) {
  GroupDef g;
  if (n.yaml().IsScalar()) {
    n.choice({"all"});
    return g;
  }
  n.allow_only({"body"});
  g.kind = GroupDef::Kind::body;
  g.body = body_id(n.at("body"));
  return g;
}

AfterDrive parse_after(const ConfigNode& d) {
  if (!d.has("after")) d.fail("missing required key 'after' (release or hold)");
  return d.at("after").choice({"release", "hold"}) == "hold" ? AfterDrive::hold : AfterDrive::release;
}

std::optional<double> optional_number(const ConfigNode& n, const std::string& key) {
  if (auto c = n.find(key)) return c->number();
  return std::nullopt;
}

DriverDef parse_driver(const ConfigNode& d) {
  const std::string type = d.at("type").choice({"move_wall", "rotate", "translate", "hold"});
  if (type == "move_wall") {
    d.allow_only({"type", "wall", "velocity", "distance", "duration"});
    MoveWallDef m;
    m.wall = d.at("wall").string();
    m.velocity = d.at("velocity").vec3();
    m.distance = optional_number(d, "distance");
    m.duration = optional_number(d, "duration");
    return m;
  }
  if (type == "rotate") {
    d.allow_only({"type", "group", "centre", "axis", "rate", "angle", "duration", "after", "with_shell"});
    RotateGroupDef r;
    r.group = parse_group(d.at("group"));
    r.centre = d.at("centre").vec3();
    r.axis = d.at("axis").vec3();
    r.rate = d.at("rate").number();
    r.angle = optional_number(d, "angle");
    r.duration = optional_number(d, "duration");
    r.after = parse_after(d);
    if (auto c = d.find("with_shell")) r.with_shell = c->boolean();
    return r;
  }
  if (type == "translate") {
    d.allow_only({"type", "group", "velocity", "distance", "duration", "after"});
    TranslateGroupDef t;
    t.group = parse_group(d.at("group"));
    t.velocity = d.at("velocity").vec3();
    t.distance = optional_number(d, "distance");
    t.duration = optional_number(d, "duration");
    t.after = parse_after(d);
    return t;
  }
  d.allow_only({"type", "group"});
  return HoldGroupDef{parse_group(d.at("group"))};
}

// effects.soft_particles of a scene file: the law file, a relative path taken from the scene file's
// folder (a scene travels with its laws, as a profile with its packings: packing/import.cpp), and
// the rules of contact/soft_particle_law.hpp. The engine reads no JSON: `laws` stay empty until
// the program reads the file (formats/scene_laws.hpp load_scene_laws).
SoftParticlesDef parse_soft_particles(const ConfigNode& n) {
  n.allow_only({"laws", "grain_contact", "beyond_range"});
  SoftParticlesDef d;
  const ConfigNode laws = n.at("laws");
  std::filesystem::path path = laws.string();
  if (path.empty()) laws.fail("'' is not allowed; allowed: the path of a law file (JSON, \"format\": \"softpack-laws\")");
  if (path.is_relative() && std::filesystem::is_regular_file(laws.file()))
    path = (std::filesystem::path(laws.file()).parent_path() / path).lexically_normal();
  d.law_file = path.string();
  if (auto c = n.find("grain_contact"))
    d.grain_contact = c->choice({"wall", "reduced-radius"}) == "wall" ? GrainContactRule::wall : GrainContactRule::reduced_radius;
  if (auto c = n.find("beyond_range"))
    d.beyond_range = c->choice({"report", "stop"}) == "stop" ? SoftParticlesDef::BeyondRange::stop
                                                             : SoftParticlesDef::BeyondRange::report;
  return d;
}

// An int: the integer the file gives must fit one (the range of the value is validate()'s).
int int_of(const ConfigNode& n) {
  const long v = n.integer();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    n.fail(fmt::format("{} is too large; expected an integer of at most {} in magnitude", v, std::numeric_limits<int>::max()));
  return static_cast<int>(v);
}

}  // namespace

Material parse_material(const ConfigNode& m, const std::string& name, const std::vector<std::string>& also) {
  std::vector<std::string> keys{"E", "nu", "mu", "density"};
  keys.insert(keys.end(), also.begin(), also.end());
  m.allow_only(keys);
  return Material{name, m.at("E").number(), m.at("nu").number(), m.at("mu").number(), m.at("density").number()};
}

EffectsDef parse_effects(const ConfigNode& n, const std::vector<std::string>& also) {
  EffectsDef e;
  std::vector<std::string> keys{"normal", "friction", "rotation", "damping", "gravity"};
  keys.insert(keys.end(), also.begin(), also.end());
  n.allow_only(keys);
  if (auto c = n.find("normal")) e.normal = c->string();  // a registered law: checked when the simulation is built
  if (auto c = n.find("friction")) e.friction = c->choice({"tsuji"}) == "tsuji";
  if (auto c = n.find("rotation")) e.rotation = c->boolean();
  if (auto c = n.find("damping")) {
    c->allow_only({"restitution", "tangential_ratio"});
    e.restitution = c->at("restitution").number();
    e.tangential_damping_ratio = c->at("tangential_ratio").number();
  }
  if (auto c = n.find("gravity")) e.gravity = c->vec3();
  return e;
}

IntegrationDef parse_integration(const ConfigNode& in) {
  IntegrationDef d;
  in.allow_only({"dt", "safety", "tangential_history"});
  if (auto c = in.find("dt")) d.dt = c->number();
  if (auto c = in.find("safety")) d.safety = c->number();
  d.history_update = in.at("tangential_history").choice({"synchronized", "standard"}) == "synchronized" ? HistoryUpdate::synchronized
                                                                                                        : HistoryUpdate::standard;
  return d;
}

NeighborDef parse_neighbor(const ConfigNode& nb) {
  nb.allow_only({"skin", "level_ratio"});
  return NeighborDef{nb.at("skin").number(), nb.at("level_ratio").number()};
}

ShellContactRadius parse_contact_radius(const ConfigNode& n) {
  return n.choice({"concave", "particle"}) == "concave" ? ShellContactRadius::concave : ShellContactRadius::particle;
}

ActiveSetDef parse_active_set(const ConfigNode& n) {
  n.allow_only({"sleep_force", "sleep_speed", "wake_force", "check_interval"});
  return ActiveSetDef{n.at("sleep_force").number(), n.at("sleep_speed").number(), n.at("wake_force").number(),
                      n.at("check_interval").number()};
}

RelaxationDef parse_relaxation(const ConfigNode& n) {
  const std::string protocol = n.at("protocol").choice({"paper", "converged"});
  if (protocol == "paper") {
    n.allow_only({"protocol", "stops", "wait", "final_wait", "quench", "settle", "active_set"});
    PaperRelaxationDef p;
    p.stops = int_of(n.at("stops"));
    p.wait = n.at("wait").number();
    p.final_wait = n.at("final_wait").number();
    if (auto q = n.find("quench")) p.quench = q->boolean();
    if (auto settle = n.find("settle")) {
      settle->allow_only({"relative", "absolute"});
      p.settle = PaperRelaxationDef::Settle{settle->at("relative").number(), settle->at("absolute").number()};
    }
    if (auto a = n.find("active_set")) p.active_set = parse_active_set(*a);
    return p;
  }
  n.allow_only({"protocol", "force_tolerance", "energy_tolerance", "check_interval", "max_time",
                "zero_velocities_at_checks", "quench", "active_set"});
  ConvergedRelaxationDef c;
  c.force_tolerance = n.at("force_tolerance").number();
  c.energy_tolerance = n.at("energy_tolerance").number();
  c.check_interval = n.at("check_interval").number();
  c.max_time = n.at("max_time").number();
  c.zero_velocities_at_checks = n.at("zero_velocities_at_checks").boolean();
  if (auto q = n.find("quench")) c.quench = q->boolean();
  if (auto a = n.find("active_set")) c.active_set = parse_active_set(*a);
  return c;
}

WatchdogDef parse_watchdog(const ConfigNode& n) {
  n.allow_only({"max_overlap_fraction", "energy_growth", "check_interval"});
  WatchdogDef w;
  if (auto c = n.find("max_overlap_fraction")) w.max_overlap_fraction = c->number();
  if (auto c = n.find("energy_growth")) w.energy_growth = c->number();
  if (auto c = n.find("check_interval")) w.check_interval = c->integer();
  return w;
}

SceneFile parse_scene(const ConfigNode& root) {
  root.allow_only(
      {"materials", "effects", "particles", "shells", "planes", "drivers", "integration", "neighbor", "watchdog", "run"});
  SceneFile out{SceneDef{}, RunDef{}, root};
  SceneDef& s = out.scene;

  const ConfigNode mats = root.at("materials");
  mats.allow_only(mats.keys());  // any names, but it must be a map
  for (const std::string& name : mats.keys()) s.materials.push_back(parse_material(mats.at(name), name));
  // Soft-particles in a scene file only: a profile's spheres are the packings' grains.
  const ConfigNode effects = root.at("effects");
  s.effects = parse_effects(effects, {"soft_particles"});
  if (auto c = effects.find("soft_particles")) s.effects.soft_particles = parse_soft_particles(*c);

  for (const ConfigNode& p : root.at("particles").items()) {
    p.allow_only({"x", "r", "material", "body", "v", "w", "mass", "soft", "rotation"});
    ParticleDef d;
    d.x = p.at("x").vec3();
    d.r = p.at("r").number();
    d.material = material_ref(s, p.at("material"));
    if (auto b = p.find("body")) d.body = body_id(*b);
    if (auto v = p.find("v")) d.v = v->vec3();
    if (auto w = p.find("w")) d.w = w->vec3();
    if (auto m = p.find("mass")) d.mass = m->number();
    if (auto soft = p.find("soft")) d.soft = soft->boolean();
    if (auto rot = p.find("rotation")) d.spin_locked = rot->choice({"free", "locked"}) == "locked";
    s.particles.push_back(d);
  }

  if (auto shells = root.find("shells"))
    for (const ConfigNode& n : shells->items()) {
      n.allow_only({"name", "body", "centre", "radius", "material", "contact_radius", "mass", "parent"});
      ShellDef d;
      d.name = n.at("name").string();
      d.body = body_id(n.at("body"));
      d.centre = n.at("centre").vec3();
      d.radius = n.at("radius").number();
      d.material = material_ref(s, n.at("material"));
      d.contact_radius = parse_contact_radius(n.at("contact_radius"));
      if (auto m = n.find("mass")) d.mass = m->number();
      if (auto up = n.find("parent")) d.parent = body_id(*up);
      s.shells.push_back(d);
    }

  if (auto planes = root.find("planes"))
    for (const ConfigNode& n : planes->items()) {
      n.allow_only({"name", "point", "normal", "material"});
      PlaneDef d;
      d.name = n.at("name").string();
      d.point = n.at("point").vec3();
      d.normal = n.at("normal").vec3();
      d.material = material_ref(s, n.at("material"));
      s.planes.push_back(d);
    }

  if (auto drivers = root.find("drivers"))
    for (const ConfigNode& d : drivers->items()) s.drivers.push_back(parse_driver(d));

  s.integration = parse_integration(root.at("integration"));
  s.neighbor = parse_neighbor(root.at("neighbor"));

  if (auto w = root.find("watchdog")) s.watchdog = parse_watchdog(*w);

  if (auto run = root.find("run")) {
    run->allow_only({"duration", "relaxation"});
    if (auto d = run->find("duration")) out.run.duration = d->number();
    if (auto r = run->find("relaxation")) out.run.relaxation = parse_relaxation(*r);
  }

  // Ranges, references and contradictions: validate()'s, located in the file by their key; the
  // rules that need the soft-particle laws when the program has read them (load_scene_laws).
  try {
    validate(s, SoftLaws::pending);
    if (out.run.duration && !(*out.run.duration > 0.0 && std::isfinite(*out.run.duration)))
      throw InputError(fmt::format("run.duration: {} s is not allowed; allowed: > 0", *out.run.duration));
    if (out.run.relaxation) validate(*out.run.relaxation, "run.relaxation");
  } catch (const InputError& e) {
    throw root.locate(e);
  }
  return out;
}

SceneFile load_scene_file(const std::string& path) { return parse_scene(ConfigNode::load_file(path)); }

}  // namespace softpack
