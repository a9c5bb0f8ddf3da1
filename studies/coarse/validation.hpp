// The many-body law's acceptance on media (issue 33, item 4; experiments/many-body.yaml,
// `validation`, written before the runs): a setting of the validation study is accepted where
// |σzz_soft − σzz_resolved| <= bound × sqrt(se_soft² + se_resolved²) at every recorded strain of the
// plan's range, loading and unloading, and τ at the end of the platen shear within the same
// bound. `softpack-coarse validation` writes the verdict of each setting (validation.md, .json).
#pragma once
#include <string>
#include <vector>

#include "coarse/probe_settings.hpp"
#include "coarse/report.hpp"

namespace softpack {

struct ValidationVerdict {
  std::string setting;
  std::size_t points = 0, agreeing = 0;  ///< loading and unloading points in the strain range
  double worst_strain = 0.0;             ///< the point farthest outside (or nearest the bound)
  int worst_phase = 1;
  double worst_excess = 0.0;             ///< |difference| / bound there (> 1: outside)
  double worst_ratio = 0.0;              ///< σzz soft / resolved there
  bool tau_measured = false;             ///< a platen shear was run
  double tau_resolved = 0.0, tau_soft = 0.0, tau_excess = 0.0;  ///< at the shear's end
  bool accepted = false;
};

ValidationVerdict judge_validation(const CoarseComparison& c, const ManyBodyProbe& plan, const std::string& setting);

/// The verdict of each setting of the study's folder `data_dir` (its profiles/SETTING.yaml and runs),
/// on the media seeds of the law's `version` (ManyBodyProbe::media_seeds_of); writes
/// out_dir/validation.md and validation.json.
std::vector<ValidationVerdict> write_validation(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& data_dir,
                                                const std::vector<std::string>& settings, const std::string& out_dir, int version = 1);

}  // namespace softpack
