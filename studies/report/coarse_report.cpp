#include "report/coarse_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "coarse/report.hpp"
#include "coarse/settings.hpp"
#include "config/yaml_node.hpp"
#include "core/types.hpp"
#include "io/atomic_file.hpp"
#include "report/report_cells.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

// The last point of a phase (1 loading, 2 shear), or none.
const CoarsePoint* last_of(const CoarseComparison& c, int phase) {
  const CoarsePoint* last = nullptr;
  for (const CoarsePoint& p : c.points)
    if (p.phase == phase) last = &p;
  return last;
}

std::string ratio_cell(const MeanError* a, const MeanError* b) {
  return a && b && b->mean != 0.0 ? fmt::format("{:.3f}", a->mean / b->mean) : "–";
}

}  // namespace

std::string write_coarse_study_report(const Study& study, const std::string& data_dir, const std::string& out_dir,
                                      const std::string& title) {
  std::vector<const StudySetting*> settings{&study.reference};
  for (const StudySetting& s : study.settings) settings.push_back(&s);
  std::string md = fmt::format(
      "# {}\n\nEach setting's medium compressed resolved and with soft-particles (docs/coarse-grain.md); its own table "
      "and figure in <setting>/. At the end of loading: σzz of the soft medium / the resolved one's (means over seeds) "
      "and K0 of each; at the end of the platen shear, τ/σzz of each. Agreement: every loading point up to that strain "
      "within 2 √(se² + se²). Within the laws: the last loading strain before any seed's soft run met a "
      "contact beyond the laws' measured range (– where its runs do not count them); past it the soft stress rests on Eq. 7 "
      "beyond its grid, the end of loading's included.\n\n"
      "| setting | changes | seeds | agreement strain | within the laws | σzz soft / resolved | K0 resolved | K0 soft | τ/σzz resolved | "
      "τ/σzz soft | speed-up | CPU resolved [s] |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      title);
  nlohmann::json rows = nlohmann::json::array();
  std::optional<CoarseComparison> reference;
  std::string paired;
  for (const StudySetting* s : settings) {
    const StudySetting& source = s->runs() ? *s : study.setting(s->of);
    const std::string folder = fmt::format("{}/{}", data_dir, source.name), changes = setting_changes(study, *s);
    CoarseGrainSettings cs =
        read_coarse_grain_settings(ConfigNode::load_string(setting_profile_text(study, source), study.path + " (setting " + source.name + ")"));
    cs.seeds = s->seeds;
    const std::optional<CoarseComparison> c = coarse_comparison(cs, folder);
    if (!c) {
      const auto failed = setting_failure(data_dir, source.name);
      md += fmt::format("| {} | {} | | {} | | | | | | | | |\n", s->name, changes, failed ? "failed: " + *failed : "not run");
      continue;
    }
    write_coarse_report(*c, cs, fmt::format("{}, setting {}", study.path, s->name), fmt::format("{}/{}", out_dir, s->name));
    const CoarsePoint* load = last_of(*c, 1);
    const CoarsePoint* shear = last_of(*c, 2);
    double cpu = 0.0;
    for (double t : c->cpu[0]) cpu += t;
    std::string seeds;
    for (auto seed : c->seeds) seeds += fmt::format("{}{}", seeds.empty() ? "" : " ", seed);  // not "x" + string: GCC 12's -Wrestrict
    const auto tau_ratio = [&](int m) { return shear ? fmt::format("{:.3f}", shear->tau[m].mean / shear->sigma[m].mean) : std::string("–"); };
    const double within = c->within_laws_strain;
    const std::string within_cell = std::isnan(within) ? "–" : within < 0.0 ? "none" : fmt::format("{:.3f}", within);
    md += fmt::format("| {} | {} | {} | {:.3f} | {} | {} | {} | {} | {} | {} | {} | {:.0f} |\n", s->name, changes, seeds, c->agreement_strain,
                      within_cell, ratio_cell(load ? &load->sigma[1] : nullptr, load ? &load->sigma[0] : nullptr),
                      load ? value_cell(load->K0[0].mean, load->K0[0].error) : "–", load ? value_cell(load->K0[1].mean, load->K0[1].error) : "–",
                      tau_ratio(0), tau_ratio(1), value_cell(c->mean_speedup.mean, c->mean_speedup.error), cpu);
    nlohmann::json shift;  // against the reference, on the same media and resolved runs
    if (s == &study.reference) {
      reference = c;
    } else if (reference) {
      std::string why;
      if (const std::optional<PairedShift> p = paired_shift(*reference, *c, &why)) {
        paired += fmt::format("| {} | {:.3f} | {} | {} | {} | {} |\n", s->name, p->strain, value_cell(p->q.mean, p->q.error),
                              p->sign() > 0 ? "more than the reference" : p->sign() < 0 ? "less than the reference" : "within 2 se",
                              value_cell(p->ratio[1].mean, p->ratio[1].error), value_cell(p->ratio[0].mean, p->ratio[0].error));
        shift = {{"strain", p->strain}, {"q", json_number(p->q.mean)}, {"q_se", json_number(p->q.error)}, {"sign", p->sign()},
                 {"ratio", json_number(p->ratio[1].mean)}, {"ratio_se", json_number(p->ratio[1].error)},
                 {"reference_ratio", json_number(p->ratio[0].mean)}, {"reference_ratio_se", json_number(p->ratio[0].error)}};
      } else {
        paired += fmt::format("| {} | – | – | {} | – | – |\n", s->name, why);
      }
    }
    rows.push_back({{"setting", s->name},
                    {"paired_against_reference", shift},
                    {"changes", changes},
                    {"seeds", c->seeds},
                    {"report", s->name + "/summary.json"},
                    {"agreement_strain", c->agreement_strain},
                    {"within_laws_strain", json_number(within)},
                    {"sigma_soft_over_resolved", load ? json_number(load->sigma[1].mean / load->sigma[0].mean) : nullptr},
                    {"speedup", json_number(c->mean_speedup.mean)},
                    {"cpu_seconds_resolved", cpu}});
  }
  if (!paired.empty())
    md += "\n## Against the reference, medium by medium\n\nA setting on the same media and resolved runs as the reference: at "
          "e*, the last loading strain at which both settings' soft runs are within their laws' measured range, q = (σzz soft − σzz soft "
          "of the reference) / σzz resolved on each medium, its mean ± standard error over the media (their own spread cancels in it); "
          "*more* or *less* than the reference when |mean q| > 2 se. Beside it, σzz soft / resolved at e* (means over the seeds, "
          "errors of the two means).\n\n| setting | e* | q | by 2 se | σzz soft / resolved | the reference's |\n|---|---|---|---|---|---|\n" +
          paired;
  write_files_atomically({{out_dir + "/table.md", md}, {out_dir + "/coarse.json", nlohmann::json{{"title", title}, {"rows", rows}}.dump(2) + "\n"}});
  return md;
}

}  // namespace softpack
