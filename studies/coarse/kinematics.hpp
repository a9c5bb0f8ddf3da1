// The soft medium's geometry against the resolved one's (issue 33, item 5; paper/many-body.md,
// "Next: the soft medium's geometry against the resolved one's", written before its runs): at the
// loading strains of the plan's range that are multiples of 0.05, per kind of body pressing a
// soft-particle (wall, grain, another soft-particle) and for all, from the soft runs' contacts
// (coarse/soft_census.hpp, contact-rows.dat) and the resolved runs' intrusions (coarse/in_place.hpp,
// seed-S.dat): bodies per soft-particle, Δn (median, 90 %), push per soft-particle (soft: its law's;
// resolved: measured, and the law's from the same geometry), the confinement the law sees (Fn over
// the law alone at the same Δn, the soft-particle's other caps removed; median where that is not 0)
// and the share of contacts below the onset (the law alone 0). Nothing is fitted on it.
#pragma once
#include <string>

#include "coarse/probe_settings.hpp"
#include "contact/soft_particle_law.hpp"

namespace softpack {

/// OUT/kinematics.md from CENSUS_ROWS (softpack-coarse soft-contacts' contact-rows.dat of the
/// media of the law's `version`) and IN_PLACE_DIR/seed-S.dat of the same seeds; `laws`: the many-body
/// settings' (they give the law alone), read from `laws_source`.
void write_kinematics_report(const ManyBodyProbe& plan, const std::string& plan_path, const SoftParticleLaws& laws, const std::string& laws_source,
                             const std::string& census_rows, const std::string& in_place_dir, const std::string& out_dir, int version);

}  // namespace softpack
