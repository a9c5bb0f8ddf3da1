// Nested soft-particles, the paper's whole model (issue 35, docs/nested.md): "A soft-particle
// contains particles of the next decade and again a set of soft-particles containing the
// remaining decades. For the last decade we only have normal particles."
//
//   level 0       a soft-particle of radius Rs: grains of its decade [r_max / Π, r_max] and
//                 sites, soft-particles of level 1 of radius Rs_1 = Rs / Π, so that the decade
//                 below begins where this one ends (r_max_1 = (r_max / Rs) Rs_1 = r_min_0)
//   level k       the same, every length divided by Π^k (`level_parameters`)
//   last level    (k = levels - 1) grains only: the paper's soft-particle
//
// The list of a level with sites (paper §3's steps 1-2 for its grains, `sample_list`) holds,
// beside its grains, the sites that carry the decade below at the same power law: the list
// volume of a decade one Π down is Π^-(4-b) times this decade's, and each site's own list holds
// β V_site of it (Eq. 2 at radius Rs / Π), so
//
//     sites = round(V_L Π^-(4-b) / (β V_site)) = round(V_L / (β V_S) Π^(b-1))
//
// (about 316 at Π = 10, b = 3.5; 18 at Π = √10). Sites and grains are placed together, largest
// first, by step 3's rule (a site that finds no place in `trials` attempts is discarded like a
// grain); in step 4 the grains grow and a site is a neighbour they grow to touch, but keeps its
// radius: its laws are measured at radius Rs / Π (docs/nested.md says why). A site's content is
// the level below's packing of its own seed (`nested_site_seed`), made when it is needed — by
// the resolved reference, or for its mass — not stored in this level's file.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "packing/generator.hpp"

namespace softpack {

/// The most sites one level's list may hold (their contents' seeds are seed * 1000 + site).
constexpr std::size_t kMaxSites = 1000;

/// A level's packing: its grains (`Packing`, as a packing without levels has them) and the
/// centres of the sites it placed, all about the shell's centre.
struct LevelPacking {
  Packing grains;
  double site_radius = 0.0;  ///< Rs / Π; 0 at the last level
  std::vector<Vec3> sites;   ///< placed sites, in list order
  std::size_t sites_drawn = 0, sites_discarded = 0;
};

/// The packing parameters of level `level` of a model whose level 0 has `top`: every length
/// (Rs, r_max) divided by Π^level, the rest the same.
PackingParameters level_parameters(const PackingParameters& top, int level);

/// Sites in the list of a level whose grains' list has volume `list_volume` (the sum of r^3 of
/// `sample_list`, without 4/3 π): round(list_volume / (β Rs^3) Π^(b-1)).
std::size_t site_count(const PackingParameters& p, double list_volume);

/// Refuses a model of `levels` levels whose last level's grains are below the scenes' smallest
/// length, or whose sites would be more than kMaxSites: InputError naming packing.levels.
void validate_levels(const PackingParameters& top, int levels);

/// The packing of one level with `levels_below` levels under it (0: grains only, the same bits
/// as generate_packing), for `seed`; the same parameters and seed give the same bits.
LevelPacking generate_level(const PackingParameters& p, int levels_below, std::uint64_t seed,
                            const PackingProgress& progress = {});

/// A site's content down to the last level: its level packing (about its own centre) and, for
/// each of its sites, that site's content in turn.
struct SiteContent {
  LevelPacking level;
  std::vector<SiteContent> sites;

  /// Solid volume of every grain inside, at every level below [m^3].
  double solid_volume() const;
  /// Grains inside, at every level below.
  std::size_t grains() const;
  /// Sites inside that have a shell when resolved (this content's and those below).
  std::size_t shells() const;
};

/// The contents of the sites of a level packing made with `p` (its level's parameters) and
/// `seed`, with `levels_below` levels under it (>= 1): site k's is generate_level one level down
/// with nested_site_seed(seed, k), and so on to the last level. `progress` ("contents", k, sites)
/// after each of the `sites` is made (down to its last level); it changes no bit.
std::vector<SiteContent> generate_contents(const PackingParameters& p, int levels_below, std::uint64_t seed,
                                           std::size_t sites, const PackingProgress& progress = {});

/// What one site of a level packing holds, expected from a sample instead of made (docs/nested.md
/// "What making the contents costs"): a content four levels deep is about 700 level packings, a
/// medium of such sites some 20 000. Each quantity X of a content is its own level's part plus,
/// for each of its n sites, a content one level down: X = x + n X', so over a sample of M level
/// packings of each level below
///
///     E[X_j] = mean_i (x_i + n_i E[X_(j+1)])      (E[X] = 0 below the last level)
///     se²(E[X_j]) = s²_i(x_i + n_i E[X_(j+1)]) / M + mean_i(n_i)² se²(E[X_(j+1)])
///
/// (the levels' samples independent; the shells' volume's error from below is bounded by se(V') +
/// se(W'), W = V + n W' holding V' too). The sample of level j is the first M packings of that level
/// breadth first from the packings of seeds nested_site_seed(seed, 0), nested_site_seed(seed, 1),
/// ... made with the top level's parameters: the seeds a medium's sites of `seed` have.
struct ContentMean {
  std::size_t sample = 0;                    ///< M, level packings drawn per level below
  double volume = 0.0, volume_error = 0.0;   ///< solid volume inside, every level [m^3]
  /// its volume and, for each site inside at every level, that site's: a resolved content's
  /// shells weigh shell_mass_fraction × density × this (measure/content_scene.hpp) [m^3]
  double shells_volume = 0.0, shells_volume_error = 0.0;
  double grains = 0.0, grains_error = 0.0;   ///< grains inside, every level
  double smallest_radius = 0.0;              ///< of the grains drawn [m]
};

/// The expected content of one site of a level packing made with `p` and `levels_below` (>= 1)
/// levels under it, from `sample` (>= 2) packings per level below (ContentMean); `progress(k, n)`
/// after each of its n packings below the top (the top packings it draws are not counted).
ContentMean sample_contents(const PackingParameters& p, int levels_below, std::uint64_t seed, std::size_t sample,
                            const std::function<void(std::size_t, std::size_t)>& progress = {});

/// The seed of the content of site `site` of a level packing made with `seed`: seed * 1000 +
/// site. InputError when it would not be a seed (above 2^63 - 1).
std::uint64_t nested_site_seed(std::uint64_t seed, std::size_t site);

}  // namespace softpack
