// The report kind `coarse` (issue 30): a study of the coarse-grain settings (its base
// experiments/coarse-grain.yaml; docs/coarse-grain.md), each setting's comparison of the resolved
// and the soft-particle medium (coarse/report.hpp) in <out>/<setting>/, and a table across them.
#pragma once
#include <string>

#include "report/study_file.hpp"

namespace softpack {

/// Writes <out_dir>/<setting>/{coarse-grain.md, curves.dat, summary.json} for every setting with
/// runs of both models on a seed, and table.md and coarse.json across the settings (a setting
/// `of` another compares that one's runs on its own seeds); returns the table.
std::string write_coarse_study_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                      const std::string& title);

}  // namespace softpack
