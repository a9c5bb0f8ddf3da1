#include "report/fast_check.hpp"
#include "report/report_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/packing_file.hpp"
#include "io/atomic_file.hpp"
#include "report/accuracy_report.hpp"
#include "report/study_runs.hpp"

namespace softpack {
namespace {

// A study (report/study_file.hpp) whose reference is profile `reference` and whose one
// setting is `candidate`, both on `seeds`: accuracy_report() then measures both from their folders.
Study pair_study(const std::string& reference, const std::string& candidate, const std::vector<std::uint64_t>& seeds,
                         const std::vector<double>& Fn_delta_n, const std::vector<double>& kt_delta_n) {
  Study st;
  st.path = "fast check";
  st.seeds = seeds;
  st.Fn_delta_n = Fn_delta_n;
  st.kt_delta_n = kt_delta_n;
  st.reference.name = reference;
  st.reference.seeds = seeds;
  StudySetting c;
  c.name = candidate;
  c.seeds = seeds;
  st.settings.push_back(c);
  return st;
}

}  // namespace

std::size_t FastCheck::compared() const {
  return static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), [](const FastCheckRow& r) { return r.established; }));
}

std::size_t FastCheck::agreeing() const {
  return static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), [](const FastCheckRow& r) { return r.agrees; }));
}

FastCheck fast_check(const std::string& data, const std::string& reference, const std::string& candidate,
                     const std::vector<std::uint64_t>& seeds, const std::vector<double>& Fn_delta_n,
                     const std::vector<double>& kt_delta_n) {
  if (seeds.size() < 2) throw InputError(fmt::format("the check needs at least 2 seeds (a jackknife), not {}", seeds.size()));
  // Two protocols on the same soft-particles: two profiles whose packings differ would compare
  // the packings as much as the protocols (the paper profile's changed in release 0.6.0, the fast
  // profile's did not), with nothing to say so.
  for (const std::uint64_t seed : seeds) {
    const std::string a = packing_path(data, reference, seed), b = packing_path(data, candidate, seed);
    if (packing_sha256(read_packing_file(a)) != packing_sha256(read_packing_file(b)))
      throw InputError(fmt::format("{} and {}: the {} and {} profiles measured different packings of seed {}; the check compares "
                                   "two protocols on the same soft-particles: give both profiles one packing section",
                                   a, b, reference, candidate, seed));
  }
  // Each profile's values and jackknife standard errors, from a comparison that takes it as the
  // reference; the first also gives the candidate's cost.
  const AccuracyReport ab = accuracy_report(pair_study(reference, candidate, seeds, Fn_delta_n, kt_delta_n), data);
  const AccuracyReport ba = accuracy_report(pair_study(candidate, reference, seeds, Fn_delta_n, kt_delta_n), data);
  const SettingRow& row = ab.rows.front();
  if (!row.complete) throw InputError(fmt::format("{}/{}: the {} profile's results are not complete on seeds {}", data, candidate,
                                                  candidate, fmt::join(seeds, ", ")));
  FastCheck c;
  c.reference = reference, c.candidate = candidate, c.seeds = seeds;
  c.reference_cpu = ab.reference_cpu;
  c.candidate_cpu = row.cpu_seconds;
  for (std::size_t k = 0; k < ab.quantities.size(); ++k) {
    FastCheckRow r;
    r.quantity = ab.quantities[k];
    r.reference = ab.reference_value[k], r.reference_sigma = ab.reference_sigma[k];
    r.candidate = ba.reference_value[k], r.candidate_sigma = ba.reference_sigma[k];
    r.z = (r.candidate - r.reference) / std::hypot(r.reference_sigma, r.candidate_sigma);
    r.established = ab.established[k];
    r.agrees = r.established && std::isfinite(r.z) && std::abs(r.z) <= 1.0;
    c.rows.push_back(r);
  }
  return c;
}

std::string write_fast_check(const FastCheck& c, const std::string& out_dir) {
  std::filesystem::create_directories(out_dir);
  std::string md = fmt::format(
      "# The {1} profile against the {0} profile on seeds {2}\n\n"
      "CPU time (packings and sweeps, as their files record it): {0} {3:.0f} s, {1} {4:.0f} s, ratio {5:.3f} "
      "({6:.1f} times less).\n\n"
      "Each value over the seeds, ± its seed-to-seed (jackknife) standard error σ, at least its own standard error; "
      "z = ({1} − {0}) / √(σ_{0}² + σ_{1}²). Agreement: |z| ≤ 1. –: the {0} profile does not tell the quantity from "
      "zero (2 σ), not compared.\n\n"
      "{7} of {8} compared quantities agree.\n\n"
      "| quantity | {0} | {1} | z | agrees |\n|---|---|---|---|---|\n",
      c.reference, c.candidate, fmt::join(c.seeds, ", "), c.reference_cpu, c.candidate_cpu, c.candidate_cpu / c.reference_cpu,
      c.reference_cpu / c.candidate_cpu, c.agreeing(), c.compared());
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : c.rows) {
    md += fmt::format("| {} | {:.4g} ± {:.2g} | {:.4g} ± {:.2g} | {} | {} |\n", r.quantity, r.reference, r.reference_sigma,
                      r.candidate, r.candidate_sigma, r.established ? fmt::format("{:+.2f}", r.z) : "–",
                      r.established ? (r.agrees ? "yes" : "no") : "–");
    rows.push_back({{"quantity", r.quantity},
                    {"reference", json_number(r.reference)},
                    {"reference_sigma", json_number(r.reference_sigma)},
                    {"candidate", json_number(r.candidate)},
                    {"candidate_sigma", json_number(r.candidate_sigma)},
                    {"z", json_number(r.z)},
                    {"established", r.established},
                    {"agrees", r.agrees}});
  }
  nlohmann::json j{{"reference", c.reference},       {"candidate", c.candidate},   {"seeds", c.seeds},
                   {"reference_cpu", c.reference_cpu}, {"candidate_cpu", c.candidate_cpu},
                   {"cpu_ratio", c.candidate_cpu / c.reference_cpu}, {"compared", c.compared()}, {"agreeing", c.agreeing()},
                   {"rows", rows}};
  write_file_atomically(out_dir + "/table.md", md);
  write_file_atomically(out_dir + "/check.json", j.dump(2) + "\n");
  return md;
}

}  // namespace softpack
