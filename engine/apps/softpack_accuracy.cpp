// softpack-accuracy: the fidelity study (report/accuracy_study.hpp, report/accuracy_report.hpp).
//
//   softpack-accuracy profiles --study experiments/accuracy-cost.yaml --out-dir DIR
//       writes DIR/<setting>.yaml for the reference and every setting that runs (a file is
//       rewritten only when its text changes) and prints their names, the reference first
//   softpack-accuracy report --study ... --data DIR --out-dir DIR/report
//       compares every setting with the reference: table.md, pareto.dat, report.json
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <filesystem>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "report/accuracy_report.hpp"
#include "report/accuracy_study.hpp"

int main(int argc, char** argv) {
  using namespace softpack;
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
  if (const auto code = parse_command_line(app, argc, argv, "softpack-accuracy")) return *code;
  try {
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
    fmt::print("{}", write_accuracy_report(accuracy_report(study, data_dir), out_dir, title));
    return 0;
  } catch (...) {
    return exit_on_error("softpack-accuracy");
  }
}
