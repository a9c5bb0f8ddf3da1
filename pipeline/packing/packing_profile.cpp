#include "packing/packing_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "profile/profile.hpp"
#include "core/error.hpp"
#include "io/sha256.hpp"
#include "packing/nested.hpp"

namespace softpack {

PackingProfile parse_packing(const ConfigNode& root) {
  root.allow_only(profile_sections());
  const ConfigNode n = root.at("packing");
  PackingProfile out;
  if (const auto import = n.find("import")) {  // packings made elsewhere: no generator
    n.allow_only({"import", "profile_bins"});
    out.import = parse_import(*import, parse_seeds(root));
    out.profile_bins = 40;
    if (const auto b = n.find("profile_bins")) {
      const long bins = b->integer();
      if (bins < 1 || bins > 100000) b->fail(fmt::format("{} is not allowed; allowed: 1 <= bins <= 100000", bins));
      out.profile_bins = static_cast<int>(bins);
    }
    if (out.import->shell == ShellSource::given) out.parameters.Rs = out.import->shell_radius * out.import->length_unit;
    return out;
  }
  n.allow_only({"import", "Rs", "r_max_over_Rs", "polydispersity", "exponent", "beta", "trials", "shell_is_neighbour",
                "nearest_neighbour", "level_ratio", "profile_bins", "levels"});
  PackingParameters& p = out.parameters;
  p.Rs = n.at("Rs").number();
  p.r_max = n.at("r_max_over_Rs").number() * p.Rs;
  p.polydispersity = n.at("polydispersity").number();
  p.exponent = n.at("exponent").number();
  p.beta = n.at("beta").number();
  p.trials = n.at("trials").integer();
  p.shell_is_neighbour = n.at("shell_is_neighbour").boolean();
  if (const auto nearest = n.find("nearest_neighbour")) {  // optional: surface when absent (releases <= 0.4.0)
    try {
      p.nearest_neighbour = parse_nearest_neighbour(nearest->string());
    } catch (const InputError& e) {
      nearest->fail(e.what());
    }
  }
  p.level_ratio = n.at("level_ratio").number();
  const long bins = n.at("profile_bins").integer();
  if (bins < 1 || bins > 100000) n.at("profile_bins").fail(fmt::format("{} is not allowed; allowed: 1 <= bins <= 100000", bins));
  out.profile_bins = static_cast<int>(bins);
  try {
    validate(p);
  } catch (const InputError& e) {
    throw root.locate(e);
  }
  if (const auto levels = n.find("levels")) {  // optional: 1 (grains only) when absent
    out.levels = static_cast<int>(std::clamp<long>(levels->integer(), -1, 1000));
    try {
      validate_levels(p, out.levels);
    } catch (const InputError& e) {
      throw root.locate(e);
    }
  }
  return out;
}

double shell_radius(const PackingProfile& profile, const std::vector<std::uint64_t>& seeds) {
  if (!profile.import || profile.import->shell == ShellSource::given) return profile.parameters.Rs;
  return import_packing(*profile.import, seeds.at(0)).Rs;
}

std::string profile_stamp(const ConfigNode& root, const std::string& stage, const std::string& release) {
  const PackingProfile packing = parse_packing(root);
  std::string extra = packing.import ? import_sources_text(*packing.import) : "";
  // The soft content's law files by their content (docs/nested.md), not their names or times.
  if (stage != "packing")
    if (const auto content = root.find("content"))
      for (const char* key : {"laws", "many_body"})
        if (const auto laws = content->find(key)) {
          if (!std::filesystem::is_regular_file(laws->string()))
            laws->fail(fmt::format("{}: no such file: {} (docs/nested.md)", laws->string(),
                                   std::string(key) == "laws" ? "the law file of the level below, made by its study first"
                                                              : "the law file of the many-body law"));
          extra += fmt::format("content.{} sha256 {}\n", key, sha256_of_file(laws->string()));
        }
  return stage_stamp(root, stage, release, extra);
}

}  // namespace softpack
