// softpack-packing-study: how the packing generator's free parameters (beta, I, r_max/Rs,
// the shell as a neighbour) set the solid fraction, the sphere count, the fitted size
// exponent and the depletion next to the shell. One parameter is varied at a time around the
// base profile's packing section, over several seeds; writes a table (.dat for gnuplot and
// Markdown) with mean and standard error over the seeds.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "config/profile.hpp"
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
    study.allow_only({"study", "base", "seeds", "vary"});
    const std::string base_path = study.at("base").string();
    const ConfigNode base = ConfigNode::load_file(base_path);
    const PackingProfile profile = parse_packing(base);
    if (profile.import)
      study.at("base").fail(fmt::format("{} imports its packings (packing.import); the study varies the generator's parameters",
                                        base_path));
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
        std::vector<double> samples[5];
        for (std::uint64_t seed : seeds) {
          const auto t0 = std::chrono::steady_clock::now();
          const Packing pk = generate_packing(p, seed);
          const auto s = packing_statistics(pk.centres, pk.radii, p.Rs, p.r_max, profile.profile_bins);
          const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          const double values[5] = {static_cast<double>(pk.radii.size()), s.solid_fraction, s.exponent.b,
                                    s.depletion_length, sec};
          for (int q = 0; q < 5; ++q) samples[q].push_back(values[q]);
          if (!quiet) fmt::print(stderr, "{} = {}: seed {}: {} spheres, solid fraction {:.4f}, b {:.3f} ({:.1f} s)\n", key,
                                 row.value, seed, pk.radii.size(), s.solid_fraction, s.exponent.b, sec);
        }
        for (int q = 0; q < 5; ++q) {
          const double n = static_cast<double>(samples[q].size());
          double m = 0.0, v2 = 0.0;
          for (double x : samples[q]) m += x / n;
          for (double x : samples[q]) v2 += (x - m) * (x - m);
          row.mean[q] = m;
          row.error[q] = n > 1 ? std::sqrt(v2 / (n - 1) / n) : 0.0;
        }
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
