#include "report/nested_report.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"
#include "measure/settings.hpp"
#include "report/report_cells.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

// The grid's values within [lo, hi].
std::vector<double> grid_within(const std::vector<double>& grid, const std::array<double, 2>& range) {
  std::vector<double> out;
  for (double d : grid)
    if (d >= range[0] - 1e-12 && d <= range[1] + 1e-12) out.push_back(d);
  return out;
}

NestedSetting measure_setting(const Study& st, const std::string& dir, const std::string& name) {
  NestedSetting s;
  s.name = name;
  s.changes = setting_changes(st, st.setting(name));
  s.rows = setting_law_rows(st, dir, name, &s.Rs);
  s.ran = !s.rows.empty();
  if (!s.ran) return s;
  StudyRuns runs(dir);
  const StudySetting& setting = st.setting(name);
  for (std::uint64_t seed : setting.seeds) {
    const PackingFile& p = runs.packing(name, seed);
    s.grains += static_cast<double>(p.radii.size()) / static_cast<double>(setting.seeds.size());
    s.sites += static_cast<double>(p.sites.centres.size()) / static_cast<double>(setting.seeds.size());
    s.cpu_packings += p.provenance.cpu_seconds;
    for (const RadiusRow& row : s.rows)
      for (const char* stage : {"normal", "tangential", "sliding"})
        if (std::filesystem::exists(sweep_path(dir, name, stage, row.scene, seed)))
          s.cpu_stages += runs.results(name, stage, row.scene, seed).total_cpu_seconds;
  }
  return s;
}

NestedPoint nested_point(const std::string& scene, const std::string& quantity, double dn, const RadiusValue& v, const RadiusValue& a) {
  NestedPoint p;
  p.scene = scene, p.quantity = quantity, p.delta_n = dn, p.value = v, p.against = a;
  p.ratio.value = v.value / a.value;
  p.ratio.error = std::abs(p.ratio.value) * std::hypot(v.error / v.value, a.error / a.value);
  return p;
}

// The criterion's onset force at radius Rs: onset_force (Rs / Rs0)^2.
double onset_at(const NestedCriterion& c, double Rs) { return c.onset_force * (Rs / c.Rs0) * (Rs / c.Rs0); }

}  // namespace

NestedComparison nested_comparison(const NestedSetting& s, const NestedSetting& against, const NestedCriterion& c,
                                   const std::vector<double>& Fn_delta_n, const std::vector<double>& kt_delta_n) {
  NestedComparison out;
  out.setting = s.name, out.against = against.name;
  const double onset = onset_at(c, s.Rs);
  const auto judge = [&](NestedPoint& p, double Fn, double Fn_against) {
    p.compared = std::isfinite(p.value.value) && std::isfinite(p.against.value) && !(Fn < onset && Fn_against < onset);
    p.agrees = p.compared && std::abs(p.value.value - p.against.value) <= c.bound * std::hypot(p.value.error, p.against.error);
    out.compared += p.compared ? 1 : 0;
    out.agreeing += p.agrees ? 1 : 0;
    out.points.push_back(p);
  };
  for (const RadiusRow& row : s.rows) {
    const auto a = std::find_if(against.rows.begin(), against.rows.end(), [&](const RadiusRow& r) { return r.scene == row.scene; });
    if (a == against.rows.end()) continue;
    const auto Fn_at = [&](const RadiusRow& r, double dn) {
      for (std::size_t k = 0; k < Fn_delta_n.size(); ++k)
        if (std::abs(Fn_delta_n[k] - dn) < 1e-12) return r.Fn[k].value;
      return kNaN;  // no normal point there: the kt point is compared
    };
    for (std::size_t k = 0; k < Fn_delta_n.size(); ++k) {
      NestedPoint p = nested_point(row.scene, "Fn", Fn_delta_n[k], row.Fn[k], a->Fn[k]);
      judge(p, row.Fn[k].value, a->Fn[k].value);
    }
    for (std::size_t k = 0; k < kt_delta_n.size() && k < row.kt.size() && k < a->kt.size(); ++k) {
      const double dn = kt_delta_n[k];
      NestedPoint p = nested_point(row.scene, "kt", dn, row.kt[k], a->kt[k]);
      judge(p, Fn_at(row, dn), Fn_at(*a, dn));
    }
  }
  return out;
}

double nested_unloaded_to(const RadiusRow& row, const std::vector<double>& Fn_delta_n, const NestedCriterion& c, double Rs) {
  const double onset = onset_at(c, Rs);
  double to = kNaN;
  for (std::size_t k = 0; k < Fn_delta_n.size() && k < row.Fn.size(); ++k) {
    if (!(row.Fn[k].value < onset)) break;
    to = Fn_delta_n[k];
  }
  return to;
}

void nested_closer(NestedComparison& c, const NestedComparison& reference) {
  c.closer = c.closer_of = 0;
  for (const NestedPoint& p : c.points) {
    if (!p.compared) continue;
    for (const NestedPoint& q : reference.points)
      if (q.compared && q.scene == p.scene && q.quantity == p.quantity && std::abs(q.delta_n - p.delta_n) < 1e-12) {
        ++c.closer_of;
        if (std::abs(p.value.value - p.against.value) < std::abs(q.value.value - q.against.value)) ++c.closer;
      }
  }
}

namespace {

nlohmann::json nested_json(const RadiusValue& v) { return {{"value", json_number(v.value)}, {"error", json_number(v.error)}}; }

}  // namespace

NestedCriterion read_nested_criterion(const std::string& path) {
  if (path.empty()) throw InputError("the nested report needs `criteria`: the file of its criterion (experiments/nested.yaml)");
  const ConfigNode root = ConfigNode::load_file(path);
  const ConfigNode n = root.at("nested");
  const ConfigNode c = n.at("criterion");
  NestedCriterion out;
  const auto range = [&](const char* key) {
    const auto items = c.at(key).items();
    if (items.size() != 2 || !(items[0].number() < items[1].number())) c.at(key).fail("allowed: [low, high] with low < high");
    return std::array<double, 2>{items[0].number(), items[1].number()};
  };
  out.Fn_delta_n = range("Fn_delta_n");
  out.kt_delta_n = range("kt_delta_n");
  out.bound = c.at("bound").number();
  out.onset_force = c.at("onset_force").number();
  out.Rs0 = n.at("packing").at("Rs").number();
  if (!(out.bound > 0.0)) c.at("bound").fail("allowed: a bound > 0");
  if (!(out.onset_force >= 0.0)) c.at("onset_force").fail("allowed: onset_force >= 0 N");
  if (!(out.Rs0 > 0.0)) n.at("packing").at("Rs").fail("allowed: Rs > 0 m");
  if (const auto d = n.find("diagnosis"))
    for (const ConfigNode& item : d->at("settings").items()) out.diagnosis.push_back(item.string());
  return out;
}

NestedReport nested_report(const Study& study, const std::string& dir) {
  NestedReport r;
  r.criterion = read_nested_criterion(study.criteria);
  if (study.nested_against.empty()) throw InputError(fmt::format("{}: the nested report needs `nested.against`", study.path));
  // Fn and kt at every grid point within the criterion's ranges: the grids of the setting compared against.
  Study st = study;
  {
    const StudySetting& against = study.setting(study.nested_against);
    const ConfigNode p = ConfigNode::load_string(setting_profile_text(study, against), study.path);
    const MeasurementSettings m = parse_measurement(p);
    st.Fn_delta_n = grid_within(m.normal.delta_n, r.criterion.Fn_delta_n);
    st.kt_delta_n = m.has_tangential ? grid_within(m.tangential.delta_n, r.criterion.kt_delta_n) : std::vector<double>{};
  }
  r.Fn_delta_n = st.Fn_delta_n;
  std::vector<std::string> names{"reference"};
  for (const StudySetting& s : study.settings) names.push_back(s.name);
  for (const std::string& n : names) r.settings.push_back(measure_setting(st, dir, n));
  const auto against = std::find_if(r.settings.begin(), r.settings.end(), [&](const NestedSetting& s) { return s.name == study.nested_against; });
  for (const NestedSetting& s : r.settings)
    if (s.name != study.nested_against && s.ran && against->ran) r.comparisons.push_back(nested_comparison(s, *against, r.criterion, st.Fn_delta_n, st.kt_delta_n));
  const auto reference = std::find_if(r.comparisons.begin(), r.comparisons.end(), [](const NestedComparison& c) { return c.setting == "reference"; });
  if (reference != r.comparisons.end())
    for (NestedComparison& c : r.comparisons)
      if (std::find(r.criterion.diagnosis.begin(), r.criterion.diagnosis.end(), c.setting) != r.criterion.diagnosis.end())
        nested_closer(c, *reference);
  return r;
}

std::string write_nested_report(const NestedReport& r, const Study& study, const std::string& out_dir, const std::string& title) {
  std::filesystem::create_directories(out_dir);
  const NestedCriterion& c = r.criterion;
  std::string t = fmt::format(
      "# {}\n\nEach setting's laws over its seeds (± seed-to-seed standard error; fits: jackknife), measured as the "
      "radius study's (docs/radius.md), and its law file `<setting>/laws.json`. The criterion ({}, written before the "
      "runs): Fn at Δn {}–{} and kt at Δn {}–{} agree with `{}`'s when |mean − mean_against| ≤ {} √(se² + se_against²); a "
      "point where Fn is below {} N × (Rs / {} m)² in both is left out.\n\n",
      title, study.criteria, c.Fn_delta_n[0], c.Fn_delta_n[1], c.kt_delta_n[0], c.kt_delta_n[1], study.nested_against, c.bound,
      c.onset_force, c.Rs0);
  t += "## Laws and cost\n\nUnloaded to: the largest Δn of the criterion's Fn range up to which the mean Fn is below the onset force "
       "(– : loaded at its first).\n\n"
       "| setting | changes | scene | Rs [m] | grains | sites | δ | a [N] | b | c [N] | kt a [N/m] | kt b | μ_soft | unloaded to | CPU packings [s] | CPU stages [s] |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  nlohmann::json j = nlohmann::json::object();
  j["criteria"] = study.criteria;
  for (const NestedSetting& s : r.settings) {
    if (!s.ran) {
      t += fmt::format("| {} | {} | not run yet | | | | | | | | | | | | | |\n", s.name, s.changes);
      continue;
    }
    nlohmann::json js_setting = {{"Rs", s.Rs}, {"grains", s.grains}, {"sites", s.sites}, {"cpu_packings", s.cpu_packings},
                                 {"cpu_stages", s.cpu_stages}, {"changes", s.changes}};
    LawFile laws;
    laws.reference_radius = s.Rs;
    for (const RadiusRow& row : s.rows) {
      std::string mu;
      for (std::size_t k = 0; k < row.mu.size(); ++k)
        mu += fmt::format("{}{}: {}", k ? "; " : "", row.mu_delta_n[k], value_cell(row.mu[k].value, row.mu[k].error));
      const double unloaded = nested_unloaded_to(row, r.Fn_delta_n, c, s.Rs);
      t += fmt::format("| {} | {} | {} | {:.6g} | {:.0f} | {:.1f} | {} | {} | {} | {} | {} | {} | {} | {} | {:.0f} | {:.0f} |\n", s.name,
                       s.changes, row.scene, s.Rs, s.grains, s.sites, value_cell(row.delta.value, row.delta.error),
                       value_cell(row.a.value, row.a.error), value_cell(row.b.value, row.b.error), value_cell(row.c.value, row.c.error),
                       value_cell(row.kt_a.value, row.kt_a.error), value_cell(row.kt_b.value, row.kt_b.error), mu,
                       std::isfinite(unloaded) ? fmt::format("{}", unloaded) : "–", s.cpu_packings, s.cpu_stages);
      js_setting["scenes"][row.scene] = {{"delta", nested_json(row.delta)}, {"a", nested_json(row.a)}, {"b", nested_json(row.b)}, {"c", nested_json(row.c)},
                                         {"kt_a", nested_json(row.kt_a)}, {"kt_b", nested_json(row.kt_b)}, {"note", row.note},
                                         {"Fn_unloaded_to", json_number(unloaded)}};
      if (std::isfinite(row.a.value)) laws.scenes[row.scene] = row_scene_laws(row);
    }
    j["settings"][s.name] = js_setting;
    if (laws.scenes.empty()) continue;
    laws.provenance.study = study.path;
    laws.provenance.seeds = study.setting(s.name).seeds;
    laws.provenance.code_version = code_version();
    laws.provenance.created =
        fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now()));
    laws.provenance.notes = fmt::format("Laws of setting '{}' of the nested study at its radius, no radius scaling (docs/nested.md).", s.name);
    std::filesystem::create_directories(out_dir + "/" + s.name);
    write_law_file_if_changed(out_dir + "/" + s.name + "/laws.json", laws);
  }
  for (const NestedComparison& cmp : r.comparisons) {
    // (Whether that is the recursion holding depends on what is compared: nested against resolved
    // content in the self-consistency test, one nested form against another in the chain.)
    t += fmt::format("\n## `{}` against `{}`: {} of {} points agree — by the criterion they {}\n\n", cmp.setting, cmp.against,
                     cmp.agreeing, cmp.compared, cmp.holds() ? "agree" : "differ");
    if (cmp.closer_of > 0)
      t += fmt::format("Nearer `{}` than `reference` at {} of the {} points compared in both: {} (experiments/nested.yaml's "
                       "diagnosis).\n\n",
                       cmp.against, cmp.closer, cmp.closer_of,
                       cmp.cause() ? (cmp.holds() ? "the whole cause of the gap" : "a cause of the gap") : "not a cause of the gap");
    t += fmt::format("| scene | quantity | Δn | {} | {} | ratio | compared | agrees |\n|---|---|---|---|---|---|---|---|\n", cmp.setting,
                     cmp.against);
    nlohmann::json points = nlohmann::json::array();
    for (const NestedPoint& p : cmp.points) {
      t += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", p.scene, p.quantity, p.delta_n, value_cell(p.value.value, p.value.error),
                       value_cell(p.against.value, p.against.error), value_cell(p.ratio.value, p.ratio.error), p.compared ? "yes" : "no",
                       p.compared ? (p.agrees ? "yes" : "no") : "–");
      points.push_back({{"scene", p.scene}, {"quantity", p.quantity}, {"delta_n", p.delta_n}, {"value", nested_json(p.value)},
                        {"against", nested_json(p.against)}, {"ratio", nested_json(p.ratio)}, {"compared", p.compared}, {"agrees", p.agrees}});
    }
    j["comparisons"].push_back({{"setting", cmp.setting}, {"against", cmp.against}, {"compared", cmp.compared},
                                {"agreeing", cmp.agreeing}, {"holds", cmp.holds()}, {"closer", cmp.closer},
                                {"closer_of", cmp.closer_of}, {"points", points}});
  }
  write_file_atomically(out_dir + "/nested.json", j.dump(1) + "\n");
  write_file_atomically(out_dir + "/table.md", t);
  return t;
}

}  // namespace softpack
