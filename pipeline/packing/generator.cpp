#include "packing/generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "core/random.hpp"
#include "packing/insertion_grid.hpp"
#include "packing/power_law.hpp"
#include "scene/limits.hpp"

namespace softpack {

// The most spheres the generator draws for one packing (its lists and grid stay within memory).
constexpr double kMaxSpheres = 5e7;

const char* name(NearestNeighbour n) { return n == NearestNeighbour::centre ? "centre" : "surface"; }

NearestNeighbour parse_nearest_neighbour(const std::string& text) {
  if (text == "surface") return NearestNeighbour::surface;
  if (text == "centre") return NearestNeighbour::centre;
  throw InputError(fmt::format("'{}' is not allowed; allowed: surface (the smallest surface gap) or centre (the nearest "
                               "centre)",
                               text));
}

void validate(const PackingParameters& p) {
  using limits::approx_text;
  const auto check = [](const char* key, double v, const limits::Range& range) {
    if (const std::string why = limits::refusal(v, range); !why.empty())
      throw InputError(fmt::format("packing.{}: {}", key, why));
  };
  check("Rs", p.Rs, limits::kPackingRs);
  check("r_max_over_Rs", p.r_max / p.Rs, limits::kRmaxOverRs);
  check("polydispersity", p.polydispersity, limits::kPolydispersity);
  check("exponent", p.exponent, limits::kExponent);
  check("beta", p.beta, limits::kBeta);
  check("trials", static_cast<double>(p.trials), limits::kTrials);
  check("level_ratio", p.level_ratio, limits::kLevelRatio);
  // Rules between values: the grains become the spheres of the sweeps' scenes (radii of at least
  // limits::kMinLength), and the insertion grid numbers its cells of 2 r_min with 21 bits.
  const double r_min = p.r_max / p.polydispersity;
  if (!(p.r_max >= limits::kMinLength))  // no polydispersity (>= 1) can help: Rs itself is too small
    throw InputError(fmt::format("packing.Rs: {} m is not allowed with r_max_over_Rs = {}: the largest radius r_max = Rs "
                                 "r_max_over_Rs would be {} m; allowed: r_max >= {} m (Rs >= {} m at this r_max_over_Rs)",
                                 limits::number_text(p.Rs), approx_text(p.r_max / p.Rs), approx_text(p.r_max),
                                 limits::number_text(limits::kMinLength), approx_text(limits::kMinLength * p.Rs / p.r_max)));
  if (!(r_min >= limits::kMinLength))
    throw InputError(fmt::format("packing.polydispersity: {} is not allowed with Rs = {} m and r_max_over_Rs = {}: the "
                                 "smallest radius r_max / Pi would be {} m; allowed: r_max / Pi >= {} m (Pi <= {})",
                                 limits::number_text(p.polydispersity), limits::number_text(p.Rs),
                                 approx_text(p.r_max / p.Rs), approx_text(r_min), limits::number_text(limits::kMinLength),
                                 approx_text(p.r_max / limits::kMinLength)));
  if (!(p.Rs / (2.0 * r_min) < limits::kInsertionCells))
    throw InputError(fmt::format("packing.polydispersity: {} is not allowed with r_max_over_Rs = {}: the shell would span "
                                 "Rs / (2 r_min) = {} cells of the insertion grid's finest level; allowed: fewer than {} "
                                 "(2^20), Pi < {}",
                                 limits::number_text(p.polydispersity), approx_text(p.r_max / p.Rs),
                                 approx_text(p.Rs / (2.0 * r_min)), limits::number_text(limits::kInsertionCells),
                                 approx_text(2.0 * limits::kInsertionCells * p.r_max / p.Rs)));
  // How many spheres the generator would draw (beta Rs^3 / <r^3>): refused here, at the profile's
  // keys and lines, rather than when the first packing is made.
  const double expected = p.beta * p.Rs * p.Rs * p.Rs / power_law::mean_cube(power_law::Law{r_min, p.r_max, p.exponent});
  if (!(expected <= kMaxSpheres))
    throw InputError(fmt::format("packing.polydispersity: {} is not allowed with beta = {}, r_max_over_Rs = {} and exponent = {}: "
                                 "the packing would hold about {:.3g} spheres (beta Rs^3 / <r^3>); allowed: at most {:g} — "
                                 "reduce packing.polydispersity or packing.beta, or raise packing.r_max_over_Rs",
                                 limits::number_text(p.polydispersity), limits::number_text(p.beta), approx_text(p.r_max / p.Rs),
                                 limits::number_text(p.exponent), expected, kMaxSpheres));
}

// Step 1: radii until V_L > beta V_S (Eq. 2); the volume compared is sum r^3 > beta Rs^3.
std::vector<double> sample_list(const PackingParameters& p, Random& rng) {
  const power_law::Law law{p.r_max / p.polydispersity, p.r_max, p.exponent};
  const double target = p.beta * p.Rs * p.Rs * p.Rs;
  const double expected = target / power_law::mean_cube(law);
  if (!(expected <= kMaxSpheres))  // NaN too; validate() says it first, at the profile's keys
    throw InputError(fmt::format("packing: these parameters ask for about {:.3g} spheres (beta Rs^3 / <r^3>); allowed: at most "
                                 "{:g} — reduce packing.beta or packing.polydispersity, or raise packing.r_max_over_Rs",
                                 expected, kMaxSpheres));
  std::vector<double> radii;
  radii.reserve(static_cast<std::size_t>(expected * 1.1) + 16);
  double volume = 0.0;
  while (volume <= target) {
    radii.push_back(power_law::sample(law, rng));
    volume += radii.back() * radii.back() * radii.back();
  }
  std::sort(radii.begin(), radii.end(), std::greater<>());  // step 2
  return radii;
}

Packing generate_packing(const PackingParameters& p, std::uint64_t seed, const PackingProgress& progress) {
  validate(p);
  Random rng(seed);
  const std::vector<double> radii = sample_list(p, rng);
  std::vector<ListBody> list;
  list.reserve(radii.size());
  for (double r : radii) list.push_back({r, true});
  std::vector<int> placed;
  return place_bodies(p, list, rng, placed, progress);
}

Packing place_bodies(const PackingParameters& p, const std::vector<ListBody>& list, Random& rng, std::vector<int>& placed,
                     const PackingProgress& progress) {
  Packing out;
  out.sampled = list.size();
  placed.assign(list.size(), -1);
  double r_top = p.r_max;
  for (const ListBody& b : list) r_top = std::max(r_top, b.r);
  InsertionGrid grid(p.r_max / p.polydispersity, r_top, p.level_ratio);
  std::vector<bool> grows;
  const std::size_t report = std::max<std::size_t>(1, list.size() / 100);

  // Step 3: random sequential insertion, largest first.
  for (std::size_t k = 0; k < list.size(); ++k) {
    const double r = list[k].r;
    bool done = false;
    for (long t = 0; t < p.trials && !done; ++t) {
      const Vec3 x = rng.in_ball(p.Rs - r);  // inside the shell without touching it
      if (!grid.overlaps(x, r)) {
        placed[k] = grid.insert(x, r);
        out.radii_inserted.push_back(r);
        grows.push_back(list[k].grows);
        done = true;
      }
    }
    if (!done) ++out.discarded;
    if (progress && (k + 1) % report == 0) progress("insert", k + 1, list.size());
  }

  // Step 4: growth, largest first, each until it touches its nearest neighbour (by surface gap
  // or by centre distance, p.nearest_neighbour); a body that does not grow is still a neighbour.
  const int n = static_cast<int>(grid.size());
  for (int id = 0; id < n; ++id) {
    if (!grows[static_cast<std::size_t>(id)]) continue;
    const Vec3& x = grid.centre(id);
    const double r = grid.radius(id);
    const double shell_gap = p.Rs - x.norm() - r;
    // Search the nearest sphere within a growing gap until one is found or the shell is
    // nearer than anything left unsearched (then the outcome is decided in both modes).
    double sphere_gap = std::numeric_limits<double>::infinity();
    if (p.nearest_neighbour == NearestNeighbour::surface) {
      for (double search = r; search < 4.0 * p.Rs; search *= 2.0) {
        sphere_gap = grid.nearest_gap(x, r, id, search);
        if (std::isfinite(sphere_gap) || shell_gap < search) break;
      }
    } else {
      // The nearest centre: searched within a growing distance until one is found (every
      // sphere is within 2 Rs); the gap to it, negative if they already overlap.
      for (double search = 2.0 * r; search < 4.0 * p.Rs; search *= 2.0) {
        const auto [distance, j] = grid.nearest_centre(x, id, search);
        if (j < 0) continue;
        sphere_gap = distance - r - grid.radius(j);
        break;
      }
    }
    double grow = 0.0;
    if (p.shell_is_neighbour) grow = std::min(sphere_gap, shell_gap);
    else if (sphere_gap <= shell_gap) grow = sphere_gap;  // else: it cannot reach its neighbour
    if (std::isfinite(grow) && grow > 0.0) {
      grid.set_radius(id, r + grow);
      ++out.grown;
    }
    if (progress && (id + 1) % static_cast<int>(std::max<std::size_t>(1, grid.size() / 100)) == 0)
      progress("grow", static_cast<std::size_t>(id + 1), grid.size());
  }

  for (int id = 0; id < n; ++id) {
    out.centres.push_back(grid.centre(id));
    out.radii.push_back(grid.radius(id));
  }
  return out;
}

}  // namespace softpack
