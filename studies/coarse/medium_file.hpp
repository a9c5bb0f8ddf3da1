// The medium file of one seed (softpack-coarse medium; read by softpack-coarse run for either
// model, so both run on the very same medium and the packings are generated once), HDF5:
//
//   /grains/{x (N, 3), r}               first-decade grains [m]
//   /sites/x (M, 3)                     soft-particle centres [m]
//   /packings/{offsets (M + 1), centres (P, 3), radii, seeds}
//                                       site k's grains: rows offsets[k] to offsets[k+1], about
//                                       the site's centre; its packing seed
//   /packings/{levels, site_radius, site_offsets (M + 1), site_centres (Q, 3)}
//                                       nested soft-particles only (levels > 1): site k's own
//                                       sites, rows site_offsets[k] to [k+1], about its centre;
//                                       their contents are made from the seeds (medium_contents)
//   /contents/{sample, volume (2), shells_volume (2), grains (2), smallest_radius}
//                                       nested with medium.content_sample: what a site's site
//                                       holds, expected from the sample (ContentMean; value and
//                                       error); its contents are then not made
//   /box/{L, H, Rs}                     [m]
//   /volumes/{grains, packings, target} [m^3] (coarse/medium.hpp)
//   /provenance/{seed, settings, code_version, seconds, cpu_seconds}
//
// `settings` is what the medium depends on: the coarse_grain section's soft_particle.profile and
// .packing and its medium section (CoarseGrainSettings::medium_text); a run refuses a medium
// made with others.
#pragma once
#include <cstdint>
#include <string>

#include "coarse/medium.hpp"
#include "core/stopwatch.hpp"

namespace softpack {

struct MediumFile {
  Medium medium;
  std::uint64_t seed = 0;
  std::string settings, code_version;
  Elapsed time;  ///< of its generation
};

void write_medium_file(const std::string& path, const MediumFile& f);
/// Reads and checks (InputError names the file and the dataset).
MediumFile read_medium_file(const std::string& path);

}  // namespace softpack
