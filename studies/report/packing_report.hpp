// The packings of a study's settings (docs/packing.md, docs/studies.md): report kinds that read
// only the packing stage's files (<dir>/<setting>/packings/seed-N.h5, `stages: [packings]`).
//
//   packings      how the generator's parameters set the packing: per setting of the study's
//                 `vary`, the sphere count, the solid fraction, the fitted size exponent b, the
//                 depletion length next to the shell and the generation time, mean ± standard
//                 error over the seeds (analysis/seed_statistics.hpp)
//   density-rule  the preregistered density rule (experiments/criteria.yaml `density`,
//                 paper/preregistration.md) over the study's `grid`: among the settings whose mean
//                 solid fraction is within the criteria's margin of the densest, the one of least
//                 mean generation time
//
// The statistics are recomputed from each packing (packing/statistics.hpp) with its profile's
// profile_bins; the time is the packing's own record (its provenance, wall-clock seconds).
#pragma once
#include <string>

#include "report/study_file.hpp"

namespace softpack {

/// Writes table.md and packing-density.dat (a gnuplot block per varied key: value, then mean and
/// error of spheres, solid fraction, b, depletion length [m], seconds) into `out_dir`; returns
/// the table. A setting not run yet is an InputError naming its file.
std::string write_packings_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                  const std::string& title);

/// Writes table.md and density-rule.json (the margin, the densest solid fraction, the seeds,
/// every setting with its grid values and statistics, the chosen one) into `out_dir`; returns
/// the table.
std::string write_density_rule_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                      const std::string& title);

}  // namespace softpack
