// The two-decade medium of the coarse-grain validation (docs/coarse-grain.md): solid grains of
// the first decade and the sites of the local packings of the second, placed at random in a
// box, and the scene of either model.
//
//   first decade   `grains` radii from P(r) ~ r^-b on [r_min, decade r_min]
//   second decade  local packings made by the soft-particles' own generator (the packing the
//                  law file was measured on), one per site, each with its own seed, as many as
//                  make the solid volume the same power law gives one decade below:
//                  V2 = V1 (r2_max^(4-b) - r2_min^(4-b)) / (r1_max^(4-b) - r1_min^(4-b))
//   placement      every body (grain, or site as a sphere of radius Rs) in decreasing size, at
//                  the first of `placement_trials` random positions in the box that overlaps
//                  nothing; the box (width L, height aspect L) holds the bodies' volume at
//                  `initial_fraction`
//
// The resolved scene puts each site's packing in a free shell (walls/spherical_shell.hpp) of
// mass shell_mass_fraction times its grains'; the soft scene puts there one soft-particle of
// radius Rs and the mass of those grains and that shell. Both have the same first-decade grains,
// the same six walls and the profile's engine settings.
//
// Nested soft-particles (packing.levels > 1 in the soft-particle's profile, docs/nested.md): a
// site's packing is a level packing — its grains and its own sites of radius Rs / Π, whose
// contents go down to the last level (packing/nested.hpp). The medium then spans the first
// decade and `levels` more; the resolved scene places each content in free shells inside the
// site's shell (measure/content_scene.hpp), the soft one gives the soft-particle the mass of
// everything inside it resolved.
#pragma once
#include <functional>
#include <cstdint>
#include <limits>
#include <vector>

#include "coarse/settings.hpp"
#include "packing/generator.hpp"
#include "packing/nested.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

struct Medium {
  double L = 0.0, H = 0.0;            ///< box width and initial height [m]
  double Rs = 0.0;                    ///< the sites' radius [m]
  std::vector<Vec3> grain_x;          ///< first-decade grains
  std::vector<double> grain_r;
  std::vector<Vec3> sites;            ///< soft-particle centres
  std::vector<Packing> packings;      ///< one per site, about the origin: the site's own grains
  std::vector<std::uint64_t> packing_seeds;
  int levels = 1;                     ///< the sites' packing.levels (1: grains only)
  double inner_radius = 0.0;          ///< levels > 1: the radius of a site's own sites, Rs / Π
  std::vector<std::vector<Vec3>> inner_sites;  ///< levels > 1: each site's own sites, about its centre
  /// levels > 1: the contents of each site's own sites, down to the last level; made from the
  /// seeds by medium_contents(), not stored in the medium file.
  std::vector<std::vector<SiteContent>> contents;
  /// levels > 1 with medium.content_sample: a site's site's content expected from a sample
  /// (packing/nested.hpp sample_contents), kept in the medium file, instead of `contents`, which
  /// are not made (content_mean.sample 0: they are).
  ContentMean content_mean;
  double grains_volume = 0.0;         ///< solid volume of the first decade [m^3]
  double packings_volume = 0.0;       ///< solid volume of the packings, every level [m^3]
  double target_volume = 0.0;         ///< V2 the packings stand for [m^3]

  double solid_volume() const { return grains_volume + packings_volume; }
  std::size_t bodies() const { return grain_x.size() + sites.size(); }
};

/// The medium of `seed` (the same settings and seed give the same bits); `progress(what, k, n)`
/// after each packing generated: what "sample" (content_sample's, n of them) or "site" (about n).
/// InputError naming medium.initial_fraction when a body finds no place.
using MediumProgress = std::function<void(const char* what, std::size_t k, std::size_t n)>;
Medium build_medium(const CoarseGrainSettings& s, std::uint64_t seed, const MediumProgress& progress = {});

/// Makes `m.contents` from the sites' seeds and `m.inner_sites` (levels > 1 without
/// content_sample; nothing otherwise): a medium read from its file has the sites' sites, not
/// their contents. InputError when the settings' packing.levels or content_sample is not the
/// medium's. `progress(sites made, sites)` after each site's content (making them all takes minutes
/// at two levels: a level packing a second or so).
void medium_contents(const CoarseGrainSettings& s, Medium& m, const std::function<void(std::size_t, std::size_t)>& progress = {});

/// What site k's own sites hold at every level below: their contents' when made (errors 0), else
/// its number of sites times the sampled mean (errors the same times the mean's). Zero at one level.
struct SiteInside {
  double volume = 0.0, volume_error = 0.0;                ///< solid volume [m^3]
  double shells_volume = 0.0, shells_volume_error = 0.0;  ///< ContentMean::shells_volume, summed [m^3]
  double grains = 0.0, grains_error = 0.0;
  double smallest_radius = std::numeric_limits<double>::infinity();  ///< of those grains (sampled: the sample's) [m]
};
SiteInside site_inside(const Medium& m, std::size_t k);

/// The packing seed of site k of medium `seed`.
std::uint64_t site_seed(std::uint64_t seed, std::size_t k);

/// The scene of `model` (resolved: InputError for a medium whose contents are sampled, not made): spheres in the order first-decade grains, then each site's (resolved:
/// its packing's grains, body k; soft: one soft-particle). Planes bottom, top, x0, x1, y0, y1.
/// `laws`: the soft model's (formats/law_file.hpp soft_particle_laws()).
SceneDef medium_scene(const CoarseGrainSettings& s, const Medium& m, CoarseModel model, const SoftParticleLaws& laws);

/// A scene of the settings' engine: materials grain (0) and wall (1), the profile's effects,
/// integration and neighbour search, the watchdog's overlap limit; no sphere, wall or driver.
SceneDef engine_scene(const CoarseGrainSettings& s);

/// The body (first-decade grain k: k; site k: grains + k) of each sphere of medium_scene().
std::vector<int> sphere_bodies(const Medium& m, CoarseModel model);

/// Mass of a site's grains [kg] at the grains' density.
double packing_mass(const Packing& p, double density);

}  // namespace softpack
