#include "report/study_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <utility>

#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "report/report_kinds.hpp"

namespace softpack {
namespace {

// The smallest seed a study may use: seeds 1-7 are the paper's seven simulations, run only to
// report; every calibration and comparison runs on held-out seeds.
constexpr std::uint64_t kFirstHeldOutSeed = 101;

// The map holding the list at the dotted `key` under `node`, and the key's last part.
std::pair<ConfigNode, std::string> descend(const ConfigNode& node, const std::string& key) {
  const std::size_t dot = key.find('.');
  if (dot == std::string::npos) return {node, (node.at(key), key)};  // there, or an InputError naming file and key
  return descend(node.at(key.substr(0, dot)), key.substr(dot + 1));
}

// The map holding the list at `key` of `parent`, and its key there: the study file's own, or for
// `{file: F, key: a.b}` the list that file holds at a.b (read where it was fixed, not copied).
// (No ConfigNode is assigned to: a YAML::Node's operator= would overwrite the node it refers to.)
std::pair<ConfigNode, std::string> list_at(const ConfigNode& parent, const std::string& key) {
  const ConfigNode n = parent.at(key);
  if (!n.yaml().IsMap()) return {parent, key};
  n.allow_only({"file", "key"});
  const auto load = [&] {
    try {
      return ConfigNode::load_file(n.at("file").string());
    } catch (const InputError& e) {
      n.at("file").fail(e.what());
    }
  };
  return descend(load(), n.at("key").string());
}

// The `seeds` of `n`, read as a profile's are (profile/profile.hpp), and all of them held out.
std::vector<std::uint64_t> read_seeds(const ConfigNode& n) {
  const auto [holder, key] = list_at(n, "seeds");
  const std::vector<std::uint64_t> seeds = parse_seeds(holder, key);
  const std::vector<ConfigNode> items = holder.at(key).items();
  for (std::size_t k = 0; k < seeds.size(); ++k)
    if (seeds[k] < kFirstHeldOutSeed)
      items[k].fail(fmt::format("seed {} is not allowed; allowed: held-out seeds >= {} (1-7 are the paper's, run only to report)",
                                seeds[k], kFirstHeldOutSeed));
  return seeds;
}

std::vector<double> read_numbers(const ConfigNode& n) {
  std::vector<double> v;
  for (const ConfigNode& x : n.items()) v.push_back(x.number());
  if (v.empty()) n.fail("at least one value is required");
  return v;
}

StudySetting read_setting(const std::string& name, const ConfigNode& n, const std::vector<std::uint64_t>& study_seeds) {
  n.allow_only({"set", "of", "seeds"});
  StudySetting s;
  s.name = name;
  if (auto set = n.find("set"))
    for (const std::string& key : set->keys()) s.set.emplace_back(key, YAML::Clone(std::as_const(set->yaml())[key]));  // ~ too
  if (auto of = n.find("of")) {
    s.of = of->string();
    if (!s.set.empty()) n.at("set").fail("a setting `of` another one takes its results: it cannot also `set` keys");
  }
  s.seeds = n.has("seeds") ? read_seeds(n) : study_seeds;
  return s;
}

// The map that holds the last part of the dotted `key` in `root`, and that part; InputError
// naming `where` when a section on the way is not there.
std::pair<YAML::Node, std::string> parent_of(YAML::Node root, const std::string& key, const std::string& where) {
  YAML::Node node = root;
  std::string path;
  for (std::size_t start = 0;;) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw InputError(fmt::format("{}: '{}': an empty part in the dotted key", where, key));
    if (dot == std::string::npos) return {node, part};
    path += (path.empty() ? "" : ".") + part;
    if (!node.IsMap() || !node[part] || !node[part].IsMap())
      throw InputError(fmt::format("{}: '{}': the base profile has no section '{}' to change", where, key, path));
    node.reset(node[part]);  // rebinds (operator= would overwrite the parent's value)
    start = dot + 1;
  }
}

// Sets the value at the dotted `key`; a null value (~) removes the key, which the base must have.
// The parent map must exist in the base (a misspelt section is refused, a new key of an existing
// section is allowed).
void replace(YAML::Node root, const std::string& key, const YAML::Node& value, const std::string& where) {
  auto [parent, last] = parent_of(root, key, where);
  if (!value.IsNull()) {
    parent[last] = YAML::Clone(value);
    return;
  }
  if (!parent.remove(last)) throw InputError(fmt::format("{}: '{}': ~ removes a key of the base profile, which has none there", where, key));
}

bool settings_named(const ConfigNode& root, const std::string& name) {
  if (!root.has("settings")) return false;
  for (const std::string& k : root.at("settings").keys())
    if (k == name) return true;
  return false;
}

constexpr const char* kNameChars = "abcdefghijklmnopqrstuvwxyz0123456789.-";

// `vary` (one key at a time) or `grid` (every combination) of `root`: settings appended to the
// study's, named "<key>-<value>..." (the key's last part); one equal to the reference is `of` it.
void generate_settings(const ConfigNode& root, Study& st, std::set<std::string>& names) {
  const bool grid = root.has("grid");
  const ConfigNode section = root.at(grid ? "grid" : "vary");
  const YAML::Node ref = YAML::Load(setting_profile_text(st, st.reference));
  std::vector<std::vector<ConfigNode>> values;
  const std::vector<std::string> keys = section.keys();
  if (keys.empty()) section.fail("at least one key of the profile is required");
  for (const std::string& key : keys) {
    const auto [holder, last] = list_at(section, key);
    values.push_back(holder.at(last).items());
    if (values.back().empty()) section.at(key).fail("at least one value is required");
    for (const ConfigNode& v : values.back())
      if (!v.yaml().IsScalar()) v.fail("allowed: a value (a number, true or false, a word)");
    (grid ? st.grid : st.vary).push_back({key, {}});
  }
  // One setting per combination of an index into each key's values (grid), or per value (vary).
  const auto add = [&](const std::vector<std::pair<std::size_t, std::size_t>>& picks) {
    StudySetting s;
    bool as_reference = true;
    for (const auto& [axis, k] : picks) {
      const std::string& key = keys[axis];
      const ConfigNode& v = values[axis][k];
      std::string part = StudyAxis{key, {}}.name() + "-" + v.yaml().Scalar();
      for (char& c : part) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (part.find_first_not_of(kNameChars) != std::string::npos)
        v.fail(fmt::format("names its setting '{}': allowed in a name are lowercase letters, digits, '.', '-'", part));
      s.name += (s.name.empty() ? "" : "-") + part;
      s.set.emplace_back(key, YAML::Clone(v.yaml()));
      const auto [parent, name] = parent_of(ref, key, fmt::format("{}: {}", st.path, key));
      const YAML::Node r = std::as_const(parent)[name];
      double a = 0.0, b = 0.0;
      as_reference = as_reference && r && r.IsScalar() &&
                     (r.Scalar() == v.yaml().Scalar() || (YAML::convert<double>::decode(r, a) &&
                                                          YAML::convert<double>::decode(v.yaml(), b) && a == b));
    }
    if (!names.insert(s.name).second) values[picks.back().first][picks.back().second].fail(fmt::format("'{}' is a name already used", s.name));
    s.seeds = st.seeds;
    if (as_reference) s.set.clear(), s.of = "reference";
    for (const auto& [axis, k] : picks) (grid ? st.grid : st.vary)[axis].points.emplace_back(values[axis][k].yaml().Scalar(), s.name);
    st.settings.push_back(std::move(s));
  };
  if (!grid) {
    for (std::size_t axis = 0; axis < values.size(); ++axis)
      for (std::size_t k = 0; k < values[axis].size(); ++k) add({{axis, k}});
    return;
  }
  std::vector<std::pair<std::size_t, std::size_t>> picks;
  for (std::size_t axis = 0; axis < values.size(); ++axis) picks.emplace_back(axis, 0);
  for (;;) {
    add(picks);
    std::size_t axis = values.size();
    while (axis > 0 && ++picks[axis - 1].second == values[axis - 1].size()) picks[--axis].second = 0;
    if (axis == 0) return;
  }
}

// The file's `settings`: names, and for one that runs the reference's seeds (compared on the
// same soft-particles); for one `of` another, a setting that runs and a subset of its seeds.
void check_settings(const ConfigNode& settings, Study& st, std::set<std::string>& names) {
  for (const std::string& name : settings.keys()) {
    const ConfigNode n = settings.at(name);
    if (name.empty() || name.find_first_not_of(kNameChars) != std::string::npos)
      n.fail("a setting's name is its profile's and folder's: lowercase letters, digits, '.', '-'");
    if (!names.insert(name).second) n.fail(fmt::format("'{}' is a name already used", name));
    st.settings.push_back(read_setting(name, n, st.seeds));
  }
  for (const auto& s : st.settings) {
    if (s.runs()) {
      for (std::uint64_t seed : s.seeds)
        if (std::find(st.reference.seeds.begin(), st.reference.seeds.end(), seed) == st.reference.seeds.end())
          settings.at(s.name).at("seeds").fail(fmt::format("seed {} is not a seed of the reference, so nothing to compare it with", seed));
      continue;
    }
    const ConfigNode n = settings.at(s.name);
    const auto source = std::find_if(st.settings.begin(), st.settings.end(), [&](const StudySetting& o) { return o.name == s.of; });
    const StudySetting* from = s.of == "reference" ? &st.reference : source != st.settings.end() ? &*source : nullptr;
    if (!from || !from->runs()) n.at("of").fail(fmt::format("'{}' is not a setting that runs", s.of));
    for (std::uint64_t seed : s.seeds)
      if (std::find(from->seeds.begin(), from->seeds.end(), seed) == from->seeds.end())
        n.at("seeds").fail(fmt::format("seed {} is not one of the seeds of '{}'", seed, s.of));
  }
}

}  // namespace

const StudySetting& Study::setting(const std::string& name) const {
  if (name == reference.name) return reference;
  for (const auto& s : settings)
    if (s.name == name) return s;
  throw InputError(fmt::format("{}: no setting '{}'", path, name));
}

namespace {

// The study's plan: its name, report kind, stages, folder and figures.
void read_plan(const ConfigNode& root, Study& st) {
  st.name = root.at("study").string();
  if (st.name.empty() || st.name.find_first_not_of(kNameChars) != std::string::npos)
    root.at("study").fail("a study's name is its make goal's and folder's: lowercase letters, digits, '.', '-'");
  if (const std::string stem = std::filesystem::path(st.path).stem().string(); st.name != stem)
    root.at("study").fail(fmt::format("the study's name is its file's ({}.yaml: `make {}`), not '{}'", stem, stem, st.name));
  st.report = root.at("report").choice(report_kind_names());
  const StudyBaseKind& kind = study_base_kind(st.base_yaml);
  st.stages = kind.default_goals;
  if (auto stages = root.find("stages")) {
    st.stages.clear();
    for (const ConfigNode& s : stages->items()) st.stages.push_back(s.choice(kind.goals));
    if (st.stages.empty()) stages->fail(fmt::format("allowed: a list of the goals of {} ({}), not empty", kind.name, fmt::join(kind.goals, ", ")));
  }
  st.out = "studies/" + st.name;
  if (auto out = root.find("out")) {
    st.out = out->string();
    if (st.out.empty() || st.out.front() == '/' || st.out.find("..") != std::string::npos ||
        st.out.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789.-/_") != std::string::npos)
      out->fail("allowed: a folder under DATA (lowercase letters, digits, '.', '-', '_', '/'; not absolute, no '..')");
  }
  if (auto archive = root.find("archive")) {
    if (!kind.archive) archive->fail(fmt::format("a study of {} reuses no archive", kind.name));
    st.archive = archive->string();
    if (!std::filesystem::is_regular_file(st.archive + "/MANIFEST.sha256"))
      archive->fail(fmt::format("{} is not an archive (no MANIFEST.sha256): allowed, a folder data/archive/<release>/<profile>", st.archive));
  }
  if (auto figures = root.find("figures"))
    for (const ConfigNode& f : figures->items()) {
      f.allow_only({"script", "data", "name"});
      StudyFigure fig{f.at("script").string(), f.at("data").string(), f.at("name").string()};
      if (!std::filesystem::is_regular_file(fig.script)) f.at("script").fail(fmt::format("{}: no such gnuplot script", fig.script));
      for (const auto& [key, v] : {std::pair{"data", fig.data}, std::pair{"name", fig.name}})
        if (v.empty() || v.front() == '/' || v.find("..") != std::string::npos || v.find_first_not_of(kNameChars + std::string("/")) != std::string::npos)
          f.at(key).fail("allowed: a file in the report's folder (lowercase letters, digits, '.', '-', '/'; not absolute, no '..')");
      st.figures.push_back(fig);
    }
}

}  // namespace

Study read_study(const std::string& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  root.allow_only({"study", "report", "archive", "stages", "out", "figures", "base", "seeds", "common", "compare", "criteria", "calibrate",
                   "radius", "nested", "reference", "settings", "vary", "grid"});
  Study st;
  st.path = path;
  st.base = root.at("base").string();
  try {
    st.base_yaml = YAML::Clone(ConfigNode::load_file(st.base).yaml());  // with the project's checks of a YAML file
  } catch (const InputError& e) {
    root.at("base").fail(e.what());
  }
  st.base_kind = study_base_kind(st.base_yaml).base;
  read_plan(root, st);
  if (const ReportKind& k = report_kind(st.report); k.base != st.base_kind)
    root.at("report").fail(fmt::format("the report kind '{}' reports studies of {}; the base {} is {}", st.report,
                                       study_base_kind(k.base).name, st.base, study_base_kind(st.base_kind).name));
  for (const std::string& section : report_kind(st.report).needs)
    if (!root.has(section)) root.fail(fmt::format("`{}` is missing: the report kind '{}' reads it", section, st.report));
  st.seeds = read_seeds(root);
  if (auto cmp = root.find("compare")) {
    cmp->allow_only({"Fn_delta_n", "kt_delta_n"});
    st.Fn_delta_n = read_numbers(cmp->at("Fn_delta_n"));
    if (auto kt = cmp->find("kt_delta_n")) st.kt_delta_n = read_numbers(*kt);  // none: kt is not compared
  }
  if (auto criteria = root.find("criteria")) {
    st.criteria = criteria->string();
    if (!std::filesystem::is_regular_file(st.criteria)) criteria->fail(fmt::format("{}: no such file", st.criteria));
  }
  if (auto cal = root.find("calibrate")) {
    cal->allow_only({"b_range"});
    const ConfigNode ranges = cal->at("b_range");
    ranges.allow_only({"soft-solid", "soft-soft"});
    for (const std::string& scene : ranges.keys()) {
      const std::vector<double> r = read_numbers(ranges.at(scene));
      if (r.size() != 2 || !(r[0] >= 0.0 && r[0] < r[1]))
        ranges.at(scene).fail("allowed: [low, high] with 0 <= low < high (a range of delta_n)");
      st.b_range[scene] = {r[0], r[1]};
    }
  }
  if (auto radius = root.find("radius")) {
    radius->allow_only({"self_similar", "fixed", "mixed", "mu_from_ht_over_Rs"});
    for (const char* variant : {"self_similar", "fixed", "mixed"})
      if (auto list = radius->find(variant))
        for (const ConfigNode& name : list->items()) {
          const std::string n = name.string();
          if (n != "reference" && !settings_named(root, n)) name.fail(fmt::format("'{}' is not a setting of this study", n));
          st.radius_variants[variant].push_back(n);
        }
    st.mu_from_ht_over_Rs = radius->at("mu_from_ht_over_Rs").number();
    if (!(st.mu_from_ht_over_Rs > 0.0 && st.mu_from_ht_over_Rs < 1.0))
      radius->at("mu_from_ht_over_Rs").fail("allowed: 0 < value < 1 (ht / Rs from which the contact slides)");
  }
  if (auto nested = root.find("nested")) {  // the nested report (report/nested_report.hpp)
    nested->allow_only({"against", "mu_from_ht_over_Rs", "mu_seeds_loaded"});
    st.nested_against = nested->at("against").string();
    if (st.nested_against != "reference" && !settings_named(root, st.nested_against))
      nested->at("against").fail("allowed: reference or a setting of this study");
    st.mu_from_ht_over_Rs = nested->at("mu_from_ht_over_Rs").number();
    if (!(st.mu_from_ht_over_Rs > 0.0 && st.mu_from_ht_over_Rs < 1.0))
      nested->at("mu_from_ht_over_Rs").fail("allowed: 0 < value < 1 (ht / Rs from which the contact slides)");
    if (auto least = nested->find("mu_seeds_loaded"); least && (least->integer() < 1 || std::size_t(least->integer()) > st.seeds.size()))
      least->fail(fmt::format("allowed: 1 to {} (the study's seeds): how many carry a normal force at every sliding point of a delta_n "
                              "for its mu_soft", st.seeds.size()));
    else if (least) st.mu_seeds_loaded = static_cast<std::size_t>(least->integer());
  }
  if (auto common = root.find("common"))
    for (const std::string& key : common->keys()) st.common.emplace_back(key, YAML::Clone(std::as_const(common->yaml())[key]));
  if (auto ref = root.find("reference")) st.reference = read_setting("reference", *ref, st.seeds);
  else st.reference = StudySetting{"reference", {}, "", st.seeds};
  if (!st.reference.of.empty()) root.at("reference").at("of").fail("the reference runs: it cannot be `of` another setting");
  for (std::uint64_t s : st.seeds)
    if (std::find(st.reference.seeds.begin(), st.reference.seeds.end(), s) == st.reference.seeds.end())
      root.at("reference").at("seeds").fail(fmt::format("the reference must hold every seed of the study; {} is missing", s));
  if (root.has("vary") && root.has("grid")) root.at("grid").fail("a study varies one key at a time (`vary`) or every combination (`grid`), not both");
  // A nested study's last level measures its reference alone: the laws the level above reads.
  if (!root.has("settings") && !root.has("vary") && !root.has("grid") && st.report != "nested")
    root.fail("no settings: give `settings`, `vary` or `grid`");
  std::set<std::string> names{"reference"};
  if (auto settings = root.find("settings")) check_settings(*settings, st, names);
  if ((root.has("vary") || root.has("grid")) && !st.reference.set.empty())
    root.at("reference").at("set").fail("`vary` and `grid` vary the base around itself: the reference sets no key (use `common`)");
  if (root.has("vary") || root.has("grid")) generate_settings(root, st, names);
  // Every profile must be one the stages accept: generated, then read as they read it.
  for (const StudySetting* s : [&] {
         std::vector<const StudySetting*> all{&st.reference};
         for (const auto& x : st.settings) all.push_back(&x);
         return all;
       }()) {
    if (s->runs()) check_setting_file(st.base_kind, setting_profile_text(st, *s), fmt::format("{} (setting {})", path, s->name));
  }
  return st;
}

std::string setting_changes(const Study& st, const StudySetting& s) {
  if (!s.runs()) return fmt::format("{} on {} of its seeds", s.of, s.seeds.size());
  if (s.set.empty()) return s.name == "reference" ? "the reference" : fmt::format("(the base, {})", st.base);
  std::string t;
  for (const auto& [key, value] : s.set) {
    YAML::Emitter e;
    e << YAML::Flow << value;
    t += (t.empty() ? "" : ", ") + key + (value.IsNull() ? std::string(" removed") : " = " + std::string(e.c_str()));
  }
  return t;
}

std::string setting_profile_text(const Study& study, const StudySetting& setting) {
  YAML::Node base = YAML::Clone(study.base_yaml);
  // An imported packing's files are relative to its profile's folder (packing/import.hpp): the
  // generated profile lives elsewhere, so they are written from the base's folder.
  const auto child = [](const YAML::Node& n, const char* key) { return n.IsMap() && n[key] ? n[key] : YAML::Node(); };
  if (YAML::Node files = child(child(child(std::as_const(base), "packing"), "import"), "files"); files.IsMap())
    for (auto it = files.begin(); it != files.end(); ++it)
      if (const std::filesystem::path p = it->second.as<std::string>(""); !p.empty() && p.is_relative())
        it->second = (std::filesystem::path(study.base).parent_path() / p).lexically_normal().string();
  for (const auto& [key, value] : study.common) replace(base, key, value, fmt::format("{}: common", study.path));
  for (const auto& [key, value] : setting.set)
    replace(base, key, value, fmt::format("{}: settings.{}.set", study.path, setting.name));
  place_setting_seeds(base, study.base_kind, setting.name, fmt::format("Study {}, setting '{}' (generated; do not edit)", study.path, setting.name),
                      setting.seeds);
  YAML::Emitter out;
  out << base;
  std::string keys;
  for (const auto& [key, value] : study.common) keys += " " + key;
  if (!study.common.empty() && !setting.set.empty()) keys += " (common), then";
  for (const auto& [key, value] : setting.set) keys += " " + key;
  return fmt::format("# Generated by softpack-study from {} (setting '{}'): {} with{} replaced.\n", study.path, setting.name,
                     study.base, keys.empty() ? " nothing" : keys) +
         out.c_str() + "\n";
}

double setting_number(const Study& study, const StudySetting& setting, const std::string& key) {
  const std::string where = fmt::format("{}: setting '{}'", study.path, setting.name);
  const StudySetting& source = setting.runs() ? setting : study.setting(setting.of);
  const auto [parent, last] = parent_of(YAML::Load(setting_profile_text(study, source)), key, where);
  const YAML::Node value = std::as_const(parent)[last];
  double number = 0.0;
  bool flag = false;
  if (value && value.IsScalar() && YAML::convert<double>::decode(value, number)) return number;
  if (value && value.IsScalar() && YAML::convert<bool>::decode(value, flag)) return flag ? 1.0 : 0.0;
  throw InputError(fmt::format("{}: {} is not a number of its profile", where, key));
}

}  // namespace softpack
