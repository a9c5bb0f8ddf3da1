// The many-body probe's analysis (issue 33; paper/many-body.md, "Preregistration"): the candidate
// laws fitted on the plan's fit arrangements and judged on its held-out ones, by the rule of
// experiments/many-body.yaml.
//
// For wall k of an arrangement with intrusions Δn_1..Δn_n (a probe file's row, coarse/multi_contact.hpp),
// F1 the single-contact force (Eq. 7 fitted to the seeds' mean of the arrangement `one` of the radius),
// v(δ) = δ² (3 − δ) / 4 (a cap's volume over the soft-particle's), a(δ) = 2δ − δ² (its base over π Rs²),
// p(v(δ)) = F1(δ) / a(δ):
//
//   pairwise     F_k = F1(Δn_k)
//   volumetric   F_k = p(ε_k) a(Δn_k),  ε_k = v(Δn_k) + β Σ_{l≠k} v(Δn_l)
//   ratio        F_k = F1(Δn_k) (Σ_l v(Δn_l) / v(Δn_k))^α
//   onset-shift  F_k = F1(d*) a(Δn_k) / a(d*),  d* = Δn_k + γ (E_union − v(Δn_k))   (the fourth part's)
//   any of them with ProbeLaw::stress: + κ p π Rs² a(Δn_k), p = Σ_{l≠k} F_l / (4π Rs²)     (the fifth part's)
//     or p = 3 Σ_{l≠k} F_l (u_l·u_k)² / (4π Rs²) along the contact, 3 Σ_{l≠k} F_l (1 − (u_l·u_k)²) / (8π Rs²)
//     across it (ProbeLaw::stress_form; the sixth part's)
//
// A candidate's error on a set of points: the root mean square of ln(F_predicted / F_measured) over
// the points whose measured force exceeds force_floor × F1(largest Δn), a prediction below that floor
// counted as the floor (with ProbeLaw::count_predicted_force, the fourth part's rule, also the
// points whose predicted force exceeds it, a measured one below counted as the floor).
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "analysis/power_fit.hpp"
#include "coarse/multi_contact.hpp"
#include "coarse/probe_settings.hpp"
#include "contact/soft_particle_law.hpp"

namespace softpack {

/// One wall of one point of a probe file.
struct ProbeWallForce {
  std::string radius, arrangement;
  std::uint64_t seed = 0;
  std::vector<double> delta_n;  ///< every wall's Δn of the point (w_k Δn)
  std::size_t wall = 0;         ///< which of them this is
  double Fn = 0.0;              ///< [N]
  PressingBody body{};          ///< what presses (the arrangement's NAME:BODY; a wall without)
  double E_union = 0.0;         ///< the volume their caps cut together (cap_union_volume), over the soft-particle's
  double others_Fn = 0.0;       ///< the sum of the point's other contacts' measured forces [N]
  double others_along = 0.0;    ///< Σ_{l≠k} F_l (u_l·u_k)²: their share along this contact's line [N]
};

/// Wall `wall` of arrangement `a` (its directions and shares) at the arrangement's Δn `dn`, with
/// its caps' union E_union and the force Fn.
ProbeWallForce probe_point(const ProbeArrangement& a, const std::string& radius, std::uint64_t seed, const std::vector<double>& delta_n,
                           std::size_t wall, double Fn);

/// others_Fn and others_along of each of the n points of one row (its walls in the order of
/// arrangement a's), from their forces Fn.
void set_other_contacts(ProbeWallForce* row, std::size_t n, const ProbeArrangement& a);

/// The walls of a probe file (PROBE_DIR/RADIUS/seed-S.dat); InputError naming the file and line.
std::vector<ProbeWallForce> read_probe_file(const std::string& path, const std::string& radius, std::uint64_t seed);

// The candidates' geometry is the engine's (contact/soft_particle_law.hpp): cap_volume, cap_area, cap_depth.

/// A candidate with its parameter (β or α; none for pairwise) and the F1 of each radius.
/// volumetric-union is volumetric with E the caps' union instead of their sum (the third
/// version's count-of-contacts form (b), paper/many-body.md, "Next"). A grain-X's force is the
/// law's times g(X) = (X / (1 + X))^grain_exponent (the third version's grain factor; 0: none).
struct ProbeLaw {
  std::string name;  ///< pairwise, volumetric, ratio, volumetric-union, onset-shift
  double parameter = 0.0;
  std::map<std::string, fit::PowerLawFit> F1;
  double grain_exponent = 0.0;
  /// A point counts in the error when its measured force is above the floor, or also when the
  /// predicted one is (the fourth part's rule: a moving onset can predict a force where none is
  /// measured); each below it counted as the floor.
  bool count_predicted_force = false;
  /// > 0: the stress term added to the law's force, stress × others_Fn / 4 × a(Δn_k) (κ p π Rs² a
  /// with p = others_Fn / (4π Rs²) and κ = stress; the fifth part's `stress` form, where the mean
  /// rule halves κ as it halves β).
  double stress = 0.0;
  /// Which stress the term takes (the sixth part's forms): the mean (stress), along the
  /// contact's line (stress-normal) or across it (stress-lateral).
  enum class StressForm { mean, normal, lateral };
  StressForm stress_form = StressForm::mean;
  /// The form of a name: stress, stress-normal, stress-lateral (InputError otherwise).
  static StressForm stress_form_of(const std::string& name);
  /// The force of wall w.wall of w's point.
  double predict(const ProbeWallForce& w) const;
  /// The same without the stress term.
  double predict_alone(const ProbeWallForce& w) const;
};

struct ProbeError {
  double rms_log = 0.0;     ///< root mean square of ln(pred / meas)
  double mean_log = 0.0;    ///< their mean (> 0: the law overpredicts)
  std::size_t points = 0;
};

struct ProbeCandidate {
  ProbeLaw law;
  double parameter_error = 0.0;  ///< jackknife over the seeds
  ProbeError fit, held_out;
  std::map<std::string, ProbeError> by_arrangement;  ///< every arrangement (fit and held out)
  std::map<std::string, ProbeError> by_radius;       ///< held-out points of each radius
};

struct ProbeAnalysis {
  std::vector<ProbeCandidate> candidates;
  std::string chosen;          ///< by the selection rule
  bool enters_engine = false;  ///< beats pairwise on every held-out arrangement of >= 2 walls
  std::vector<std::string> notes;
};

/// The points' error under `law`, for the points of the listed arrangements (all when empty).
ProbeError probe_error(const ProbeLaw& law, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                       const ManyBodyProbe& plan);

/// The same with walls[i]'s prediction predict(i) (the law's floors and counting rule; a fit that
/// has the law's forces at hand).
ProbeError probe_error(const ProbeLaw& law, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                       const ManyBodyProbe& plan, const std::function<double(std::size_t)>& predict);

/// F1 of each radius: Eq. 7 (relative residuals, the plan's floor as onset) on the mean over the
/// seeds of the single contact `one` (the arrangement `one`, or `one:BODY` of another body).
std::map<std::string, fit::PowerLawFit> fit_single_contact(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls,
                                                           const std::string& one = "one");
/// `field` of the law (its parameter unless said) in [0, hi] with the least error on
/// `arrangements`: a grid of 1/1000 of the range, then golden sections about its best point.
double fit_parameter(ProbeLaw law, double hi, const std::vector<ProbeWallForce>& walls, const std::vector<std::string>& arrangements,
                     const ManyBodyProbe& plan, double ProbeLaw::*field = &ProbeLaw::parameter);
/// Whether run `s` is in the list `v` (a plan's fit or held-out runs).
inline bool listed(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

/// x in [0, hi] with the least err(x): a grid of `steps`, then golden sections about its best
/// point (a fit with the laws' forces at hand: coarse/probe_soft_soft.cpp, coarse/probe_body.cpp).
template <class Err>
double least_of(const Err& err, double hi, int steps) {
  double best = 0.0, best_e = err(0.0);
  for (int i = 1; i <= steps; ++i)
    if (const double x = hi * i / steps, e = err(x); e < best_e) best = x, best_e = e;
  double a = std::max(0.0, best - hi / steps), b = std::min(hi, best + hi / steps);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 40; ++i) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (err(x1) < err(x2)) b = x2;
    else a = x1;
  }
  const double x = 0.5 * (a + b);
  return err(x) < best_e ? x : best;
}
/// The jackknife standard error over the plan's seeds of what `fit` makes of the points without
/// each seed.
double jackknife_over_seeds(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls,
                            const std::function<double(const std::vector<ProbeWallForce>&)>& fit);
/// Its standard error by the jackknife over the plan's seeds (F1 of `one` and the parameter fitted
/// again without each seed).
double jackknife_parameter(const std::string& name, double hi, const std::vector<ProbeWallForce>& walls,
                           const std::vector<std::string>& arrangements, const ManyBodyProbe& plan, const std::string& one = "one");

/// Everything the rule asks, on the walls of every probe file of the plan.
ProbeAnalysis analyse_probe(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls);

}  // namespace softpack
