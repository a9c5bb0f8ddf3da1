#include "scene/scene_yaml.hpp"

#include <fmt/format.h>

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

std::optional<double> optional_positive(const ConfigNode& n, const std::string& key) {
  if (auto c = n.find(key)) return c->positive();
  return std::nullopt;
}

DriverDef parse_driver(const ConfigNode& d) {
  const std::string type = d.at("type").choice({"move_wall", "rotate", "translate", "hold"});
  if (type == "move_wall") {
    d.allow_only({"type", "wall", "velocity", "distance", "duration"});
    MoveWallDef m;
    m.wall = d.at("wall").string();
    m.velocity = d.at("velocity").vec3();
    m.distance = optional_positive(d, "distance");
    m.duration = optional_positive(d, "duration");
    return m;
  }
  if (type == "rotate") {
    d.allow_only({"type", "group", "centre", "axis", "rate", "angle", "duration", "after", "with_shell"});
    RotateGroupDef r;
    r.group = parse_group(d.at("group"));
    r.centre = d.at("centre").vec3();
    r.axis = d.at("axis").vec3();
    r.rate = d.at("rate").number();
    r.angle = optional_positive(d, "angle");
    r.duration = optional_positive(d, "duration");
    r.after = parse_after(d);
    if (auto c = d.find("with_shell")) r.with_shell = c->boolean();
    return r;
  }
  if (type == "translate") {
    d.allow_only({"type", "group", "velocity", "distance", "duration", "after"});
    TranslateGroupDef t;
    t.group = parse_group(d.at("group"));
    t.velocity = d.at("velocity").vec3();
    t.distance = optional_positive(d, "distance");
    t.duration = optional_positive(d, "duration");
    t.after = parse_after(d);
    return t;
  }
  d.allow_only({"type", "group"});
  return HoldGroupDef{parse_group(d.at("group"))};
}

void parse_effects(const ConfigNode& n, EffectsDef& e) {
  n.allow_only({"normal", "friction", "rotation", "damping", "gravity"});
  if (auto c = n.find("normal")) e.normal = c->string();  // a registered law: checked when the simulation is built
  if (auto c = n.find("friction")) e.friction = c->choice({"tsuji"}) == "tsuji";
  if (auto c = n.find("rotation")) e.rotation = c->boolean();
  if (auto c = n.find("damping")) {
    c->allow_only({"restitution", "tangential_ratio"});
    e.restitution = c->at("restitution").in_range(0.0, true, 1.0, false);
    e.tangential_damping_ratio = c->at("tangential_ratio").non_negative();
  }
  if (auto c = n.find("gravity")) e.gravity = c->vec3();
}

}  // namespace

RelaxationDef parse_relaxation(const ConfigNode& n) {
  const std::string protocol = n.at("protocol").choice({"paper", "converged"});
  if (protocol == "paper") {
    n.allow_only({"protocol", "stops", "wait", "final_wait"});
    PaperRelaxationDef p;
    p.stops = static_cast<int>(n.at("stops").integer());
    if (p.stops < 0) n.at("stops").fail("allowed: stops >= 0");
    p.wait = n.at("wait").positive();
    p.final_wait = n.at("final_wait").positive();
    return p;
  }
  n.allow_only({"protocol", "force_tolerance", "energy_tolerance", "check_interval", "max_time",
                "zero_velocities_at_checks"});
  ConvergedRelaxationDef c;
  c.force_tolerance = n.at("force_tolerance").positive();
  c.energy_tolerance = n.at("energy_tolerance").positive();
  c.check_interval = n.at("check_interval").positive();
  c.max_time = n.at("max_time").positive();
  c.zero_velocities_at_checks = n.at("zero_velocities_at_checks").boolean();
  return c;
}

WatchdogDef parse_watchdog(const ConfigNode& n) {
  n.allow_only({"max_overlap_fraction", "energy_growth", "check_interval"});
  WatchdogDef w;
  if (auto c = n.find("max_overlap_fraction")) w.max_overlap_fraction = c->positive();
  if (auto c = n.find("energy_growth")) {
    w.energy_growth = c->number();
    if (!(w.energy_growth > 1.0)) c->fail(fmt::format("{} is not allowed; allowed: > 1", c->yaml().Scalar()));
  }
  if (auto c = n.find("check_interval")) {
    w.check_interval = c->integer();
    if (w.check_interval < 1) c->fail(fmt::format("{} is not allowed; allowed: an integer >= 1 (steps)", w.check_interval));
  }
  return w;
}

SceneFile parse_scene(const ConfigNode& root) {
  root.allow_only(
      {"materials", "effects", "particles", "shells", "planes", "drivers", "integration", "neighbor", "watchdog", "run"});
  SceneFile out;
  SceneDef& s = out.scene;

  const ConfigNode mats = root.at("materials");
  mats.allow_only(mats.keys());  // any names, but it must be a map
  for (const std::string& name : mats.keys()) {
    const ConfigNode m = mats.at(name);
    m.allow_only({"E", "nu", "mu", "density"});
    s.materials.push_back(Material{name, m.at("E").positive(), m.at("nu").in_range(-1.0, true, 0.5, true),
                                   m.at("mu").non_negative(), m.at("density").positive()});
  }

  parse_effects(root.at("effects"), s.effects);

  for (const ConfigNode& p : root.at("particles").items()) {
    p.allow_only({"x", "r", "material", "body", "v", "w"});
    ParticleDef d;
    d.x = p.at("x").vec3();
    d.r = p.at("r").positive();
    d.material = material_ref(s, p.at("material"));
    if (auto b = p.find("body")) d.body = body_id(*b);
    if (auto v = p.find("v")) d.v = v->vec3();
    if (auto w = p.find("w")) d.w = w->vec3();
    s.particles.push_back(d);
  }

  if (auto shells = root.find("shells"))
    for (const ConfigNode& n : shells->items()) {
      n.allow_only({"name", "body", "centre", "radius", "material", "contact_radius"});
      ShellDef d;
      d.name = n.at("name").string();
      d.body = body_id(n.at("body"));
      d.centre = n.at("centre").vec3();
      d.radius = n.at("radius").positive();
      d.material = material_ref(s, n.at("material"));
      d.contact_radius = n.at("contact_radius").choice({"concave", "particle"}) == "concave"
                             ? ShellContactRadius::concave
                             : ShellContactRadius::particle;
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

  const ConfigNode in = root.at("integration");
  in.allow_only({"dt", "safety", "tangential_history"});
  if (auto c = in.find("dt")) s.integration.dt = c->positive();
  if (auto c = in.find("safety")) s.integration.safety = c->in_range(0.0, true, 1.0, false);
  s.integration.history_update = in.at("tangential_history").choice({"synchronized", "standard"}) == "synchronized"
                                     ? HistoryUpdate::synchronized
                                     : HistoryUpdate::standard;

  const ConfigNode nb = root.at("neighbor");
  nb.allow_only({"skin", "level_ratio"});
  s.neighbor.skin = nb.at("skin").positive();
  s.neighbor.level_ratio = nb.at("level_ratio").in_range(1.0, true, 1e3, false);

  if (auto w = root.find("watchdog")) s.watchdog = parse_watchdog(*w);

  if (auto run = root.find("run")) {
    run->allow_only({"duration", "relaxation"});
    if (auto d = run->find("duration")) out.run.duration = d->positive();
    if (auto r = run->find("relaxation")) out.run.relaxation = parse_relaxation(*r);
  }

  // Semantic checks (load_scene_file prefixes the file name to their messages).
  validate(s);
  if (out.run.relaxation) validate(*out.run.relaxation);
  return out;
}

SceneFile load_scene_file(const std::string& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  try {
    return parse_scene(root);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind(path, 0) == 0) throw;
    throw InputError(path + ": " + msg);
  }
}

}  // namespace softpack
