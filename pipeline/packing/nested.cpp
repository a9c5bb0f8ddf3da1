#include "packing/nested.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"
#include "core/random.hpp"

namespace softpack {

// The most levels a model may have: at Π = 10 five levels span five decades below Rs, beyond
// any medium of the paper (high-performance concrete spans four).
constexpr int kMaxLevels = 6;

PackingParameters level_parameters(const PackingParameters& top, int level) {
  PackingParameters p = top;
  const double scale = std::pow(top.polydispersity, -static_cast<double>(level));
  p.Rs = top.Rs * scale;
  p.r_max = top.r_max * scale;
  return p;
}

std::size_t site_count(const PackingParameters& p, double list_volume) {
  const double n = list_volume / (p.beta * p.Rs * p.Rs * p.Rs) * std::pow(p.polydispersity, p.exponent - 1.0);
  return static_cast<std::size_t>(std::llround(n));
}

void validate_levels(const PackingParameters& top, int levels) {
  if (levels < 1 || levels > kMaxLevels)
    throw InputError(fmt::format("packing.levels: {} is not allowed; allowed: 1 (grains only, the paper's soft-particle) to {} "
                                 "(each level below holds the next decade, docs/nested.md)",
                                 levels, kMaxLevels));
  if (levels == 1) return;
  // The last level's grains are the smallest: its parameters pass the generator's rules.
  try {
    validate(level_parameters(top, levels - 1));
  } catch (const InputError& e) {
    throw InputError(fmt::format("packing.levels: {} levels are not allowed with these packing parameters: the last level "
                                 "(every length divided by Pi^{}) fails: {}",
                                 levels, levels - 1, e.what()));
  }
  // About Π^(b-1) sites per level with sites (site_count with the list volume β V_S).
  const double sites = std::pow(top.polydispersity, top.exponent - 1.0);
  if (!(sites * 1.05 < static_cast<double>(kMaxSites)))
    throw InputError(fmt::format("packing.levels: {} is not allowed with polydispersity {} and exponent {}: a level would hold "
                                 "about Pi^(b-1) = {:.0f} sites; allowed: fewer than {} (1.05 Pi^(b-1)), or levels: 1",
                                 levels, top.polydispersity, top.exponent, sites, kMaxSites));
}

ContentMean sample_contents(const PackingParameters& p, int levels_below, std::uint64_t seed, std::size_t sample,
                            const std::function<void(std::size_t, std::size_t)>& progress) {
  if (levels_below < 1) throw InputError(fmt::format("sample_contents: {} levels below; a content needs one at least", levels_below));
  if (sample < 2) throw InputError(fmt::format("content_sample: {}; allowed: 2 or more (a mean and its error)", sample));
  // One sampled packing: its own grains' part and its sites.
  struct Drawn {
    std::uint64_t seed;
    double volume;
    std::size_t grains, sites;
  };
  ContentMean out;
  out.sample = sample;
  out.smallest_radius = std::numeric_limits<double>::infinity();
  std::size_t drawn = 0;
  // Each level's parameters one level down from the one above, as generate_contents chains them
  // (the same bits: the sample is the medium's own contents).
  std::vector<PackingParameters> params{p};
  for (int j = 1; j <= levels_below; ++j) params.push_back(level_parameters(params.back(), 1));
  const auto draw = [&](int level, std::uint64_t s) {
    const LevelPacking l = generate_level(params[static_cast<std::size_t>(level)], levels_below - level, s);
    if (level > 0 && progress) {
      ++drawn;  // over-drawn parents count too: the total grows with them
      progress(drawn, std::max(drawn, sample * static_cast<std::size_t>(levels_below)));
    }
    Drawn d{s, 0.0, l.grains.radii.size(), l.sites.size()};
    for (double r : l.grains.radii) {
      d.volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
      if (level > 0) out.smallest_radius = std::min(out.smallest_radius, r);
    }
    return d;
  };
  // Breadth first, level by level: level 0 the top packings of seeds nested_site_seed(seed, k),
  // level j the sites of level j - 1's packings in order, drawing more of those when short.
  std::vector<std::vector<Drawn>> levels(static_cast<std::size_t>(levels_below) + 1);
  std::uint64_t next_top = 0;
  const auto more = [&](auto& self, std::size_t j) -> void {
    if (j == 0) {
      if (next_top >= kMaxSites)
        throw InputError(fmt::format("sample_contents: the {} top packings of seed {} hold too few sites for a sample of {}", kMaxSites, seed, sample));
      levels[0].push_back(draw(0, nested_site_seed(seed, next_top++)));
      return;
    }
    // The next child of level j - 1's packings, in order; a parent with no site is passed over.
    std::size_t taken = levels[j].size(), parent = 0;
    while (true) {
      while (parent >= levels[j - 1].size()) self(self, j - 1);
      const Drawn& up = levels[j - 1][parent];
      if (taken < up.sites) {
        levels[j].push_back(draw(static_cast<int>(j), nested_site_seed(up.seed, taken)));
        return;
      }
      taken -= up.sites, ++parent;
    }
  };
  for (std::size_t j = 1; j <= static_cast<std::size_t>(levels_below); ++j)
    while (levels[j].size() < sample) more(more, j);
  // Bottom up: E[X_j] over the sample's x_i + n_i E[X_(j+1)] (mean_error: the mean and its standard
  // error, as every mean in the project), its error squared plus mean(n)² times the level below's.
  double V = 0.0, V2 = 0.0, W = 0.0, W2 = 0.0, G = 0.0, G2 = 0.0;  // E and se² one level down
  for (std::size_t j = static_cast<std::size_t>(levels_below); j >= 1; --j) {
    std::vector<double> v, w, g, n;
    for (std::size_t i = 0; i < sample; ++i) {
      const Drawn& d = levels[j][i];
      n.push_back(static_cast<double>(d.sites));
      v.push_back(d.volume + n.back() * V);
      w.push_back(v.back() + n.back() * W);
      g.push_back(static_cast<double>(d.grains) + n.back() * G);
    }
    const double n_mean = mean_error(n).mean;
    const auto with_below = [&](const std::vector<double>& x, double below_se2) {
      const MeanError e = mean_error(x);
      return std::pair{e.mean, e.error * e.error + n_mean * n_mean * below_se2};
    };
    // w_i = x_i + n_i (E[V'] + E[W']): its error from below bounded by se(V') + se(W').
    const double W2_below = std::pow(std::sqrt(V2) + std::sqrt(W2), 2);
    std::tie(V, V2) = with_below(v, V2);
    std::tie(W, W2) = with_below(w, W2_below);
    std::tie(G, G2) = with_below(g, G2);
  }
  out.volume = V, out.volume_error = std::sqrt(V2);
  out.shells_volume = W, out.shells_volume_error = std::sqrt(W2);
  out.grains = G, out.grains_error = std::sqrt(G2);
  return out;
}

std::uint64_t nested_site_seed(std::uint64_t seed, std::size_t site) {
  if (site >= kMaxSites) throw InputError(fmt::format("site {}: a level holds at most {} sites", site, kMaxSites));
  if (seed > (kMaxSeed - site) / kMaxSites)
    throw InputError(fmt::format("seed {}: the content of its site {} would need the seed {} * {} + {}, above 2^63 - 1; allowed: "
                                 "seed <= {}",
                                 seed, site, seed, kMaxSites, site, (kMaxSeed - kMaxSites) / kMaxSites));
  return seed * kMaxSites + site;
}

LevelPacking generate_level(const PackingParameters& p, int levels_below, std::uint64_t seed, const PackingProgress& progress) {
  validate(p);
  if (levels_below < 0) throw InputError(fmt::format("packing.levels: {} levels below is not allowed", levels_below));
  if (levels_below > 0) validate_levels(p, levels_below + 1);
  Random rng(seed);
  const std::vector<double> radii = sample_list(p, rng);
  LevelPacking out;
  std::vector<ListBody> list;
  list.reserve(radii.size() + kMaxSites);
  if (levels_below > 0) {
    double volume = 0.0;
    for (double r : radii) volume += r * r * r;
    out.site_radius = p.Rs / p.polydispersity;
    out.sites_drawn = site_count(p, volume);
    if (out.sites_drawn > kMaxSites)
      throw InputError(fmt::format("packing.levels: the list of seed {} holds {} sites; allowed: at most {}", seed,
                                   out.sites_drawn, kMaxSites));
  }
  // Largest first (step 2); a site before the grains of its radius.
  std::size_t grain = 0;
  for (std::size_t s = 0; s < out.sites_drawn; ++s) {
    while (grain < radii.size() && radii[grain] > out.site_radius) list.push_back({radii[grain++], true});
    list.push_back({out.site_radius, false});
  }
  while (grain < radii.size()) list.push_back({radii[grain++], true});

  std::vector<int> placed;
  Packing all = place_bodies(p, list, rng, placed, progress);
  out.grains.sampled = radii.size();
  for (std::size_t k = 0; k < list.size(); ++k) {
    const int id = placed[k];
    if (!list[k].grows) {
      if (id < 0) ++out.sites_discarded;
      else out.sites.push_back(all.centres[static_cast<std::size_t>(id)]);
      continue;
    }
    if (id < 0) {
      ++out.grains.discarded;
      continue;
    }
    const auto i = static_cast<std::size_t>(id);
    out.grains.centres.push_back(all.centres[i]);
    out.grains.radii.push_back(all.radii[i]);
    out.grains.radii_inserted.push_back(all.radii_inserted[i]);
    if (all.radii[i] != all.radii_inserted[i]) ++out.grains.grown;
  }
  return out;
}

double SiteContent::solid_volume() const {
  double v = 0.0;
  for (double r : level.grains.radii) v += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  for (const SiteContent& c : sites) v += c.solid_volume();
  return v;
}

std::size_t SiteContent::grains() const {
  std::size_t n = level.grains.radii.size();
  for (const SiteContent& c : sites) n += c.grains();
  return n;
}

std::size_t SiteContent::shells() const {
  std::size_t n = sites.size();
  for (const SiteContent& c : sites) n += c.shells();
  return n;
}

std::vector<SiteContent> generate_contents(const PackingParameters& p, int levels_below, std::uint64_t seed, std::size_t sites,
                                           const PackingProgress& progress) {
  std::vector<SiteContent> out;
  if (levels_below < 1) return out;
  const PackingParameters below = level_parameters(p, 1);
  for (std::size_t k = 0; k < sites; ++k) {
    SiteContent c;
    const std::uint64_t s = nested_site_seed(seed, k);
    c.level = generate_level(below, levels_below - 1, s);
    c.sites = generate_contents(below, levels_below - 1, s, c.level.sites.size());
    out.push_back(std::move(c));
    if (progress) progress("contents", k + 1, sites);
  }
  return out;
}

}  // namespace softpack
