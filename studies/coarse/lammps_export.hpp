// The soft model of a coarse-grain medium as a LAMMPS run (issue 34, docs/lammps.md): `softpack-coarse
// export --lammps` writes into a folder
//
//   medium.data       LAMMPS data file (atom_style sphere): the first-decade grains, type 1, then the
//                     soft-particles, type 2 (radius Rs, the mass of their packing and shell), in the
//                     engine scene's order (coarse/medium.hpp medium_scene), so atom ID k is sphere k-1
//   laws.json         a copy of the settings' law file
//   in.compression    the compression of coarse/compression.hpp as a LAMMPS input a user can read
//                     and change: its settings as variables at the top, then the styles, the walls,
//                     and the phases (phase.in: the loop over a phase's increments)
//   phase.in          a phase's increments, each by increment.in
//   increment.in      one increment: the top wall moves, stands under the quench, a row of curve.dat
//   settings.yaml     the coarse_grain section it was made from (provenance)
//
// The pairs: two grains meet by LAMMPS's pair granular (Hertz, Mindlin, Tsuji damping) with the
// corrections of bench/lammps/README.md (C2: kt = Dt, C3: xgammat, C4: the e' whose LAMMPS
// polynomial gives the engine's damping coefficient); a soft-particle meets anything by softpack/soft.
// The walls: a soft-particle meets fix softpack/wall; a grain meets LAMMPS's fix wall/gran (C1: the
// wall's E/(1+nu)); the top wall's grain side is a region that follows softpack/wall's position.
// C5 (fix wall/gran converts e' again at every run's init): every run after the first is `pre no`.
//
// What the engine's compression records and LAMMPS's input does not: Z and the bodies in contact,
// and the elastic energy (NaN and 0 in the results file read back, read_lammps_run).
#pragma once
#include <string>

#include "coarse/compression.hpp"
#include "coarse/medium_file.hpp"
#include "coarse/settings.hpp"
#include "core/material.hpp"

namespace softpack {

/// The engine's Hertz–Mindlin–Tsuji contact of two grains of `grain` (and of a grain and a wall of
/// `wall`) in the terms of LAMMPS's pair granular and fix wall/gran (bench/lammps/README.md C1–C4).
struct LammpsGranular {
  double E = 0.0, nu = 0.0;    ///< hertz/material E, nu of pair granular (the grains')
  double E_wall = 0.0;         ///< fix wall/gran's E: E / (1 + nu) (C1)
  double damping_code = 0.0;   ///< the e' given to `damping tsuji`: alpha_L(e') = the engine's zeta (C4)
  double Dt = 0.0;             ///< `tangential mindlin` kt (C2)
  double xgammat = 0.0;        ///< `tangential mindlin` xgammat (C3)
  double mu = 0.0, mu_wall = 0.0;
};

/// InputError when LAMMPS's walls cannot be the engine's (a wall of another E or nu than the grains').
LammpsGranular lammps_granular(const Material& grain, const Material& wall, double restitution, double tangential_ratio);

/// LAMMPS's polynomial of `damping tsuji`, alpha_L(e') (bench/lammps/README.md C4), and its inverse on
/// [-0.2, 1.05] where it decreases (InputError outside alpha_L's range there).
double lammps_tsuji_alpha(double e);
double lammps_tsuji_code(double alpha);

/// Writes the folder above for the soft model of `mf` (`config` is the settings' path, for the
/// comments). InputError for settings LAMMPS's input cannot carry (rotation locked).
void write_lammps_export(const CoarseGrainSettings& s, const std::string& config, const MediumFile& mf, const std::string& out_dir);

/// A LAMMPS run of that input read back: curve.dat's rows, and from log.lammps the loop time
/// summed over its runs, the steps and the ranks (CompressionRun::time is that time; its cpu, the
/// time × ranks). InputError naming the file when one is missing, a row is malformed, the rows are
/// not the settings' count, the run did not end (log.lammps lacks the input's last line) or its
/// settings.yaml is not `s`'s coarse_grain section.
struct LammpsRun {
  CompressionRun run;
  int ranks = 0;
};
LammpsRun read_lammps_run(const std::string& dir, const CoarseGrainSettings& s, const MediumFile& mf);

}  // namespace softpack
