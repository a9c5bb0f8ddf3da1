// The soft-particle packing generator: the modified Aste (1996) algorithm of paper §3.
//
//   1. draw radii from the truncated power law (Eq. 1) until the list volume V_L exceeds
//      beta times the shell volume V_S (Eq. 2);
//   2. sort the list by decreasing radius;
//   3. give each sphere `trials` random positions inside the shell (no overlap with the shell:
//      centre within Rs - r), keep the first that overlaps no inserted sphere, discard the
//      sphere after `trials` failures;
//   4. from the largest inserted sphere down, grow each until it touches its nearest neighbour.
//
// Whether the shell counts as a neighbour in step 4 is a choice (the paper is silent):
//   shell_is_neighbour = true:  the nearest neighbour is the nearest sphere or the shell; a
//                               sphere nearer to the shell than to any sphere grows until it
//                               touches the shell;
//   shell_is_neighbour = false: the nearest neighbour is the nearest sphere; a sphere that
//                               would cross the shell on its way there does not grow.
// It sets the gap between the shell and the outermost grains, hence where the soft-particle
// starts to push back (delta of Table 1).
//
// Which sphere is "the nearest neighbour" is a second reading (`packing.nearest_neighbour`):
//   surface: the sphere with the smallest surface gap |x_i - x_j| - r_i - r_j, the first one the
//            growing sphere touches; after growth no two spheres overlap (the default);
//   centre:  the sphere whose centre is nearest, |x_i - x_j| smallest; the sphere grows until it
//            touches that one and may overlap nearer surfaces on its way (a larger sphere
//            further off), so the packing starts with overlaps that its first relaxation
//            pushes apart. With shell_is_neighbour the shell still bounds the growth.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "core/types.hpp"

namespace softpack {

/// Which sphere step 4 grows a sphere to touch (see above).
enum class NearestNeighbour { surface, centre };
const char* name(NearestNeighbour n);
/// "surface" or "centre"; InputError naming what is allowed otherwise.
NearestNeighbour parse_nearest_neighbour(const std::string& text);

struct PackingParameters {
  double Rs = 0.0;              ///< shell radius [m]
  double r_max = 0.0;           ///< largest radius of the list [m]
  double polydispersity = 0.0;  ///< Pi = r_max / r_min
  double exponent = 0.0;        ///< b of Eq. 1
  double beta = 0.0;            ///< list volume / shell volume (Eq. 2)
  long trials = 0;              ///< I
  bool shell_is_neighbour = true;
  NearestNeighbour nearest_neighbour = NearestNeighbour::surface;
  double level_ratio = 0.0;     ///< cell size ratio of the insertion grid (cost only)
};

/// Validates the parameters: the one owner of their ranges. InputError names the profile key
/// "packing.<name>" and the allowed range.
void validate(const PackingParameters& p);

struct Packing {
  std::vector<Vec3> centres;   ///< inserted spheres, largest (before growth) first; shell at 0
  std::vector<double> radii;   ///< after growth
  std::vector<double> radii_inserted;  ///< before growth
  std::size_t sampled = 0;     ///< spheres in the list
  std::size_t discarded = 0;   ///< spheres that found no place in `trials` attempts
  std::size_t grown = 0;       ///< spheres that grew to touch a neighbour
};

/// Progress of a long generation: phase ("insert", "grow"), spheres done, spheres in all.
using PackingProgress = std::function<void(const std::string& phase, std::size_t done, std::size_t total)>;

/// Generates the packing of `seed`: the same parameters and seed give the same bits.
Packing generate_packing(const PackingParameters& p, std::uint64_t seed, const PackingProgress& progress = {});

/// Steps 1 and 2: radii drawn from Eq. 1 until the list volume exceeds beta V_S, sorted by
/// decreasing radius.
std::vector<double> sample_list(const PackingParameters& p, Random& rng);

/// One body of a list that steps 3 and 4 place: its radius, and whether step 4 grows it. A
/// grain grows; a soft-particle of the level below (packing/nested.hpp) keeps the radius its
/// laws are measured at, and is a neighbour the grains grow to touch.
struct ListBody {
  double r = 0.0;
  bool grows = true;
};

/// Steps 3 and 4 on a list sorted by decreasing radius, drawing from `rng`: the placed bodies
/// in list order (`Packing::centres`, `radii`, `radii_inserted`; `discarded`, `grown`; `sampled`
/// is the list's length) and, for each entry of the list, its index among them (-1: discarded).
/// The insertion grid spans the list's radii and `p`'s.
Packing place_bodies(const PackingParameters& p, const std::vector<ListBody>& list, Random& rng, std::vector<int>& placed,
                     const PackingProgress& progress = {});

}  // namespace softpack
