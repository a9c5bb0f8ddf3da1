#include "report/fits_report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/types.hpp"
#include "formats/fit_file.hpp"
#include "io/atomic_file.hpp"
#include "report/report_cells.hpp"
#include "report/study_runs.hpp"

namespace softpack {

std::string write_fits_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                              const std::string& title) {
  std::vector<const StudySetting*> settings{&study.reference};
  for (const StudySetting& s : study.settings) {
    // A fit file is of all its setting's seeds: a setting on fewer of them would show another's fit.
    if (!s.runs() && s.seeds != study.setting(s.of).seeds)
      throw InputError(fmt::format("{}: setting '{}' is '{}' on fewer seeds: the fits kind reports each setting's fit files, made on "
                                   "all its seeds; give it the seeds of '{}' or `set` a key", study.path, s.name, s.of, s.of));
    settings.push_back(&s);
  }
  std::string md = fmt::format(
      "# {}\n\nEq. 7's coefficients ± their leave-one-seed-out (jackknife) standard error; Eq. 8's (kt) ± the fit's "
      "standard error; χ²/dof of Eq. 7 over every point as experiments/criteria.yaml judges it.\n",
      title);
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& scene : kStudyScenes) {
    md += fmt::format("\n## {}\n\n| setting | fit | a [N] | b | c [N] | δ | kt a | kt b | χ²/dof |\n"
                      "|---|---|---|---|---|---|---|---|---|\n",
                      scene);
    for (const StudySetting* s : settings) {
      const std::string folder = s->runs() ? s->name : s->of;
      const std::string path = fmt::format("{}/{}/fits/{}.json", data_dir, folder, scene);
      if (!std::filesystem::exists(path)) {
        const auto failed = setting_failure(data_dir, folder);
        md += fmt::format("| {} | {} | {} | | | | | | |\n", s->name, setting_changes(study, *s), failed ? "failed: " + *failed : "not run");
        continue;
      }
      const FitEstimates f = read_fit_file(path);
      const fit::Jackknife jk = f.jackknife.value_or(fit::Jackknife{});
      const auto normal = [&](const char* key, double jk_error) {
        const auto it = f.normal.find(key);
        return it == f.normal.end() ? std::pair{kNaN, kNaN} : std::pair{it->second.value, jk.done ? jk_error : kNaN};
      };
      const auto kt = [&](const char* key) {
        if (!f.tangential || !f.tangential->count(key)) return std::pair{kNaN, kNaN};
        const table::Estimate& e = f.tangential->at(key);
        return std::pair{e.value, e.error};
      };
      const std::pair<double, double> values[6] = {normal("a", jk.a), normal("b", jk.b), normal("c", jk.c),
                                                   normal("delta", jk.delta), kt("a"), kt("b")};
      const double chi2 = f.judged ? f.judged->chi2_per_dof : kNaN;
      md += fmt::format("| {} | {} |", s->name, setting_changes(study, *s));
      nlohmann::json row = {{"setting", s->name}, {"scene", scene}, {"path", path}, {"chi2_per_dof", json_number(chi2)}};
      const char* names[6] = {"a", "b", "c", "delta", "kt_a", "kt_b"};
      for (int k = 0; k < 6; ++k) {
        md += fmt::format(" {} |", value_cell(values[k].first, values[k].second));
        row[names[k]] = {json_number(values[k].first), json_number(values[k].second)};
      }
      md += fmt::format(" {} |\n", std::isfinite(chi2) ? fmt::format("{:.3g}", chi2) : "–");
      rows.push_back(row);
    }
  }
  write_files_atomically({{out_dir + "/table.md", md}, {out_dir + "/fits.json", nlohmann::json{{"title", title}, {"rows", rows}}.dump(2) + "\n"}});
  return md;
}

}  // namespace softpack
