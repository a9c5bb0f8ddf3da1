// The coarse-grain validation (issue 17, docs/coarse-grain.md): a two-decade medium simulated
// (a) resolved, every grain of both decades, the second decade's grains in the local packings
// of free shells, and (b) with each local packing replaced by one soft-particle that follows the
// law file. Its settings: experiments/coarse-grain.yaml, section `coarse_grain`.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"
#include "measure/settings.hpp"
#include "packing/generator.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

enum class CoarseModel { resolved, soft };
const char* name(CoarseModel m);
/// "resolved" or "soft"; InputError naming what is allowed otherwise.
CoarseModel parse_coarse_model(const std::string& text);

struct CoarseGrainSettings {
  // The soft-particle: the profile its laws were measured with (material, engine settings,
  // packing with the study's overrides), the law file, and how it meets a solid grain.
  std::string profile;            ///< e.g. experiments/fast.yaml
  SimulationSettings simulation;  ///< that profile's material and `simulation`
  RelaxationDef relaxation;       ///< that profile's `relaxation` (the multi-contact probe's)
  double normal_speed = 0.0;      ///< that profile's `normal.speed` [m/s] (the probe's walls)
  PackingParameters packing;      ///< that profile's packing, with `packing` overrides
  /// that profile's packing.levels: > 1, nested soft-particles (the sites' packings hold
  /// soft-particles of the level below; coarse/medium.hpp, docs/nested.md)
  int levels = 1;
  std::string laws;               ///< law file (formats/law_file.hpp)
  /// a law file whose many-body law the soft-particles follow instead of `laws`' own (empty:
  /// `laws`' own, if it has one): the nested chain's levels measure pairwise laws only
  std::string many_body;
  GrainContactRule grain_contact = GrainContactRule::wall;
  SoftParticlesDef::BeyondRange beyond_range = SoftParticlesDef::BeyondRange::report;
  double shell_mass_fraction = 0.0;  ///< resolved: free shell mass / its grains' mass
  /// soft: the soft-particles' spin held at zero (`rotation: locked`; default free): a bound on
  /// what a rolling and torsion resistance could give (paper/many-body.md), not a law.
  bool spin_locked = false;

  // The medium: first-decade grains from P(r) ~ r^-exponent on [r_min, decade r_min], the
  // local packings' solid volume from the same law one decade below (docs/coarse-grain.md).
  long grains = 0;
  double r_min_over_Rs = 0.0;  ///< r_min of the first decade / Rs
  double decade = 0.0;         ///< r_max / r_min of the first decade
  double exponent = 0.0;
  double initial_fraction = 0.0;  ///< bodies' volume / box volume of the random placement
  double aspect = 0.0;            ///< box height / width
  long placement_trials = 0;
  /// levels > 1: the sites' contents weighed from this many level packings per level below
  /// (packing/nested.hpp sample_contents; the soft model and the resolved estimate only); 0:
  /// every content made (docs/nested.md "What making the contents costs")
  long content_sample = 0;
  /// `plan.levels_added` (levels > 1): the resolved estimate also plans this medium with each
  /// site's soft-particle this many levels deeper at the same Π (coarse/resolved_estimate.hpp;
  /// experiments/three-decades.yaml states the rule); 0: no plan
  int plan_levels_added = 0;

  // Uniaxial (oedometric) compression by the top wall, then unloading.
  double speed = 0.0;          ///< [m/s]
  double strain = 0.0;         ///< loading, of the initial height
  double unload_strain = 0.0;  ///< unloading after it
  double record_strain = 0.0;  ///< a row of the curve every this much strain
  /// Then the platen shear: the top wall moves along +x by `shear` of the initial height (0: none),
  /// a row every `record_shear`, each at rest as the others.
  double shear = 0.0, record_shear = 0.0;
  /// After each increment the wall stands while the medium relaxes this long [s] with the
  /// per-grain velocity quench (scene/relaxation_def.hpp), so that each row is a state at rest
  /// as the laws were measured; 0: the wall never stops.
  double relax = 0.0;
  /// The watchdog's overlap limit (scene key watchdog.max_overlap_fraction) of both models.
  double max_overlap_fraction = WatchdogDef::kMaxOverlapFraction;

  std::vector<std::uint64_t> seeds;
  std::string section_text;  ///< the `coarse_grain` section as read (provenance)
  std::string medium_text;   ///< what a medium depends on: soft_particle.profile and .packing, `medium`
};

/// Reads and checks experiments/coarse-grain.yaml; InputError names the file, the key and what
/// is allowed. `root_dir`: where relative paths (profile, laws) start.
CoarseGrainSettings read_coarse_grain_settings(const std::string& path, const std::string& root_dir = ".");
/// The same of a file already read (a study's generated settings, report/study_file.hpp).
CoarseGrainSettings read_coarse_grain_settings(const ConfigNode& root, const std::string& root_dir = ".");

/// The configuration stamps of the coarse-grain stages (workflow/coarse.mk: a stage reruns when
/// its stamp changes, not when a program is relinked): 16 hex digits of the SHA-256 of "softpack
/// VERSION", the stage and the text of exactly what it reads --
///   medium    the soft-particle profile's path (the medium file records it) and `packing` section,
///             the study's packing overrides, `medium`;
///   resolved  the medium's, the profile's `material` and `simulation` sections, shell_mass_fraction,
///             `compression`;
///   soft      the resolved model's, the law file's SHA-256 (its content, not its time), grain_contact,
///             beyond_range, and `rotation: locked` when set (a free spin leaves the stamp as before).
/// So a variant that changes only how a soft-particle meets a grain keeps its media and resolved runs.
struct CoarseStamps {
  std::string medium, resolved, soft;
};
CoarseStamps coarse_stamps(const std::string& path, const std::string& version, const std::string& root_dir = ".");
CoarseStamps coarse_stamps(const ConfigNode& root, const std::string& version, const std::string& root_dir = ".");

}  // namespace softpack
