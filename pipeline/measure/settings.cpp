#include "measure/settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "profile/profile.hpp"
#include "core/error.hpp"
#include "forces/contact_models.hpp"
#include "packing/packing_profile.hpp"
#include "scene/limits.hpp"
#include "scene/scene_yaml.hpp"
#include "scene/validate.hpp"

namespace softpack {

ContactScene parse_contact_scene(const std::string& name) {
  if (name == "soft-solid") return ContactScene::soft_solid;
  if (name == "soft-soft") return ContactScene::soft_soft;
  throw InputError(fmt::format("scene '{}' is not allowed; allowed: soft-solid, soft-soft", name));
}

std::string scene_name(ContactScene s) { return s == ContactScene::soft_solid ? "soft-solid" : "soft-soft"; }

namespace {

// The loading speed and the rotation rate: the ranges of a driver's (scene/limits.hpp), named
// by the profile's keys.
constexpr limits::Range kSpeed{0.0, limits::kDriveSpeed.hi, true, false, "speed", "m/s"};
constexpr limits::Range kRate{0.0, limits::kRate.hi, true, false, "rate", "rad/s"};

// Strictly increasing values in [lo, hi).
// (lo_included false: lo < value < hi, one rule stated once, in one message.)
std::vector<double> increasing_list(const ConfigNode& n, double lo, double hi, bool lo_included = true) {
  std::vector<double> out;
  for (const ConfigNode& v : n.items()) {
    const double x = v.number();
    if (!((lo_included ? x >= lo : x > lo) && x < hi))
      v.fail(fmt::format("{} is not allowed; allowed: {} {} value < {}", x, lo, lo_included ? "<=" : "<", hi));
    if (!out.empty() && !(x > out.back()))
      v.fail(fmt::format("{} does not increase (after {}); the grid must be strictly increasing", x, out.back()));
    out.push_back(x);
  }
  if (out.empty()) n.fail("at least one value is required");
  return out;
}

// The `content` section: required by a packing of nested soft-particles, refused otherwise.
std::optional<ContentSettings> parse_content(const ConfigNode& root) {
  const int levels = parse_packing(root).levels;
  const auto node = root.find("content");
  if (!node) {
    if (levels > 1)
      root.at("packing").at("levels").fail(fmt::format("{} levels need a `content` section: how the soft-particles of the level "
                                                       "below are held (form: soft or resolved, docs/nested.md)",
                                                       levels));
    return std::nullopt;
  }
  if (levels == 1)
    node->fail("a packing without levels holds no soft-particles; allowed: `content` with packing.levels > 1, or no `content`");
  ContentSettings c;
  c.form = node->at("form").choice({"soft", "resolved"}) == "soft" ? ContentForm::soft : ContentForm::resolved;
  const ConfigNode fraction = node->at("shell_mass_fraction");
  c.shell_mass_fraction = fraction.number();
  if (!(c.shell_mass_fraction >= 0.0 && c.shell_mass_fraction <= 100.0))
    fraction.fail(fmt::format("{} is not allowed; allowed: 0 <= shell_mass_fraction <= 100 (a shell's mass / its grains')",
                              c.shell_mass_fraction));
  if (c.form == ContentForm::resolved) {
    node->allow_only({"form", "shell_mass_fraction"});
    return c;
  }
  node->allow_only({"form", "shell_mass_fraction", "laws", "grain_contact", "many_body"});
  c.grain_contact = node->at("grain_contact").choice({"wall", "reduced-radius"}) == "wall" ? GrainContactRule::wall
                                                                                         : GrainContactRule::reduced_radius;
  // Read when a scene is built (measure/contact_scenes.cpp): the law file of the level below is
  // made by that level's study, which may not have run when this profile is read (docs/nested.md).
  c.laws = node->at("laws").string();
  if (c.laws.empty()) node->at("laws").fail("allowed: the path of the law file of the level below");
  if (const auto mb = node->find("many_body")) {
    c.many_body = mb->string();
    if (c.many_body.empty()) mb->fail("allowed: the path of a law file with a many-body law (`many_body`), or no key");
  }
  return c;
}

}  // namespace

MeasurementSettings parse_measurement(const ConfigNode& root) {
  root.allow_only(profile_sections());
  MeasurementSettings m;
  SimulationSettings& s = m.simulation;
  {
    // The grains' material; `wall` (optional: E, nu, mu, each left out the grains') is the
    // shells' and the plane wall's (the soft-solid scene's solid).
    const ConfigNode material = root.at("material");
    s.material = parse_material(material, "grain", {"wall"});
    s.wall_material = s.material;
    s.wall_material.name = "wall";
    if (const auto wall = material.find("wall")) {
      wall->allow_only({"E", "nu", "mu"});
      if (const auto v = wall->find("E")) s.wall_material.E = v->number();
      if (const auto v = wall->find("nu")) s.wall_material.nu = v->number();
      if (const auto v = wall->find("mu")) s.wall_material.mu = v->number();
    }
  }
  const ConfigNode sim = root.at("simulation");
  sim.allow_only({"effects", "integration", "neighbor", "shells"});
  s.effects = parse_effects(sim.at("effects"));
  s.integration = parse_integration(sim.at("integration"));
  s.neighbor = parse_neighbor(sim.at("neighbor"));
  const ConfigNode shells = sim.at("shells");
  shells.allow_only({"contact_radius"});
  s.shell_contact_radius = parse_contact_radius(shells.at("contact_radius"));
  m.relaxation = parse_relaxation(root.at("relaxation"));
  if (auto w = root.find("watchdog")) m.watchdog = parse_watchdog(*w);
  try {  // the scene's rules, named by the profile's keys
    validate_material(s.material, "material");
    validate_material(s.wall_material, "material.wall");
    validate_effects(s.effects, {s.material, s.wall_material}, "simulation.effects");
    validate_integration(s.integration, "simulation.integration");
    validate_neighbor(s.neighbor, "simulation.neighbor");
    validate(m.relaxation, "relaxation");
    validate_watchdog(m.watchdog, "watchdog");
  } catch (const InputError& e) {
    throw root.locate(e);
  }
  // The law effects.normal names, from the engine's registry: when the profile is read (so by
  // softpack-config, before anything runs), not when the first simulation is built.
  try {
    (void)contact_model(s.effects.normal);
  } catch (const InputError& e) {
    const ConfigNode effects = sim.at("effects");
    if (const auto n = effects.find("normal")) n->fail(std::string(e.what()).substr(std::string("effects.normal: ").size()));
    effects.fail(e.what());
  }

  s.content = parse_content(root);

  const ConfigNode nn = root.at("normal");
  nn.allow_only({"scenes", "delta_n", "speed", "path", "second_radius_ratio"});
  for (const ConfigNode& v : nn.at("scenes").items()) {
    try {
      m.normal.scenes.push_back(parse_contact_scene(v.string()));
    } catch (const InputError& e) {
      v.fail(e.what());
    }
    // Each scene once: two columns of one scene would be averaged, fitted and tabled twice.
    if (std::count(m.normal.scenes.begin(), m.normal.scenes.end(), m.normal.scenes.back()) > 1)
      v.fail(fmt::format("'{}' is listed twice; allowed: each of soft-solid, soft-soft at most once", v.string()));
  }
  if (m.normal.scenes.empty()) nn.at("scenes").fail("at least one scene is required; allowed: soft-solid, soft-soft");
  m.normal.delta_n = increasing_list(nn.at("delta_n"), 0.0, 1.0);
  m.normal.speed = nn.at("speed").number();
  if (const std::string why = limits::refusal(m.normal.speed, kSpeed); !why.empty()) nn.at("speed").fail(why);
  m.normal.incremental = nn.at("path").choice({"incremental", "direct"}) == "incremental";
  if (const auto v = nn.find("second_radius_ratio")) {
    m.normal.second_radius_ratio = v->number();
    if (!(m.normal.second_radius_ratio >= 0.1 && m.normal.second_radius_ratio <= 10.0))
      v->fail(fmt::format("{} is not allowed; allowed: 0.1 <= ratio <= 10 (Rs of the second soft-particle / Rs)",
                          m.normal.second_radius_ratio));
  }

  // A subset of the normal grid: the tangential and sliding stages start from its saved states.
  const auto subset_of_normal = [&](const ConfigNode& list, const std::vector<double>& values, const char* stage) {
    for (std::size_t k = 0; k < values.size(); ++k)
      if (std::find(m.normal.delta_n.begin(), m.normal.delta_n.end(), values[k]) == m.normal.delta_n.end())
        list.items()[k].fail(fmt::format("{} is not in normal.delta_n: the {} stage starts from the saved normal states",
                                         values[k], stage));
  };
  if (const auto sl = root.find("sliding")) {
    sl->allow_only({"delta_n", "ht_over_Rs", "speed"});
    m.has_sliding = true;
    m.sliding.delta_n = increasing_list(sl->at("delta_n"), 0.0, 1.0);
    subset_of_normal(sl->at("delta_n"), m.sliding.delta_n, "sliding");
    m.sliding.ht_over_Rs = increasing_list(sl->at("ht_over_Rs"), 0.0, 1.0, false);  // ht = 0: the normal state itself
    m.sliding.speed = sl->at("speed").number();
    if (const std::string why = limits::refusal(m.sliding.speed, kSpeed); !why.empty()) sl->at("speed").fail(why);
  }

  if (!root.has("tangential")) {  // a normal-only profile
    m.has_tangential = false;
    return m;
  }
  const ConfigNode tn = root.at("tangential");
  tn.allow_only({"delta_n", "alpha_deg", "rate", "after_rotation"});
  m.tangential.delta_n = increasing_list(tn.at("delta_n"), 0.0, 1.0);
  subset_of_normal(tn.at("delta_n"), m.tangential.delta_n, "tangential");
  std::vector<double> alpha;
  for (const ConfigNode& v : tn.at("alpha_deg").items()) {
    const double a = v.number();
    if (!(a >= -90.0 && a <= 90.0)) v.fail(fmt::format("{} is not allowed; allowed: -90 <= value <= 90 (degrees)", a));
    if (!alpha.empty() && !(a > alpha.back())) v.fail(fmt::format("{} does not increase; the grid must be strictly increasing", a));
    alpha.push_back(a);
  }
  if (alpha.empty()) tn.at("alpha_deg").fail("at least one angle is required");
  m.tangential.alpha_deg = alpha;
  m.tangential.rate = tn.at("rate").number();
  if (const std::string why = limits::refusal(m.tangential.rate, kRate); !why.empty()) tn.at("rate").fail(why);
  m.tangential.after = tn.at("after_rotation").choice({"release", "hold"}) == "release" ? AfterRotation::release : AfterRotation::hold;
  return m;
}

void validate_sweep_steps(const MeasurementSettings& m, double Rs, double dt) {
  validate_steps(m.relaxation, dt, "relaxation");
  // The longest approach of a normal point: from the previous point (incremental) or from 0.
  const std::vector<double>& grid = m.normal.delta_n;
  double way = 0.0;
  for (std::size_t k = 0; k < grid.size(); ++k) way = std::max(way, grid[k] - (m.normal.incremental && k > 0 ? grid[k - 1] : 0.0));
  validate_steps(way * Rs / m.normal.speed, dt, "normal.speed",
                 fmt::format("{} m/s, the approach of {} m (delta_n {} of Rs = {} m) in {} s,", limits::number_text(m.normal.speed),
                             limits::approx_text(way * Rs), limits::approx_text(way), limits::number_text(Rs),
                             limits::approx_text(way * Rs / m.normal.speed)));
  if (m.has_sliding) {  // the longest move of a sliding point: the largest step of its grid
    const double orbit_rate = m.sliding.speed / Rs;  // soft-soft: the second soft-particle's orbit [rad/s]
    if (!(orbit_rate * dt <= limits::kMaxRotationPerStep))
      throw InputError(fmt::format("sliding.speed: {} m/s turns the second soft-particle's orbit by {} rad in a time step of "
                                   "dt = {} s; allowed: at most {} rad per step (speed <= {} m/s)",
                                   limits::number_text(m.sliding.speed), limits::approx_text(orbit_rate * dt),
                                   limits::approx_text(dt), limits::number_text(limits::kMaxRotationPerStep),
                                   limits::approx_text(limits::kMaxRotationPerStep / dt * Rs)));
    const std::vector<double>& ht = m.sliding.ht_over_Rs;
    double step = ht.front();
    for (std::size_t k = 1; k < ht.size(); ++k) step = std::max(step, ht[k] - ht[k - 1]);
    validate_steps(step * Rs / m.sliding.speed, dt, "sliding.speed",
                   fmt::format("{} m/s, the move of {} m (ht_over_Rs {} of Rs = {} m) in {} s,", limits::number_text(m.sliding.speed),
                               limits::approx_text(step * Rs), limits::approx_text(step), limits::number_text(Rs),
                               limits::approx_text(step * Rs / m.sliding.speed)));
  }
  if (!m.has_tangential) return;
  // The largest rotation of a tangential point, and its turn per time step.
  double angle = 0.0;
  for (const double a : m.tangential.alpha_deg) angle = std::max(angle, std::abs(a) * std::numbers::pi / 180.0);
  const double rate = m.tangential.rate;
  if (!(rate * dt <= limits::kMaxRotationPerStep))
    throw InputError(fmt::format("tangential.rate: {} rad/s turns the soft-particle by {} rad in a time step of dt = {} s; "
                                 "allowed: at most {} rad per step (rate <= {} rad/s)",
                                 limits::number_text(rate), limits::approx_text(rate * dt), limits::approx_text(dt),
                                 limits::number_text(limits::kMaxRotationPerStep),
                                 limits::approx_text(limits::kMaxRotationPerStep / dt)));
  validate_steps(angle / rate, dt, "tangential.rate",
                 fmt::format("{} rad/s, the rotation of {} rad in {} s,", limits::number_text(rate), limits::approx_text(angle),
                             limits::approx_text(angle / rate)));
}

}  // namespace softpack
