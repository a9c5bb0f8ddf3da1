// The response report (docs/studies.md): how the normal law answers one key of the profile. The
// study's settings (and its reference) each set the same single key to another value; for each
// one that runs, Fn at the study's compare.Fn_delta_n in both scenes, mean ± standard error over
// its seeds (analysis/seed_statistics.hpp), its change against the reference in units of their
// combined standard error (z), and the CPU time of its packings and normal sweeps.
#pragma once
#include <string>

#include "report/study_file.hpp"

namespace softpack {

/// Reads the normal results under `data_dir` (<dir>/<setting>/normal/...); settings not run yet
/// are listed as such. Writes table.md and response.dat (value of the key, CPU seconds, then per
/// scene and Δn: Fn, its error, Fn over the reference's and its error — NaN where the reference
/// does not tell its Fn from zero —: the figure's columns) into `out_dir`; returns the table.
std::string write_response_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                  const std::string& title);

}  // namespace softpack
