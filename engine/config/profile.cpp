#include "config/profile.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "core/error.hpp"
#include "core/fnv1a.hpp"

namespace softpack {

const std::vector<std::string>& profile_sections() {
  static const std::vector<std::string> sections{"profile",    "description", "seeds",  "material",   "packing",
                                                 "simulation", "relaxation",  "normal", "tangential", "watchdog"};
  return sections;
}

const std::vector<std::string>& profile_stages() {
  static const std::vector<std::string> stages{"packing", "normal", "tangential", "average"};
  return stages;
}

const std::vector<std::string>& stage_sections(const std::string& stage) {
  static const std::map<std::string, std::vector<std::string>> sections{
      {"packing", {"packing"}},
      {"normal", {"packing", "material", "simulation", "relaxation", "normal"}},
      {"tangential", {"packing", "material", "simulation", "relaxation", "normal", "tangential"}},
      {"average", {"seeds", "packing", "material", "simulation", "relaxation", "normal", "tangential"}},
  };
  const auto it = sections.find(stage);
  if (it == sections.end())
    throw InputError(fmt::format("stage '{}' is not allowed; allowed: packing, normal, tangential, average", stage));
  return it->second;
}

std::string section_text(const ConfigNode& root, const std::string& section) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << section << YAML::Value << root.at(section).yaml() << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string stage_text(const ConfigNode& root, const std::string& stage) {
  std::string text;
  for (const std::string& s : stage_sections(stage)) text += section_text(root, s);
  return text;
}

std::string stage_stamp(const ConfigNode& root, const std::string& stage, const std::string& version) {
  Fnv1a h;
  h.add("softpack " + version + "\n" + stage_text(root, stage));
  return fmt::format("{:016x}", h.value);
}

std::vector<std::uint64_t> parse_seeds(const ConfigNode& root) {
  std::vector<std::uint64_t> seeds;
  std::set<long> seen;
  for (const ConfigNode& s : root.at("seeds").items()) {
    const long v = s.integer();
    if (v < 0) s.fail(fmt::format("{} is not allowed; allowed: a seed >= 0", v));
    if (!seen.insert(v).second) s.fail(fmt::format("seed {} is listed twice", v));
    seeds.push_back(static_cast<std::uint64_t>(v));
  }
  if (seeds.empty()) root.at("seeds").fail("at least one seed is required");
  return seeds;
}

}  // namespace softpack
