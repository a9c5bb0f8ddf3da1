#include "report/calibration_report.hpp"
#include "report/report_cells.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <span>
#include <stdexcept>

#include "analysis/average.hpp"
#include "analysis/fit_options.hpp"
#include "analysis/power_fit.hpp"
#include "analysis/seed_statistics.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "io/atomic_file.hpp"
#include "report/stage_timing.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

using Seeds = std::vector<std::uint64_t>;

// Two grains (or a grain and its shell) are in contact after growth when their gap is below this
// fraction of Rs (growth leaves them touching to 1e-12 Rs: docs/packing.md).
constexpr double kTouchingGap = 1e-9;

std::vector<std::string> quantity_names(const Study& st) {
  std::vector<std::string> n{"solid fraction", "coordination after growth", "grains"};
  for (const auto& scene : kStudyScenes) {
    for (const char* k : {"delta", "a", "b", "b fixed range"}) n.push_back(fmt::format("{} {}", scene, k));
    for (double d : st.Fn_delta_n) n.push_back(fmt::format("{} Fn({})", scene, d));
    for (double d : st.kt_delta_n) n.push_back(fmt::format("{} kt({})", scene, d));
    for (double d : st.kt_delta_n) n.push_back(fmt::format("{} kt/Fn({})", scene, d));
    for (double d : st.Fn_delta_n) n.push_back(fmt::format("{} overlap max({})", scene, d));
    for (double d : st.Fn_delta_n) n.push_back(fmt::format("{} overlap q99({})", scene, d));
    n.push_back(fmt::format("{} contacts per grain at 0", scene));
    n.push_back(fmt::format("{} contacts per grain at onset", scene));
  }
  return n;
}

// The quantities of the sensitivity figure, in its column order.
const std::vector<std::string> kSensitivityColumns{
    "solid fraction",       "soft-solid delta",   "soft-solid b",         "soft-solid b fixed range", "soft-solid Fn(0.3)",
    "soft-solid kt/Fn(0.5)", "soft-soft delta",   "soft-soft Fn(0.5)",    "soft-soft kt/Fn(0.5)"};

// Contacts per grain of a grown packing: grain–grain contacts counted at both grains, grain–shell
// at the grain, over the grains (all pairs: the packings hold a few thousand grains).
double coordination(const PackingFile& p) {
  const std::size_t n = p.radii.size();
  if (n == 0) return kNaN;
  const double tol = kTouchingGap * p.Rs;
  std::size_t ends = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.Rs - p.centres[i].norm() - p.radii[i] <= tol) ++ends;
    for (std::size_t j = i + 1; j < n; ++j)
      if ((p.centres[i] - p.centres[j]).norm() - p.radii[i] - p.radii[j] <= tol) ends += 2;
  }
  return static_cast<double>(ends) / static_cast<double>(n);
}

double value_at(const std::vector<double>& x, const std::vector<MeanError>& y, double at) {
  for (std::size_t k = 0; k < x.size(); ++k)
    if (std::abs(x[k] - at) < 1e-9) return y[k].mean;
  return kNaN;
}

// Every quantity of one setting on `seeds` (soft-soft's seed k stands for its pair); notes of
// what could not be measured.
std::vector<double> measure(const Study& st, StudyRuns& runs, const std::string& folder, const Seeds& seeds,
                            const fit::FitSection& section, std::vector<std::string>* notes) {
  std::vector<double> q;
  const auto note = [&](std::string text) {
    if (notes) notes->push_back(std::move(text));
  };
  // The packings.
  std::vector<double> phi, z, grains;
  for (std::uint64_t s : seeds) {
    const PackingFile& p = runs.packing(folder, s);
    double v = 0.0;
    for (double r : p.radii) v += r * r * r;
    phi.push_back(v / (p.Rs * p.Rs * p.Rs));
    z.push_back(coordination(p));
    grains.push_back(static_cast<double>(p.radii.size()));
  }
  for (const auto* v : {&phi, &z, &grains}) {
    q.push_back(mean_error(*v).mean);
    note("");
  }
  for (const auto& scene : kStudyScenes) {
    const fit::FitOptions options = section.options_for(scene);
    std::vector<SweepColumns> normal, tangential;
    std::vector<double> at_zero, at_onset;
    // Per Δn of Fn_delta_n, per seed: the largest overlap and its 99th percentile.
    std::vector<std::vector<double>> overlap(st.Fn_delta_n.size()), overlap_q99(st.Fn_delta_n.size());
    for (std::uint64_t s : seeds) {
      const SweepResults& n = runs.results(folder, "normal", scene, s);
      normal.push_back(n);
      // The largest overlap / smaller radius at the compared Δn (results of release 0.5.0 on).
      for (std::size_t k = 0; k < n.overlap_max.size(); ++k)
        for (std::size_t d = 0; d < st.Fn_delta_n.size(); ++d)
          if (std::abs(n.delta_n[k] - st.Fn_delta_n[d]) < 1e-9) {
            overlap[d].push_back(n.overlap_max[k]);
            overlap_q99[d].push_back(n.overlap_q99[k]);
          }
      tangential.push_back(runs.results(folder, "tangential", scene, s));
      double N = static_cast<double>(runs.packing(folder, s).radii.size());
      if (scene == "soft-soft") N += static_cast<double>(runs.packing(folder, runs.partner(folder, s)).radii.size());
      // Contacts per grain after the first relaxation (the first point, Δn = 0) and at the first
      // point loaded in the fit's sense (Fn above onset_force × the sweep's largest).
      if (!n.contacts.empty()) at_zero.push_back(static_cast<double>(n.contacts.front()) / N);
      double top = 0.0;
      for (const Vec3& F : n.force) top = std::max(top, F.x());
      for (std::size_t k = 0; k < n.force.size(); ++k)
        if (n.force[k].x() > options.onset_force * top && n.delta_n[k] > 0.0) {
          at_onset.push_back(static_cast<double>(n.contacts[k]) / N);
          break;
        }
    }
    const NormalAverage na = average_normal(normal);
    const TangentialAverage ta = average_tangential(tangential);
    std::vector<double> mean, error;
    for (const auto& m : na.Fn) mean.push_back(m.mean), error.push_back(m.error);
    fit::PowerLawFit f, fixed;
    std::string why, why_fixed;
    try {
      f = fit::fit_normal_law(na.delta_n, mean, error, options);
    } catch (const InputError& e) {
      why = fmt::format("{}: {}", scene, e.what());
    }
    // b on the study's fixed range: the same points for every setting, whatever its onset.
    const auto range = st.b_range.find(scene);
    if (range == st.b_range.end()) {
      why_fixed = fmt::format("{}: no calibrate.b_range for this scene", scene);
    } else {
      std::vector<double> x, y, e;
      for (std::size_t k = 0; k < na.delta_n.size(); ++k)
        if (na.delta_n[k] >= range->second.first - 1e-12 && na.delta_n[k] <= range->second.second + 1e-12)
          x.push_back(na.delta_n[k]), y.push_back(mean[k]), e.push_back(error[k]);
      try {
        fixed = fit::fit_normal_law(x, y, e, options);
      } catch (const InputError& ex) {
        why_fixed = fmt::format("{} b on [{}, {}]: {}", scene, range->second.first, range->second.second, ex.what());
      }
    }
    for (double v : {f.delta, f.a, f.b}) {
      q.push_back(why.empty() ? v : kNaN);
      note(why);
    }
    q.push_back(why_fixed.empty() ? fixed.b : kNaN);
    note(why_fixed);
    for (double d : st.Fn_delta_n) {
      q.push_back(value_at(na.delta_n, na.Fn, d));
      note("");
    }
    for (double d : st.kt_delta_n) {
      q.push_back(value_at(ta.kt_delta_n, ta.kt, d));
      note("");
    }
    for (double d : st.kt_delta_n) {
      q.push_back(value_at(ta.kt_delta_n, ta.kt, d) / value_at(na.delta_n, na.Fn, d));
      note("");
    }
    for (const auto* o : {&overlap, &overlap_q99})
      for (std::size_t d = 0; d < st.Fn_delta_n.size(); ++d) {
        q.push_back((*o)[d].size() == seeds.size() ? mean_error((*o)[d]).mean : kNaN);
        note((*o)[d].size() == seeds.size() ? "" : fmt::format("{}: no overlap recorded (results before release 0.5.0)", scene));
      }
    q.push_back(at_zero.size() == seeds.size() ? mean_error(at_zero).mean : kNaN);
    note("");
    q.push_back(at_onset.size() == seeds.size() ? mean_error(at_onset).mean : kNaN);
    note(at_onset.size() == seeds.size() ? "" : fmt::format("{}: a seed has no loaded point", scene));
  }
  return q;
}

fit::FitSection profile_fit_section(const Study& st, const StudySetting& s) {
  const ConfigNode p = ConfigNode::load_string(setting_profile_text(st, s), fmt::format("{} (setting {})", st.path, s.name));
  return fit::parse_fit_section(p);
}

}  // namespace

CalibrationReport calibration_report(const Study& st, const std::string& dir) {
  StudyRuns runs(dir);
  CalibrationReport r;
  r.quantities = quantity_names(st);
  std::vector<const StudySetting*> all{&st.reference};
  for (const auto& s : st.settings) all.push_back(&s);
  for (const StudySetting* s : all) {
    CalibrationRow row;
    row.name = s->name;
    row.knob = s->name == "reference" ? fmt::format("(the base, {})", st.base) : setting_changes(st, *s);
    row.seeds = s->seeds.size();
    const StudySetting& src = s->runs() ? *s : st.setting(s->of);
    if (const auto failed = setting_failure(dir, src.name)) {
      row.failed = *failed;
      r.rows.push_back(row);
      continue;
    }
    const ProfileTiming time = collect_timing(study_files(dir, src.name, s->seeds));
    row.cpu_seconds = time.total().cpu;
    row.complete = time.complete();
    if (!row.complete) {
      r.rows.push_back(row);
      continue;
    }
    const fit::FitSection fit_section = profile_fit_section(st, src);
    std::vector<std::string> notes;
    row.value = measure(st, runs, src.name, s->seeds, fit_section, &notes);
    row.note = notes;
    // Leave-one-seed-out jackknife.
    const std::size_t ns = s->seeds.size(), nq = row.value.size();
    std::vector<std::vector<double>> leave(nq);
    if (ns > 1)
      for (std::size_t i = 0; i < ns; ++i) {
        Seeds rest = s->seeds;
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
        const std::vector<double> v = measure(st, runs, src.name, rest, fit_section, nullptr);
        for (std::size_t k = 0; k < nq; ++k) leave[k].push_back(v[k]);
      }
    for (std::size_t k = 0; k < nq; ++k) row.error.push_back(jackknife_error(leave[k]));
    r.rows.push_back(row);
  }
  return r;
}

namespace {


std::size_t index_of(const CalibrationReport& r, const std::string& name) {
  const auto it = std::find(r.quantities.begin(), r.quantities.end(), name);
  if (it == r.quantities.end()) throw std::logic_error("calibration report: no quantity '" + name + "'");
  return static_cast<std::size_t>(it - r.quantities.begin());
}

// The change of quantity k of a setting against the base in units of their errors:
// z = Δ / √(σ² + σ_base²) (NaN where either is not measured).
double change_z(const CalibrationRow& row, const CalibrationRow& base, std::size_t k) {
  return (row.value[k] - base.value[k]) / std::hypot(row.error[k], base.error[k]);
}

// One Markdown table: a row per complete setting, a column per quantity (value ± standard error).
std::string table(const CalibrationReport& r, const std::vector<std::string>& columns) {
  std::string md = "| setting |";
  for (const auto& c : columns) md += fmt::format(" {} |", c);
  md += "\n|---|";
  for (std::size_t k = 0; k < columns.size(); ++k) md += "---|";
  md += "\n";
  for (const auto& row : r.rows) {
    if (!row.complete) continue;
    md += fmt::format("| {} |", row.name);
    for (const auto& c : columns) {
      const std::size_t k = index_of(r, c);
      md += fmt::format(" {} |", value_cell(row.value[k], row.error[k]));
    }
    md += "\n";
  }
  return md + "\n";
}

}  // namespace

std::string write_calibration_report(const CalibrationReport& r, const std::string& out_dir, const std::string& title) {
  std::filesystem::create_directories(out_dir);
  std::string md = fmt::format(
      "# {}\n\nEvery value over the setting's seeds ± its seed-to-seed (jackknife) standard error. Eq. 7 fitted as each "
      "setting's profile says (its `fit` section); \"b fixed range\": Eq. 7 on the study's fixed range of Δn. Coordination "
      "after growth: contacts closed to 1e-9 Rs per grain (a grain–grain contact counts at both grains). Contacts per "
      "grain: closed contacts of the scene (grain–grain, grain–shell, grain–wall) over its grains, after the first "
      "relaxation (Δn = 0) and at the first loaded point. Overlap max(Δn), q99(Δn): the largest overlap over the smaller "
      "radius of its contact at that point, and the value 99 % of the contacts do not exceed (results of release 0.5.0 "
      "on); the Hertz law holds for overlaps << 1.\n\n## Settings\n\n| setting | changes | seeds | CPU [s] |\n|---|---|---|---|\n",
      title);
  for (const auto& row : r.rows)
    md += fmt::format("| {} | {} | {} | {} |\n", row.name, row.knob, row.seeds,
                      row.complete           ? fmt::format("{:.0f}", row.cpu_seconds)
                      : row.failed.empty() ? std::string("not run yet")
                                             : "failed: " + row.failed);
  // The columns of each table: packings and onsets; then each scene's law.
  std::vector<std::string> onset{"solid fraction", "coordination after growth", "grains"};
  for (const auto& scene : kStudyScenes)
    for (const char* k : {"delta", "contacts per grain at 0", "contacts per grain at onset"}) onset.push_back(scene + " " + k);
  md += "\n## Packings and onsets\n\n" + table(r, onset);
  for (const auto& scene : kStudyScenes) {
    std::vector<std::string> cols;
    for (const auto& q : r.quantities)
      if (q.rfind(scene + " ", 0) == 0 && q.find("contacts") == std::string::npos) cols.push_back(q);
    md += fmt::format("## {}\n\n{}", scene, table(r, cols));
  }
  // The change of each quantity against the base: z = Δ / √(σ² + σ_base²).
  const CalibrationRow* base = r.rows.empty() || !r.rows.front().complete ? nullptr : &r.rows.front();
  if (base) {
    md += "## Change against the base\n\n(setting − base) / √(σ² + σ_base²); |z| ≥ 2 in bold.\n\n| quantity |";
    for (const auto& row : r.rows)
      if (row.complete && &row != base) md += fmt::format(" {} |", row.name);
    md += "\n|---|";
    for (const auto& row : r.rows)
      if (row.complete && &row != base) md += "---|";
    md += "\n";
    for (std::size_t k = 0; k < r.quantities.size(); ++k) {
      md += fmt::format("| {} |", r.quantities[k]);
      for (const auto& row : r.rows) {
        if (!row.complete || &row == base) continue;
        const double z = change_z(row, *base, k);
        md += std::isfinite(z) ? (std::abs(z) >= 2.0 ? fmt::format(" **{:+.1f}** |", z) : fmt::format(" {:+.1f} |", z)) : " – |";
      }
      md += "\n";
    }
  }
  // Notes: what could not be measured.
  std::string notes;
  for (const auto& row : r.rows)
    for (std::size_t k = 0; k < row.note.size(); ++k)
      if (!row.note[k].empty()) notes += fmt::format("- {}: {}: {}\n", row.name, r.quantities[k], row.note[k]);
  if (!notes.empty()) md += "\n## Not measured\n\n" + notes;
  write_file_atomically(out_dir + "/table.md", md);

  // onset.dat: per complete setting, the solid fraction and the onsets, for the figure.
  std::string dat = "# index setting phi phi_err delta_solid err delta_soft err z_growth z_growth_err\n";
  std::size_t i = 0;
  const std::size_t kphi = index_of(r, "solid fraction"), kz = index_of(r, "coordination after growth"),
                    ks = index_of(r, "soft-solid delta"), kf = index_of(r, "soft-soft delta");
  for (const auto& row : r.rows) {
    if (!row.complete) continue;
    const auto v = [&](std::size_t k) { return std::isfinite(row.value[k]) ? fmt::format("{:.6g}", row.value[k]) : "NaN"; };
    const auto e = [&](std::size_t k) { return std::isfinite(row.error[k]) ? fmt::format("{:.6g}", row.error[k]) : "0"; };
    dat += fmt::format("{} \"{}\" {} {} {} {} {} {} {} {}\n", i++, row.name, v(kphi), e(kphi), v(ks), e(ks), v(kf), e(kf), v(kz), e(kz));
  }
  write_file_atomically(out_dir + "/onset.dat", dat);

  // sensitivity.dat: the coefficient change per parameter change, for the figure
  // (figures/calibration_sensitivity.gp): per complete setting but the base (rows) and headline
  // quantity (columns), z = Δ / √(σ² + σ_base²) and the relative change Δ / base.
  std::string sens = "# column row z relative_change setting quantity\n";
  if (base) {
    std::size_t row_index = 0;
    for (const auto& row : r.rows) {
      if (!row.complete || &row == base) continue;
      for (std::size_t c = 0; c < kSensitivityColumns.size(); ++c) {
        const auto at = std::find(r.quantities.begin(), r.quantities.end(), kSensitivityColumns[c]);
        if (at == r.quantities.end()) continue;  // a study that does not compare at these Δn
        const auto k = static_cast<std::size_t>(at - r.quantities.begin());
        const double z = change_z(row, *base, k);
        const double rel = (row.value[k] - base->value[k]) / base->value[k];
        sens += fmt::format("{} {} {} {} \"{}\" \"{}\"\n", c, row_index, std::isfinite(z) ? fmt::format("{:.4g}", z) : "NaN",
                            std::isfinite(rel) ? fmt::format("{:.4g}", rel) : "NaN", row.name, kSensitivityColumns[c]);
      }
      ++row_index;
    }
  }
  write_file_atomically(out_dir + "/sensitivity.dat", sens);

  nlohmann::json j;
  j["quantities"] = r.quantities;
  for (const auto& row : r.rows) {
    nlohmann::json values = nlohmann::json::array(), errors = nlohmann::json::array();
    for (std::size_t k = 0; k < row.value.size(); ++k) {
      values.push_back(json_number(row.value[k]));
      errors.push_back(json_number(row.error[k]));
    }
    j["settings"].push_back({{"name", row.name},
                             {"changes", row.knob},
                             {"seeds", row.seeds},
                             {"complete", row.complete},
                             {"failed", row.failed},
                             {"cpu_seconds", row.cpu_seconds},
                             {"value", values},
                             {"error", errors}});
  }
  write_file_atomically(out_dir + "/calibration.json", j.dump(2) + "\n");
  return md;
}

}  // namespace softpack
