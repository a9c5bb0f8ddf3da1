#include "config/profile.hpp"

#include <fmt/format.h>

#include <map>

#include "core/error.hpp"
#include "core/fnv1a.hpp"
#include "core/random.hpp"

namespace softpack {

const std::vector<std::string>& profile_sections() {
  static const std::vector<std::string> sections{"profile",    "description", "seeds",  "material",   "packing",
                                                 "simulation", "relaxation",  "normal", "tangential", "watchdog",
                                                 "fit",        "sliding"};
  return sections;
}

const std::vector<std::string>& profile_stages() {
  static const std::vector<std::string> stages{"packing", "normal", "tangential", "average", "sliding"};
  return stages;
}

const std::vector<std::string>& stage_sections(const std::string& stage) {
  static const std::map<std::string, std::vector<std::string>> sections{
      {"packing", {"packing"}},
      {"normal", {"packing", "material", "simulation", "relaxation", "normal"}},
      {"tangential", {"packing", "material", "simulation", "relaxation", "normal", "tangential"}},
      // The sliding measurement (issue 16) starts from the normal states, as the tangential one.
      {"sliding", {"packing", "material", "simulation", "relaxation", "normal", "sliding"}},
      // The average stage's results are the averages and the fits (their `fit` section is read by
      // softpack-fit only, but averaging costs seconds: one stamp for both).
      {"average", {"seeds", "packing", "material", "simulation", "relaxation", "normal", "tangential", "fit"}},
  };
  const auto it = sections.find(stage);
  if (it == sections.end())
    throw InputError(fmt::format("stage '{}' is not allowed; allowed: packing, normal, tangential, average, sliding", stage));
  return it->second;
}

bool optional_section(const std::string& section) {
  return section == "fit" || section == "tangential" || section == "sliding";
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

std::vector<std::uint64_t> parse_seeds(const ConfigNode& root) {
  std::vector<std::uint64_t> seeds;
  std::map<std::uint64_t, std::size_t> seen;  // seed -> its first index
  const std::vector<ConfigNode> items = root.at("seeds").items();
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
  if (seeds.empty()) root.at("seeds").fail("at least one seed is required");
  return seeds;
}

}  // namespace softpack
