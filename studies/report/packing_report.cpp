#include "report/packing_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <filesystem>

#include "analysis/seed_statistics.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "packing/statistics.hpp"
#include "profile/profile.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

// One setting's packings: spheres, solid fraction, fitted b, depletion length [m], seconds.
struct PackingRow {
  MeanError q[5];
};

PackingRow measure_packings(StudyRuns& runs, const Study& study, const StudySetting& s) {
  const std::string folder = s.runs() ? s.name : s.of;
  const int bins = static_cast<int>(setting_number(study, s, "packing.profile_bins"));
  std::vector<double> samples[5];
  for (std::uint64_t seed : s.seeds) {
    const std::string path = packing_path(runs.dir(), folder, seed);
    if (!std::filesystem::exists(path))
      throw InputError(fmt::format("{}: no packing of setting '{}' seed {} (run: make {} SETTINGS=\"{}\")", path, folder, seed,
                                   study.name, folder));
    const PackingFile& p = runs.packing(folder, seed);
    const PackingStatistics st = packing_statistics(p.centres, p.radii, p.Rs, p.parameters.r_max, bins);
    const double values[5] = {static_cast<double>(p.radii.size()), st.solid_fraction, st.exponent.b, st.depletion_length,
                              p.provenance.seconds};
    for (int k = 0; k < 5; ++k) samples[k].push_back(values[k]);
  }
  PackingRow row;
  for (int k = 0; k < 5; ++k) row.q[k] = mean_error(samples[k]);
  return row;
}

// A value as written in the study file, for the JSON: an integer, a number or true/false.
nlohmann::json written_json(const std::string& text) {
  long long i = 0;
  if (const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
      ec == std::errc() && end == text.data() + text.size())
    return i;
  if (text == "true" || text == "false") return text == "true";
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    throw InputError(fmt::format("'{}' is not a number, true or false: the packing reports tabulate numbers", text));
  }
}

std::string packings_provenance(const Study& study, const std::string& title) {
  return fmt::format("{}: softpack-study {}, base {}, seeds {}", title, code_version(), study.base, fmt::join(study.seeds, " "));
}

}  // namespace

std::string write_packings_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                  const std::string& title) {
  if (study.vary.empty()) throw InputError(fmt::format("{}: the report kind 'packings' reads the settings of `vary`", study.path));
  StudyRuns runs(data_dir);
  const std::string prov = packings_provenance(study, title);
  std::string dat = "# " + prov + "\n# the reference's packing section:\n";
  const ConfigNode reference = ConfigNode::load_string(setting_profile_text(study, study.reference), study.path);
  for (std::string line; const char c : section_text(reference, "packing")) {
    if (c != '\n') line += c;
    else dat += "#   " + line + "\n", line.clear();
  }
  dat += "# columns: parameter value spheres spheres_err solid_fraction err exponent err depletion_length[m] err seconds err\n";
  std::string md = "# Packing density study\n\n" + prov +
                   "\n\nMean ± standard error over the seeds; one parameter varied at a time around the reference "
                   "(marked: the reference's value).\n\n| parameter | value | spheres | solid fraction | fitted b | "
                   "depletion length [mm] | seconds |\n|---|---|---|---|---|---|---|\n";
  for (std::size_t a = 0; a < study.vary.size(); ++a) {
    const StudyAxis& axis = study.vary[a];
    const std::string parameter = axis.name();
    if (a > 0) dat += "\n\n";  // a gnuplot index per key
    for (const auto& point : axis.points) {
      const StudySetting& s = study.setting(point.second);
      const PackingRow r = measure_packings(runs, study, s);
      const double value = setting_number(study, s, axis.key);
      dat += fmt::format("{} {:.6g}", parameter, value);
      for (const MeanError& m : r.q) dat += fmt::format(" {:.8g} {:.3g}", m.mean, m.error);
      dat += "\n";
      md += fmt::format("| {} | {} | {:.0f} ± {:.0f} | {:.4f} ± {:.4f} | {:.3f} ± {:.3f} | {:.3f} ± {:.3f} | {:.1f} |\n",
                        parameter, s.runs() ? fmt::format("{:g}", value) : fmt::format("**{:g}**", value), r.q[0].mean,
                        r.q[0].error, r.q[1].mean, r.q[1].error, r.q[2].mean, r.q[2].error, 1e3 * r.q[3].mean,
                        1e3 * r.q[3].error, r.q[4].mean);
    }
  }
  write_files_atomically({{out_dir + "/packing-density.dat", dat}, {out_dir + "/table.md", md}});
  return md;
}

std::string write_density_rule_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                       const std::string& title) {
  if (study.grid.empty())
    throw InputError(fmt::format("{}: the report kind 'density-rule' judges the settings of `grid`", study.path));
  const ConfigNode criteria = ConfigNode::load_file(study.criteria);
  const ConfigNode density = criteria.at("density");
  const double margin = density.at("solid_fraction_margin").number();
  if (!(margin >= 0.0 && margin < 1.0))
    density.at("solid_fraction_margin").fail(fmt::format("must be 0 <= margin < 1, got {}", margin));
  if (study.seeds.size() < 2) throw InputError(fmt::format("{}: seeds: at least two (a standard error needs two)", study.path));
  StudyRuns runs(data_dir);
  const std::size_t n = study.grid.front().points.size();
  std::vector<PackingRow> rows;
  for (std::size_t k = 0; k < n; ++k) rows.push_back(measure_packings(runs, study, study.setting(study.grid.front().points[k].second)));
  double densest = 0.0;
  for (const PackingRow& r : rows) densest = std::max(densest, r.q[1].mean);
  std::size_t chosen = n;
  for (std::size_t k = 0; k < n; ++k)
    if (rows[k].q[1].mean >= densest - margin && (chosen == n || rows[k].q[4].mean < rows[chosen].q[4].mean)) chosen = k;

  const std::string prov = packings_provenance(study, title) + ", criteria " + study.criteria;
  std::string head, line;
  for (const StudyAxis& axis : study.grid) head += axis.name() + " | ", line += "---|";
  std::string md = fmt::format(
      "# The density rule\n\n{}\n\nThe rule ({}, paper/preregistration.md): among the settings whose mean solid fraction is "
      "within {:g} of the densest ({:.4f}), the one of least mean generation time. Mean ± standard error over the seeds.\n\n"
      "| {}spheres | solid fraction | fitted b | seconds | within the margin |\n|{}---|---|---|---|---|\n",
      prov, study.criteria, margin, densest, head, line);
  nlohmann::json settings = nlohmann::json::array();
  for (std::size_t k = 0; k < n; ++k) {
    const PackingRow& r = rows[k];
    const bool within = r.q[1].mean >= densest - margin;
    nlohmann::json j;
    std::string cells;
    for (const StudyAxis& axis : study.grid) {
      j[axis.name()] = written_json(axis.points[k].first);
      cells += axis.points[k].first + " | ";
    }
    md += fmt::format("| {}{:.0f} ± {:.0f} | {:.4f} ± {:.4f} | {:.3f} ± {:.3f} | {:.1f} ± {:.1f} | {}{} |\n", cells, r.q[0].mean,
                      r.q[0].error, r.q[1].mean, r.q[1].error, r.q[2].mean, r.q[2].error, r.q[4].mean, r.q[4].error,
                      within ? "yes" : "no", k == chosen ? " (**chosen**)" : "");
    j["spheres"] = {r.q[0].mean, r.q[0].error};
    j["solid_fraction"] = {r.q[1].mean, r.q[1].error};
    j["exponent"] = {r.q[2].mean, r.q[2].error};
    j["seconds"] = {r.q[4].mean, r.q[4].error};
    j["within_margin"] = within;
    j["setting"] = study.grid.front().points[k].second;
    settings.push_back(j);
  }
  nlohmann::json choice;
  std::string rule;
  for (const StudyAxis& axis : study.grid) {
    choice[axis.name()] = written_json(axis.points[chosen].first);
    rule += (rule.empty() ? "" : ", ") + axis.name() + " = " + axis.points[chosen].first;
  }
  md += fmt::format("\nChosen: {} (setting {}).\n", rule, study.grid.front().points[chosen].second);
  const nlohmann::json j = {{"provenance", prov}, {"margin", margin}, {"densest_solid_fraction", densest},
                            {"seeds", study.seeds}, {"settings", settings}, {"chosen", choice}};
  write_files_atomically({{out_dir + "/table.md", md}, {out_dir + "/density-rule.json", j.dump(2) + "\n"}});
  return md;
}

}  // namespace softpack
