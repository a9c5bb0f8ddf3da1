#include "analysis/average.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <set>

#include "profile/profile.hpp"
#include "core/error.hpp"

namespace softpack {

void check_distinct_seeds(const std::vector<SeedFile>& files, const std::string& option) {
  for (std::size_t j = 1; j < files.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const SeedFile &a = files[i], &b = files[j];
      std::error_code ec;
      if (a.path == b.path || std::filesystem::equivalent(a.path, b.path, ec))
        throw InputError(fmt::format("{}: {} and {} are the same file; allowed: each seed's results once", option, a.path,
                                     b.path));
      if (a.seed == b.seed)
        throw InputError(fmt::format("{}: {} and {} are both results of seed {}; allowed: each seed's results once", option,
                                     a.path, b.path, a.seed));
      if (!a.packing_sha256.empty() && a.packing_sha256 == b.packing_sha256)
        throw InputError(fmt::format("{}: {} (seed {}) and {} (seed {}) are measurements of one packing (its content has "
                                     "SHA-256 {}); allowed: each packing once, whatever its seed number",
                                     option, a.path, a.seed, b.path, b.seed, a.packing_sha256));
    }
}

void check_one_configuration(const std::vector<SeedFile>& files, const std::string& option, const std::string& stage,
                             const std::string& expected_config, const std::string& expected_stamp, const std::string& profile_path) {
  for (std::size_t k = 0; k < files.size(); ++k) {
    const SeedFile &a = files.front(), &b = files[k];
    if (b.config != a.config)
      throw InputError(fmt::format("{}: {} and {} were computed with different configurations ({}); an average never mixes "
                                   "configurations: make them again with one profile",
                                   option, a.path, b.path, first_difference(a.config, b.config, a.path, b.path)));
    if (b.stamp != a.stamp)
      throw InputError(fmt::format("{}: {} and {} were computed with different configurations (stamps '{}' and '{}': another "
                                   "release, or other imported sources); an average never mixes configurations: make them "
                                   "again with one profile",
                                   option, a.path, b.path, a.stamp, b.stamp));
    if (expected_config.empty()) continue;
    if (b.config != expected_config)
      throw InputError(fmt::format("{}: {} was computed with another configuration than {} holds now ({}); make it again with this "
                                   "profile (make does)",
                                   option, b.path, profile_path, first_difference(b.config, expected_config, b.path, profile_path)));
    check_stamp(b.path, stage, b.stamp, expected_stamp, profile_path);
  }
}

void check_same_seeds(const std::vector<SeedFile>& normal, const std::vector<SeedFile>& tangential) {
  const auto seeds = [](const std::vector<SeedFile>& files) {
    std::set<std::uint64_t> s;
    for (const SeedFile& f : files) s.insert(f.seed);
    return s;
  };
  const std::set<std::uint64_t> n = seeds(normal), t = seeds(tangential);
  if (n != t)
    throw InputError(fmt::format("--tangential: results of seeds {}, --normal: of seeds {}; allowed: the same seeds for both "
                                 "(one scene's laws over the same soft-particles)",
                                 fmt::join(t, ", "), fmt::join(n, ", ")));
}

namespace {

void same_grid(const std::vector<SweepColumns>& seeds) {
  if (seeds.empty()) throw InputError("no sweep results to average");
  for (const SweepColumns& s : seeds)
    if (s.delta_n != seeds[0].delta_n || s.alpha_deg != seeds[0].alpha_deg)
      throw InputError(fmt::format("{}: its (delta_n, alpha) grid differs from that of {}; results of one profile share it",
                                   s.path, seeds[0].path));
}

MeanError column(const std::vector<SweepColumns>& seeds, std::vector<double> SweepColumns::*field, std::size_t k) {
  std::vector<double> v;
  for (const SweepColumns& s : seeds) v.push_back((s.*field)[k]);
  return mean_error(v);
}

}  // namespace

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0 ? sxy / sxx : 0.0;
}

NormalAverage average_normal(const std::vector<SweepColumns>& seeds) {
  same_grid(seeds);
  NormalAverage a;
  a.seeds = seeds.size();
  a.delta_n = seeds[0].delta_n;
  for (std::size_t k = 0; k < a.delta_n.size(); ++k) {
    a.Fn.push_back(column(seeds, &SweepColumns::Fn, k));
    a.Ft_parallel.push_back(column(seeds, &SweepColumns::Ft_parallel, k));
    a.Ft_perpendicular.push_back(column(seeds, &SweepColumns::Ft_perpendicular, k));
    std::vector<double> per_seed;
    for (const SweepColumns& s : seeds) per_seed.push_back(s.Fn[k]);
    a.Fn_per_seed.push_back(std::move(per_seed));
  }
  return a;
}

TangentialAverage average_tangential(const std::vector<SweepColumns>& seeds) {
  same_grid(seeds);
  TangentialAverage a;
  a.seeds = seeds.size();
  const SweepColumns& g = seeds[0];
  a.delta_n = g.delta_n;
  a.alpha_deg = g.alpha_deg;
  a.ht = g.ht;
  for (std::size_t k = 0; k < g.delta_n.size(); ++k) {
    a.Ft_parallel.push_back(column(seeds, &SweepColumns::Ft_parallel, k));
    a.Ft_perpendicular.push_back(column(seeds, &SweepColumns::Ft_perpendicular, k));
    a.Fn.push_back(column(seeds, &SweepColumns::Fn, k));
  }
  // kt per seed and Delta_n: the slope of Ft_parallel(ht) over the alpha grid (around ht = 0).
  for (std::size_t k = 0; k < g.delta_n.size();) {
    std::size_t end = k;
    while (end < g.delta_n.size() && g.delta_n[end] == g.delta_n[k]) ++end;
    std::vector<double> per_seed;
    for (const SweepColumns& s : seeds) {
      const std::vector<double> ht(s.ht.begin() + k, s.ht.begin() + end), F(s.Ft_parallel.begin() + k, s.Ft_parallel.begin() + end);
      per_seed.push_back(slope(ht, F));
    }
    a.kt_delta_n.push_back(g.delta_n[k]);
    a.kt.push_back(mean_error(per_seed));
    a.kt_per_seed.push_back(per_seed);
    k = end;
  }
  return a;
}

}  // namespace softpack
