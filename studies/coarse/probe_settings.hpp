// The many-body probe's plan (issue 33; experiments/many-body.yaml, section `many_body_probe`;
// paper/many-body.md): which soft-particles (the coarse-grain settings' generator, packing seeds,
// radii) are pressed in which arrangements (coarse/multi_contact.hpp) to which Δn, which
// arrangements fit the candidate laws and which are only predicted, the selection rule and the
// media validation's criterion — all read and checked here, before any run.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
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
  /// Each kind of pressing body (wall, grain-X, soft) with its arrangements, in the plan's order.
  std::vector<std::pair<std::string, std::vector<std::string>>> body_groups;
  /// The fourth part (`confined`; paper/many-body.md, "Next: the soft-soft contact under
  /// confinement"): BODY+walls-D kinds (coarse/multi_contact.hpp) with their arrangements, run as
  /// bodies-KIND like body_groups' but not in the second part's analysis. Absent: none.
  std::vector<std::pair<std::string, std::vector<std::string>>> confined_groups;
  /// A confined kind given as {arrangements, delta_n} (the seventh part's) runs its own Δn grid;
  /// the others run delta_n.
  std::map<std::string, std::vector<double>> kind_delta_n;
  /// The Δn a group of bodies-KIND runs through (KIND's own grid, else delta_n).
  const std::vector<double>& delta_n_of(const std::string& kind) const;
  std::vector<std::string> shear_arrangements;
  std::vector<double> shear_delta_n, shear_ht;  ///< Δn; the slides ht / Rs
  /// The law's third version (`third_version`; paper/many-body.md, "Next"): which runs fit and
  /// which test each of its parts. Absent: no third version is analysed.
  struct ThirdVersionPlan {
    std::vector<std::string> count_forms;                ///< volumetric (E summed), volumetric-union
    std::vector<std::string> count_fit, count_held_out;  ///< arrangements of the `wall` bodies, beside fit and held_out
    std::vector<std::string> grain_fit, grain_held_out;  ///< grain-X kinds of `bodies`
  };
  std::optional<ThirdVersionPlan> third;
  /// A soft-soft law's analysis on the confined runs (coarse/probe_soft_soft.hpp): its forms and
  /// which runs fit and test them, as NAME:KIND of confined (the plan's `fit` or `held_out`
  /// arrangements of each of its `kinds`, or of `held_out_kinds`).
  struct SoftSoftPlan {
    std::vector<std::string> forms;          ///< volumetric-union, onset-shift, stress, stress-normal, stress-lateral
    std::vector<std::string> fit, held_out;  ///< NAME:KIND of confined_groups
    bool joint_beta_ss = false;              ///< the sixth's: β_ss fitted with κ (else the baseline's)
  };
  /// `fourth_version` (paper/many-body.md, "The fourth part's analysis"; against the third
  /// version's soft-soft law), `fifth_version` ("Next: the soft-soft push carried by the
  /// neighbours' stress"; against the fourth's) and `sixth_version` ("Next: the neighbour's stress
  /// along the contact"; against the fifth's). Absent: none (each needs the one before).
  std::optional<SoftSoftPlan> fourth, fifth, sixth;
  /// `seventh_version` ("Next: a grain or a wall pressing a confined soft-particle"): a grain-X or
  /// wall at the first contact of confined kinds, its forms union-refit, stress, stress-joint
  /// (coarse/probe_body.hpp) against the fifth version's law; fit and held_out as NAME:KIND.
  std::optional<SoftSoftPlan> seventh;
  /// The media seeds each version of the law is judged on: 1, validation.media_seeds (the first
  /// law's); N >= 2, validation.vN_media_seeds (none before that version). No seed in two.
  std::map<int, std::vector<std::uint64_t>> media_seeds;
  /// Those of `version`; InputError naming its key when the plan has none.
  const std::vector<std::uint64_t>& media_seeds_of(int version) const;
  double strain_lo = 0.0, strain_hi = 0.0;
  double bound_in_standard_errors = 0.0;
  std::string section_text;           ///< the section as read (provenance)
  /// What decides each group of runs (seed: the walls' arrangements; bodies-KIND; shear), as text.
  std::vector<std::pair<std::string, std::string>> runs_text;

  /// The groups of runs (seed, bodies-KIND, shear) with their stamps (make's: a group's runs are
  /// redone when its stamp changes, not when the plan's selection, validation or another group
  /// do): a hash of what decides them and the release.
  std::vector<std::pair<std::string, std::string>> runs_stamps(const std::string& release) const;
  /// "# stamp HASH\n": the first line of a file of the group of `part` (walls: seed; bodies with
  /// `kind`: bodies-KIND; shear), which make compares with the group's stamp now (workflow/coarse.mk),
  /// so the results say what decided them and a fresh clone reruns nothing.
  std::string stamp_line(const std::string& part, const std::string& kind, const std::string& release) const;
  /// The kinds of body_groups, in order.
  std::vector<std::string> body_kinds() const;
  /// The kinds of confined_groups, in order.
  std::vector<std::string> confined_kinds() const;
  /// Those with a soft-particle at the first contact (the fourth to sixth parts': soft=true), or
  /// with a grain or a wall there (the seventh's: soft=false).
  std::vector<std::string> confined_kinds(bool soft) const;

  /// The fit arrangements, then the held-out ones.
  std::vector<std::string> arrangements() const;
  /// The arrangements of `kind` as NAME:KIND (InputError for a kind in neither body_groups nor confined_groups).
  std::vector<std::string> bodies(const std::string& kind) const;
  /// The settings with the shell of radius `radius` (a name of `radii`; InputError otherwise).
  CoarseGrainSettings settings_at(const std::string& radius) const;
};

/// The law's versions a plan may judge on media (1 to this), and the key of each one's seeds:
/// media_seeds (1), vN_media_seeds.
constexpr int kLawVersions = 9;
std::string media_seeds_key(int version);

/// Reads and checks the plan; InputError names the file, the key and what is allowed.
/// `root_dir`: where the settings path starts.
ManyBodyProbe read_many_body_probe(const std::string& path, const std::string& root_dir = ".");

}  // namespace softpack
