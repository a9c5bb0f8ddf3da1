#include "coarse/settings.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <sstream>

#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "io/sha256.hpp"
#include "packing/nested.hpp"
#include "packing/packing_profile.hpp"

namespace softpack {

const char* name(CoarseModel m) { return m == CoarseModel::resolved ? "resolved" : "soft"; }

CoarseModel parse_coarse_model(const std::string& text) {
  if (text == "resolved") return CoarseModel::resolved;
  if (text == "soft") return CoarseModel::soft;
  throw InputError(fmt::format("model: '{}' is not allowed; allowed: resolved, soft", text));
}

namespace {

double in_range(const ConfigNode& n, double lo, double hi, bool lo_open = false) {
  const double v = n.number();
  if (!((lo_open ? v > lo : v >= lo) && v <= hi)) n.fail(fmt::format("{} is not allowed; allowed: {} {} value <= {}", v, lo, lo_open ? "<" : "<=", hi));
  return v;
}

long count_in(const ConfigNode& n, long lo, long hi) {
  const long v = n.integer();
  if (v < lo || v > hi) n.fail(fmt::format("{} is not allowed; allowed: {} <= value <= {}", v, lo, hi));
  return v;
}

std::string resolve(const std::string& root_dir, const std::string& p) {
  return std::filesystem::path(p).is_absolute() ? p : (std::filesystem::path(root_dir) / p).string();
}

}  // namespace

CoarseGrainSettings read_coarse_grain_settings(const std::string& path, const std::string& root_dir) {
  return read_coarse_grain_settings(ConfigNode::load_file(path), root_dir);
}

CoarseGrainSettings read_coarse_grain_settings(const ConfigNode& root, const std::string& root_dir) {
  root.allow_only({"coarse_grain"});
  const ConfigNode c = root.at("coarse_grain");
  c.allow_only({"soft_particle", "medium", "compression", "plan", "seeds"});
  CoarseGrainSettings s;
  {
    std::ostringstream text;
    text << c.yaml();
    s.section_text = text.str();
    // The packings' generator (profile, packing) and the medium: what build_medium() reads.
    const ConfigNode sp = c.at("soft_particle");
    std::ostringstream medium;
    medium << "profile: " << sp.at("profile").yaml() << "\n";
    if (auto p = sp.find("packing")) medium << "packing: " << p->yaml() << "\n";
    medium << c.at("medium").yaml();
    s.medium_text = medium.str();
  }

  const ConfigNode sp = c.at("soft_particle");
  sp.allow_only({"profile", "packing", "laws", "many_body", "grain_contact", "beyond_range", "shell_mass_fraction", "rotation"});
  s.profile = sp.at("profile").string();
  const ConfigNode profile = ConfigNode::load_file(resolve(root_dir, s.profile));
  {
    const MeasurementSettings measurement = parse_measurement(profile);
    s.simulation = measurement.simulation;
    s.relaxation = measurement.relaxation;
    s.normal_speed = measurement.normal.speed;
  }
  {
    const PackingProfile pp = parse_packing(profile);
    s.packing = pp.parameters, s.levels = pp.levels;
  }
  if (auto p = sp.find("packing")) {
    p->allow_only({"beta", "trials"});
    if (auto b = p->find("beta")) s.packing.beta = b->number();
    if (auto t = p->find("trials")) s.packing.trials = t->integer();
    try {
      validate(s.packing);
      validate_levels(s.packing, s.levels);  // the profile's levels with the overridden beta and trials
    } catch (const InputError& e) {
      p->fail(e.what());
    }
  }
  s.laws = resolve(root_dir, sp.at("laws").string());
  if (auto mb = sp.find("many_body")) {
    if (mb->string().empty()) mb->fail("allowed: the path of a law file with a many-body law (`many_body`), or no key");
    s.many_body = resolve(root_dir, mb->string());
  }
  s.grain_contact = sp.at("grain_contact").choice({"wall", "reduced-radius"}) == "wall" ? GrainContactRule::wall
                                                                                       : GrainContactRule::reduced_radius;
  s.beyond_range = sp.at("beyond_range").choice({"report", "stop"}) == "report" ? SoftParticlesDef::BeyondRange::report
                                                                               : SoftParticlesDef::BeyondRange::stop;
  s.shell_mass_fraction = in_range(sp.at("shell_mass_fraction"), 0.0, 10.0, true);
  if (auto r = sp.find("rotation")) {
    s.spin_locked = r->choice({"free", "locked"}) == "locked";
    if (s.spin_locked && !s.simulation.effects.rotation)
      r->fail(fmt::format("locked needs the profile's effects.rotation ({} has none: no sphere spins)", s.profile));
  }

  const ConfigNode m = c.at("medium");
  m.allow_only({"grains", "r_min_over_Rs", "decade", "exponent", "initial_fraction", "aspect", "placement_trials", "content_sample"});
  s.grains = count_in(m.at("grains"), 1, 100000);
  s.r_min_over_Rs = in_range(m.at("r_min_over_Rs"), 0.0, 100.0, true);
  s.decade = in_range(m.at("decade"), 1.0, 1000.0, true);
  s.exponent = in_range(m.at("exponent"), 1.0, 20.0);
  s.initial_fraction = in_range(m.at("initial_fraction"), 0.0, 0.5, true);
  s.aspect = in_range(m.at("aspect"), 0.1, 10.0);
  s.placement_trials = count_in(m.at("placement_trials"), 1, 100000000);
  if (auto cs = m.find("content_sample")) {
    if (s.levels == 1)
      cs->fail(fmt::format("the sites hold no soft-particles ({}'s packing.levels is 1): there is no content to sample; remove it",
                           s.profile));
    s.content_sample = count_in(*cs, 2, 100000);
  }

  const ConfigNode k = c.at("compression");
  k.allow_only({"speed", "strain", "unload_strain", "record_strain", "relax", "max_overlap_fraction", "shear", "record_shear"});
  if (auto sh = k.find("shear")) s.shear = in_range(*sh, 0.0, 1.0);
  if (s.shear > 0.0) s.record_shear = in_range(k.at("record_shear"), 0.0, s.shear, true);  // shear 0: none, no rows
  else if (auto rs = k.find("record_shear")) rs->fail("no platen shear (shear is 0 or absent): record_shear is not read; remove it");
  if (auto r = k.find("relax")) s.relax = in_range(*r, 0.0, 1000.0);
  s.speed = in_range(k.at("speed"), 0.0, 10.0, true);
  s.strain = in_range(k.at("strain"), 0.0, 0.9, true);
  s.unload_strain = in_range(k.at("unload_strain"), 0.0, s.strain);
  s.record_strain = in_range(k.at("record_strain"), 0.0, s.strain, true);
  if (auto w = k.find("max_overlap_fraction")) s.max_overlap_fraction = in_range(*w, 0.0, 100.0, true);

  if (auto plan = c.find("plan")) {
    plan->allow_only({"levels_added"});
    const ConfigNode a = plan->at("levels_added");
    if (s.levels == 1)
      a.fail(fmt::format("the sites hold no soft-particles ({}'s packing.levels is 1): there are no levels to add; remove `plan`", s.profile));
    s.plan_levels_added = static_cast<int>(count_in(a, 1, 4));
  }

  s.seeds = parse_seeds(c);
  return s;
}

CoarseStamps coarse_stamps(const std::string& path, const std::string& version, const std::string& root_dir) {
  return coarse_stamps(ConfigNode::load_file(path), version, root_dir);
}

CoarseStamps coarse_stamps(const ConfigNode& root, const std::string& version, const std::string& root_dir) {
  const CoarseGrainSettings s = read_coarse_grain_settings(root, root_dir);  // checked first
  const ConfigNode c = root.at("coarse_grain");
  const ConfigNode sp = c.at("soft_particle");
  const ConfigNode profile = ConfigNode::load_file(resolve(root_dir, s.profile));
  const auto text = [](const ConfigNode& n) {
    std::ostringstream t;
    t << n.yaml();
    return t.str() + "\n";
  };
  const auto stamp = [&](const std::string& stage, const std::string& what) {
    return sha256_of_bytes("softpack " + version + "\nstage " + stage + "\n" + what).substr(0, 16);
  };
  std::string medium = "profile: " + s.profile + "\n" + section_text(profile, "packing") + "overrides: " + (sp.has("packing") ? text(sp.at("packing")) : "\n") +
                       "medium:\n" + text(c.at("medium"));
  std::string resolved = medium + section_text(profile, "material") + section_text(profile, "simulation") +
                         "shell_mass_fraction: " + text(sp.at("shell_mass_fraction")) + "compression:\n" + text(c.at("compression"));
  std::string soft = resolved + "laws: " + sha256_of_file(s.laws) +
                     (s.many_body.empty() ? "" : "\nmany_body: " + sha256_of_file(s.many_body)) + "\ngrain_contact: " + text(sp.at("grain_contact")) +
                     "beyond_range: " + text(sp.at("beyond_range")) + (s.spin_locked ? "rotation: locked\n" : "");
  return {stamp("medium", medium), stamp("resolved", resolved), stamp("soft", soft)};
}

}  // namespace softpack
