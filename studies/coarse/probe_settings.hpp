// The many-body probe's plan (issue 33; experiments/many-body.yaml, section `many_body_probe`;
// paper/many-body.md): which soft-particles (the coarse-grain settings' generator, packing seeds,
// radii) are pressed in which arrangements (coarse/multi_contact.hpp) to which Δn, which
// arrangements fit the candidate laws and which are only predicted, the selection rule and the
// media validation's criterion — all read and checked here, before any run.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "coarse/settings.hpp"

namespace softpack {

struct ManyBodyProbe {
  std::string settings_path;          ///< the coarse-grain settings (the soft-particle)
  CoarseGrainSettings settings;
  std::vector<std::uint64_t> seeds;   ///< packing seeds
  std::map<std::string, double> radii;  ///< name -> Rs [m] (the settings' grains)
  std::vector<double> delta_n;        ///< increasing, in (0, 1)
  std::vector<std::string> fit, held_out;  ///< arrangement names, disjoint
  std::vector<std::string> candidates;     ///< pairwise, volumetric, ratio
  double force_floor = 0.0;           ///< of F1(largest Δn), in (0, 1)
  double tie_factor = 0.0;            ///< >= 1
  /// The second part (paper/many-body.md): the arrangements again with other pressing bodies,
  /// and the confined shear of walls' arrangements.
  std::vector<std::string> body_arrangements, body_kinds;
  std::vector<std::string> shear_arrangements;
  std::vector<double> shear_delta_n, shear_ht;  ///< Δn; the slides ht / Rs
  std::vector<std::uint64_t> media_seeds;
  std::vector<std::uint64_t> v3_media_seeds;  ///< the third version's media (none before it)
  double strain_lo = 0.0, strain_hi = 0.0;
  double bound_in_standard_errors = 0.0;
  std::string section_text;           ///< the section as read (provenance)
  std::string runs_text;              ///< the keys that decide the runs: settings .. shear, not the analysis' and validation's

  /// The stamp of the runs (make's: a run is redone when it changes, not when the plan's
  /// selection or validation do): a hash of runs_text and the release.
  std::string runs_stamp(const std::string& release) const;

  /// The fit arrangements, then the held-out ones.
  std::vector<std::string> arrangements() const;
  /// Each body arrangement with each kind: NAME:KIND.
  std::vector<std::string> bodies() const;
  /// The settings with the shell of radius `radius` (a name of `radii`; InputError otherwise).
  CoarseGrainSettings settings_at(const std::string& radius) const;
};

/// Reads and checks the plan; InputError names the file, the key and what is allowed.
/// `root_dir`: where the settings path starts.
ManyBodyProbe read_many_body_probe(const std::string& path, const std::string& root_dir = ".");

}  // namespace softpack
