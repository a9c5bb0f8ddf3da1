// The uniaxial (oedometric) compression of a medium (coarse/medium.hpp): the top wall moves
// down at constant speed by `strain` of the initial height, the other five walls stand, then it
// moves back up by `unload_strain`. A row of the curve every `record_strain`:
//
//   strain           (H0 - H) / H0
//   sigma_top        the top wall's load along its normal / L^2 [Pa]       (the axial stress)
//   sigma_bottom     the bottom wall's, likewise [Pa]
//   sigma_lateral    the four side walls' mean load along their normals / (L H) [Pa]
//   fraction         solid volume (both decades) / L^2 H
//   bodies in contact: pairs of bodies (a first-decade grain, a soft-particle or a site's
//                    packing) touching with a normal force > 0, by kind, and Z = 2 pairs / bodies
//   kinetic, elastic energy [J]
//   beyond_range     soft model: the soft contacts' evaluations beyond the laws' measured range up
//                    to this row (-1: not counted: the resolved model); max_dn the largest Δn met
//                    so far (NaN: not counted). The stress is Eq. 7's within its grid while 0.
//
// Then, with `shear`, the platen shear (phase 2): the top wall moves along +x, the rows add
//   shear            the top wall's displacement along x / H0
//   tau              the force the grains put on it along -x / L^2 [Pa] (the shear stress)
#pragma once
#include <functional>
#include <limits>
#include <vector>

#include "coarse/medium.hpp"
#include "core/stopwatch.hpp"
#include "forces/contact_models.hpp"
#include "sim/simulation.hpp"

namespace softpack {

struct CurveRow {
  double strain = 0.0;
  int phase = 1;  ///< 1 loading, -1 unloading, 2 shear
  double shear = 0.0, tau = 0.0;
  double sigma_top = 0.0, sigma_bottom = 0.0, sigma_lateral = 0.0;
  double fraction = 0.0;
  long grain_grain = 0, grain_soft = 0, soft_soft = 0;  ///< bodies in contact, by kind
  double Z = 0.0;
  double kinetic = 0.0, elastic = 0.0;
  long beyond_range = -1;  ///< soft model: evaluations beyond the laws' range so far (-1: not counted)
  double max_dn = std::numeric_limits<double>::quiet_NaN();  ///< soft model: the largest Δn met so far
};

/// The last loading strain (phase 1) whose row counts no soft contact beyond the laws' range: where
/// the soft model's stress is still within the measured laws. NaN when the rows do not count them
/// (the resolved model, LAMMPS, a run from before the count); -1 when the first row already does.
double strain_within_laws(const std::vector<CurveRow>& rows);

struct CompressionRun {
  std::vector<CurveRow> rows;
  long steps = 0;
  double dt = 0.0;
  std::size_t spheres = 0, bodies = 0;
  RangeStats soft;  ///< soft model only: its contacts beyond the laws' measured range
  Elapsed time;           ///< of the simulation (the scene's construction and the steps)
};

/// The row of the current state.
CurveRow curve_row(const Simulation& sim, const Medium& m, const std::vector<int>& body_of, double H0, int phase);

/// Runs the compression of `scene` (medium_scene()); progress(strain done, strain in all, row)
/// after each row; `observe` (optional) sees the simulation at each row (it must not change it).
CompressionRun run_compression(const SceneDef& scene, const Medium& m, CoarseModel model, const CoarseGrainSettings& s,
                               const std::function<void(double, double, const CurveRow&)>& progress = {},
                               const std::function<void(const Simulation&, const CurveRow&)>& observe = {});

}  // namespace softpack
