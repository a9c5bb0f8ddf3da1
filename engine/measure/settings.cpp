#include "measure/settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "config/profile.hpp"
#include "core/error.hpp"
#include "scene/scene_yaml.hpp"

namespace softpack {

ContactScene parse_contact_scene(const std::string& name) {
  if (name == "soft-solid") return ContactScene::soft_solid;
  if (name == "soft-soft") return ContactScene::soft_soft;
  throw InputError(fmt::format("scene '{}' is not allowed; allowed: soft-solid, soft-soft", name));
}

std::string scene_name(ContactScene s) { return s == ContactScene::soft_solid ? "soft-solid" : "soft-soft"; }

namespace {

Material parse_material(const ConfigNode& n) {
  n.allow_only({"E", "nu", "mu", "density"});
  return Material{"grain", n.at("E").positive(), n.at("nu").in_range(-1.0, true, 0.5, true), n.at("mu").non_negative(),
                  n.at("density").positive()};
}

std::vector<double> increasing_list(const ConfigNode& n, double lo, double hi) {
  std::vector<double> out;
  for (const ConfigNode& v : n.items()) {
    const double x = v.in_range(lo, false, hi, true);
    if (!out.empty() && !(x > out.back()))
      v.fail(fmt::format("{} does not increase (after {}); the grid must be strictly increasing", x, out.back()));
    out.push_back(x);
  }
  if (out.empty()) n.fail("at least one value is required");
  return out;
}

}  // namespace

MeasurementSettings parse_measurement(const ConfigNode& root) {
  root.allow_only(profile_sections());
  MeasurementSettings m;
  SimulationSettings& s = m.simulation;
  s.material = parse_material(root.at("material"));
  const ConfigNode sim = root.at("simulation");
  sim.allow_only({"restitution", "tangential_damping_ratio", "safety", "tangential_history", "skin", "level_ratio",
                  "shell_contact_radius"});
  s.restitution = sim.at("restitution").in_range(0.0, true, 1.0, false);
  s.tangential_damping_ratio = sim.at("tangential_damping_ratio").non_negative();
  s.safety = sim.at("safety").in_range(0.0, true, 1.0, false);
  s.history_update = sim.at("tangential_history").choice({"synchronized", "standard"}) == "synchronized"
                         ? HistoryUpdate::synchronized
                         : HistoryUpdate::standard;
  s.skin = sim.at("skin").positive();
  s.level_ratio = sim.at("level_ratio").in_range(1.0, true, 1e3, false);
  s.shell_contact_radius = sim.at("shell_contact_radius").choice({"concave", "particle"}) == "concave"
                               ? ShellContactRadius::concave
                               : ShellContactRadius::particle;
  m.relaxation = parse_relaxation(root.at("relaxation"));

  const ConfigNode nn = root.at("normal");
  nn.allow_only({"scenes", "delta_n", "speed", "path"});
  for (const ConfigNode& v : nn.at("scenes").items()) {
    try {
      m.normal.scenes.push_back(parse_contact_scene(v.string()));
    } catch (const InputError& e) {
      v.fail(e.what());
    }
  }
  m.normal.delta_n = increasing_list(nn.at("delta_n"), 0.0, 1.0);
  if (m.normal.delta_n.front() != 0.0) nn.at("delta_n").fail("must start at 0 (the undeformed state)");
  m.normal.speed = nn.at("speed").positive();
  m.normal.incremental = nn.at("path").choice({"incremental", "direct"}) == "incremental";

  const ConfigNode tn = root.at("tangential");
  tn.allow_only({"delta_n", "alpha_deg", "rate", "after_rotation"});
  m.tangential.delta_n = increasing_list(tn.at("delta_n"), 0.0, 1.0);
  for (std::size_t k = 0; k < m.tangential.delta_n.size(); ++k)
    if (std::find(m.normal.delta_n.begin(), m.normal.delta_n.end(), m.tangential.delta_n[k]) == m.normal.delta_n.end())
      tn.at("delta_n").items()[k].fail(fmt::format("{} is not in normal.delta_n: the tangential stage shears the saved normal states",
                                                   m.tangential.delta_n[k]));
  std::vector<double> alpha;
  for (const ConfigNode& v : tn.at("alpha_deg").items()) {
    const double a = v.in_range(-90.0, false, 90.0, false);
    if (!alpha.empty() && !(a > alpha.back())) v.fail(fmt::format("{} does not increase; the grid must be strictly increasing", a));
    alpha.push_back(a);
  }
  if (alpha.empty()) tn.at("alpha_deg").fail("at least one angle is required");
  m.tangential.alpha_deg = alpha;
  m.tangential.rate = tn.at("rate").positive();
  m.tangential.after = tn.at("after_rotation").choice({"release", "hold"}) == "release" ? AfterRotation::release : AfterRotation::hold;

  if (auto w = root.find("watchdog")) m.watchdog = parse_watchdog(*w);
  return m;
}

}  // namespace softpack
