#include "report/accuracy_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include "analysis/average.hpp"
#include "analysis/power_fit.hpp"
#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "formats/sweep_file.hpp"
#include "io/atomic_file.hpp"
#include "report/stage_timing.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

using Seeds = std::vector<std::uint64_t>;

// The seeds of each scene a measurement uses: soft-soft's seed k stands for the pair (k, next).
struct SeedSets {
  Seeds solid, soft;
};

// The setting whose runs hold a setting's results (itself, or the one it is `of`).
const StudySetting& source(const Study& st, const StudySetting& s) { return s.runs() ? s : st.setting(s.of); }

using Runs = StudyRuns;

std::vector<std::string> names(const Study& st) {
  std::vector<std::string> n;
  for (const auto& scene : kStudyScenes) {
    for (const char* k : {"a", "b", "c", "delta"}) n.push_back(fmt::format("{} normal {}", scene, k));
    for (const char* k : {"a", "b", "c"}) n.push_back(fmt::format("{} tangential {}", scene, k));
    for (double d : st.Fn_delta_n) n.push_back(fmt::format("{} Fn({})", scene, d));
    for (double d : st.kt_delta_n) n.push_back(fmt::format("{} kt({})", scene, d));
  }
  return n;
}

// The quantities of one scene from its seeds' results files, appended to `out`.
void measure_scene(const Study& st, Runs& runs, const std::string& folder, const std::string& scene,
                   const Seeds& seeds, std::vector<Quantity>& out) {
  std::vector<SweepColumns> normal, tangential;
  for (std::uint64_t s : seeds) {
    normal.push_back(runs.results(folder, "normal", scene, s));
    tangential.push_back(runs.results(folder, "tangential", scene, s));
  }
  const NormalAverage n = average_normal(normal);
  const TangentialAverage t = average_tangential(tangential);
  std::vector<double> mean, error;
  for (const auto& m : n.Fn) mean.push_back(m.mean), error.push_back(m.error);
  const auto push = [&](const std::string& what, double v, double error, std::string note = "") {
    out.push_back({fmt::format("{} {}", scene, what), v, error, std::move(note)});
  };
  fit::PowerLawFit fn, kt;
  std::string fn_note, kt_note;
  try {
    fn = fit::fit_normal_law(n.delta_n, mean, error);
  } catch (const InputError& e) {
    fn_note = e.what();
  }
  // δ is known only to within the grid step below the first loaded point (the fit starts there,
  // and pins δ just under it): its error is at least that step / √12 (a uniform distribution).
  double delta_error = fn.delta_error;
  for (std::size_t k = 1; fn_note.empty() && k < n.delta_n.size(); ++k)
    if (n.delta_n[k] >= fn.delta) {
      delta_error = std::max(delta_error, (n.delta_n[k] - n.delta_n[k - 1]) / std::sqrt(12.0));
      break;
    }
  for (auto [k, v, e] : {std::tuple{"a", fn.a, fn.a_error}, {"b", fn.b, fn.b_error}, {"c", fn.c, fn.c_error},
                         {"delta", fn.delta, delta_error}})
    push(fmt::format("normal {}", k), fn_note.empty() ? v : kNaN, fn_note.empty() ? e : kNaN, fn_note);
  std::vector<double> kt_mean, kt_error;
  for (const auto& m : t.kt) kt_mean.push_back(m.mean), kt_error.push_back(m.error);
  if (!fn_note.empty()) kt_note = "no normal fit";
  else try {
      kt = fit::fit_tangential_law(t.kt_delta_n, kt_mean, kt_error, fn.delta);
    } catch (const InputError& e) {
      kt_note = e.what();
    }
  for (auto [k, v, e] : {std::tuple{"a", kt.a, kt.a_error}, {"b", kt.b, kt.b_error}, {"c", kt.c, kt.c_error}})
    push(fmt::format("tangential {}", k), kt_note.empty() ? v : kNaN, kt_note.empty() ? e : kNaN, kt_note);
  const auto at = [](const std::vector<double>& x, const std::vector<MeanError>& y, double d) {
    for (std::size_t k = 0; k < x.size(); ++k)
      if (std::abs(x[k] - d) < 1e-9) return y[k];
    return MeanError{kNaN, kNaN};
  };
  for (double d : st.Fn_delta_n) {
    const MeanError m = at(n.delta_n, n.Fn, d);
    push(fmt::format("Fn({})", d), m.mean, m.error);
  }
  for (double d : st.kt_delta_n) {
    const MeanError m = at(t.kt_delta_n, t.kt, d);
    push(fmt::format("kt({})", d), m.mean, m.error);
  }
}

std::vector<Quantity> measure(const Study& st, Runs& runs, const std::string& folder, const SeedSets& s) {
  std::vector<Quantity> q;
  measure_scene(st, runs, folder, "soft-solid", s.solid, q);
  measure_scene(st, runs, folder, "soft-soft", s.soft, q);
  return q;
}

// The median over the loaded normal points (Fn at least 1% of the sweep's largest) of the largest
// unbalanced force over the mean contact force after the relaxation: how far from rest the
// setting measures.
double median_residual(Runs& runs, const std::string& folder, const Seeds& seeds) {
  std::vector<double> ratios;
  for (const auto& scene : kStudyScenes)
    for (std::uint64_t s : seeds) {
      const SweepResults& r = runs.results(folder, "normal", scene, s);
      const double top = *std::max_element(r.Fn.begin(), r.Fn.end());
      for (std::size_t k = 0; k < r.Fn.size(); ++k)
        if (top > 0 && r.Fn[k] >= 0.01 * top) ratios.push_back(r.final_force_ratio[k]);
    }
  if (ratios.empty()) return kNaN;
  std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2), ratios.end());
  return ratios[ratios.size() / 2];
}

}  // namespace

AccuracyReport accuracy_report(const Study& st, const std::string& dir) {
  Runs runs(dir);
  AccuracyReport r;
  r.quantities = names(st);
  const StudySetting& ref = st.reference;
  const TimingInputs ref_files = study_files(dir, ref.name, ref.seeds);
  const ProfileTiming ref_time = collect_timing(ref_files);
  if (!ref_time.complete())
    throw InputError(fmt::format("{}/{}: the reference's results are not complete (make accuracy runs it first); missing: {}", dir,
                                 ref.name, ref_time.stages.empty() ? "everything" : "some of its files"));
  r.reference_cpu = ref_time.total().cpu;
  // The reference on all its seeds, and its leave-one-seed-out jackknife standard errors.
  const std::vector<Quantity> all = measure(st, runs, ref.name, {ref.seeds, ref.seeds});
  const std::size_t nq = all.size(), ns = ref.seeds.size();
  std::vector<std::vector<double>> leave(nq);
  for (std::size_t i = 0; i < ns; ++i) {
    Seeds rest = ref.seeds;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
    const std::vector<Quantity> q = measure(st, runs, ref.name, {rest, rest});
    for (std::size_t k = 0; k < nq; ++k) leave[k].push_back(q[k].value);
  }
  for (std::size_t k = 0; k < nq; ++k) {
    r.reference_value.push_back(all[k].value);
    // The jackknife, floored by the reference's own standard error: where every leave-one-out fit
    // pins δ at the same grid point the jackknife collapses (to 1e-7), the fit's error does not.
    const double jack = jackknife_error(leave[k]);
    r.reference_sigma.push_back(std::isfinite(all[k].error) ? std::max(jack, all[k].error) : jack);
    // Established: the reference measures it, and distinguishes it from zero (2 σ); else it is
    // left out of the errors (a force at a Δn below the onset is zero within round-off).
    r.established.push_back(std::isfinite(all[k].value) && std::abs(all[k].value) >= 2.0 * r.reference_sigma.back());
  }
  const auto row_of = [&](const StudySetting& s) {
    SettingRow row;
    row.name = s.name;
    row.knob = setting_changes(st, s);
    row.runs = s.runs();
    row.seeds = s.seeds.size();
    const StudySetting& src = source(st, s);
    if (const auto failed = setting_failure(dir, src.name)) {
      row.failed = *failed;
      return row;
    }
    const ProfileTiming time = collect_timing(study_files(dir, src.name, s.seeds));
    row.cpu_seconds = time.total().cpu;
    row.complete = time.complete();
    if (!row.complete) return row;
    row.residual = median_residual(runs, src.name, s.seeds);
    std::vector<Quantity> mine, theirs;
    if (s.runs()) {  // paired: the same soft-particles, soft-soft on the pairs both runs made
      SeedSets same{s.seeds, {}};
      for (std::uint64_t seed : s.seeds)
        if (runs.partner(s.name, seed) == runs.partner(ref.name, seed)) same.soft.push_back(seed);
      mine = measure(st, runs, s.name, same);
      theirs = measure(st, runs, ref.name, same);
    } else {  // fewer seeds: against the reference on all of its seeds
      mine = measure(st, runs, src.name, {s.seeds, s.seeds});
      theirs = all;
    }
    double sum = 0.0;
    std::size_t counted = 0;
    for (std::size_t k = 0; k < nq; ++k) {
      const double z = (mine[k].value - theirs[k].value) / r.reference_sigma[k];
      row.z.push_back(z);
      if (!r.established[k] || !std::isfinite(z)) continue;
      sum += z * z, ++counted;
      if (std::abs(z) >= row.max_z) row.max_z = std::abs(z), row.worst = r.quantities[k];
    }
    row.rms_z = counted ? std::sqrt(sum / static_cast<double>(counted)) : kNaN;
    return row;
  };
  for (const auto& s : st.settings) r.rows.push_back(row_of(s));
  for (auto& a : r.rows) {
    if (!a.complete) continue;
    a.pareto = std::none_of(r.rows.begin(), r.rows.end(), [&](const SettingRow& b) {
      return b.complete && &b != &a && b.cpu_seconds <= a.cpu_seconds && b.max_z <= a.max_z &&
             (b.cpu_seconds < a.cpu_seconds || b.max_z < a.max_z);
    });
  }
  return r;
}

std::string write_accuracy_report(const AccuracyReport& r, const std::string& out_dir, const std::string& title) {
  std::filesystem::create_directories(out_dir);
  // The unit of cost: the setting named paper (the paper's protocol), or else the reference.
  double paper_cpu = r.reference_cpu;
  std::string unit = "reference";
  for (const auto& row : r.rows)
    if (row.name == "paper" && row.complete) paper_cpu = row.cpu_seconds, unit = "paper";
  std::string md = fmt::format("# {}\n\nReference: {:.0f} CPU-s. Error: (setting − reference) / σ, σ the reference's "
                               "seed-to-seed (jackknife) standard error; paired on the same seeds for the settings that run. Residual: the median, "
                               "over the loaded normal points (Fn >= 1% of the sweep's largest), of the largest unbalanced force "
                               "over the mean contact force after the relaxation.\n\n",
                               title, r.reference_cpu);
  md += fmt::format("| setting | changes | seeds | CPU [s] | CPU / {} | max abs(z) | worst quantity | rms z | residual | Pareto |\n", unit);
  md += "|---|---|---|---|---|---|---|---|---|---|\n";
  std::string dat = "# index setting cpu_seconds cpu_over_paper max_z rms_z pareto runs\n";
  std::size_t index = 0;
  for (const auto& row : r.rows) {
    if (!row.complete) {
      md += fmt::format("| {} | {} | {} | {} | | | | | | |\n", row.name, row.knob, row.seeds,
                        row.failed.empty() ? "not run yet" : "failed: " + row.failed);
      continue;
    }
    md += fmt::format("| {} | {} | {} | {:.0f} | {:.3f} | {:.2f} | {} | {:.2f} | {:.1e} | {} |\n", row.name, row.knob, row.seeds,
                      row.cpu_seconds, row.cpu_seconds / paper_cpu, row.max_z, row.worst, row.rms_z, row.residual,
                      row.pareto ? "yes" : "");
    dat += fmt::format("{} \"{}\" {:.6g} {:.6g} {:.6g} {:.6g} {} {}\n", index++, row.name, row.cpu_seconds,
                       row.cpu_seconds / paper_cpu, row.max_z, row.rms_z, row.pareto ? 1 : 0, row.runs ? 1 : 0);
  }
  md += "\n## Error of every quantity (z)\n\n"
        "σ: the reference's jackknife standard error over its seeds, at least its own standard error (of the mean, or of "
        "the fit). –: not established by the reference (not measured, or within 2 σ of zero), left out of max abs(z) and "
        "rms z.\n\n| quantity | reference | σ |";
  for (const auto& row : r.rows)
    if (row.complete) md += " " + row.name + " |";
  md += "\n|---|---|---|";
  for (const auto& row : r.rows)
    if (row.complete) md += "---|";
  md += "\n";
  for (std::size_t k = 0; k < r.quantities.size(); ++k) {
    md += fmt::format("| {} | {:.4g} | {:.2g} |", r.quantities[k], r.reference_value[k], r.reference_sigma[k]);
    for (const auto& row : r.rows)
      if (row.complete) md += r.established[k] ? fmt::format(" {:+.2f} |", row.z[k]) : std::string(" – |");
    md += "\n";
  }
  write_file_atomically(out_dir + "/table.md", md);
  write_file_atomically(out_dir + "/pareto.dat", dat);
  nlohmann::json j;
  j["quantities"] = r.quantities;
  j["reference"] = {{"value", r.reference_value},
                    {"sigma", r.reference_sigma},
                    {"established", r.established},
                    {"cpu_seconds", r.reference_cpu}};
  for (const auto& row : r.rows)
    j["settings"].push_back({{"name", row.name},
                             {"changes", row.knob},
                             {"seeds", row.seeds},
                             {"complete", row.complete},
                             {"failed", row.failed},
                             {"cpu_seconds", row.cpu_seconds},
                             {"z", row.z},
                             {"max_z", row.max_z},
                             {"rms_z", row.rms_z},
                             {"median_final_force_ratio", row.residual},
                             {"pareto", row.pareto}});
  write_file_atomically(out_dir + "/report.json", j.dump(2) + "\n");
  return md;
}

}  // namespace softpack
