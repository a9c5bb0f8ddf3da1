// softpack-packing-study: how the packing generator's free parameters (beta, I, r_max/Rs,
// the shell as a neighbour) set the solid fraction, the sphere count, the fitted size
// exponent and the depletion next to the shell. One parameter is varied at a time around the
// base profile's packing section, over several seeds; writes a table (.dat for gnuplot and
// Markdown) with mean and standard error over the seeds.
// With `criteria:` instead of `vary:` the study applies the preregistered density rule of
// experiments/criteria.yaml (paper/preregistration.md): every (beta, trials) of its grid on its
// select seeds, and the cheapest setting within the margin of the densest is chosen
// (density-rule.md, density-rule.json).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "analysis/seed_statistics.hpp"
#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "packing/statistics.hpp"

namespace softpack::apps::packing_study_app {
namespace {

struct Row {
  std::string parameter;
  double value = 0.0;
  double mean[5] = {}, error[5] = {};  // spheres, solid fraction, exponent, depletion length, seconds
};

void set(PackingParameters& p, const std::string& key, double v) {
  if (key == "beta") p.beta = v;
  else if (key == "r_max_over_Rs") p.r_max = v * p.Rs;
  else if (key == "shell_is_neighbour") p.shell_is_neighbour = v != 0.0;
}

// Generates the packing of every seed with p and returns the mean and standard error over the
// seeds of each statistic; `label` names the setting in the progress lines.
Row measure(const PackingParameters& p, const std::vector<std::uint64_t>& seeds, int profile_bins, bool quiet,
            const std::string& label) {
  Row row;
  std::vector<double> samples[5];
  for (const std::uint64_t seed : seeds) {
    const auto t0 = std::chrono::steady_clock::now();
    const Packing pk = generate_packing(p, seed);
    const auto s = packing_statistics(pk.centres, pk.radii, p.Rs, p.r_max, profile_bins);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double values[5] = {static_cast<double>(pk.radii.size()), s.solid_fraction, s.exponent.b,
                              s.depletion_length, sec};
    for (int q = 0; q < 5; ++q) samples[q].push_back(values[q]);
    if (!quiet) fmt::print(stderr, "{}: seed {}: {} spheres, solid fraction {:.4f}, b {:.3f} ({:.1f} s)\n", label, seed,
                           pk.radii.size(), s.solid_fraction, s.exponent.b, sec);
  }
  for (int q = 0; q < 5; ++q) {
    const MeanError m = mean_error(samples[q]);
    row.mean[q] = m.mean, row.error[q] = m.error;
  }
  return row;
}

// The density rule of experiments/criteria.yaml (paper/preregistration.md, "The packing density").
int density_rule(const ConfigNode& study, const std::string& study_path, const std::string& base_path,
                 const PackingProfile& profile, const std::string& out_dir, bool quiet) {
  const auto start = std::chrono::steady_clock::now();
  const std::string criteria_path = study.at("criteria").string();
  const ConfigNode criteria = ConfigNode::load_file(criteria_path);
  const ConfigNode density = criteria.at("density");
  const ConfigNode grid = density.at("grid");
  grid.allow_only({"beta", "trials"});
  const double margin = density.at("solid_fraction_margin").number();
  if (!(margin >= 0.0 && margin < 1.0))
    density.at("solid_fraction_margin").fail(fmt::format("must be 0 <= margin < 1, got {}", margin));
  std::vector<std::uint64_t> seeds;
  for (const ConfigNode& s : criteria.at("seeds").at("select").items()) {
    const long v = s.integer();
    if (v < 101) s.fail(fmt::format("a select seed must be held out (101 or above; 1-7 are the paper's), got {}", v));
    seeds.push_back(static_cast<std::uint64_t>(v));
  }
  if (seeds.size() < 2) criteria.at("seeds").at("select").fail("at least two select seeds (a standard error needs two)");

  struct Setting {
    double beta;
    long trials;
    Row row;
  };
  std::vector<Setting> settings;
  for (const ConfigNode& b : grid.at("beta").items())
    for (const ConfigNode& t : grid.at("trials").items()) {
      PackingParameters p = profile.parameters;
      p.beta = b.number();
      p.trials = t.integer();
      try {
        validate(p);
      } catch (const InputError& e) {
        b.fail(e.what());
      }
      settings.push_back({p.beta, p.trials, {}});
    }
  for (std::size_t k = 0; k < settings.size(); ++k) {
    PackingParameters p = profile.parameters;
    p.beta = settings[k].beta;
    p.trials = settings[k].trials;
    settings[k].row = measure(p, seeds, profile.profile_bins, quiet,
                              fmt::format("[{}/{}] beta {:g}, trials {}", k + 1, settings.size(), p.beta, p.trials));
  }
  double densest = 0.0;
  for (const Setting& s : settings) densest = std::max(densest, s.row.mean[1]);
  std::size_t chosen = settings.size();
  for (std::size_t k = 0; k < settings.size(); ++k)
    if (settings[k].row.mean[1] >= densest - margin &&
        (chosen == settings.size() || settings[k].row.mean[4] < settings[chosen].row.mean[4]))
      chosen = k;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string prov = fmt::format("softpack-packing-study {}, study {}, criteria {}, base {}, seeds {}, {:.1f} s",
                                       code_version(), study_path, criteria_path, base_path, fmt::join(seeds, " "), seconds);
  std::string md = fmt::format(
      "# The density rule\n\n{}\n\nThe rule (experiments/criteria.yaml, paper/preregistration.md): among the settings "
      "whose mean solid fraction is within {:g} of the densest ({:.4f}), the one of least mean generation time. Mean ± "
      "standard error over the seeds.\n\n| beta | trials | spheres | solid fraction | fitted b | seconds | within the "
      "margin |\n|---|---|---|---|---|---|---|\n",
      prov, margin, densest);
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    const bool within = s.row.mean[1] >= densest - margin;
    md += fmt::format("| {:g} | {} | {:.0f} ± {:.0f} | {:.4f} ± {:.4f} | {:.3f} ± {:.3f} | {:.1f} ± {:.1f} | {}{} |\n",
                      s.beta, s.trials, s.row.mean[0], s.row.error[0], s.row.mean[1], s.row.error[1], s.row.mean[2],
                      s.row.error[2], s.row.mean[4], s.row.error[4], within ? "yes" : "no", k == chosen ? " (**chosen**)" : "");
    rows.push_back({{"beta", s.beta},
                    {"trials", s.trials},
                    {"spheres", {s.row.mean[0], s.row.error[0]}},
                    {"solid_fraction", {s.row.mean[1], s.row.error[1]}},
                    {"exponent", {s.row.mean[2], s.row.error[2]}},
                    {"seconds", {s.row.mean[4], s.row.error[4]}},
                    {"within_margin", within}});
  }
  md += fmt::format("\nChosen: beta = {:g}, trials = {}.\n", settings[chosen].beta, settings[chosen].trials);
  const nlohmann::json j = {{"provenance", prov},
                            {"margin", margin},
                            {"densest_solid_fraction", densest},
                            {"seeds", seeds},
                            {"settings", rows},
                            {"chosen", {{"beta", settings[chosen].beta}, {"trials", settings[chosen].trials}}}};
  write_files_atomically({{(std::filesystem::path(out_dir) / "density-rule.md").string(), md},
                          {(std::filesystem::path(out_dir) / "density-rule.json").string(), j.dump(2) + "\n"}});
  if (!quiet)
    fmt::print(stderr, "softpack-packing-study: density rule: beta {:g}, trials {} ({:.1f} s) -> {}\n", settings[chosen].beta,
               settings[chosen].trials, seconds, out_dir);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"softpack-packing-study: packing statistics against beta, I, r_max/Rs and the shell rule"};
  std::string study_path, out_dir;
  bool quiet = false;
  app.add_option("--config", study_path, "study file, e.g. experiments/packing-density.yaml")->required();
  app.add_option("--out", out_dir, "directory for packing-density.dat and packing-density.md")->required();
  app.add_flag("--quiet", quiet, "no progress lines");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-packing-study")) return *code;
  try {
    const auto start = std::chrono::steady_clock::now();
    const ConfigNode study = ConfigNode::load_file(study_path);
    study.allow_only({"study", "base", "seeds", "vary", "criteria"});
    const std::string base_path = study.at("base").string();
    const ConfigNode base = ConfigNode::load_file(base_path);
    const PackingProfile profile = parse_packing(base);
    if (profile.import)
      study.at("base").fail(fmt::format("{} imports its packings (packing.import); the study varies the generator's parameters",
                                        base_path));
    if (study.has("criteria")) {
      if (study.has("vary") || study.has("seeds"))
        study.at("criteria").fail("a density-rule study takes its grid and seeds from the criteria file: no `vary` or `seeds` beside it");
      return density_rule(study, study_path, base_path, profile, out_dir, quiet);
    }
    const std::vector<std::uint64_t> seeds = parse_seeds(study);
    const ConfigNode vary = study.at("vary");
    vary.allow_only({"beta", "trials", "r_max_over_Rs", "shell_is_neighbour"});

    std::vector<Row> rows;
    for (const std::string& key : vary.keys()) {
      for (const ConfigNode& v : vary.at(key).items()) {
        Row row;
        row.parameter = key;
        PackingParameters p = profile.parameters;
        if (key == "trials") {  // a count, read exactly: 1.5 or 1e300 are none
          p.trials = v.integer();
          row.value = static_cast<double>(p.trials);
        } else {
          row.value = key == "shell_is_neighbour" ? (v.boolean() ? 1.0 : 0.0) : v.number();
          set(p, key, row.value);
        }
        try {
          validate(p);
        } catch (const InputError& e) {
          v.fail(e.what());
        }
        const Row measured = measure(p, seeds, profile.profile_bins, quiet, fmt::format("{} = {}", key, row.value));
        std::copy(std::begin(measured.mean), std::end(measured.mean), std::begin(row.mean));
        std::copy(std::begin(measured.error), std::end(measured.error), std::begin(row.error));
        rows.push_back(row);
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string prov = fmt::format("softpack-packing-study {}, study {}, base {}, {} seeds, {:.1f} s", code_version(),
                                         study_path, base_path, seeds.size(), seconds);
    std::string dat = "# " + prov + "\n# base packing section:\n";
    for (std::string line; const char c : section_text(base, "packing")) {
      if (c == '\n') {
        dat += "#   " + line + "\n";
        line.clear();
      } else {
        line += c;
      }
    }
    dat += "# columns: parameter value spheres spheres_err solid_fraction err exponent err depletion_length[m] err seconds err\n";
    std::string md = "# Packing density study\n\n" + prov + "\n\nMean ± standard error over the seeds; one parameter varied "
                     "at a time around the base profile.\n\n| parameter | value | spheres | solid fraction | fitted b | "
                     "depletion length [mm] | seconds |\n|---|---|---|---|---|---|---|\n";
    std::string previous;
    for (const Row& r : rows) {
      if (r.parameter != previous && !previous.empty()) dat += "\n\n";  // gnuplot index per parameter
      previous = r.parameter;
      dat += fmt::format("{} {:.6g}", r.parameter, r.value);
      for (int q = 0; q < 5; ++q) dat += fmt::format(" {:.8g} {:.3g}", r.mean[q], r.error[q]);
      dat += "\n";
      md += fmt::format("| {} | {:g} | {:.0f} ± {:.0f} | {:.4f} ± {:.4f} | {:.3f} ± {:.3f} | {:.3f} ± {:.3f} | {:.1f} |\n",
                        r.parameter, r.value, r.mean[0], r.error[0], r.mean[1], r.error[1], r.mean[2], r.error[2],
                        1e3 * r.mean[3], 1e3 * r.error[3], r.mean[4]);
    }
    write_file_atomically((std::filesystem::path(out_dir) / "packing-density.dat").string(), dat);
    write_file_atomically((std::filesystem::path(out_dir) / "packing-density.md").string(), md);
    if (!quiet) fmt::print(stderr, "softpack-packing-study: {} rows in {:.1f} s -> {}\n", rows.size(), seconds, out_dir);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-packing-study");
  }
}

}  // namespace softpack::apps::packing_study_app
