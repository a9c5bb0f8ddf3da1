// The registry of a study's report kinds (issue 30): a study file names its kind (`report:`), and
// softpack-study report writes that kind's report from the settings' results. One entry per
// kind; a new kind is a function that reads the study's results and writes its files, and one
// line of report_kinds.cpp.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "report/study_file.hpp"

namespace softpack {

struct ReportKind {
  std::string name;   ///< what a study file's `report:` says
  std::string title;  ///< the table's first line, before "(study file, release X)"
  std::string files;  ///< what it writes, for --help and the messages
  std::vector<std::string> needs;  ///< the study file's sections it reads (e.g. compare, criteria)
  /// Reads the settings' results under `data_dir` and writes the report into `out_dir`;
  /// returns the table (Markdown) it wrote.
  std::function<std::string(const Study&, const std::string& data_dir, const std::string& out_dir,
                            const std::string& title)>
      write;
  StudyBase base = StudyBase::profile;  ///< the base of the studies it reports (report/study_base.hpp)
};

/// Every kind, in the order of their names.
const std::vector<ReportKind>& report_kinds();
std::vector<std::string> report_kind_names();
/// The kind named `name`; InputError naming the kinds there are.
const ReportKind& report_kind(const std::string& name);

}  // namespace softpack
