#include "report/radius_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "analysis/average.hpp"
#include "analysis/fit_options.hpp"
#include "analysis/power_fit.hpp"
#include "analysis/seed_statistics.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "measure/settings.hpp"
#include "packing/packing_profile.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

using Seeds = std::vector<std::uint64_t>;

struct SettingInfo {
  const StudySetting* setting = nullptr;
  double Rs = 0.0, r_max = 0.0;
  MeasurementSettings measure;
  fit::FitSection fit;
};

SettingInfo setting_info(const Study& st, const std::string& name) {
  SettingInfo i;
  i.setting = &st.setting(name);
  const ConfigNode p = ConfigNode::load_string(setting_profile_text(st, *i.setting), fmt::format("{} (setting {})", st.path, name));
  const PackingProfile packing = parse_packing(p);
  i.Rs = packing.parameters.Rs;
  i.r_max = packing.parameters.r_max;
  i.measure = parse_measurement(p);
  i.fit = fit::parse_fit_section(p);
  return i;
}

std::vector<std::string> scenes_of(const SettingInfo& i) {
  std::vector<std::string> s;
  for (ContactScene c : i.measure.normal.scenes) s.push_back(scene_name(c));
  return s;
}

// Whether every seed of every scene has the stage's results (the packings too for "normal").
bool has_stage(const std::string& dir, const std::string& name, const SettingInfo& i, const std::string& stage) {
  for (std::uint64_t seed : i.setting->seeds) {
    if (stage == "normal" && !std::filesystem::exists(packing_path(dir, name, seed))) return false;
    for (const std::string& scene : scenes_of(i))
      if (!std::filesystem::exists(sweep_path(dir, name, stage, scene, seed))) return false;
  }
  return true;
}

// Eq. 7 and Eq. 8 on the mean over `use` (indices into the seeds' columns).
struct Fits {
  fit::PowerLawFit normal, tangential;
  bool has_normal = false, has_tangential = false;
};
Fits fit_laws(const std::vector<SweepColumns>& normal, const std::vector<SweepColumns>& tangential, const std::vector<std::size_t>& use,
              const fit::FitOptions& options, std::string* why) {
  std::vector<SweepColumns> n, t;
  for (std::size_t k : use) {
    n.push_back(normal[k]);
    if (!tangential.empty()) t.push_back(tangential[k]);
  }
  Fits f;
  if (n.empty()) return f;
  const NormalAverage na = average_normal(n);
  std::vector<double> mean, error;
  for (const auto& m : na.Fn) mean.push_back(m.mean), error.push_back(m.error);
  try {
    f.normal = fit::fit_normal_law(na.delta_n, mean, error, options);
    f.has_normal = true;
    if (t.empty()) return f;  // no tangential results (yet)
    const TangentialAverage ta = average_tangential(t);
    std::vector<double> kt, kt_error;
    for (const auto& m : ta.kt) kt.push_back(m.mean), kt_error.push_back(m.error);
    f.tangential = fit::fit_tangential_law(ta.kt_delta_n, kt, kt_error, f.normal.delta, options);
    f.has_tangential = true;
  } catch (const InputError& e) {
    if (why && why->empty()) *why = e.what();
  }
  return f;
}

// The jackknife of each coefficient: fits leaving out one seed in turn.
void jackknife(const std::vector<SweepColumns>& normal, const std::vector<SweepColumns>& tangential, const fit::FitOptions& options,
               RadiusRow& row) {
  std::vector<double> delta, a, b, c, kt_a, kt_b;
  for (std::size_t out = 0; out < normal.size(); ++out) {
    std::vector<std::size_t> use;
    for (std::size_t k = 0; k < normal.size(); ++k)
      if (k != out) use.push_back(k);
    const Fits f = fit_laws(normal, tangential, use, options, nullptr);
    if (f.has_normal) delta.push_back(f.normal.delta), a.push_back(f.normal.a), b.push_back(f.normal.b), c.push_back(f.normal.c);
    if (f.has_tangential) kt_a.push_back(f.tangential.a), kt_b.push_back(f.tangential.b);
  }
  const auto err = [&](const std::vector<double>& v) { return v.size() == normal.size() ? jackknife_error(v) : kNaN; };
  row.delta.error = err(delta), row.a.error = err(a), row.b.error = err(b), row.c.error = err(c);
  row.kt_a.error = err(kt_a), row.kt_b.error = err(kt_b);
}

RadiusValue at(const std::vector<double>& x, const std::vector<MeanError>& y, double where) {
  for (std::size_t k = 0; k < x.size(); ++k)
    if (std::abs(x[k] - where) < 1e-9) return {y[k].mean, y[k].error};
  return {kNaN, kNaN};
}

}  // namespace

// μ_soft per sliding Δn: per seed the mean of −Ft'/Fn' over the plateau (ht / Rs >= from) and
// its largest value, in the contact's frame (turned by alpha_deg about +z); then over seeds.
void sliding_friction(const std::vector<SweepResults>& sliding, const std::vector<double>& sliding_delta_n, double Rs, double from,
                      std::size_t least, RadiusRow& row) {
  const std::size_t needed = least == 0 ? sliding.size() : least;
  for (double dn : sliding_delta_n) {
    std::vector<double> plateau, peak;
    for (const SweepResults& s : sliding) {
      double sum = 0.0, top = -1e300;
      std::size_t n = 0;
      bool loaded = true;
      for (std::size_t k = 0; k < s.delta_n.size(); ++k) {
        if (std::abs(s.delta_n[k] - dn) > 1e-12) continue;
        const double th = s.alpha_deg[k] * std::acos(-1.0) / 180.0;
        const Vec3& F = s.force[k];
        const double Fn = F.x() * std::cos(th) + F.y() * std::sin(th), Ft = -F.x() * std::sin(th) + F.y() * std::cos(th);
        if (!(Fn > 0.0)) {
          loaded = false;
          continue;
        }
        const double mu = -Ft / Fn;
        top = std::max(top, mu);
        if (s.ht[k] / Rs >= from - 1e-12) sum += mu, ++n;
      }
      if (loaded && n > 0) plateau.push_back(sum / static_cast<double>(n)), peak.push_back(top);
    }
    row.mu_delta_n.push_back(dn);
    if (plateau.size() >= needed && !plateau.empty()) {
      const MeanError p = mean_error(plateau), q = mean_error(peak);
      row.mu.push_back({p.mean, p.error});
      row.mu_peak.push_back({q.mean, q.error});
      if (plateau.size() < sliding.size())
        row.note += fmt::format("{}mu at delta_n {}: from the {} of {} seeds with a normal force while sliding", row.note.empty() ? "" : "; ",
                                dn, plateau.size(), sliding.size());
    } else {
      row.mu.push_back({kNaN, kNaN});
      row.mu_peak.push_back({kNaN, kNaN});
      row.note += fmt::format("{}mu at delta_n {}: a seed has no normal force while sliding", row.note.empty() ? "" : "; ", dn);
    }
  }
}

namespace {

RadiusRow measure_row(const Study& st, StudyRuns& runs, const std::string& name, const SettingInfo& info,
                      const std::string& scene) {
  RadiusRow row;
  row.setting = name, row.scene = scene, row.Rs = info.Rs, row.r_max = info.r_max;
  const Seeds& seeds = info.setting->seeds;
  row.seeds = seeds.size();
  std::vector<SweepColumns> normal, tangential;
  std::vector<SweepResults> sliding;
  double grains = 0.0;
  // A setting still running is reported from what it has: the normal stage first.
  const bool with_tangential = has_stage(runs.dir(), name, info, "tangential");
  const bool with_sliding = info.measure.has_sliding && has_stage(runs.dir(), name, info, "sliding");
  if (!with_tangential) row.note = "no tangential results yet";
  if (info.measure.has_sliding && !with_sliding) row.note += std::string(row.note.empty() ? "" : "; ") + "no sliding results yet";
  for (std::uint64_t s : seeds) {
    normal.push_back(runs.results(name, "normal", scene, s));
    if (with_tangential) tangential.push_back(runs.results(name, "tangential", scene, s));
    if (with_sliding) sliding.push_back(runs.results(name, "sliding", scene, s));
    grains += static_cast<double>(runs.packing(name, s).radii.size());
  }
  row.grains = grains / static_cast<double>(seeds.size());
  const fit::FitOptions options = info.fit.options_for(scene);
  std::vector<std::size_t> all(seeds.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  std::string why;
  const Fits f = fit_laws(normal, tangential, all, options, &why);
  if (!why.empty()) row.note += std::string(row.note.empty() ? "" : "; ") + why;
  row.delta.value = f.has_normal ? f.normal.delta : kNaN;
  row.a.value = f.has_normal ? f.normal.a : kNaN;
  row.b.value = f.has_normal ? f.normal.b : kNaN;
  row.c.value = f.has_normal ? f.normal.c : kNaN;
  row.kt_a.value = f.has_tangential && with_tangential ? f.tangential.a : kNaN;
  row.kt_b.value = f.has_tangential && with_tangential ? f.tangential.b : kNaN;
  if (f.has_normal) row.dn_min = f.normal.dn_min, row.dn_max = f.normal.dn_max;
  if (f.has_tangential) row.kt_dn_min = f.tangential.dn_min, row.kt_dn_max = f.tangential.dn_max;
  jackknife(normal, tangential, options, row);
  const NormalAverage na = average_normal(normal);
  for (double d : st.Fn_delta_n) row.Fn.push_back(at(na.delta_n, na.Fn, d));
  if (with_tangential) {
    const TangentialAverage ta = average_tangential(tangential);
    for (double d : st.kt_delta_n) row.kt.push_back(at(ta.kt_delta_n, ta.kt, d));
  } else {
    row.kt.assign(st.kt_delta_n.size(), RadiusValue{kNaN, kNaN});
  }
  if (with_sliding) sliding_friction(sliding, info.measure.sliding.delta_n, info.Rs, st.mu_from_ht_over_Rs, st.mu_seeds_loaded, row);
  return row;
}

const RadiusRow* find_row(const RadiusReport& r, const std::string& setting, const std::string& scene) {
  for (const RadiusRow& row : r.rows)
    if (row.setting == setting && row.scene == scene) return &row;
  return nullptr;
}

void add_scaling(RadiusReport& r, const std::string& variant, const std::vector<std::string>& names) {
  for (const char* scene : {"soft-solid", "soft-soft"}) {
    std::vector<const RadiusRow*> rows;
    for (const std::string& n : names)
      if (const RadiusRow* row = find_row(r, n, scene)) rows.push_back(row);
    if (rows.size() < 2) continue;
    const auto scaling = [&](const std::string& quantity, std::size_t groups, auto value) {
      std::vector<std::vector<double>> x(groups), y(groups), e(groups);
      for (const RadiusRow* row : rows)
        for (std::size_t g = 0; g < groups; ++g) {
          const RadiusValue v = value(*row, g);
          if (!(v.value > 0.0) || !(v.error > 0.0) || !std::isfinite(v.error)) continue;
          x[g].push_back(std::log(row->Rs / r.R0)), y[g].push_back(std::log(v.value)), e[g].push_back(v.error / v.value);
        }
      RadiusScalingRow s;
      s.variant = variant, s.scene = scene, s.quantity = quantity;
      s.exponent = common_exponent(x, y, e, &s.chi2_per_dof);
      s.R_min = rows.front()->Rs, s.R_max = rows.back()->Rs, s.radii = rows.size();
      r.scaling.push_back(s);
    };
    scaling("Fn", r.Fn_delta_n.size(), [](const RadiusRow& row, std::size_t g) { return row.Fn[g]; });
    // The local exponents of Fn and kt between neighbouring radii (a curved log-log line shows here).
    if (rows.size() > 2) {
      const std::vector<const RadiusRow*> all = rows;
      for (std::size_t i = 0; i + 1 < all.size(); ++i) {
        rows = {all[i], all[i + 1]};
        scaling("Fn, neighbouring radii", r.Fn_delta_n.size(), [](const RadiusRow& row, std::size_t g) { return row.Fn[g]; });
        scaling("kt, neighbouring radii", r.kt_delta_n.size(), [](const RadiusRow& row, std::size_t g) { return row.kt[g]; });
      }
      rows = all;
    }
    scaling("kt", r.kt_delta_n.size(), [](const RadiusRow& row, std::size_t g) { return row.kt[g]; });
    scaling("a", 1, [](const RadiusRow& row, std::size_t) { return row.a; });
  }
}

// Linear interpolation of the mean force on a grid; NaN outside it.
double interpolate(const NormalAverage& a, double dn) {
  for (std::size_t k = 1; k < a.delta_n.size(); ++k)
    if (dn >= a.delta_n[k - 1] - 1e-12 && dn <= a.delta_n[k] + 1e-12) {
      const double t = (dn - a.delta_n[k - 1]) / (a.delta_n[k] - a.delta_n[k - 1]);
      return (1.0 - t) * a.Fn[k - 1].mean + t * a.Fn[k].mean;
    }
  return kNaN;
}

MixedRow mixed_row(const Study& st, StudyRuns& runs, const std::string& name, const SettingInfo& info, double R0) {
  MixedRow m;
  m.setting = name;
  m.ratio = info.measure.normal.second_radius_ratio;
  std::vector<SweepColumns> measured, reference;
  for (std::uint64_t s : info.setting->seeds) measured.push_back(runs.results(name, "normal", "soft-soft", s));
  for (std::uint64_t s : st.reference.seeds) reference.push_back(runs.results("reference", "normal", "soft-soft", s));
  const NormalAverage me = average_normal(measured), ref = average_normal(reference);
  const double R1 = info.Rs, R2 = m.ratio * info.Rs;
  const double onset = info.fit.options_for("soft-soft").onset_force;
  double top = 0.0;
  for (const auto& f : me.Fn) top = std::max(top, f.mean);
  const std::vector<std::pair<std::string, double>> rules{
      {"reduced radius, R_eq = 2 R1 R2 / (R1 + R2)", 2.0 * R1 * R2 / (R1 + R2)}, {"R_eq = R1", R1}, {"R_eq = R2", R2}};
  for (const auto& [rule, Req] : rules) {
    std::vector<double> dev;
    for (std::size_t k = 0; k < me.delta_n.size(); ++k) {
      const double hn = me.delta_n[k] * R1, F = me.Fn[k].mean;
      const double predicted = (Req / R0) * (Req / R0) * interpolate(ref, hn / Req);
      if (!(F > onset * top) || !(predicted > 0.0)) continue;
      dev.push_back(F / predicted - 1.0);
      if (m.rules.empty()) m.delta_n.push_back(me.delta_n[k]), m.measured.push_back(F), m.predicted.push_back(predicted);
    }
    m.rules.push_back(rule);
    const MeanError d = dev.empty() ? MeanError{kNaN, kNaN} : mean_error(dev);
    m.deviation.push_back({d.mean, d.error});
  }
  return m;
}

}  // namespace

RadiusValue common_exponent(const std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& y,
                            const std::vector<std::vector<double>>& y_error, double* chi2_per_dof) {
  // Per group the weighted means; the slope from the deviations about them (one intercept each).
  double sxy = 0.0, sxx = 0.0;
  std::size_t points = 0, groups = 0;
  std::vector<double> xm(x.size()), ym(x.size());
  for (std::size_t g = 0; g < x.size(); ++g) {
    if (x[g].size() < 2) continue;
    double w = 0.0, wx = 0.0, wy = 0.0;
    for (std::size_t i = 0; i < x[g].size(); ++i) {
      const double wi = 1.0 / (y_error[g][i] * y_error[g][i]);
      w += wi, wx += wi * x[g][i], wy += wi * y[g][i];
    }
    xm[g] = wx / w, ym[g] = wy / w;
    for (std::size_t i = 0; i < x[g].size(); ++i) {
      const double wi = 1.0 / (y_error[g][i] * y_error[g][i]);
      sxy += wi * (x[g][i] - xm[g]) * (y[g][i] - ym[g]);
      sxx += wi * (x[g][i] - xm[g]) * (x[g][i] - xm[g]);
    }
    points += x[g].size(), ++groups;
  }
  if (groups == 0 || !(sxx > 0.0)) return {kNaN, kNaN};
  const double n = sxy / sxx;
  double chi2 = 0.0;
  for (std::size_t g = 0; g < x.size(); ++g) {
    if (x[g].size() < 2) continue;
    for (std::size_t i = 0; i < x[g].size(); ++i) {
      const double r = (y[g][i] - ym[g] - n * (x[g][i] - xm[g])) / y_error[g][i];
      chi2 += r * r;
    }
  }
  const double dof = static_cast<double>(points) - static_cast<double>(groups) - 1.0;
  const double s2 = dof > 0.0 ? chi2 / dof : kNaN;
  if (chi2_per_dof) *chi2_per_dof = s2;
  return {n, std::sqrt(1.0 / sxx) * (s2 > 1.0 ? std::sqrt(s2) : 1.0)};
}

std::vector<RadiusRow> setting_law_rows(const Study& st, const std::string& dir, const std::string& setting, double* Rs) {
  StudyRuns runs(dir);
  const SettingInfo info = setting_info(st, setting);
  if (Rs) *Rs = info.Rs;
  std::vector<RadiusRow> rows;
  if (!has_stage(dir, setting, info, "normal")) return rows;
  for (const std::string& scene : scenes_of(info)) rows.push_back(measure_row(st, runs, setting, info, scene));
  return rows;
}

RadiusReport radius_report(const Study& st, const std::string& dir) {
  RadiusReport r;
  r.Fn_delta_n = st.Fn_delta_n, r.kt_delta_n = st.kt_delta_n;
  StudyRuns runs(dir);
  std::vector<std::string> names{"reference"};
  for (const auto& [variant, list] : st.radius_variants)
    for (const std::string& n : list)
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  const SettingInfo reference = setting_info(st, "reference");
  r.R0 = reference.Rs;
  for (const char* stage : {"normal", "tangential", "sliding"})
    if (!has_stage(dir, "reference", reference, stage))
      throw InputError(fmt::format("{}/reference: the reference of the radius study has no {} results yet (make radius)", dir, stage));
  for (const std::string& n : names) {
    const SettingInfo info = setting_info(st, n);
    if (!has_stage(dir, n, info, "normal")) {
      r.missing.push_back(n);
      continue;
    }
    const auto mixed = st.radius_variants.find("mixed");
    const bool is_mixed = mixed != st.radius_variants.end() &&
                          std::find(mixed->second.begin(), mixed->second.end(), n) != mixed->second.end();
    if (is_mixed) {
      r.mixed.push_back(mixed_row(st, runs, n, info, r.R0));
      continue;
    }
    for (const std::string& scene : scenes_of(info)) r.rows.push_back(measure_row(st, runs, n, info, scene));
  }
  for (const char* variant : {"self_similar", "fixed"}) {
    const auto it = st.radius_variants.find(variant);
    if (it != st.radius_variants.end()) add_scaling(r, variant, it->second);
  }
  return r;
}

}  // namespace softpack
