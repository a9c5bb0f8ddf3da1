// The `packing` section of a profile (paper §3): the generator's parameters (packing/generator.hpp,
// whose validate() owns their ranges) and the bins of the packing file's radial profile; or,
// instead of the generator's parameters, `import`: packings made elsewhere (packing/import.hpp).
#pragma once
#include <optional>

#include "config/yaml_node.hpp"
#include "core/version.hpp"
#include "packing/generator.hpp"
#include "packing/import.hpp"

namespace softpack {

struct PackingProfile {
  PackingParameters parameters;      ///< generated packings (Rs: the given shell's, imported ones)
  int profile_bins = 0;              ///< bins of the radial solid-fraction profile
  int levels = 1;                    ///< levels of nested soft-particles from these packings down (packing/nested.hpp)
  std::optional<ImportSpec> import;  ///< packings imported by softpack-import, not generated
};

/// Reads and validates the `packing` section of a profile file; InputError with file, line and
/// column names the key and what is allowed.
PackingProfile parse_packing(const ConfigNode& root);

/// The stage's configuration stamp (profile/profile.hpp, stage_stamp) as Make takes it from
/// `softpack-config PROFILE stamp STAGE`: of the release, the stage's sections and, for imported
/// packings, the SHA-256 of every seed's source file (import_sources_text, which refuses two seeds
/// of one content). Every stage records it with its results and compares its inputs' with it.
std::string profile_stamp(const ConfigNode& root, const std::string& stage, const std::string& release = release_version());

/// The shell radius Rs [m] of the profile's packings: the generator's, the given shell's, or (an
/// imported shell read from the file) that of the first seed's import.
double shell_radius(const PackingProfile& profile, const std::vector<std::uint64_t>& seeds);

}  // namespace softpack
