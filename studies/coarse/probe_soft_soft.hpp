// A soft-soft law analysed on the probe's confined runs (issue 33; paper/many-body.md, "The fourth
// part's analysis", "Next: the soft-soft push carried by the neighbours' stress" and "Next: the
// neighbour's stress along the contact", each written
// before what it judges was computed; experiments/many-body.yaml, `fourth_version`,
// `fifth_version`): a resolved soft-particle pressed by another while walls confine it (the
// confined kinds, coarse/multi_contact.hpp's BODY+walls-D), the force on the pressing one.
//
// Each form is applied as the engine applies a soft-soft law, the mean rule: o is the mean over
// the two soft-particles of their caps' union less this contact's cap, p̄ the mean of their other
// contacts' stress Σ F_l / (4π R²) — in the probe half the centre's, the pressing soft-particle
// having no other contact; X the soft-soft single contact (Eq. 7 on one:soft):
//
//   baseline          the law to beat: the third version's (volumetric-union with its β_ss) for
//                     the fourth part, the fourth version's for the fifth, the fifth's for the
//                     sixth (not fitted here)
//   volumetric-union  F = X(d*) a(Δn) / a(d*), d* the depth of the cap of volume v(Δn) + β o
//   onset-shift       F = X(d*) a(Δn) / a(d*), d* = Δn + γ o
//   stress            the baseline's force + κ p̄ π R² a(Δn)
//   stress-normal     the same with p the stress along the contact's line, stress-lateral across it
//                     (the sixth part's, β_ss fitted with κ: ProbeLaw::StressForm)
//
// Each parameter in [0, 10], fitted on the plan's `fit` runs with the soft arrangements of
// `bodies`; the form with the least error on `held_out` (both radii) is chosen, and enters the
// engine only if that error is below the baseline's at each radius. A point counts when the
// measured or the predicted force is above the floor (ProbeLaw::count_predicted_force).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "coarse/probe_third.hpp"

namespace softpack {

struct SoftSoftVersion {
  struct Form {
    std::string name;       ///< the baseline's name (third, fourth, fifth), or the form's (volumetric-union, onset-shift, stress, ...)
    std::string base;       ///< the form it is made on: volumetric-union or onset-shift
    std::string stress;     ///< its stress term's form (stress, stress-normal, stress-lateral); empty: none
    FittedValue parameter;  ///< the engine's β_ss, γ or κ (the mean rule's); its se by the jackknife over the seeds
    FittedValue beta_ss;    ///< a stress form's: the β_ss beneath it (its baseline's, or fitted with κ: joint_beta_ss)
    ProbeError fit, held_out, unconfined;  ///< unconfined: the soft arrangements of bodies (in the fit)
    std::map<std::string, ProbeError> held_out_by_radius;
    std::map<std::string, ProbeError> by_arrangement;  ///< every arrangement of the fit, the held-out and the reported runs
  };
  std::vector<Form> forms;  ///< the baseline's first
  std::string chosen;       ///< by the plan's rule
  bool enters_engine = false;
  std::vector<std::string> notes;
  const Form& form(const std::string& name) const;  ///< InputError when there is none
};

/// The confined runs of the plan that `part` neither fits nor holds out: their errors are reported.
std::vector<std::string> reported_runs(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part);

/// The analysis of `part` (the plan's fourth or fifth); `soft` the bodies files' points (their
/// soft arrangements are used), `confined` the confined kinds' (the first contact's force is the
/// measured one), `baseline` the law to beat (its name, and its form with its β_ss or γ).
SoftSoftVersion analyse_soft_soft(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::vector<ProbeWallForce>& soft,
                                  const std::vector<ProbeWallForce>& confined, const SoftSoftVersion::Form& baseline);

/// The analysis written to OUT/NAME.md, .json and .dat (each radius and confined run of the part:
/// the measured force's mean and standard error over the seeds, and each form's), and the
/// variables figures/confined_soft.gp draws it with (OUT/NAME-vars.gp); `title` heads them.
SoftSoftVersion write_soft_soft(const ManyBodyProbe& plan, const ManyBodyProbe::SoftSoftPlan& part, const std::string& plan_path,
                                const std::vector<ProbeWallForce>& soft, const std::vector<ProbeWallForce>& confined,
                                const SoftSoftVersion::Form& baseline, const std::string& title, const std::string& out_dir,
                                const std::string& name);

}  // namespace softpack
