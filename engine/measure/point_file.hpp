// One measured point of a sweep, with the simulation state it ended in: the checkpoint that
// lets an interrupted sweep resume, and the normal states the tangential stage starts from.
// HDF5 groups: /result (the numbers), /state (SimulationState), /provenance.
#pragma once
#include <string>
#include <vector>

#include "relax/relaxation.hpp"
#include "sim/simulation.hpp"

namespace softpack {

struct PointResult {
  double delta_n = 0.0, hn = 0.0;    ///< normal deformation, hn = delta_n Rs [m]
  double alpha_deg = 0.0, ht = 0.0;  ///< tangential stage: rotation and ht = pi Rs alpha / 180 [m]
  Vec3 force = Vec3::Zero();          ///< on the second body [N]
  Vec3 force_first = Vec3::Zero();    ///< load on the first shell [N] (minus force in balance)
  Vec3 force_between = Vec3::Zero();  ///< elastic force of the first body's spheres on the second's [N]
  long contacts = 0;                  ///< closed contacts at the end
  long relax_steps = 0;
  double relax_time = 0.0;            ///< simulated [s]
  std::vector<RelaxationCheck> checks;
  long steps = 0;                     ///< all steps of the point (loading, rotation, relaxation)
  double seconds = 0.0;               ///< wall-clock time of the point
};

struct PointProvenance {
  std::string stage;   ///< "normal" or "tangential"
  std::string scene;   ///< "soft-solid" or "soft-soft"
  std::string config;  ///< the configuration the point depends on (YAML)
  std::string code_version;
};

void write_point_file(const std::string& path, const PointResult& r, const SimulationState& state,
                      const PointProvenance& prov);

/// Reads a point file, with the simulation state when `with_state`. InputError, naming the file
/// and the dataset, when it is missing, unreadable, not a point file, or inconsistent (columns of
/// different lengths, values that are not finite, spring ids outside the state).
struct PointFile {
  PointResult result;
  SimulationState state;
  PointProvenance provenance;
};
PointFile read_point_file(const std::string& path, bool with_state);

/// The results of a whole sweep: arrays over the points, the relaxation checks flattened.
void write_sweep_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                      const std::string& packings, std::uint64_t seed, double seconds);

}  // namespace softpack
