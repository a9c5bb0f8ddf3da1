// What the resolved model of a medium would cost, from what it holds and a measured cost per
// sphere-step (issue 35, docs/nested.md "The three-decade medium"): a medium of nested
// soft-particles over three decades is too large to run resolved here, so its soft run's cost is
// set against an estimate, stated before the runs it judges (experiments/three-decades.yaml):
//
//   spheres   N = the first decade's grains + every grain of every site at every level (its
//             sites' sites expected from a sample when the medium's are: medium.content_sample)
//   step      dt = the engine's step for the resolved scene (integrate/time_step.hpp: the smallest
//             grain's Rayleigh time times the profile's safety; of a sampled medium, the smallest
//             grain the sample drew: the medium's own, among some 10^6, may be a little smaller)
//   steps     n = the soft run's simulated time (its steps times its step) / dt: the same
//             compression of the same medium, each row the same wall travel and rest
//   cost      N n c, c the CPU seconds per sphere-step of resolved runs that did run (their CPU
//             time / (spheres steps)), the mean over them
//
// The plan (settings `plan.levels_added` a, experiments/three-decades.yaml states the rule): the
// same medium with each site's soft-particle a levels deeper at the same Π. Its soft run costs
// this one's (the same explicit bodies, whose step it is); resolved, its sites' sites' contents
// of D levels each (D = levels - 1) hold (n^(D+a) - 1) / (n^D - 1) times the grains, every level
// holding as many grains and n sites as the one above (self-similar levels), n the mean sites of
// the medium's own site packings; its step is the engine's for the smallest grain / Π^a.
//
// c is measured on media of one level, whose grains and contacts per grain are like the nested
// medium's; an estimate, not a run. Its error is that of N's expected value (the sample's) and of
// c over the runs, not the scatter of one resolved medium about it.
#pragma once
#include <string>
#include <vector>

#include "coarse/medium.hpp"
#include "coarse/result_file.hpp"

namespace softpack {

/// The resolved cost of the medium a levels deeper (the header's plan).
struct DeeperPlan {
  int levels_added = 0;            ///< a (0: no plan)
  double sites_per_packing = 0.0;  ///< n
  double depth_ratio = 0.0;        ///< (n^(D+a) - 1) / (n^D - 1)
  double spheres = 0.0, spheres_error = 0.0;
  double smallest_radius = 0.0;    ///< [m]
  double dt = 0.0;                 ///< [s]
  double steps = 0.0;
  double cpu = 0.0, cpu_error = 0.0;  ///< [s]
};

struct ResolvedEstimate {
  double spheres = 0.0, spheres_error = 0.0;  ///< N (expected from the sample when the medium's contents are sampled)
  std::size_t content_sample = 0;  ///< the medium's (0: its contents made)
  double smallest_radius = 0.0;    ///< [m]
  double dt = 0.0;                 ///< [s]
  double simulated_time = 0.0;     ///< of the soft run [s]
  double steps = 0.0;              ///< n
  double cpu_per_sphere_step = 0.0, cpu_per_sphere_step_error = 0.0;  ///< c [s], its standard error over the runs
  std::size_t measured_runs = 0;
  double cpu = 0.0, cpu_error = 0.0;  ///< N n c [s], its error from N's and c's
  double soft_cpu = 0.0;           ///< the soft run's, measured [s]
  DeeperPlan deeper;               ///< the settings' plan (levels_added 0: none)
  double speed_up() const { return cpu / soft_cpu; }
};

/// The estimate of the medium's resolved run from its soft run and resolved runs of other media;
/// InputError when `soft` is not a soft run of this medium or a measured run is not resolved.
ResolvedEstimate estimate_resolved(const CoarseGrainSettings& s, const Medium& m, const CoarseResult& soft,
                                   const std::vector<CoarseResult>& measured);

/// The estimate as JSON text (every quantity with its unit; the measured runs' paths).
/// With its provenance: the settings file and medium file it was made from, the code version.
std::string resolved_estimate_json(const ResolvedEstimate& e, const std::string& config, const std::string& medium, const CoarseResult& soft,
                                   const std::vector<CoarseResult>& measured);

}  // namespace softpack
