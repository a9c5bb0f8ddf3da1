#include "config/profile.hpp"

#include <fmt/format.h>

#include <set>

#include "core/error.hpp"

namespace softpack {

const std::vector<std::string>& profile_sections() {
  // "description" is free text for people; no stage reads it, so editing it reruns nothing.
  // "watchdog" holds the thresholds that stop a run gone wrong (sim/watchdog.hpp): it changes
  // no result, so no stage stamp or recorded configuration includes it.
  static const std::vector<std::string> sections{"profile",    "description", "seeds",  "material",   "packing",
                                                 "simulation", "relaxation",  "normal", "tangential", "watchdog"};
  return sections;
}

PackingProfile parse_packing(const ConfigNode& root) {
  root.allow_only(profile_sections());
  const ConfigNode n = root.at("packing");
  n.allow_only({"Rs", "r_max_over_Rs", "polydispersity", "exponent", "beta", "trials", "shell_is_neighbour",
                "level_ratio", "profile_bins"});
  PackingProfile out;
  PackingParameters& p = out.parameters;
  p.Rs = n.at("Rs").positive();
  p.r_max = n.at("r_max_over_Rs").in_range(0.0, true, 1.0, true) * p.Rs;
  p.polydispersity = n.at("polydispersity").in_range(1.0, true, 1e6, false);
  p.exponent = n.at("exponent").in_range(1.0, true, 20.0, false);
  p.beta = n.at("beta").positive();
  const long trials = n.at("trials").integer();
  if (trials < 1) n.at("trials").fail(fmt::format("{} is not allowed; allowed: trials >= 1", trials));
  p.trials = trials;
  p.shell_is_neighbour = n.at("shell_is_neighbour").boolean();
  p.level_ratio = n.at("level_ratio").in_range(1.0, true, 1e3, false);
  const long bins = n.at("profile_bins").integer();
  if (bins < 1 || bins > 100000) n.at("profile_bins").fail(fmt::format("{} is not allowed; allowed: 1 <= bins <= 100000", bins));
  out.profile_bins = static_cast<int>(bins);
  validate(p);
  return out;
}

std::string section_text(const ConfigNode& root, const std::string& section) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << section << YAML::Value << root.at(section).yaml() << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
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
