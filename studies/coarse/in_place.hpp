// The many-body law measured in place (issue 33, item 5; paper/many-body.md, "Next: measuring the
// law in place", written before its runs): the resolved medium compressed again, and at each
// recorded loading strain, for each site (its packing of fines in its free shell), the push each
// other body gives it — the sum over that body's contacts with the site's fines of the normal
// force, along the line from the body to the site's centre — against the soft-particle law's
// prediction from the same geometry: the body's intrusion Δn into the site's sphere (a grain of
// radius r at distance d: (Rs + r − d) / Rs; another site: (2 Rs − d) / Rs; a wall: (Rs − d) / Rs)
// and the site's other intrusions (the law's E: their caps' sum or union), by the law file's
// many-body law and by its pairwise laws (the paper's: a grain as a wall). Nothing is fitted on it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "coarse/compression.hpp"
#include "coarse/probe_settings.hpp"
#include "contact/soft_particle_law.hpp"

namespace softpack {

/// One body intruding one site (Δn > 0) at one strain.
struct InPlaceContact {
  double strain = 0.0;
  std::size_t site = 0;
  int kind = 0;            ///< 0 wall, 1 grain, 2 another site
  double dn = 0.0;         ///< its intrusion over Rs
  double ratio = 0.0;      ///< a grain's r / Rs (0 otherwise)
  std::size_t count = 0;   ///< the site's intruding bodies
  double measured = 0.0;   ///< the push on the site's fines [N]
  double law = 0.0;        ///< the law file's many-body law's [N]
  double pairwise = 0.0;   ///< its pairwise laws' [N]
};

/// The engine's partners of a body pressing a site: the site as body 1, a soft-particle of radius
/// Rs; a wall (kind 0), a grain of radius ratio Rs (1) or another site (2) as body 2.
ContactPartners site_partners(double Rs, int kind, double ratio);

/// Whether the reports table a recorded strain: a multiple of 0.05.
bool tabled_strain(double strain);

/// The rows of OUT/seed-S.dat (write_in_place_seed's); InputError naming the file and the line
/// otherwise. `laws`: set to the law file its header names (empty if it names none).
std::vector<InPlaceContact> read_in_place_rows(const std::string& path, std::string* laws = nullptr);

/// The site contacts of the resolved medium's current state (the medium's resolved scene).
std::vector<InPlaceContact> in_place_contacts(const Simulation& sim, const Medium& m, const SoftParticleLaws& laws, double strain);

/// Compresses the resolved medium of MEDIA_DIR/seed-S.h5 (the settings `config`, the law file of
/// those settings) and writes OUT/seed-S.dat: every site contact at each recorded loading strain
/// within the plan's strain range.
void write_in_place_seed(const ManyBodyProbe& plan, const std::string& config, const std::string& media_dir, std::uint64_t seed,
                         const std::string& out_dir, const std::function<void(double, double, const CurveRow&)>& progress = {});

/// Reads OUT/seed-S.dat of each of the plan's seeds (the media seeds of the law's `version`) and
/// writes OUT/in-place.md: per strain and kind of body, the sums and the errors of both laws.
void write_in_place_report(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& out_dir, int version);

}  // namespace softpack
