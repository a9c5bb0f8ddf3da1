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

/// One soft setting against another on the same media and resolved runs (a bound read against the
/// version it changes, paper/many-body.md): at each loading point of the plan's strain range, the
/// difference of their mean σzz against bound × sqrt(se² + se²) of it.
struct SettingShift {
  std::string setting, base;
  std::size_t points = 0;       ///< loading points in the strain range
  std::size_t above = 0;        ///< the setting's σzz above the base's by more than the bound
  std::size_t below = 0;        ///< below it by more than the bound
  double gap_share = 0.0;       ///< mean of (σzz setting − σzz base) / (σzz resolved − σzz base)
  bool moves_up() const { return points > 0 && 2 * above >= points; }  ///< at at least half the points
};
/// InputError when the two comparisons' points are not the same strains (not the same study's runs).
SettingShift shift_against(const CoarseComparison& base, const CoarseComparison& c, const ManyBodyProbe& plan, const std::string& base_name,
                           const std::string& setting);

/// The verdict of each setting of the study's folder `data_dir` (its profiles/SETTING.yaml and runs),
/// on the media seeds of the law's `version` (ManyBodyProbe::media_seeds_of); writes
/// out_dir/validation.md and validation.json. With `against` (one of `settings`), each other soft
/// setting is also read against it (SettingShift), in a section of its own.
std::vector<ValidationVerdict> write_validation(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& data_dir,
                                                const std::vector<std::string>& settings, const std::string& out_dir, int version = 1,
                                                const std::string& against = "");

}  // namespace softpack
