// The verdict file of a profile (softpack-table --criteria; tables/verdict.json beside
// tables/verdict.md and tables/verdict.tex): the preregistered fit selection over both scenes, every
// coefficient against the paper with its tolerance and status, the published curves against our
// averages, and Table 2's unit (analysis/verdict.hpp, analysis/fit_selection.hpp). One source for
// the report's verdict table (paper/generated, from the JSON) and the regression tests.
//
//   {"criteria": path, "profile_fit": {"scene": {"judged", "jackknife"}}, 
//    "selection": {"chosen", "why", "any_stable", "profile_fit_is_chosen",
//                  "candidates": {"name": {"scene": {"a","b","c","delta","chi2_per_dof","runs_z",
//                                 "jackknife_b","jackknife_delta","stable","adequate","reason"}}}},
//    "unit": {"readings", "q": {"scene": [..]}, "selected", "test_q", "passed"},
//    "lines": [{"table","scene","key","ours","error","paper","deviation","tolerance","status"}],
//    "curves": [{"scene","points","within_two","median_abs_z","ratio_min","ratio_max","joint_chi2","joint_p"}],
//    "reproduced", "judged", "provenance"}
#pragma once
#include <string>
#include <vector>

#include "analysis/fit_selection.hpp"
#include "analysis/verdict.hpp"
#include "formats/fit_file.hpp"

namespace softpack {

struct VerdictInputs {
  std::string criteria_path, provenance;
  std::vector<FitEstimates> fits;  ///< one per scene, with candidates, judged, jackknife
  fit::FitCriteria fit_criteria;
  fit::Selection selection;
  bool profile_fit_is_chosen = false;
  verdict::Verdict verdict;
};

std::string verdict_json_text(const VerdictInputs& v);
std::string verdict_markdown(const VerdictInputs& v);
/// The verdict table as a booktabs tabular (rows: table, scene, coefficient; ours, paper,
/// deviation, tolerance, status).
std::string verdict_latex(const VerdictInputs& v);

}  // namespace softpack
