// An experiment profile (experiments/<name>.yaml): every parameter of the workflow, in
// sections read by the stages. Each stage reads only its slice and records it, with the
// seed and code version, in the files it writes.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"
#include "packing/generator.hpp"

namespace softpack {

struct PackingProfile {
  PackingParameters parameters;
  int profile_bins = 0;  ///< bins of the radial solid-fraction profile
};

/// Reads and validates the `packing` section of a profile file.
PackingProfile parse_packing(const ConfigNode& root);

/// The keys a profile file may hold at its top level (the sections of the stages).
const std::vector<std::string>& profile_sections();

/// Canonical text of a section (YAML, keys in file order, comments dropped), recorded as the
/// provenance of the outputs that depend on it.
std::string section_text(const ConfigNode& root, const std::string& section);

/// The seeds of the profile (`seeds` list): non-negative, distinct.
std::vector<std::uint64_t> parse_seeds(const ConfigNode& root);

}  // namespace softpack
