// softpack-accuracy: the fidelity study (report/accuracy_study.hpp, report/accuracy_report.hpp).
//
//   softpack-accuracy profiles --study experiments/accuracy-cost.yaml --out-dir DIR
//       writes DIR/<setting>.yaml for the reference and every setting that runs (a file is
//       rewritten only when its text changes) and prints their names, the reference first
//   softpack-accuracy report --study ... --data DIR --out-dir DIR/report
//       compares every setting with the reference: table.md, pareto.dat, report.json
//   softpack-accuracy calibrate --study experiments/calibrate.yaml --data DIR --out-dir DIR/report
//       the calibration study's report (report/calibration_report.hpp): every setting's laws and
//       packings with their seed-to-seed errors, and their change against the base
//   softpack-accuracy radius --study experiments/radius-study.yaml --data DIR --out-dir DIR/report
//       the radius study's report (report/radius_report.hpp): the laws per radius, their scaling,
//       the friction coefficient, the contact of two radii, and the law file laws.json
//   softpack-accuracy check --data DIR --reference experiments/paper.yaml --candidate experiments/fast.yaml --out-dir DIR
//       the candidate profile against the reference profile on the seeds of both (the fast
//       profile's confirmation, report/fast_check.hpp): table.md, check.json
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <filesystem>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "report/accuracy_report.hpp"
#include "report/accuracy_study.hpp"
#include "report/calibration_report.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"
#include "report/fast_check.hpp"
#include "report/radius_report.hpp"

namespace softpack::apps::accuracy_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-accuracy: the fidelity study, what each knob of a measurement buys and costs (docs/accuracy.md)"};
  app.require_subcommand(1);
  std::string study_path, out_dir, data_dir, title = "Accuracy against cost";
  CLI::App* profiles = app.add_subcommand("profiles", "write the profile of the reference and of every setting that runs");
  profiles->add_option("--study", study_path, "study file, e.g. experiments/accuracy-cost.yaml")->required();
  profiles->add_option("--out-dir", out_dir, "folder of the generated profiles")->required();
  CLI::App* report = app.add_subcommand("report", "compare every setting with the reference (table, Pareto data, JSON)");
  report->add_option("--study", study_path, "study file")->required();
  report->add_option("--data", data_dir, "folder holding <setting>/{packings,normal,tangential}/ of every setting")->required();
  report->add_option("--out-dir", out_dir, "folder of table.md, pareto.dat, report.json")->required();
  report->add_option("--title", title, "first line of the table");
  CLI::App* calibrate = app.add_subcommand("calibrate", "the calibration study's report: every setting's laws and packings, "
                                                        "and their change against the base (table.md, onset.dat, calibration.json)");
  calibrate->add_option("--study", study_path, "study file, e.g. experiments/calibrate.yaml")->required();
  calibrate->add_option("--data", data_dir, "folder holding <setting>/{packings,normal,tangential}/ of every setting")->required();
  calibrate->add_option("--out-dir", out_dir, "folder of table.md, onset.dat, calibration.json")->required();
  calibrate->add_option("--title", title, "first line of the table");
  CLI::App* radius = app.add_subcommand("radius", "the radius study's report: the laws per radius, their scaling, the friction "
                                                  "coefficient, two radii (table.md, radius.json, scaling.dat, friction.dat, laws.json)");
  radius->add_option("--study", study_path, "study file, e.g. experiments/radius-study.yaml")->required();
  radius->add_option("--data", data_dir, "folder holding <setting>/{packings,normal,tangential,sliding}/ of every setting")->required();
  radius->add_option("--out-dir", out_dir, "folder of the report and the law file")->required();
  radius->add_option("--title", title, "first line of the table");
  std::string reference_file, candidate_file;
  std::vector<double> Fn_at{0.3, 0.4, 0.5}, kt_at{0.4, 0.5};
  CLI::App* check = app.add_subcommand("check", "a profile against another on their seeds (the fast profile's confirmation)");
  check->add_option("--data", data_dir, "folder holding <profile>/{packings,normal,tangential}/ of both, e.g. data")->required();
  check->add_option("--reference", reference_file, "reference profile, e.g. experiments/paper.yaml")->required();
  check->add_option("--candidate", candidate_file, "profile checked against it, e.g. experiments/fast.yaml")->required();
  check->add_option("--Fn-at", Fn_at, "Delta_n where Fn is compared (points of both normal grids)")->capture_default_str();
  check->add_option("--kt-at", kt_at, "Delta_n where kt is compared (points of both tangential grids)")->capture_default_str();
  check->add_option("--out-dir", out_dir, "folder of table.md, check.json")->required();
  if (const auto code = parse_command_line(app, argc, argv, "softpack-accuracy")) return *code;
  try {
    if (check->parsed()) {
      // Each profile's folder is its file's name, as the workflow makes it (DATA/<profile>/).
      const auto seeds_of = [](const std::string& file) { return parse_seeds(ConfigNode::load_file(file)); };
      const std::vector<std::uint64_t> seeds = seeds_of(reference_file);
      if (seeds_of(candidate_file) != seeds)
        throw InputError(fmt::format("{} and {} have different seeds: the check compares them on the same soft-particles",
                                     candidate_file, reference_file));
      const FastCheck c = fast_check(data_dir, std::filesystem::path(reference_file).stem().string(),
                                     std::filesystem::path(candidate_file).stem().string(), seeds, Fn_at, kt_at);
      fmt::print("{}", write_fast_check(c, out_dir));
      return 0;
    }
    const AccuracyStudy study = read_accuracy_study(study_path);
    if (profiles->parsed()) {
      std::filesystem::create_directories(out_dir);
      std::vector<const StudySetting*> run{&study.reference};
      for (const auto& s : study.settings)
        if (s.runs()) run.push_back(&s);
      for (const StudySetting* s : run) {
        const std::string path = out_dir + "/" + s->name + ".yaml", text = setting_profile_text(study, *s);
        if (read_text_file(path) != text) write_file_atomically(path, text);
        fmt::print("{}\n", s->name);
      }
      return 0;
    }
    if (radius->parsed()) {
      const RadiusReport r = radius_report(study, data_dir);
      if (radius->count("--title") == 0) title = "Radius and friction (" + study_path + ")";
      const std::string table = write_radius_report(r, study, out_dir, title);
      write_law_file(out_dir + "/laws.json", radius_law_file(r, study, code_version()));
      fmt::print("{}", table);
      return 0;
    }
    if (calibrate->parsed()) {
      fmt::print("{}", write_calibration_report(calibration_report(study, data_dir), out_dir, title));
      return 0;
    }
    fmt::print("{}", write_accuracy_report(accuracy_report(study, data_dir), out_dir, title));
    return 0;
  } catch (...) {
    return exit_on_error("softpack-accuracy");
  }
}

}  // namespace softpack::apps::accuracy_app
