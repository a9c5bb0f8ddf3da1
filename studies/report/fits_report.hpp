// The fits report (docs/fit.md, "The choice"; docs/studies.md): how the Eq. 7 and Eq. 8 fits
// depend on the fit's options and on which soft-particles were measured. Every setting of the
// study sets keys of the `fit` section only, so its sweeps are the reference's (shared by stamp,
// workflow/studies.mk) and its stages are the averages and fits (`stages: [fits]`). For each
// setting and scene, the coefficients of its fit file (softpack-fit --criteria): Eq. 7's a, b, c
// and δ ± their leave-one-seed-out (jackknife) standard errors, Eq. 8's a and b ± the fit's own
// standard errors, and χ²/dof of Eq. 7 over every point as the criteria judge it.
#pragma once
#include <string>

#include "report/study_file.hpp"

namespace softpack {

/// Reads <dir>/<setting>/fits/<scene>.json of the reference and of every setting (a setting
/// whose fits are not there yet is listed as not run); writes table.md and fits.json into
/// `out_dir`; returns the table.
std::string write_fits_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                              const std::string& title);

}  // namespace softpack
