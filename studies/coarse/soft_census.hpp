// Where the coarse-grained medium uses the soft-particle law (issue 33, item 5; paper/many-body.md,
// "The probe's second part", 4): at each row of a soft model's compression, every closed contact of
// a soft-particle (a contact between two soft-particles counted once for each), its partner (a
// wall, a first-decade grain and its r / Rs, another soft-particle), its Δn = h / R (the law's R),
// its soft-particle's number of closed contacts n and cap volume E = Σ v(Δn) (contact/
// soft_particle_law.hpp cap_volume), against the many-body probe's range: Δn up to its largest,
// n up to 6, E up to the cube's at its largest Δn.
#pragma once
#include <string>
#include <vector>

#include "coarse/compression.hpp"
#include "coarse/probe_settings.hpp"

namespace softpack {

struct SoftCensus {
  double strain = 0.0;
  int phase = 1;
  std::size_t soft_particles = 0, contacts = 0;
  std::size_t wall = 0, grain = 0, soft = 0;                ///< contacts by partner
  double force_wall = 0.0, force_grain = 0.0, force_soft = 0.0;  ///< their Σ Fn [N]
  double dn_median = 0.0, dn_p90 = 0.0, dn_max = 0.0;
  double beyond_dn = 0.0;        ///< fraction of the contacts with Δn above the probe's largest
  double beyond_n = 0.0;         ///< on a soft-particle with more than 6 contacts
  double beyond_E = 0.0;         ///< on a soft-particle with E above the probe's largest
  double n_mean = 0.0;           ///< closed contacts per soft-particle
  double grain_ratio_median = 0.0;  ///< r / Rs of the grain partners (0 without any)
  double grain_ratio_force = 0.0;   ///< the same, weighted by Fn
};

/// One closed contact of a soft-particle, seen from it.
struct SoftSide {
  std::size_t soft = 0;  ///< the soft-particle's index among the sites
  int partner = 0;       ///< 0 wall, 1 grain, 2 another soft-particle
  double dn = 0.0;       ///< Δn
  double Fn = 0.0;       ///< the law's force [N]
  double ratio = 0.0;    ///< a grain partner's r / Rs (0 otherwise)
};

/// The closed contacts of the soft-particles in the simulation's current state (spheres in
/// medium_scene()'s order: the grains, then one soft-particle per site; one between two
/// soft-particles twice, once from each).
std::vector<SoftSide> soft_sides(const Simulation& sim, const Medium& m);

/// The census of the simulation's current state (soft_sides()). `dn_max`, `E_max`: the probe's range.
SoftCensus soft_census(const Simulation& sim, const Medium& m, const CurveRow& row, double dn_max, double E_max);
/// The same from its contacts.
SoftCensus soft_census(const std::vector<SoftSide>& sides, const Medium& m, const CurveRow& row, double dn_max, double E_max);

/// Runs the soft model of each media seed of the plan (the medium files MEDIA_DIR/seed-S.h5, the
/// settings `config`; the media seeds of the law's `version`) and writes OUT/contacts.dat (every
/// row of every seed), OUT/contacts.md and OUT/contact-rows.dat (every contact at each loading row
/// within the plan's strain range: seed strain soft-particle kind Δn r/Rs its contacts Fn, the
/// rows of coarse/kinematics.hpp).
void write_soft_census(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& config, const std::string& media_dir,
                       const std::string& out_dir, int version = 1);

}  // namespace softpack
