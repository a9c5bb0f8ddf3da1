// softpack-table: Tables 1 and 2 of the paper with our fitted coefficients beside the published
// ones (analysis/fit_table.hpp). Reads the fit files of softpack-fit (formats/fit_file.hpp) and
// experiments/published.yaml, writes table1.md, table1.tex, table2.md, table2.tex and prints the
// Markdown tables. With --criteria and --averages, also the verdict by the preregistered rules
// (verdict.json, verdict.md, verdict.tex; formats/verdict_file.hpp) and kt_unit.md, and Table 2
// carries a and c in the unit the rule reads the paper's in (when its test passes).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <algorithm>
#include <set>

#include "analysis/fit_selection.hpp"
#include "analysis/fit_table.hpp"
#include "analysis/kt_unit.hpp"
#include "analysis/verdict.hpp"
#include "formats/verdict_file.hpp"
#include "formats/average_file.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/fit_file.hpp"
#include "packing/packing_profile.hpp"
#include "io/atomic_file.hpp"

namespace softpack::apps::table_app {
namespace {

/// The published coefficients of one scene in `table` ("table1" or "table2") into `column`,
/// with their digits as written in the file.
void add_published(table::Column& column, const ConfigNode& root, const std::string& table, const std::vector<std::string>& keys) {
  const ConfigNode t = root.at(table);
  if (!t.has(column.scene)) t.fail(fmt::format("no scene '{}'; allowed: {}", column.scene, fmt::join(t.keys(), ", ")));
  const ConfigNode s = t.at(column.scene);
  s.allow_only(keys);
  for (const std::string& k : keys)
    if (s.has(k)) {
      const ConfigNode v = s.at(k);
      column.published[k] = v.number();
      column.published_text[k] = v.yaml().Scalar();
    }
}

}  // namespace

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  CLI::App app{"softpack-table: Tables 1 and 2 (fitted coefficients of Eqs. 7 and 8) beside the paper's"};
  std::vector<std::string> fit_paths;
  std::string published_path, out_dir, gnuplot_path;
  app.add_option("--fits", fit_paths, "fit files of softpack-fit, one per scene, in column order, e.g. "
                                      "data/paper/fit/soft-solid.json data/paper/fit/soft-soft.json")
      ->required();
  app.add_option("--published", published_path, "the published coefficients, experiments/published.yaml")->required();
  app.add_option("--out-dir", out_dir, "writes table1.md, table1.tex, table2.md, table2.tex, e.g. data/paper/tables")->required();
  app.add_option("--gnuplot", gnuplot_path,
                 "also write the published coefficients as gnuplot variables (paper_a_solid=...; paper_kt_a_soft=...) for "
                 "figures/*.gp");
  std::vector<std::string> average_paths;
  double Rs = 0.0;
  auto* averages = app.add_option("--averages", average_paths,
                                  "seed averages of softpack-average, one per scene (any order): also write kt_unit.md, the "
                                  "readings of Table 2's unit tested on kt/Fn (needs --Rs)");
  app.add_option("--Rs", Rs, "shell radius [m] of the profile (softpack-config PROFILE gnuplot), for kt_unit.md")->needs(averages);
  std::string config_path, criteria_path;
  app.add_option("--criteria", criteria_path,
                 "the preregistered criteria (experiments/criteria.yaml): the fit selection over the scenes, Table 2's unit and "
                 "the verdict (verdict.json, .md, .tex; needs --averages and fit files made with softpack-fit --criteria)")
      ->needs(averages);
  app.add_option("--config", config_path,
                 "the profile the fits must have been made with (make gives it); without it, they must agree with each other");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-table")) return *code;

  try {
    const auto start = Clock::now();
    const ConfigNode root = ConfigNode::load_file(published_path);
    root.allow_only({"table1", "table2"});
    table::Table t1{"Table 1 (normal, Eq. 7)", table::table1_rows(), {}};
    table::Table t2{"Table 2 (tangential spring, Eq. 8)", table::table2_rows(), {}};
    if (!average_paths.empty() && criteria_path.empty())
      throw InputError("--averages needs --criteria (experiments/criteria.yaml): Table 2's unit is decided by its rule");
    if (!average_paths.empty() && !(Rs > 0.0)) throw InputError("--averages needs --Rs, the shell radius in metres (> 0)");
    std::optional<verdict::Criteria> criteria;
    std::optional<fit::FitCriteria> fit_criteria;
    if (!criteria_path.empty()) {
      const ConfigNode c = ConfigNode::load_file(criteria_path);
      criteria = verdict::parse_criteria(c);
      fit_criteria = fit::parse_fit_criteria(c);
    }
    std::vector<AverageFile> average_files;
    for (const std::string& path : average_paths) {
      average_files.push_back(read_average_file(path));
      if (!average_files.back().has_kt)
        throw InputError(fmt::format("{}: no /kt group: Table 2's unit needs the tangential averages", path));
    }
    const auto published_law = [&](const std::string& scene, const char* which) {
      const ConfigNode s = root.at(which).at(scene);
      table::PublishedLaw l{s.at("a").number(), s.at("b").number(), s.at("c").number(),
                            root.at("table1").at(scene).at("delta").number()};
      return l;
    };
    std::set<std::string> scenes;
    std::vector<std::string> sources;
    // One configuration per table: every fit of the stamp of the first and, with --config, of the profile's now.
    const std::string stamp = config_path.empty() ? "" : profile_stamp(ConfigNode::load_file(config_path), "average");
    std::optional<FitEstimates> first;
    std::vector<FitEstimates> fits;
    for (const std::string& path : fit_paths) {
      FitEstimates fit = read_fit_file(path);
      fits.push_back(fit);
      if (!first) first = fit;
      if (fit.stamp != first->stamp)
        throw InputError(fmt::format("--fits: {} and {} were made with different configurations (stamps '{}' and '{}'); a table "
                                     "never mixes configurations: make them again with one profile",
                                     fit_paths.front(), path, first->stamp, fit.stamp));
      if (!config_path.empty()) check_stamp(path, "average", fit.stamp, stamp, config_path);
      if (!scenes.insert(fit.scene).second)
        throw InputError(fmt::format("{}: scene '{}' is given twice in --fits; allowed: one fit file per scene", path, fit.scene));
      table::Column c1{fit.scene, std::move(fit.normal), {}, {}};
      table::Column c2{fit.scene, std::move(fit.tangential), {}, {}};
      add_published(c1, root, "table1", {"a", "b", "c", "delta"});
      add_published(c2, root, "table2", {"a", "b", "c"});
      t1.columns.push_back(std::move(c1));
      t2.columns.push_back(std::move(c2));
      sources.push_back(fmt::format("{} ({}, softpack-fit {})", path, fit.scene, fit.code_version));
    }

    std::optional<VerdictInputs> verdict_inputs;
    if (criteria) {
      VerdictInputs vi;
      vi.criteria_path = criteria_path;
      vi.fit_criteria = *fit_criteria;
      std::vector<std::vector<fit::CandidateFit>> per_scene;
      std::vector<verdict::SceneInput> inputs;
      for (const FitEstimates& f : fits) {
        if (f.candidates.empty())
          throw InputError(fmt::format("--fits: the fit of {} has no candidates: make it with softpack-fit --criteria {}", f.scene,
                                       criteria_path));
        per_scene.push_back(f.candidates);
        const auto a = std::find_if(average_files.begin(), average_files.end(), [&](const AverageFile& x) { return x.scene == f.scene; });
        if (a == average_files.end()) throw InputError(fmt::format("--averages: no average of scene {}", f.scene));
        verdict::SceneInput in;
        in.scene = f.scene;
        in.normal = f.normal;
        in.tangential = f.tangential;
        if (f.jackknife && f.jackknife->done) in.jackknife = f.jackknife->covariance;
        in.delta_n = a->delta_n, in.Fn = a->Fn, in.Fn_stderr = a->Fn_stderr;
        in.kt_delta_n = a->kt_delta_n, in.kt = a->kt, in.kt_stderr = a->kt_stderr;
        in.paper_normal = published_law(f.scene, "table1");
        in.paper_tangential = published_law(f.scene, "table2");
        inputs.push_back(std::move(in));
      }
      vi.selection = fit::select_fit(per_scene, *fit_criteria);
      // The profile's fit is the chosen candidate when their coefficients agree (both fitted the same averages).
      vi.profile_fit_is_chosen = true;
      for (const FitEstimates& f : fits) {
        if (vi.selection.chosen >= f.candidates.size()) {
          vi.profile_fit_is_chosen = false;
          break;
        }
        const fit::CandidateFit& c = f.candidates.at(vi.selection.chosen);
        vi.profile_fit_is_chosen = vi.profile_fit_is_chosen && c.normal && c.normal->a == f.normal.at("a").value &&
                                   c.normal->b == f.normal.at("b").value && c.normal->c == f.normal.at("c").value;
      }
      vi.fits = fits;
      vi.verdict = verdict::judge(inputs, *criteria, Rs);
      // Table 2 in the reading the rule settled on, beside our N/m.
      if (vi.verdict.unit.passed) {
        const std::string u = vi.verdict.unit.selected;
        const double m = verdict::metres_per_unit(u, Rs);
        for (const char* k : {"a", "c"}) t2.rows.push_back({std::string(k) + "_per_" + u, fmt::format("{} [N/{}], the paper's unit read per {}", k, u, u),
                                                            fmt::format("${}$ [N/{}], the paper's unit read per {}", k, u, u)});
        for (table::Column& c2 : t2.columns) {
          if (c2.ours)
            for (const char* k : {"a", "c"})
              if (const auto it = c2.ours->find(k); it != c2.ours->end())
                (*c2.ours)[std::string(k) + "_per_" + u] = table::Estimate{it->second.value * m, it->second.error * m};
          for (const char* k : {"a", "c"})
            if (const auto it = c2.published.find(k); it != c2.published.end()) {
              c2.published[std::string(k) + "_per_" + u] = it->second;
              if (const auto t = c2.published_text.find(k); t != c2.published_text.end())
                c2.published_text[std::string(k) + "_per_" + u] = t->second;
            }
        }
      }
      verdict_inputs = std::move(vi);
    }

    const std::string md1 = table::to_markdown(t1), md2 = table::to_markdown(t2);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const std::string provenance = fmt::format("softpack-table {}; fits: {}; published: {}; {:.3f} s", code_version(),
                                               fmt::join(sources, ", "), published_path, seconds);
    namespace fs = std::filesystem;
    const auto out = [&](const std::string& name) { return (fs::path(out_dir) / name).string(); };
    // Every input read and checked before anything is written, then the outputs as one: a refusal
    // or a full disk leaves no table of this run (nor a mix of this run's and an earlier one's).
    std::vector<std::pair<std::string, std::string>> outputs{
        {out("table1.md"), md1 + "\n<!-- " + provenance + " -->\n"},
        {out("table2.md"), md2 + "\n<!-- " + provenance + " -->\n"},
        {out("table1.tex"), table::to_latex(t1, t1.title + "\n" + provenance)},
        {out("table2.tex"), table::to_latex(t2, t2.title + "\n" + provenance)}};
    if (!gnuplot_path.empty()) {
      // Suffix of the figure scripts' variables: soft-solid -> _solid, soft-soft -> _soft. Eq. 8's
      // delta is Table 1's (paper §5).
      std::string gp = fmt::format("# softpack-table {}: the published coefficients of {} for gnuplot\n", code_version(),
                                   published_path);
      for (std::size_t i = 0; i < t1.columns.size(); ++i) {
        const std::string sfx = t1.columns[i].scene == "soft-solid" ? "solid" : "soft";
        const auto value = [](const table::Column& c, const std::string& k) {
          const auto it = c.published.find(k);
          return it == c.published.end() ? std::string("NaN") : fmt::format("{}", it->second);
        };
        for (const char* k : {"a", "b", "c", "delta"}) gp += fmt::format("paper_{}_{}={}; ", k, sfx, value(t1.columns[i], k));
        for (const char* k : {"a", "b", "c"}) gp += fmt::format("paper_kt_{}_{}={}; ", k, sfx, value(t2.columns[i], k));
        gp += fmt::format("paper_kt_delta_{}={}\n", sfx, value(t1.columns[i], "delta"));
      }
      outputs.emplace_back(gnuplot_path, gp);
    }
    if (verdict_inputs) {
      verdict_inputs->provenance = provenance;
      const auto readings = table::kt_readings(Rs, criteria->readings);
      std::vector<table::KtUnitScene> scenes;
      for (const AverageFile& a : average_files)
        scenes.push_back(table::kt_unit_scene(a.scene, a.delta_n, a.Fn, a.Fn_stderr, a.kt_delta_n, a.kt, a.kt_stderr,
                                              published_law(a.scene, "table1"), published_law(a.scene, "table2"), readings,
                                              criteria->established_sigmas));
      outputs.emplace_back(out("kt_unit.md"), table::kt_unit_markdown(scenes, readings) + "\n<!-- " + provenance + " -->\n");
      outputs.emplace_back(out("verdict.json"), verdict_json_text(*verdict_inputs));
      outputs.emplace_back(out("verdict.md"), verdict_markdown(*verdict_inputs));
      outputs.emplace_back(out("verdict.tex"), verdict_latex(*verdict_inputs));
    }
    write_files_atomically(outputs);
    fmt::print("{}\n{}", md1, md2);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-table");
  }
}

}  // namespace softpack::apps::table_app
