// The unit of Table 2 (issue 14; paper/paper.tex, "The unit of Table 2"). The paper prints its
// tangential spring constants in "N/m" without saying of what: 0.74 N/m against our hundreds of
// N per metre of ht. A ratio that does not depend on the absolute force level decides between
// the readings: kt/Fn at equal Δn. If the paper's kt is in N per U (U a metre, a millimetre, a
// degree or a radian of α, or a unit of ht/Rs), ours in N/m converts as kt_U = kt · (metres of
// ht per U), and
//
//   q = (kt_ours,U / Fn_ours) / (kt_paper / Fn_paper)     at the same Δn
//
// is 1 for the right reading when both soft-particles are alike in shape of response — whatever
// their absolute stiffness. ht = π Rs α / 180 (paper §4): a degree of α is π Rs / 180 m of ht, a
// radian (or a unit of ht/Rs) Rs m.
#pragma once
#include <string>
#include <vector>

namespace softpack::table {

struct KtReading {
  std::string key;     ///< "m", "mm", "deg", "rad" (experiments/criteria.yaml, table2_unit.readings)
  std::string name;    ///< "per degree of alpha", ...
  std::string unit;    ///< "N/deg", ...
  double metres = 0.0; ///< metres of ht per unit: kt_U = kt[N/m] × metres
};
/// Metres of ht in one degree of α, π Rs / 180 (ht = π Rs α / 180, paper §4).
double metres_per_degree(double Rs);
/// The candidate readings for a shell of radius Rs [m], in a fixed order; with `keys`, those only, in that order
/// (InputError for an unknown key).
std::vector<KtReading> kt_readings(double Rs, const std::vector<std::string>& keys = {});

/// Eq. 7 or 8 as published: a Δn^b + c for Δn >= δ, else 0 (fit::evaluate).
struct PublishedLaw {
  double a = 0.0, b = 0.0, c = 0.0, delta = 0.0;
  double operator()(double dn) const;
};

struct KtUnitPoint {
  double delta_n = 0.0;
  double ours = 0.0, ours_error = 0.0;  ///< kt/Fn measured [1/m of ht] and its standard error
  double paper = 0.0;                   ///< kt/Fn of the published fits [paper's unit / N]
  std::vector<double> q;                ///< per reading: (ours × metres) / paper
  bool established = false;             ///< our Fn and kt both above established_sigmas standard errors: counted in the mean
};

struct KtUnitScene {
  std::string scene;
  std::vector<KtUnitPoint> points;  ///< the Δn where both are measured and positive
  std::vector<double> mean_log_q;   ///< per reading: mean of ln q over the established points (NaN: none)
};

/// kt/Fn of ours (the seed averages: Δn, Fn ± se, kt Δn, kt ± se) against the published fits'
/// at every Δn of our kt grid where all four are positive. Standard error of ours by first-order
/// propagation of the two (independent) standard errors; a point where our Fn or kt is within
/// established_sigmas of its standard errors of zero is listed but not counted in the mean
/// (experiments/criteria.yaml, table2_unit).
KtUnitScene kt_unit_scene(const std::string& scene, const std::vector<double>& delta_n, const std::vector<double>& Fn,
                          const std::vector<double>& Fn_error, const std::vector<double>& kt_delta_n,
                          const std::vector<double>& kt, const std::vector<double>& kt_error, const PublishedLaw& normal,
                          const PublishedLaw& tangential, const std::vector<KtReading>& readings, double established_sigmas);

/// The Markdown report: per scene the points and q of every reading, then each reading's
/// geometric-mean q per scene and the reading closest to 1 on the first scene given.
std::string kt_unit_markdown(const std::vector<KtUnitScene>& scenes, const std::vector<KtReading>& readings);

}  // namespace softpack::table
