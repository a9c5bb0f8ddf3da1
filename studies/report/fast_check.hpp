// The fast profile against the paper profile on the paper's seeds (issue 13, docs/accuracy.md
// "The fast profile"): the quantities of the fidelity study (report/accuracy_report.hpp: a, b,
// c, δ of Eq. 7, a, b, c of Eq. 8, Fn and kt at a few Δn, both scenes), each profile's
// seed-to-seed (jackknife) standard error over the seeds, whether the two agree within their
// combined standard error, and what each cost in CPU time (the sums its files record).
//
// This is a report on seeds both profiles ran, not a calibration: the fast profile is chosen on
// held-out seeds (experiments/studies/fast-profile.yaml) and only checked here.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace softpack {

struct FastCheckRow {
  std::string quantity;
  double reference = 0.0, reference_sigma = 0.0;  ///< value over the seeds, jackknife standard error
  double candidate = 0.0, candidate_sigma = 0.0;
  double z = 0.0;            ///< (candidate - reference) / sqrt(reference_sigma^2 + candidate_sigma^2)
  bool established = false;  ///< the reference tells it from zero (2 of its σ): compared
  bool agrees = false;       ///< established and |z| <= 1
};

struct FastCheck {
  std::string reference, candidate;  ///< the profiles (folders under the data folder)
  std::vector<std::uint64_t> seeds;
  double reference_cpu = 0.0, candidate_cpu = 0.0;  ///< [s], packings and sweeps
  std::vector<FastCheckRow> rows;
  std::size_t compared() const;
  std::size_t agreeing() const;
};

/// Reads <data>/<profile>/{packings,normal,tangential}/ of both profiles on `seeds` (InputError
/// naming the missing file when one is not there, or the two packings of a seed that differ).
FastCheck fast_check(const std::string& data, const std::string& reference, const std::string& candidate,
                     const std::vector<std::uint64_t>& seeds, const std::vector<double>& Fn_delta_n,
                     const std::vector<double>& kt_delta_n);

/// <out_dir>/table.md and check.json; returns the text of table.md.
std::string write_fast_check(const FastCheck& check, const std::string& out_dir);

}  // namespace softpack
