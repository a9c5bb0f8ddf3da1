#include "coarse/probe_settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <tuple>

#include "coarse/multi_contact.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "io/sha256.hpp"
#include "profile/profile.hpp"

namespace softpack {
namespace {

double number_in(const ConfigNode& n, double lo, double hi, bool lo_open, bool hi_open) {
  const double v = n.number();
  if (!((lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi)))
    n.fail(fmt::format("{} is not allowed; allowed: {} {} value {} {}", v, lo, lo_open ? "<" : "<=", hi_open ? "<" : "<=", hi));
  return v;
}

std::vector<double> increasing(const ConfigNode& n) {
  std::vector<double> out;
  for (const ConfigNode& v : n.items()) {
    out.push_back(number_in(v, 0.0, 1.0, true, true));
    if (out.size() > 1 && !(out.back() > out[out.size() - 2])) v.fail("the values must increase");
  }
  if (out.empty()) n.fail("an empty list is not allowed; give at least one");
  return out;
}

// A run is fitted or held out, not both: the first of `held` also in `fit` refused at `key`.
void fitted_or_held_out(const std::vector<std::string>& fit, const std::vector<std::string>& held, const ConfigNode& key) {
  for (const std::string& a : held)
    if (std::find(fit.begin(), fit.end(), a) != fit.end()) key.fail(fmt::format("'{}' is also fitted: a run is fitted or held out, not both", a));
}

std::vector<std::string> names(const ConfigNode& n, const std::vector<std::string>& allowed = {}) {
  std::vector<std::string> out;
  for (const ConfigNode& item : n.items()) {
    const std::string s = allowed.empty() ? item.string() : item.choice(allowed);
    if (allowed.empty()) {
      try {
        builtin_arrangement(s, 0);
      } catch (const InputError& e) {
        item.fail(e.what());
      }
    }
    if (std::find(out.begin(), out.end(), s) != out.end()) item.fail(fmt::format("'{}' is listed twice", s));
    out.push_back(s);
  }
  if (out.empty()) n.fail("an empty list is not allowed; give at least one");
  return out;
}

}  // namespace

std::vector<std::string> ManyBodyProbe::arrangements() const {
  std::vector<std::string> out = fit;
  out.insert(out.end(), held_out.begin(), held_out.end());
  return out;
}

std::vector<std::string> ManyBodyProbe::body_kinds() const {
  std::vector<std::string> out;
  for (const auto& [kind, arrangements] : body_groups) out.push_back(kind);
  return out;
}

std::vector<std::string> ManyBodyProbe::confined_kinds() const {
  std::vector<std::string> out;
  for (const auto& [kind, arrangements] : confined_groups) out.push_back(kind);
  return out;
}

const std::vector<double>& ManyBodyProbe::delta_n_of(const std::string& kind) const {
  const auto own = kind_delta_n.find(kind);
  return own == kind_delta_n.end() ? delta_n : own->second;
}

std::vector<std::string> ManyBodyProbe::confined_kinds(bool soft) const {
  std::vector<std::string> out;
  for (const auto& [kind, arrangements] : confined_groups)
    if ((parse_pressing_body(kind).kind == PressingBody::Kind::soft) == soft) out.push_back(kind);
  return out;
}

std::string media_seeds_key(int version) { return version == 1 ? "media_seeds" : fmt::format("v{}_media_seeds", version); }

const std::vector<std::uint64_t>& ManyBodyProbe::media_seeds_of(int version) const {
  const auto at = media_seeds.find(version);
  if (at == media_seeds.end()) throw InputError(fmt::format("validation.{}: none in the plan; version {} of the law has no media", media_seeds_key(version), version));
  return at->second;
}

std::vector<std::string> ManyBodyProbe::bodies(const std::string& kind) const {
  for (const auto* groups : {&body_groups, &confined_groups})
    for (const auto& [k, arrangements] : *groups)
      if (k == kind) {
        std::vector<std::string> out;
        for (const std::string& a : arrangements) out.push_back(a + ":" + kind);
        return out;
      }
  std::vector<std::string> kinds = body_kinds();
  for (const auto& [k, arrangements] : confined_groups) kinds.push_back(k);
  throw InputError(fmt::format("pressing body '{}' is not allowed; allowed: the plan's bodies and confined ({})", kind, fmt::join(kinds, ", ")));
}

std::vector<std::pair<std::string, std::string>> ManyBodyProbe::runs_stamps(const std::string& release) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [group, text] : runs_text)
    out.emplace_back(group, sha256_of_bytes("softpack " + release + "\nmany-body probe runs " + group + "\n" + text).substr(0, 16));
  return out;
}

std::string ManyBodyProbe::stamp_line(const std::string& part, const std::string& kind, const std::string& release) const {
  const std::string group = part == "walls" ? "seed" : part == "bodies" ? "bodies-" + kind : "shear";
  for (const auto& [name, hash] : runs_stamps(release))
    if (name == group) return fmt::format("# stamp {}\n", hash);
  throw InputError(fmt::format("the plan has no group of runs '{}'", group));
}

CoarseGrainSettings ManyBodyProbe::settings_at(const std::string& radius) const {
  const auto it = radii.find(radius);
  if (it == radii.end()) {
    std::string allowed;
    for (const auto& [name, Rs] : radii) {
      if (!allowed.empty()) allowed += ", ";
      allowed += name;
    }
    throw InputError(fmt::format("radius '{}' is not allowed; allowed: {}", radius, allowed));
  }
  CoarseGrainSettings s = settings;
  s.packing.Rs = it->second;
  validate(s.packing);
  return s;
}

ManyBodyProbe read_many_body_probe(const std::string& path, const std::string& root_dir) {
  const ConfigNode root = ConfigNode::load_file(path);
  root.allow_only({"many_body_probe"});
  const ConfigNode c = root.at("many_body_probe");
  c.allow_only({"settings", "seeds", "radii", "delta_n", "fit", "held_out", "candidates", "selection", "bodies", "confined", "shear", "third_version", "fourth_version", "fifth_version", "sixth_version", "seventh_version", "validation"});
  ManyBodyProbe p;
  std::ostringstream text;
  text << c.yaml();
  p.section_text = text.str();
  const auto yaml_of = [&](const ConfigNode& n, const std::string& key) {
    std::ostringstream t;
    t << n.at(key).yaml();
    return key + ": " + t.str() + "\n";
  };
  p.settings_path = c.at("settings").string();
  const auto in_root = [&](const std::string& f) { return std::filesystem::path(f).is_absolute() ? std::filesystem::path(f) : std::filesystem::path(root_dir) / f; };
  const std::filesystem::path settings_file = in_root(p.settings_path);
  p.settings = read_coarse_grain_settings(settings_file.string(), root_dir);
  // The runs depend on the settings and their profile as they are written (relaxation, approach
  // speed, material, packing generator): their whole text, not their names, enters the stamps.
  const auto text_of = [](const ConfigNode& n) {
    std::ostringstream t;
    t << n.yaml();
    return t.str() + "\n";
  };
  const std::string common = "settings: " + text_of(ConfigNode::load_file(settings_file.string())) + "profile: " +
                             text_of(ConfigNode::load_file(in_root(p.settings.profile).string())) + yaml_of(c, "seeds") + yaml_of(c, "radii");
  p.runs_text.emplace_back("seed", common + yaml_of(c, "delta_n") + yaml_of(c, "fit") + yaml_of(c, "held_out"));
  for (const std::string& kind : c.at("bodies").keys()) p.runs_text.emplace_back("bodies-" + kind, common + yaml_of(c, "delta_n") + yaml_of(c.at("bodies"), kind));
  if (c.has("confined"))
    for (const std::string& kind : c.at("confined").keys())
      p.runs_text.emplace_back("bodies-" + kind, common + (c.at("confined").at(kind).yaml().IsMap() ? "" : yaml_of(c, "delta_n")) + yaml_of(c.at("confined"), kind));
  p.runs_text.emplace_back("shear", common + yaml_of(c, "shear"));
  p.seeds = parse_seeds(c);
  const ConfigNode radii = c.at("radii");
  for (const std::string& name : radii.keys()) {
    if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
      radii.fail(fmt::format("radius name '{}' is not allowed; allowed: lower-case letters, digits and '-'", name));
    p.radii[name] = number_in(radii.at(name), 0.0, 1.0, true, false);
    try {
      p.settings_at(name);
    } catch (const InputError& e) {
      radii.at(name).fail(e.what());
    }
  }
  if (p.radii.empty()) radii.fail("no radius; give at least one, e.g. reference: 0.016");
  p.delta_n = increasing(c.at("delta_n"));
  p.fit = names(c.at("fit"));
  p.held_out = names(c.at("held_out"));
  fitted_or_held_out(p.fit, p.held_out, c.at("held_out"));
  if (std::find(p.fit.begin(), p.fit.end(), "one") == p.fit.end()) c.at("fit").fail("'one' (the single contact, F1 of every candidate) must be in fit");
  p.candidates = names(c.at("candidates"), {"pairwise", "volumetric", "ratio"});
  const ConfigNode sel = c.at("selection");
  sel.allow_only({"force_floor", "tie_factor"});
  p.force_floor = number_in(sel.at("force_floor"), 0.0, 1.0, true, true);
  p.tie_factor = number_in(sel.at("tie_factor"), 1.0, 10.0, false, false);
  const auto plain = [](const ConfigNode& list, const std::vector<std::string>& v) {
    for (const std::string& a : v)
      if (a.find(':') != std::string::npos) list.fail(fmt::format("'{}' is not allowed here; allowed: arrangement names without :BODY", a));
  };
  const ConfigNode bodies = c.at("bodies");
  for (const std::string& kind : bodies.keys()) {
    try {
      const PressingBody b = parse_pressing_body(kind);
      if (b.name() != kind) throw InputError(fmt::format("write it {}", b.name()));
      if (b.walls_at > 0.0) throw InputError("a BODY+walls-D kind goes in confined (the second part's analysis reads bodies)");
    } catch (const InputError& e) {
      bodies.fail(fmt::format("body '{}': {}", kind, e.what()));
    }
    std::vector<std::string> arrangements = names(bodies.at(kind));
    plain(bodies.at(kind), arrangements);
    if (kind != "wall" && std::find(arrangements.begin(), arrangements.end(), "one") == arrangements.end())
      bodies.at(kind).fail("'one' (the kind's single contact, its F1) must be in the list");
    p.body_groups.emplace_back(kind, std::move(arrangements));
  }
  if (p.body_groups.empty()) bodies.fail("no pressing body; give at least one, e.g. soft: [one, opposite]");
  if (c.has("confined")) {  // the fourth part: BODY+walls-D, runs RADIUS/bodies-KIND-S.dat like bodies'
    const ConfigNode confined = c.at("confined");
    for (const std::string& kind : confined.keys()) {
      try {
        const PressingBody b = parse_pressing_body(kind);
        if (!(b.walls_at > 0.0)) throw InputError("allowed: BODY+walls-D, e.g. soft+walls-0.2 (other bodies go in bodies)");
        if (b.name() != kind) throw InputError(fmt::format("write it {}", b.name()));
      } catch (const InputError& e) {
        confined.fail(fmt::format("body '{}': {}", kind, e.what()));
      }
      // A list of arrangements (run through delta_n), or {arrangements, delta_n} with a grid of its own.
      const ConfigNode entry = confined.at(kind);
      const bool own_grid = entry.yaml().IsMap();
      if (own_grid) {
        entry.allow_only({"arrangements", "delta_n"});
        p.kind_delta_n[kind] = increasing(entry.at("delta_n"));
      }
      const ConfigNode list = own_grid ? entry.at("arrangements") : entry;
      std::vector<std::string> arrangements = names(list);
      plain(list, arrangements);
      if (std::find(arrangements.begin(), arrangements.end(), "one") != arrangements.end())
        list.fail("'one' has no wall to confine it; its single contact is bodies' one:BODY");
      for (const std::string& a : arrangements) try {  // what the kind asks of its walls (multi_contact.hpp)
          builtin_arrangement(a + ":" + kind, 0);
        } catch (const InputError& e) {
          list.fail(e.what());
        }
      p.confined_groups.emplace_back(kind, std::move(arrangements));
    }
  }
  const ConfigNode shear = c.at("shear");
  shear.allow_only({"arrangements", "delta_n", "ht_over_Rs"});
  p.shear_arrangements = names(shear.at("arrangements"));
  plain(shear.at("arrangements"), p.shear_arrangements);
  if (std::find(p.shear_arrangements.begin(), p.shear_arrangements.end(), "one") == p.shear_arrangements.end())
    shear.at("arrangements").fail("'one' (the unconfined shear every ratio is taken over) must be in the list");
  p.shear_delta_n = increasing(shear.at("delta_n"));
  p.shear_ht = increasing(shear.at("ht_over_Rs"));
  if (p.shear_ht.size() < 3) shear.at("ht_over_Rs").fail("give at least three: the first two make kt, the last the sliding ratio");
  if (c.has("third_version")) {
    const ConfigNode t = c.at("third_version");
    t.allow_only({"count_forms", "count_fit", "count_held_out", "grain_fit", "grain_held_out"});
    ManyBodyProbe::ThirdVersionPlan third;
    third.count_forms = names(t.at("count_forms"), {"volumetric", "volumetric-union"});
    const auto of_kind = [&](const std::string& key, const std::string& kind, bool kinds) {
      std::vector<std::string> out = names(t.at(key), kinds ? p.body_kinds() : std::vector<std::string>{});
      for (const std::string& a : out) {
        const auto group = std::find_if(p.body_groups.begin(), p.body_groups.end(), [&](const auto& g) { return g.first == kind; });
        if (kinds ? a.rfind("grain-", 0) != 0 : group == p.body_groups.end() || std::find(group->second.begin(), group->second.end(), a) == group->second.end())
          t.at(key).fail(fmt::format("'{}' is not allowed; allowed: {}", a, kinds ? "the grain-X kinds of bodies" : "the arrangements of bodies." + kind));
      }
      return out;
    };
    third.count_fit = of_kind("count_fit", "wall", false);
    third.count_held_out = of_kind("count_held_out", "wall", false);
    third.grain_fit = of_kind("grain_fit", "", true);
    third.grain_held_out = of_kind("grain_held_out", "", true);
    for (const auto& [fit_list, held_list, key] : {std::tuple{&third.count_fit, &third.count_held_out, "count_held_out"},
                                                   std::tuple{&third.grain_fit, &third.grain_held_out, "grain_held_out"}})
      fitted_or_held_out(*fit_list, *held_list, t.at(key));
    p.third = third;
  }
  for (const auto& [key, before] : {std::pair{"fourth_version", "third_version"}, std::pair{"fifth_version", "fourth_version"},
                                    std::pair{"sixth_version", "fifth_version"}, std::pair{"seventh_version", "sixth_version"}}) {
    if (!c.has(key)) continue;
    const ConfigNode f = c.at(key);
    const bool sixth = std::string(key) == "sixth_version", seventh = std::string(key) == "seventh_version";
    const char* forms_key = seventh ? "forms" : "soft_forms";
    f.allow_only(sixth ? std::vector<std::string>{"soft_forms", "joint_beta_ss", "kinds", "fit", "held_out_kinds", "held_out"}
                       : std::vector<std::string>{forms_key, "kinds", "fit", "held_out_kinds", "held_out"});
    if (!c.has(before) || p.confined_groups.empty())
      f.fail(fmt::format("needs {} (the law to beat{}) and confined (its runs)", before, seventh ? " is the fifth version, which it decides" : ""));
    ManyBodyProbe::SoftSoftPlan plan;
    // the stress forms stand on the fourth version's law (their baseline's), so only the fifth and
    // sixth have them; the sixth's take the stress along or across the contact too; the seventh's
    // are a grain's or a wall's (coarse/probe_body.hpp)
    plan.forms = names(f.at(forms_key), seventh                                 ? std::vector<std::string>{"union-refit", "stress", "stress-joint"}
                                        : sixth                                 ? std::vector<std::string>{"stress", "stress-normal", "stress-lateral"}
                                        : std::string(key) == "fifth_version" ? std::vector<std::string>{"volumetric-union", "onset-shift", "stress"}
                                                                              : std::vector<std::string>{"volumetric-union", "onset-shift"});
    if (sixth && f.has("joint_beta_ss")) plan.joint_beta_ss = f.at("joint_beta_ss").boolean();
    const auto kinds_of = [&](const std::string& k) {
      std::vector<std::string> out;
      for (const ConfigNode& item : f.at(k).items()) {
        const std::string kind = item.string();
        const std::vector<std::string> allowed = p.confined_kinds();
        if (std::find(allowed.begin(), allowed.end(), kind) == allowed.end())
          item.fail(fmt::format("'{}' is not a confined kind of the plan; allowed: {}", kind, fmt::join(allowed, ", ")));
        if (std::find(out.begin(), out.end(), kind) != out.end()) item.fail(fmt::format("'{}' is listed twice", kind));
        // the soft-soft parts judge a soft-particle at the first contact, the seventh a grain or a wall
        if ((parse_pressing_body(kind).kind == PressingBody::Kind::soft) == seventh)
          item.fail(fmt::format("'{}' is not allowed here; allowed: confined kinds with {} at the first contact", kind, seventh ? "a grain or a wall" : "a soft-particle"));
        out.push_back(kind);
      }
      if (out.empty()) f.at(k).fail("give at least one confined kind");
      return out;
    };
    const std::vector<std::string> kinds = kinds_of("kinds"), held_kinds = f.has("held_out_kinds") ? kinds_of("held_out_kinds") : kinds;
    if (seventh)  // each body's β and κ are fitted on its own runs and judged on its own held-out ones
      for (const auto& [list, k] : {std::pair{&kinds, "kinds"}, std::pair{&held_kinds, "held_out_kinds"}})
        for (const PressingBody::Kind body : {PressingBody::Kind::grain, PressingBody::Kind::wall})
          if (std::none_of(list->begin(), list->end(), [&](const std::string& kind) { return parse_pressing_body(kind).kind == body; }))
            f.at(f.has(k) ? k : "kinds").fail(fmt::format("give a {} kind: the grains' and the wall's laws are each fitted and judged on their own runs",
                                                          body == PressingBody::Kind::grain ? "grain-X+walls-D" : "wall+walls-D"));
    const auto runs_of = [&](const std::string& kind) -> const std::vector<std::string>& {
      return std::find_if(p.confined_groups.begin(), p.confined_groups.end(), [&](const auto& g) { return g.first == kind; })->second;
    };
    for (const auto& [list, k, of] : {std::tuple{&plan.fit, "fit", &kinds}, std::tuple{&plan.held_out, "held_out", &held_kinds}}) {
      std::vector<std::string> arrangements = names(f.at(k));
      if (sixth && std::string(k) == "fit") {  // the sixth's fit may name a run NAME:KIND as it is
        std::vector<std::string> crossed;
        for (const std::string& a : arrangements) {
          const auto colon = a.find(':');
          if (colon == std::string::npos) {
            crossed.push_back(a);
            continue;
          }
          const std::string name = a.substr(0, colon), kind = a.substr(colon + 1);
          const std::vector<std::string> allowed = p.confined_kinds();
          if (std::find(allowed.begin(), allowed.end(), kind) == allowed.end())
            f.at(k).fail(fmt::format("'{}': '{}' is not a confined kind of the plan; allowed: {}", a, kind, fmt::join(allowed, ", ")));
          if (std::find(runs_of(kind).begin(), runs_of(kind).end(), name) == runs_of(kind).end())
            f.at(k).fail(fmt::format("'{}' is not run for confined kind {}; allowed: {}", name, kind, fmt::join(runs_of(kind), ", ")));
          list->push_back(a);
        }
        arrangements = crossed;
      }
      plain(f.at(k), arrangements);
      for (const std::string& kind : *of) {
        const auto& runs = runs_of(kind);
        for (const std::string& a : arrangements) {
          if (std::find(runs.begin(), runs.end(), a) == runs.end())
            f.at(k).fail(fmt::format("'{}' is not run for confined kind {}; allowed: {}", a, kind, fmt::join(runs, ", ")));
          list->push_back(a + ":" + kind);
        }
      }
    }
    fitted_or_held_out(plan.fit, plan.held_out, f.at("held_out"));
    (std::string(key) == "fourth_version" ? p.fourth : std::string(key) == "fifth_version" ? p.fifth : sixth ? p.sixth : p.seventh) = plan;
  }
  const ConfigNode val = c.at("validation");
  std::vector<std::string> keys{"strain_range", "bound_in_standard_errors"};
  for (int v = 1; v <= kLawVersions; ++v) keys.push_back(media_seeds_key(v));
  val.allow_only(keys);
  for (int v = 1; v <= kLawVersions; ++v) {
    if (v > 1 && !val.has(media_seeds_key(v))) continue;
    p.media_seeds[v] = parse_seeds(val, media_seeds_key(v));
    for (const std::uint64_t seed : p.media_seeds[v])
      for (const auto& [earlier, seeds] : p.media_seeds)
        if (earlier < v && std::find(seeds.begin(), seeds.end(), seed) != seeds.end())
          val.at(media_seeds_key(v)).fail(fmt::format("seed {} is also in {}: a law is judged on media no earlier run has used", seed, media_seeds_key(earlier)));
  }
  const std::vector<ConfigNode> range = val.at("strain_range").items();
  if (range.size() != 2) val.at("strain_range").fail("give two strains, [from, to]");
  p.strain_lo = number_in(range[0], 0.0, 1.0, false, true);
  p.strain_hi = number_in(range[1], 0.0, 1.0, true, true);
  if (!(p.strain_hi > p.strain_lo)) val.at("strain_range").fail("the second strain must exceed the first");
  p.bound_in_standard_errors = number_in(val.at("bound_in_standard_errors"), 0.0, 10.0, true, false);
  return p;
}

}  // namespace softpack
