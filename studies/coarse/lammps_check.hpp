// The soft-particle medium in LAMMPS against softpack's engine (issue 34, deliverable 3b;
// experiments/lammps.yaml, written before the runs; docs/lammps.md; make lammps-check): for each
// setting of the plan's study and each rank count, LAMMPS's runs of the exported compression
// (coarse/lammps_export.hpp) against the engine's soft runs on the same media, by the coarse-grain
// report's comparison (coarse/report.hpp: the engine in its slot 0, LAMMPS in slot 1), judged by
// the plan's rule: σzz at every loading and unloading point of strain_range and K0 at every loading
// point of k0_strain_range within bound × sqrt(se² + se²). Reported outside the rule: τ at the end of
// the shear, the paired difference, and the runs on 2 ranks against those on 1.
//
// Folders: the engine's runs DIR/SETTING/soft/seed-S.h5 of the study (its profiles/SETTING.yaml),
// LAMMPS's OUT/SETTING/npR/seed-S.h5 (softpack-coarse lammps-curve), the report OUT/report/.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "coarse/report.hpp"

namespace softpack {

struct LammpsCheckPlan {
  std::string study;  ///< the study folder whose media and engine runs are compared
  std::vector<std::string> settings;
  std::vector<std::uint64_t> seeds;
  std::vector<int> ranks;
  double strain_lo = 0.0, strain_hi = 0.0, k0_lo = 0.0, k0_hi = 0.0;
  double bound = 0.0;  ///< in standard errors of the two means
};

/// experiments/lammps.yaml's `lammps_check`; InputError naming the key.
LammpsCheckPlan read_lammps_check_plan(const std::string& path);

struct LammpsVerdict {
  std::string setting;
  int ranks = 0;
  std::size_t sigma_points = 0, sigma_agreeing = 0, k0_points = 0, k0_agreeing = 0;
  double worst_strain = 0.0, worst_excess = 0.0, worst_ratio = 0.0;  ///< σzz's point farthest from the bound (|diff| / bound)
  double k0_worst_strain = 0.0, k0_worst_excess = 0.0;
  double end_ratio = 0.0;                   ///< σzz LAMMPS / engine at the end of loading
  MeanError end_sigma[2], end_K0[2];        ///< there, [0] the engine, [1] LAMMPS
  MeanError end_difference;                 ///< there, LAMMPS − engine paired by seed
  MeanError tau[2];                         ///< at the end of the shear
  double seconds[2] = {0.0, 0.0};           ///< the runs' wall time summed over seeds
  bool accepted() const { return sigma_points > 0 && sigma_agreeing == sigma_points && k0_points > 0 && k0_agreeing == k0_points; }
};

/// The verdict of one comparison (slot 0 the engine, 1 LAMMPS) by the plan's rule.
/// `end_strain`: the settings' end of loading (its σzz, K0 and ratio are reported).
LammpsVerdict judge_lammps(const CoarseComparison& c, const LammpsCheckPlan& plan, const std::string& setting, int ranks, double end_strain);

/// Every setting and rank count of the plan: OUT/report/check.md and check.json; the verdicts.
std::vector<LammpsVerdict> write_lammps_check(const LammpsCheckPlan& plan, const std::string& plan_path, const std::string& out_dir);

}  // namespace softpack
