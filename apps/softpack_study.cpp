// softpack-study: a study of settings of a base profile (report/study_file.hpp,
// docs/studies.md), what make's study goals run (workflow/studies.mk).
//
//   softpack-study profiles --study experiments/studies/accuracy.yaml --out-dir DIR
//       writes DIR/<setting>.yaml for the reference and every setting that runs (a file is
//       rewritten only when its text changes) and prints their names, the reference first
//   softpack-study plan --study FILE --data DATA
//       what make needs of the study, as shell assignments: its folder under DATA, the make
//       arguments that run a setting (report/study_base.hpp), its figures (script:data:name)
//   softpack-study share --study FILE --data DIR --setting S --earlier "A B" --release V
//       the stages S takes from an earlier setting, one "stage folder earlier" a line (same stamp,
//       its seeds among the earlier one's; workflow/studies.mk links them)
//   softpack-study report --study FILE --data DIR --out-dir DIR/report [--title T]
//       the report of the study's kind (`report:`; the kinds: report/report_kinds.cpp, and
//       softpack-study report --help)
//   softpack-study check --data DIR --reference experiments/paper.yaml --candidate experiments/fast.yaml --out-dir DIR
//       the candidate profile against the reference profile on the seeds of both (the fast
//       profile's confirmation, report/fast_check.hpp): table.md, check.json
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <sstream>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "core/version.hpp"
#include "report/study_base.hpp"
#include "report/study_file.hpp"
#include "report/fast_check.hpp"
#include "report/report_kinds.hpp"

namespace softpack::apps::study_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-study: a study of settings of a base profile, its profiles, plan and report (docs/studies.md)"};
  app.require_subcommand(1);
  std::string study_path, out_dir, data_dir, title;
  CLI::App* profiles = app.add_subcommand("profiles", "write the profile of the reference and of every setting that runs");
  profiles->add_option("--study", study_path, "study file, e.g. experiments/studies/accuracy.yaml")->required();
  profiles->add_option("--out-dir", out_dir, "folder of the generated profiles")->required();
  CLI::App* plan = app.add_subcommand("plan", "what make needs of the study, as shell assignments: study_dir (its folder under "
                                              "DATA), study_args (the make arguments that run a setting, @SETTING@ its name), study_figures (script:data:name)");
  plan->add_option("--study", study_path, "study file")->required();
  plan->add_option("--data", data_dir, "DATA, the folder the study's own folder is in")->required();
  std::string setting, earlier, release;
  CLI::App* share = app.add_subcommand("share", "the stages a setting shares with an earlier one (same stamp, its seeds among theirs): "
                                                "stage folder earlier, a line each");
  share->add_option("--study", study_path, "study file")->required();
  share->add_option("--data", data_dir, "the study's folder (its profiles/ and <setting>/)")->required();
  share->add_option("--setting", setting, "the setting about to run")->required();
  share->add_option("--earlier", earlier, "the settings run before it, in order, separated by spaces");
  share->add_option("--release", release, "the release the stamps are of (make passes CMakeLists.txt's)")->required();
  std::string kinds;
  for (const ReportKind& k : report_kinds()) kinds += fmt::format("; {}: {}", k.name, k.files);
  CLI::App* report = app.add_subcommand("report", "the study's report, of the kind its file names (`report:`" + kinds + ")");
  report->add_option("--study", study_path, "study file")->required();
  report->add_option("--data", data_dir, "folder holding <setting>/{packings,normal,tangential,...}/ of every setting")->required();
  report->add_option("--out-dir", out_dir, "folder of the report")->required();
  report->add_option("--title", title, "first line of the table (default: the kind's title, the study file and the release)");
  std::string reference_file, candidate_file;
  std::vector<double> Fn_at{0.3, 0.4, 0.5}, kt_at{0.4, 0.5};
  CLI::App* check = app.add_subcommand("check", "a profile against another on their seeds (the fast profile's confirmation)");
  check->add_option("--data", data_dir, "folder holding <profile>/{packings,normal,tangential}/ of both, e.g. data")->required();
  check->add_option("--reference", reference_file, "reference profile, e.g. experiments/paper.yaml")->required();
  check->add_option("--candidate", candidate_file, "profile checked against it, e.g. experiments/fast.yaml")->required();
  check->add_option("--Fn-at", Fn_at, "Delta_n where Fn is compared (points of both normal grids)")->capture_default_str();
  check->add_option("--kt-at", kt_at, "Delta_n where kt is compared (points of both tangential grids)")->capture_default_str();
  check->add_option("--out-dir", out_dir, "folder of table.md, check.json")->required();
  if (const auto code = parse_command_line(app, argc, argv, "softpack-study")) return *code;
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
    const Study study = read_study(study_path);
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
    if (plan->parsed()) {
      std::string figures;
      for (const StudyFigure& f : study.figures) figures += (figures.empty() ? "" : " ") + f.script + ":" + f.data + ":" + f.name;
      const std::string dir = data_dir + "/" + study.out;
      const std::string args = setting_make_args(study.base_kind, dir, study.stages,
                                                 study.archive.empty() ? "FROM_SCRATCH=1" : "ARCHIVE=" + study.archive);
      fmt::print("study_dir='{}'\nstudy_args='{}'\nstudy_figures='{}'\n", dir, args, figures);
      return 0;
    }
    if (share->parsed()) {
      std::vector<std::string> before;
      std::istringstream words(earlier);
      for (std::string w; words >> w;) before.push_back(w);
      for (const SharedStage& s : shareable_stages(study.base_kind, data_dir, setting, before, release))
        fmt::print("{} {} {}\n", s.stage, s.folder, s.earlier);
      return 0;
    }
    const ReportKind& kind = report_kind(study.report);
    if (title.empty()) title = fmt::format("{} ({}, release {})", kind.title, study_path, release_version());
    // Results of another configuration than the settings' now are reported as they are, and said so.
    if (const std::vector<std::string> stale = stale_settings(study, data_dir, release_version()); !stale.empty()) {
      const std::string say = fmt::format("{} {} results of another configuration than the study file gives {} now (a stage's "
                                          "stamp differs): rerun, make {} SETTINGS=\"{}\"", fmt::join(stale, ", "),
                                          stale.size() == 1 ? "holds" : "hold", stale.size() == 1 ? "it" : "them", study.name, fmt::join(stale, " "));
      fmt::print(stderr, "softpack-study: warning: {}\n", say);
      title += "\n\n> **Stale:** " + say + ".";
    }
    std::filesystem::create_directories(out_dir);
    fmt::print("{}", kind.write(study, data_dir, out_dir, title));
    return 0;
  } catch (...) {
    return exit_on_error("softpack-study");
  }
}

}  // namespace softpack::apps::study_app
