#include "profile/profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "core/fnv1a.hpp"
#include "core/random.hpp"

namespace softpack {

const std::vector<std::string>& profile_sections() {
  static const std::vector<std::string> sections{"profile",    "description", "seeds",  "material",   "packing",
                                                 "simulation", "relaxation",  "normal", "tangential", "watchdog",
                                                 "fit",        "sliding",     "content"};
  return sections;
}

const std::vector<std::string>& profile_stages() {
  static const std::vector<std::string> stages{"packing", "normal", "tangential", "average", "sliding"};
  return stages;
}

const std::vector<std::string>& stage_sections(const std::string& stage) {
  static const std::map<std::string, std::vector<std::string>> sections{
      {"packing", {"packing"}},
      {"normal", {"packing", "material", "simulation", "content", "relaxation", "normal"}},
      {"tangential", {"packing", "material", "simulation", "content", "relaxation", "normal", "tangential"}},
      // The sliding measurement (issue 16) starts from the normal states, as the tangential one.
      {"sliding", {"packing", "material", "simulation", "content", "relaxation", "normal", "sliding"}},
      // The average stage's results are the averages and the fits (their `fit` section is read by
      // softpack-fit only, but averaging costs seconds: one stamp for both).
      {"average", {"seeds", "packing", "material", "simulation", "content", "relaxation", "normal", "tangential", "fit"}},
  };
  const auto it = sections.find(stage);
  if (it == sections.end())
    throw InputError(fmt::format("stage '{}' is not allowed; allowed: packing, normal, tangential, average, sliding", stage));
  return it->second;
}

bool optional_section(const std::string& section) {
  return section == "fit" || section == "tangential" || section == "sliding" || section == "content";
}

std::string section_text(const ConfigNode& root, const std::string& section) {
  // An optional section left out is no text: a profile without it has the stamps it had before
  // the section existed (and the archives made then stay valid).
  if (optional_section(section) && !root.has(section)) return "";
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << section << YAML::Value << root.at(section).yaml() << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string stage_text(const ConfigNode& root, const std::string& stage) {
  std::string text;
  for (const std::string& s : stage_sections(stage)) text += section_text(root, s);
  return text;
}

std::string stage_stamp(const ConfigNode& root, const std::string& stage, const std::string& version, const std::string& extra) {
  Fnv1a h;
  h.add("softpack " + version + "\n" + stage_text(root, stage) + extra);
  return fmt::format("{:016x}", h.value);
}

std::string recorded_stage_text(const std::string& config) {
  std::size_t at = 0;
  while (config.compare(at, 2, "# ") == 0) {
    const std::size_t end = config.find('\n', at);
    if (end == std::string::npos) return "";
    at = end + 1;
  }
  return config.substr(at);
}

std::string first_difference(const std::string& a, const std::string& b, const std::string& name_a, const std::string& name_b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    const std::size_t ea = std::min(a.find('\n', i), a.size()), eb = std::min(b.find('\n', j), b.size());
    const std::string la = i < a.size() ? a.substr(i, ea - i) : "(none)";
    const std::string lb = j < b.size() ? b.substr(j, eb - j) : "(none)";
    if (la != lb) {
      const auto trim = [](std::string t) { return t.erase(0, std::min(t.find_first_not_of(' '), t.size())); };
      return fmt::format("'{}' in {}, '{}' in {}", trim(la), name_a, trim(lb), name_b);
    }
    i = ea + 1, j = eb + 1;
  }
  return "";
}

void check_stamp(const std::string& path, const std::string& stage, const std::string& recorded, const std::string& expected,
                 const std::string& profile_path) {
  if (recorded.empty() || recorded == expected) return;
  throw InputError(fmt::format("{}: made with another configuration of the {} stage (stamp {}) than {} holds now (stamp {}); "
                               "results of two configurations are never mixed: make it again with this profile (make does)",
                               path, stage, recorded, profile_path, expected));
}

void check_planned_stamp(const std::string& profile_path, const std::string& stage, const std::string& planned,
                         const std::string& now) {
  if (planned.empty() || planned == now) return;
  throw InputError(fmt::format("{}: the {} stage's sections changed since make planned this run (stamp {} then, {} now); "
                               "nothing was computed: run make again, it reruns what the change touches",
                               profile_path, stage, planned, now));
}

std::vector<std::uint64_t> parse_seeds(const ConfigNode& root, const std::string& key) {
  std::vector<std::uint64_t> seeds;
  std::map<std::uint64_t, std::size_t> seen;  // seed -> its first index
  const std::vector<ConfigNode> items = root.at(key).items();
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ConfigNode& s = items[k];
    if (!s.yaml().IsScalar()) s.fail("expected a seed, an integer like 3");
    std::string error;
    const auto v = parse_seed(s.yaml().Scalar(), error);
    if (!v) s.fail(error);
    const auto [first, fresh] = seen.emplace(*v, k);
    if (!fresh)
      s.fail(fmt::format("seed {} is listed twice (first as seeds[{}]); the seeds must be distinct, each is one packing", *v,
                         first->second));
    seeds.push_back(*v);
  }
  if (seeds.empty()) root.at(key).fail("at least one seed is required");
  return seeds;
}

}  // namespace softpack
