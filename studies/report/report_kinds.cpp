#include "report/report_kinds.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"
#include "report/accuracy_report.hpp"
#include "report/calibration_report.hpp"
#include "report/coarse_report.hpp"
#include "report/fits_report.hpp"
#include "report/nested_report.hpp"
#include "report/packing_report.hpp"
#include "report/radius_report.hpp"
#include "report/response_report.hpp"

namespace softpack {

const std::vector<ReportKind>& report_kinds() {
  static const std::vector<ReportKind> kinds{
      {"accuracy", "Accuracy against cost", "table.md, pareto.dat, report.json (report/accuracy_report.hpp)", {"compare"},
       [](const Study& study, const std::string& data, const std::string& out, const std::string& title) {
         return write_accuracy_report(accuracy_report(study, data), out, title);
       }},
      {"calibration", "Calibration", "table.md, onset.dat, sensitivity.dat, calibration.json (report/calibration_report.hpp)", {"compare"},
       [](const Study& study, const std::string& data, const std::string& out, const std::string& title) {
         return write_calibration_report(calibration_report(study, data), out, title);
       }},
      {"radius", "Radius and friction",
       "table.md, radius.json, scaling.dat, friction.dat and the law file laws.json (report/radius_report.hpp)", {"compare", "radius"},
       [](const Study& study, const std::string& data, const std::string& out, const std::string& title) {
         const RadiusReport r = radius_report(study, data);
         const std::string table = write_radius_report(r, study, out, title);
         write_law_file_if_changed(out + "/laws.json", radius_law_file(r, study, code_version()));
         return table;
       }},
      {"coarse", "Coarse-grain validation",
       "table.md, coarse.json and per setting <setting>/coarse-grain.md, curves.dat, summary.json (report/coarse_report.hpp)", {},
       write_coarse_study_report, StudyBase::coarse_grain},
      {"density-rule", "The density rule", "table.md, density-rule.json (report/packing_report.hpp)", {"grid", "criteria"},
       write_density_rule_report},
      {"fits", "Fit options", "table.md, fits.json (report/fits_report.hpp)", {}, write_fits_report},
      {"nested", "Nested soft-particles",
       "table.md, nested.json and per setting <setting>/laws.json (report/nested_report.hpp)", {"nested", "criteria"},
       [](const Study& study, const std::string& data, const std::string& out, const std::string& title) {
         return write_nested_report(nested_report(study, data), study, out, title);
       }},
      {"packings", "Packing density", "table.md, packing-density.dat (report/packing_report.hpp)", {"vary"},
       write_packings_report},
      {"response", "Response of the normal law", "table.md, response.dat (report/response_report.hpp)", {"compare"},
       write_response_report},
  };
  return kinds;
}

std::vector<std::string> report_kind_names() {
  std::vector<std::string> names;
  for (const ReportKind& k : report_kinds()) names.push_back(k.name);
  return names;
}

const ReportKind& report_kind(const std::string& name) {
  for (const ReportKind& k : report_kinds())
    if (k.name == name) return k;
  throw InputError(fmt::format("no report kind '{}'; allowed: {}", name, fmt::join(report_kind_names(), ", ")));
}

}  // namespace softpack
