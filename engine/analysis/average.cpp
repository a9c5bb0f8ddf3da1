#include "analysis/average.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "formats/file_kind.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {

MeanError mean_error(const std::vector<double>& v) {
  MeanError m;
  const double n = static_cast<double>(v.size());
  if (v.empty()) return m;
  for (double x : v) m.mean += x / n;
  if (v.size() > 1) {
    double ss = 0.0;
    for (double x : v) ss += (x - m.mean) * (x - m.mean);
    m.error = std::sqrt(ss / (n - 1.0) / n);
  }
  return m;
}

namespace {

/// Same length as `ref` and finite, or InputError naming the file and datasets.
void check_column(const std::string& path, const std::string& name, const std::vector<double>& v, const std::string& ref_name,
                  std::size_t ref_size) {
  if (v.size() != ref_size)
    throw InputError(fmt::format("{}: {} has {} values but {} has {}; allowed: the same number", path, name, v.size(), ref_name,
                                 ref_size));
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InputError(fmt::format("{}: {}[{}] = {} is not allowed; allowed: finite numbers", path, name, i, v[i]));
}

}  // namespace

AverageFile read_average_file(const std::string& path) {
  const h5::File in = h5::File::open(path);
  if (!in.exists("normal/delta_n") || !in.exists("provenance/scene")) {
    const std::string kind = kind_of(in);
    throw InputError(fmt::format("{}: not a softpack average file ({})", path,
                                 kind.empty() ? "no /normal/delta_n or /provenance/scene" : "it is " + kind));
  }
  AverageFile a;
  a.path = path;
  a.scene = in.read_string("provenance/scene");
  if (a.scene != "soft-solid" && a.scene != "soft-soft")
    throw InputError(fmt::format("{}: /provenance/scene: '{}' is not allowed; allowed: soft-solid, soft-soft", path, a.scene));
  a.profile = in.read_string("provenance/profile");
  a.code_version = in.read_string("provenance/code_version");
  a.seeds = in.read_scalar_int64("normal/seeds");
  if (a.seeds < 1) throw InputError(fmt::format("{}: /normal/seeds: {} is not allowed; allowed: >= 1", path, a.seeds));
  a.delta_n = in.read_doubles("normal/delta_n");
  a.Fn = in.read_doubles("normal/Fn_mean");
  a.Fn_stderr = in.read_doubles("normal/Fn_stderr");
  check_column(path, "/normal/Fn_mean", a.Fn, "/normal/delta_n", a.delta_n.size());
  check_column(path, "/normal/Fn_stderr", a.Fn_stderr, "/normal/delta_n", a.delta_n.size());
  check_column(path, "/normal/delta_n", a.delta_n, "/normal/delta_n", a.delta_n.size());
  a.has_kt = in.exists("kt");
  if (a.has_kt) {
    a.kt_delta_n = in.read_doubles("kt/delta_n");
    a.kt = in.read_doubles("kt/mean");
    a.kt_stderr = in.read_doubles("kt/stderr");
    check_column(path, "/kt/delta_n", a.kt_delta_n, "/kt/delta_n", a.kt_delta_n.size());
    check_column(path, "/kt/mean", a.kt, "/kt/delta_n", a.kt_delta_n.size());
    check_column(path, "/kt/stderr", a.kt_stderr, "/kt/delta_n", a.kt_delta_n.size());
  }
  return a;
}

namespace {

void same_grid(const std::vector<SweepResults>& seeds) {
  if (seeds.empty()) throw InputError("no sweep results to average");
  for (const SweepResults& s : seeds)
    if (s.delta_n != seeds[0].delta_n || s.alpha_deg != seeds[0].alpha_deg)
      throw InputError(fmt::format("{}: its (delta_n, alpha) grid differs from that of {}; results of one profile share it",
                                   s.path, seeds[0].path));
}

MeanError column(const std::vector<SweepResults>& seeds, std::vector<double> SweepResults::*field, std::size_t k) {
  std::vector<double> v;
  for (const SweepResults& s : seeds) v.push_back((s.*field)[k]);
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

NormalAverage average_normal(const std::vector<SweepResults>& seeds) {
  same_grid(seeds);
  NormalAverage a;
  a.seeds = seeds.size();
  a.delta_n = seeds[0].delta_n;
  for (std::size_t k = 0; k < a.delta_n.size(); ++k) {
    a.Fn.push_back(column(seeds, &SweepResults::Fn, k));
    a.Ft_parallel.push_back(column(seeds, &SweepResults::Ft_parallel, k));
    a.Ft_perpendicular.push_back(column(seeds, &SweepResults::Ft_perpendicular, k));
  }
  return a;
}

TangentialAverage average_tangential(const std::vector<SweepResults>& seeds) {
  same_grid(seeds);
  TangentialAverage a;
  a.seeds = seeds.size();
  const SweepResults& g = seeds[0];
  a.delta_n = g.delta_n;
  a.alpha_deg = g.alpha_deg;
  a.ht = g.ht;
  for (std::size_t k = 0; k < g.delta_n.size(); ++k) {
    a.Ft_parallel.push_back(column(seeds, &SweepResults::Ft_parallel, k));
    a.Ft_perpendicular.push_back(column(seeds, &SweepResults::Ft_perpendicular, k));
    a.Fn.push_back(column(seeds, &SweepResults::Fn, k));
  }
  // kt per seed and Delta_n: the slope of Ft_parallel(ht) over the alpha grid (around ht = 0).
  for (std::size_t k = 0; k < g.delta_n.size();) {
    std::size_t end = k;
    while (end < g.delta_n.size() && g.delta_n[end] == g.delta_n[k]) ++end;
    std::vector<double> per_seed;
    for (const SweepResults& s : seeds) {
      const std::vector<double> ht(s.ht.begin() + k, s.ht.begin() + end), F(s.Ft_parallel.begin() + k, s.Ft_parallel.begin() + end);
      per_seed.push_back(slope(ht, F));
    }
    a.kt_delta_n.push_back(g.delta_n[k]);
    a.kt.push_back(mean_error(per_seed));
    k = end;
  }
  return a;
}

}  // namespace softpack
