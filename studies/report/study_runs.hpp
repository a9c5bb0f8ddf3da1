// The results files of a study's runs (workflow/studies.mk: <dir>/<setting>/{packings, normal,
// tangential}/...), each read once: the reports (accuracy, calibration) come back to the same
// files many times for their jackknife (analysis/seed_statistics.hpp) and paired comparisons.
#pragma once
#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"
#include "report/stage_timing.hpp"

namespace softpack {

/// Why a setting's run failed: the first line of <dir>/<setting>/failed.txt, which
/// workflow/studies.mk writes for a failed setting ("its run failed (no message)" when empty);
/// none when it did not fail.
inline std::optional<std::string> setting_failure(const std::string& dir, const std::string& setting) {
  std::ifstream in(fmt::format("{}/{}/failed.txt", dir, setting));
  if (!in) return std::nullopt;
  std::string line;
  std::getline(in, line);
  return line.empty() ? "its run failed (no message)" : line;
}

/// The two scenes of a study's runs.
inline const std::vector<std::string> kStudyScenes{"soft-solid", "soft-soft"};

inline std::string sweep_path(const std::string& dir, const std::string& setting, const std::string& stage,
                              const std::string& scene, std::uint64_t seed) {
  return fmt::format("{}/{}/{}/{}-seed-{}.h5", dir, setting, stage, scene, seed);
}

inline std::string packing_path(const std::string& dir, const std::string& setting, std::uint64_t seed) {
  return fmt::format("{}/{}/packings/seed-{}.h5", dir, setting, seed);
}

/// The files of a running setting's measurement on `seeds` (both scenes), for its cost and completeness.
inline TimingInputs study_files(const std::string& dir, const std::string& setting, const std::vector<std::uint64_t>& seeds) {
  TimingInputs in;
  for (std::uint64_t s : seeds) {
    in.packings.push_back(packing_path(dir, setting, s));
    for (const std::string& scene : kStudyScenes) {
      in.normal.push_back(sweep_path(dir, setting, "normal", scene, s));
      in.tangential.push_back(sweep_path(dir, setting, "tangential", scene, s));
    }
  }
  return in;
}

class StudyRuns {
 public:
  explicit StudyRuns(std::string dir) : dir_(std::move(dir)) {}
  const std::string& dir() const { return dir_; }
  const SweepResults& results(const std::string& folder, const std::string& stage, const std::string& scene, std::uint64_t seed) {
    const std::string path = sweep_path(dir_, folder, stage, scene, seed);
    auto it = sweeps_.find(path);
    if (it == sweeps_.end()) it = sweeps_.emplace(path, read_sweep_results_file(path, stage, scene)).first;
    return it->second;
  }
  const PackingFile& packing(const std::string& folder, std::uint64_t seed) {
    const std::string path = packing_path(dir_, folder, seed);
    auto it = packings_.find(path);
    if (it == packings_.end()) it = packings_.emplace(path, read_packing_file(path)).first;
    return it->second;
  }
  /// The seed of the second packing of soft-soft's seed `seed` in `folder`, as its normal results
  /// record it ("<path> (seed k), <path> (seed m)"): the pairing is the workflow's, read, not redone.
  std::uint64_t partner(const std::string& folder, std::uint64_t seed) {
    const SweepResults& r = results(folder, "normal", "soft-soft", seed);
    const std::size_t at = r.packings.rfind("(seed ");
    if (at == std::string::npos || at == r.packings.find("(seed "))
      throw InputError(fmt::format("{}: /provenance/packings: '{}' names no second packing", r.path, r.packings));
    return std::stoull(r.packings.substr(at + 6));
  }

 private:
  std::string dir_;
  std::map<std::string, SweepResults> sweeps_;
  std::map<std::string, PackingFile> packings_;
};

}  // namespace softpack
