// softpack-config: what a profile holds, as the stages read it, for Make (workflow/stamps.mk)
// and for people. The same readers and the same section lists as the stages
// (profile/profile.hpp, packing/packing_profile.hpp, measure/settings.hpp), so Make never parses
// YAML and a profile the stages would refuse is refused here, with the same message.
//
//   softpack-config PROFILE seeds             the seeds, one line: 1 2 3
//   softpack-config PROFILE scenes            the scenes of the sweeps: soft-solid soft-soft
//   softpack-config PROFILE sections STAGE    the sections STAGE reads
//   softpack-config PROFILE text STAGE        their canonical text (what the stamp covers)
//   softpack-config PROFILE stamp STAGE       the stage's configuration stamp (16 hex digits)
//   softpack-config PROFILE gnuplot           Rs, E and nu as gnuplot variables (the figures)
//   softpack-config PROFILE stages            the stages it has (a normal-only profile: packing normal;
//                                             with a `sliding` section, sliding at the end)
//   softpack-config PROFILE packings          generated or imported (which program makes them)
//   softpack-config PROFILE name              the name the profile gives itself (`profile:`; empty
//                                             without one): make refuses one that is not its own
//   softpack-config PROFILE stale FILE...      of the result files given, those whose recorded stamp
//                                             is not their stage's stamp now (Make reruns them)
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

#include "analysis/fit_options.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "core/version.hpp"
#include "formats/file_kind.hpp"
#include "measure/settings.hpp"
#include "packing/packing_profile.hpp"

namespace softpack::apps::config_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-config: the seeds, scenes, sections and stamps of a profile, as the stages read it"};
  app.require_subcommand(1);
  std::string profile, stage, release = release_version();
  app.add_option("profile", profile, "profile file, e.g. experiments/paper.yaml")->required();
  auto* seeds = app.add_subcommand("seeds", "the profile's seeds, on one line");
  auto* scenes = app.add_subcommand("scenes", "the scenes of its sweeps, on one line");
  auto* sections = app.add_subcommand("sections", "the sections a stage reads, on one line");
  auto* text = app.add_subcommand("text", "the canonical text of the sections a stage reads");
  auto* stamp = app.add_subcommand("stamp", "the stage's configuration stamp: a hash of the release and of that text");
  auto* gnuplot = app.add_subcommand("gnuplot", "Rs, E and nu as gnuplot variables: Rs=...; E=...; nu=...");
  auto* stages = app.add_subcommand("stages", "the stages the profile has, on one line (a normal-only profile: packing normal)");
  auto* packings = app.add_subcommand("packings", "generated (softpack-pack) or imported (softpack-import, packing.import)");
  auto* name = app.add_subcommand("name", "the name the profile gives itself (its `profile:` key; an empty line without one)");
  auto* stale = app.add_subcommand(
      "stale", "of the result files given, those whose recorded stamp is not their stage's stamp now, one per line (make reruns them)");
  std::vector<std::string> stale_files;
  stale->add_option("files", stale_files, "packing, sweep results, average and fit files (missing ones are skipped)");
  for (auto* sub : {sections, text, stamp})
    sub->add_option("stage", stage, "packing, normal, tangential, average or sliding")
        ->required()
        ->check(CLI::IsMember(profile_stages()));
  stamp->add_option("--release", release, "the release the stamp includes (default: this build's, " + release_version() + ")");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-config")) return *code;
  try {
    const ConfigNode root = ConfigNode::load_file(profile);
    // Every section the stages read, read as they read it: a profile a stage would refuse is refused here.
    const auto seed_list = parse_seeds(root);
    const auto packing = parse_packing(root);
    const MeasurementSettings settings = parse_measurement(root);
    fit::parse_fit_section(root);
    if (*seeds) fmt::print("{}\n", fmt::join(seed_list, " "));
    if (*scenes) {
      std::vector<std::string> names;
      for (const ContactScene s : settings.normal.scenes) names.push_back(scene_name(s));
      fmt::print("{}\n", fmt::join(names, " "));
    }
    if (*sections) {  // an optional section the profile leaves out is not read
      std::vector<std::string> read;
      for (const std::string& s : stage_sections(stage))
        if (!optional_section(s) || root.has(s)) read.push_back(s);
      fmt::print("{}\n", fmt::join(read, " "));
    }
    // Imported packings: every stage also depends on the bytes of the source files (their SHA-256).
    if (*text) fmt::print("{}{}", stage_text(root, stage), packing.import ? import_sources_text(*packing.import) : "");
    if (*stamp) fmt::print("{}\n", profile_stamp(root, stage, release));
    if (*gnuplot)
      fmt::print("Rs={}; E={}; nu={}\n", shell_radius(packing, seed_list), settings.simulation.material.E,
                 settings.simulation.material.nu);
    if (*stages)
      fmt::print("{}{}\n", settings.has_tangential ? "packing normal tangential average" : "packing normal",
                 settings.has_sliding ? " sliding" : "");
    if (*packings) fmt::print("{}\n", packing.import ? "imported" : "generated");
    if (*name) fmt::print("{}\n", root.find("profile") ? root.find("profile")->string() : "");
    if (*stale) {
      // One configuration per result, also for make's up-to-date check: a result made with
      // another configuration than the profile's now (an edit during a run, reverted since) is
      // out of date whatever its time.
      std::map<std::string, std::string> now;  // stage -> its stamp, computed once
      for (const std::string& file : stale_files) {
        const auto r = recorded_stamp(file);
        const auto& stages = profile_stages();
        if (!r || std::find(stages.begin(), stages.end(), r->stage) == stages.end()) continue;
        if (!now.contains(r->stage)) now[r->stage] = profile_stamp(root, r->stage, release);
        if (r->stamp != now[r->stage]) fmt::print("{}\n", file);
      }
    }
    return 0;
  } catch (...) {
    return exit_on_error("softpack-config");
  }
}

}  // namespace softpack::apps::config_app
