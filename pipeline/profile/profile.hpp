// An experiment profile (experiments/<name>.yaml): every parameter of the workflow, in
// sections read by the stages. This is the profile's schema: which sections there are, which
// stage reads which (the one list of them: the stages record these sections with their results,
// softpack-config gives Make their stamps), and their canonical text. The sections' contents
// are read by their owners: packing/packing_profile.hpp, measure/settings.hpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"

namespace softpack {

/// The keys a profile file may hold at its top level.
const std::vector<std::string>& profile_sections();

/// The stages of the workflow, in order: packing, normal, tangential, average.
const std::vector<std::string>& profile_stages();

/// The sections a stage's results depend on (InputError for an unknown stage). `description`
/// (free text) and `watchdog` (when to stop a run gone wrong; it changes no result) are in none.
const std::vector<std::string>& stage_sections(const std::string& stage);

/// Sections a profile may leave out (`fit`: the fit's defaults, analysis/fit_options.hpp;
/// `tangential`: a normal-only profile, whose tangential stage does not exist).
bool optional_section(const std::string& section);

/// Canonical text of a section (YAML, keys in file order, comments dropped), recorded as the
/// provenance of the outputs that depend on it; "" for an optional section left out.
std::string section_text(const ConfigNode& root, const std::string& section);

/// The canonical text of a stage's sections, concatenated: what its results depend on.
std::string stage_text(const ConfigNode& root, const std::string& stage);

/// The stage's configuration stamp: 16 hex digits of a 64-bit FNV-1a hash of "softpack VERSION",
/// the stage's text and `extra` (what else the stage depends on: the digests of imported
/// packings' source files). It changes when a section the stage reads changes, and only then.
std::string stage_stamp(const ConfigNode& root, const std::string& stage, const std::string& version,
                        const std::string& extra = "");

/// The configuration a result records (formats/sweep_file.hpp, provenance/config) without the
/// comment lines that open it (its stage, scene and packings): the profile's canonical text of the
/// stage's sections (stage_text), the same for every seed of one configuration.
std::string recorded_stage_text(const std::string& config);

/// The first line where two configuration texts differ, as "'<line of a>' in A, '<line of b>'
/// in B" (names_a, name_b; "(none)" past the end of one); "" when they are equal.
std::string first_difference(const std::string& a, const std::string& b, const std::string& name_a, const std::string& name_b);

/// The consumers' rule (docs/measurement.md, "One configuration per result"): InputError unless
/// the stamp a file records of the `stage` that made it is `expected`, the stage's stamp of the
/// profile now. The message names the file, the stage, both stamps and the profile, and says what
/// to do. A file written before stamps were recorded records none (""): the caller compares the
/// configuration text it records instead, where it records one.
void check_stamp(const std::string& path, const std::string& stage, const std::string& recorded, const std::string& expected,
                 const std::string& profile_path);

/// A stage run by Make is given the stamp Make planned it with (--stamp; workflow/stamps.mk):
/// InputError when the profile's stamp of that stage now (`now`) differs, the profile having been
/// edited since make read it (a revert before the run ends would otherwise leave results of the
/// edited profile that make takes as up to date). `planned` "": run by hand, nothing to compare.
void check_planned_stamp(const std::string& profile_path, const std::string& stage, const std::string& planned,
                         const std::string& now);

/// The seeds of the profile (`seeds` list, or the list at `key` of `root`): seeds as parse_seed()
/// (core/random.hpp) reads them, distinct.
std::vector<std::uint64_t> parse_seeds(const ConfigNode& root, const std::string& key = "seeds");

}  // namespace softpack
