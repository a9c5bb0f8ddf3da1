// The `packing` section of a profile (paper §3): the generator's parameters (packing/generator.hpp,
// whose validate() owns their ranges) and the bins of the packing file's radial profile.
#pragma once
#include "config/yaml_node.hpp"
#include "packing/generator.hpp"

namespace softpack {

struct PackingProfile {
  PackingParameters parameters;
  int profile_bins = 0;  ///< bins of the radial solid-fraction profile
};

/// Reads and validates the `packing` section of a profile file; InputError with file, line and
/// column names the key and what is allowed.
PackingProfile parse_packing(const ConfigNode& root);

}  // namespace softpack
