// The probe's seventh part (issue 33; paper/many-body.md, "Next: a grain or a wall pressing a
// confined soft-particle", written before its runs; experiments/many-body.yaml, `seventh_version`):
// a grain or a wall at the first contact of a soft-particle whose other contacts, walls at Δn = D,
// already press it (coarse/multi_contact.hpp's BODY+walls-D), the force on that body, from the
// shallow intrusions the media's grains make.
//
// For the first contact k at Δn (a grain of radius X Rs: g = (X / (1 + X))^p, p the fifth version's
// grain exponent; a wall: g = 1), U the caps' union, F_l the other contacts' measured forces and X1
// the walls' single contact (Eq. 7 on the first part's `one`, as the third version's):
//
//   fifth         F = g X1(δ*) a(Δn) / a(δ*), v(δ*) = v(Δn) + β_b (U − v(Δn))   the law to beat:
//                 the fifth version's, β_b its grains' or its walls' (not fitted here)
//   union-refit   the same with β_b fitted
//   stress        fifth + κ_b g p π R² a(Δn), p = Σ_{l≠k} F_l / (4π R²) (the soft-particle's own:
//                 no mean rule, the grain or wall has no stress), β_b kept, κ_b fitted
//   stress-joint  the same with β_b and κ_b fitted together
//
// b is the body: every grain-X shares one β and one κ, the wall has its own; each fitted on its own
// runs of the plan's fit, in [0, 10], ± the jackknife over the seeds. Error: the fourth part's (a
// point counts when its measured or predicted force is above the floor). The form with the least
// held-out error (both radii, grains and wall together) is chosen; it enters the engine only if
// that error is below fifth's at each radius.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "coarse/probe_third.hpp"

namespace softpack {

/// The fifth version's law of a soft-particle's contact with a grain or a wall (the third
/// version's count form and grain law, which the fourth and fifth kept).
struct FifthBodyLaw {
  std::string form;  ///< the count form: volumetric-union
  double beta_wall = 0.0, beta_grain = 0.0, grain_exponent = 0.0;
};

struct BodyVersion {
  struct BodyLaw {
    FittedValue beta, kappa;  ///< β_b, κ_b (κ 0: no stress term)
  };
  struct Form {
    std::string name;                     ///< fifth, union-refit, stress, stress-joint
    std::map<std::string, BodyLaw> body;  ///< "grain", "wall"
    ProbeError fit, held_out;
    std::map<std::string, ProbeError> held_out_by_radius;
    std::map<std::string, ProbeError> by_arrangement;  ///< every run of the fit and the held-out
  };
  /// What the fifth version gives of a shallow contact: one kind at one Δn of its grid (Δn < 0.1),
  /// over every arrangement and seed of a radius.
  struct Shallow {
    std::string radius, kind;
    double delta_n = 0.0;
    std::size_t points = 0, pushed = 0;  ///< first contacts; those with a measured force above 0
    double measured = 0.0, fifth = 0.0;  ///< the mean measured force and the fifth version's mean [N]
  };
  std::vector<Form> forms;  ///< fifth first
  std::vector<Shallow> shallow;
  /// Reported, not in the rule: fifth and the chosen form on the earlier parts' runs, where every
  /// contact moves at once (the first part's walls, the second's grains): "walls", "grains".
  std::map<std::string, std::pair<ProbeError, ProbeError>> earlier;
  std::string chosen;       ///< by the plan's rule
  bool enters_engine = false;
  std::vector<std::string> notes;
  const Form& form(const std::string& name) const;  ///< InputError when there is none
};

/// "grain" for a grain-X kind, "wall" for a wall.
std::string body_of(const PressingBody& b);

/// The analysis of `part` (the plan's seventh); `walls` the seed files' points (X1 from their
/// `one`), `confined` the bodies files' points of the grain and wall confined kinds, `grains`
/// the bodies files' points of the grain-X kinds (for BodyVersion::earlier; may be empty).
BodyVersion analyse_body_version(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::vector<ProbeWallForce>& walls,
                                 const std::vector<ProbeWallForce>& confined, const FifthBodyLaw& fifth,
                                 const std::vector<ProbeWallForce>& grains = {});

/// The analysis written to OUT/NAME.md, .json and .dat (each radius and run of the part: the
/// measured force's mean and standard error over the seeds, and each form's), and the variables
/// figures/confined_soft.gp draws it with (OUT/NAME-vars.gp).
BodyVersion write_body_version(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::string& plan_path,
                               const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& confined, const FifthBodyLaw& fifth,
                               const std::vector<ProbeWallForce>& grains, const std::string& out_dir, const std::string& name);

}  // namespace softpack
