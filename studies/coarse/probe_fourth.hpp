// The probe's fourth part analysed (issue 33; paper/many-body.md, "The fourth part's analysis",
// written before any of it was computed; experiments/many-body.yaml, `fourth_version`): the
// soft-soft law's many-body forms on a resolved soft-particle pressed by another while walls
// confine it (the confined kinds, coarse/multi_contact.hpp's BODY+walls-D).
//
// Each form is applied as the engine applies a soft-soft law, the mean rule: o is the mean over
// the two soft-particles of their caps' union less this contact's cap — in the probe half the
// centre's, the pressing soft-particle having no other contact; X the soft-soft single contact
// (Eq. 7 on one:soft):
//
//   third             the third version's law: volumetric-union with the law file's β_ss (not fitted)
//   volumetric-union  F = X(d*) a(Δn) / a(d*), d* the depth of the cap of volume v(Δn) + β o
//   onset-shift       F = X(d*) a(Δn) / a(d*), d* = Δn + γ o
//
// β and γ in [0, 10], fitted on the plan's `fit` of every confined kind with the soft
// arrangements of `bodies`; the form with the least error on `held_out` (both radii) is chosen,
// and enters the engine only if that error is below the third version's at each radius. A point
// counts when the measured or the predicted force is above the floor (ProbeLaw::count_predicted_force).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "coarse/probe_third.hpp"

namespace softpack {

struct FourthVersion {
  struct Form {
    std::string name;       ///< third, volumetric-union, onset-shift
    FittedValue parameter;  ///< the engine's β_ss or γ (the mean rule's); its se by the jackknife over the seeds
    ProbeError fit, held_out, unconfined;  ///< unconfined: the soft arrangements of bodies (in the fit)
    std::map<std::string, ProbeError> held_out_by_radius;
    std::map<std::string, ProbeError> by_arrangement;  ///< every arrangement of the fit and the held-out runs
  };
  std::vector<Form> forms;  ///< the third version's first
  std::string chosen;       ///< by the plan's rule
  bool enters_engine = false;
  std::vector<std::string> notes;
};

/// The analysis; `soft` the bodies files' points (their soft arrangements are used), `confined`
/// the confined kinds' (the first contact's force is the measured one), `beta_ss` the third
/// version's.
FourthVersion analyse_fourth_version(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& soft, const std::vector<ProbeWallForce>& confined,
                                     const FittedValue& beta_ss);

/// The analysis written to OUT/fourth-version.md, .json and .dat (each radius, arrangement and Δn:
/// the measured force's mean and standard error over the seeds, and each form's).
FourthVersion write_fourth_version(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& soft,
                                   const std::vector<ProbeWallForce>& confined, const FittedValue& beta_ss, const std::string& out_dir);

}  // namespace softpack
