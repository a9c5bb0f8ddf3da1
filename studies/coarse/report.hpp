// The comparison of the two models of the coarse-grain validation (one setting of a study of the
// coarse-grain settings: report kind `coarse`, report/coarse_report.hpp; docs/coarse-grain.md): over the seeds that ran both, on the common strain grid of the settings
// (each run's curve interpolated linearly in strain, loading and unloading apart),
//
//   per model   the mean and standard error over seeds of sigma_zz (top wall), K0 =
//               sigma_lateral / sigma_zz, the solid fraction and Z;
//   paired      the difference soft - resolved of each seed, its mean and standard error;
//   agreement   sigma_zz of the soft model agrees at a strain when the mean difference is within
//               2 standard errors of the resolved model's seed-to-seed spread of the mean plus
//               that of the soft model's (2 sqrt(se_a^2 + se_b^2)); the report states the largest
//               loading strain up to which every point agrees;
//   within the laws  the last loading strain before any seed's soft run evaluates a contact beyond
//               the laws' measured range (its stress past it rests on Eq. 7 outside its grid);
//   speed-up    CPU time of the resolved run / that of the soft run, per seed, and its mean;
//   shear       (phase 2) the same on the grid of the top wall's displacement, with tau;
//   paired shift  a setting's soft runs against another's on the same media and the same resolved
//               runs (paired_shift): per medium the difference of the two soft σzz over the resolved
//               σzz at the last loading strain both are within their laws, its mean and standard
//               error (the media's own spread cancels in it).
//
// Written to `out`: coarse-grain.md (the table, with what was compared), curves.dat (the columns
// the figure draws, a block per phase) and summary.json.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/seed_statistics.hpp"  // MeanError
#include "coarse/result_file.hpp"

namespace softpack {

/// One grid point of the comparison.
struct CoarsePoint {
  double strain = 0.0;
  int phase = 1;     ///< 1 loading, -1 unloading, 2 shear (then `shear` is the grid's variable)
  double shear = 0.0;
  MeanError sigma[2], K0[2], fraction[2], Z[2];  ///< [0] resolved, [1] soft
  MeanError tau[2];                              ///< the shear stress on the top wall [Pa]
  MeanError sigma_difference;                    ///< soft - resolved, paired by seed
  std::vector<double> sigma_seed[2];             ///< σzz of each seed (CoarseComparison::seeds' order; NaN: no value)
  bool agrees = false;
};

struct CoarseComparison {
  std::vector<std::uint64_t> seeds;
  std::vector<CoarsePoint> points;
  double agreement_strain = 0.0;  ///< every loading point up to it agrees
  std::vector<double> cpu[2];     ///< per seed [s]
  std::vector<double> speedup;    ///< per seed
  MeanError mean_speedup;
  std::int64_t spheres[2] = {0, 0}, bodies = 0, beyond_range = 0;
  double max_dn = 0.0;
  /// The last loading strain up to which no seed's soft run met a contact beyond the laws' range
  /// (strain_within_laws, the smallest over the seeds): NaN when a run does not count them row by row.
  double within_laws_strain = std::numeric_limits<double>::quiet_NaN();
};

/// A setting's soft runs against a base setting's on the same media and resolved runs.
struct PairedShift {
  double strain = 0.0;  ///< e*: the last loading strain both settings' soft runs are within their laws
  MeanError q;          ///< per medium (σzz soft − σzz soft of the base) / σzz resolved at e*: mean, standard error
  MeanError ratio[2];   ///< σzz soft / σzz resolved at e* (means over seeds): [0] the base's, [1] the setting's
  /// +1: mean q > 2 se (the setting carries more), −1: mean q < −2 se, 0: within.
  int sign() const { return q.mean > 2.0 * q.error ? 1 : q.mean < -2.0 * q.error ? -1 : 0; }
};

/// The paired shift of `c` against `base`; none (with the reason in `why`) when they are not runs of
/// the same seeds and resolved runs, or either's soft runs do not count the contacts beyond their
/// laws or meet one from their first row.
std::optional<PairedShift> paired_shift(const CoarseComparison& base, const CoarseComparison& c, std::string* why = nullptr);

/// The comparison of paired runs (resolved[k] and soft[k] of the same seed).
CoarseComparison compare_coarse(const std::vector<CoarseResult>& resolved, const std::vector<CoarseResult>& soft, double strain,
                                double unload_strain, double step, double shear = 0.0, double shear_step = 0.0);

/// A run's results file in a setting's folder `dir` (workflow/coarse.mk): DIR/<model>/seed-S.h5.
std::string coarse_run_path(const std::string& dir, CoarseModel model, std::uint64_t seed);

/// The comparison of the runs in `dir` of the settings' seeds that have both; none when none has.
std::optional<CoarseComparison> coarse_comparison(const CoarseGrainSettings& s, const std::string& dir);

/// Writes the comparison's coarse-grain.md, curves.dat and summary.json into `out`; `label` says
/// whose settings they are (the study and the setting).
void write_coarse_report(const CoarseComparison& c, const CoarseGrainSettings& s, const std::string& label, const std::string& out);

/// "mean ± error" (the mean by fmt_value, the error to 2 significant digits), the mean alone when
/// the error is undefined, "–" when the mean is: the coarse-grain reports' cells.
std::string coarse_pm(const MeanError& m, const char* fmt_value = "{:.4g}");

}  // namespace softpack
