#include "packing/packing_profile.hpp"

#include <fmt/format.h>

#include "config/profile.hpp"
#include "core/error.hpp"

namespace softpack {

PackingProfile parse_packing(const ConfigNode& root) {
  root.allow_only(profile_sections());
  const ConfigNode n = root.at("packing");
  n.allow_only({"Rs", "r_max_over_Rs", "polydispersity", "exponent", "beta", "trials", "shell_is_neighbour",
                "nearest_neighbour", "level_ratio", "profile_bins"});
  PackingProfile out;
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
  return out;
}

}  // namespace softpack
