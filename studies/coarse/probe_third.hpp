// The many-body law's third version (issue 33; paper/many-body.md, "Next", written before the
// runs it names were read; experiments/many-body.yaml, `third_version`): each part fitted on the
// probe only, on the runs the plan names, and predicted on the ones it holds out.
//
//   count of contacts   the walls' volumetric law with E the sum of the caps (volumetric) or their
//                       union (volumetric-union), β fitted on `fit` + count_fit, the form chosen
//                       by `selection` on `held_out` + count_held_out
//   grains              F1 g(X), g(X) = (X / (1 + X))^p: p on the single contacts of grain_fit,
//                       then the grains' β on their arrangements of two or more (the chosen form);
//                       predicted on grain_held_out
//   soft-particles      the engine's mean rule (half the centre's others) with β_ss fitted on the
//                       soft arrangements (its fit error only: no soft run is left out)
//   tangential gain     kt / kt_one predicted as the walls' law's normal gain, on every confined
//                       shear row (no parameter)
//
// Writes OUT/third-version.md and .json, and returns what the law file's many_body becomes.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "coarse/probe_second.hpp"

namespace softpack {

struct FittedValue {
  double value = 0.0, se = 0.0;  ///< se: the jackknife over the plan's seeds
};

struct ThirdVersion {
  struct CountForm {
    std::string name;
    FittedValue beta;
    ProbeError fit, held_out;
    std::map<std::string, ProbeError> by_arrangement;
  };
  std::vector<CountForm> count;
  std::string count_chosen;  ///< by the plan's rule
  FittedValue grain_p, grain_beta;
  /// Every arrangement of the grain kinds: the third version's error, and the engine's until now
  /// (the walls' β of the first part, a grain taken as a wall).
  std::map<std::string, ProbeError> grain, grain_before;
  ProbeError grain_fit, grain_held_out;
  FittedValue soft_beta;  ///< β_ss of the engine's mean rule
  std::map<std::string, ProbeError> soft;
  ProbeError soft_fit;
  struct Gain {
    std::string radius, arrangement;
    double delta_n = 0.0;
    LogRatio kt;             ///< measured kt / kt_one
    double predicted = 0.0;  ///< the walls' law's Fn / F1 at the arrangement's first wall
  };
  std::vector<Gain> gain;
  ProbeError gain_error;  ///< rms and mean of ln(predicted) − the measured mean log, over the rows
  std::vector<std::string> notes;
};

/// The analysis; `walls` the seed files', `bodies` the bodies files', `second` the second part
/// (its shear ratios).
ThirdVersion analyse_third_version(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& bodies,
                                   const SecondPart& second, double beta_before);

/// The analysis written to OUT/third-version.md and .json.
ThirdVersion write_third_version(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& walls,
                                 const std::vector<ProbeWallForce>& bodies, const SecondPart& second, double beta_before,
                                 const std::string& out_dir);

}  // namespace softpack
