// The sweep point file: one measured point of a sweep with the simulation state it ended in,
// the checkpoint that lets an interrupted sweep resume and the normal states the tangential
// stage starts from (measure/sweeps.hpp). HDF5 layout:
//
//   /result/...      PointResult: delta_n, hn, alpha_deg, ht, force, force_first, force_between
//                    (3), contacts, relax_steps, relax_time, steps, seconds, and per relaxation
//                    check checks/{time, force_ratio, energy_ratio, kinetic_energy,
//                    elastic_energy, max_unbalanced_force, mean_contact_force, contacts}
//   /state/...       SimulationState: time, steps, x, v, w, F, T, plane_points, shell_centres
//                    (N, 3), pair_springs/{i, j, xi}, plane_springs/<w>/{i, xi},
//                    shell_springs/<w>/{i, xi}
//   /provenance/...  stage, scene, config, code_version (formats/sweep_provenance.hpp)
#pragma once
#include <string>

#include "formats/sweep_provenance.hpp"
#include "io/hdf5_file.hpp"
#include "measure/point_result.hpp"
#include "state/simulation_state.hpp"

namespace softpack {

/// Writes the file atomically.
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

/// "a sweep point file (a checkpoint of softpack-normal)" when `f` has the layout of one, else
/// "" (formats/file_kind.hpp).
std::string describe_point_file(const h5::File& f);

}  // namespace softpack
