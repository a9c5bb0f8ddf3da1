#include "formats/average_file.hpp"

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <utility>

#include "core/error.hpp"
#include "formats/file_kind.hpp"
#include "formats/h5_fields.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

using namespace formats;

constexpr const char *kNormalDeltaN = "normal/delta_n", *kNormalFn = "normal/Fn", *kSeeds = "normal/seeds";
constexpr const char *kNormalFnPerSeed = "normal/Fn_per_seed", *kKtPerSeed = "kt/per_seed";
constexpr const char *kKt = "kt", *kKtDeltaN = "kt/delta_n", *kKtMean = "kt/mean", *kKtStderr = "kt/stderr";
constexpr const char *kScene = "provenance/scene", *kProfile = "provenance/profile", *kCodeVersion = "provenance/code_version";
constexpr std::array kAverageLayout{kNormalDeltaN, kScene};  // what makes a file an average file
const std::string kMean = "_mean", kStderr = "_stderr";  // the two columns of a MeanError

std::string header(const std::string& what, const AverageProvenance& p, const std::vector<std::string>& inputs) {
  std::string h = fmt::format("# softpack-average {}: {} of scene {} (profile {}), mean and standard error over {} seeds\n",
                              p.code_version, what, p.scene, p.profile, inputs.size());
  for (const auto& in : inputs) h += "#   from " + in + "\n";
  return h;
}

void write_dat_files(const std::string& dir, const NormalAverage& n, const TangentialAverage* tangential, const AverageProvenance& p) {
  const auto path = [&](const std::string& name) { return (std::filesystem::path(dir) / name).string(); };
  std::string dat = header("normal force", p, p.normal_inputs) +
                    "# columns: delta_n Fn_mean[N] Fn_stderr Ft_parallel_mean Ft_parallel_stderr Ft_perpendicular_mean "
                    "Ft_perpendicular_stderr seeds\n";
  for (std::size_t k = 0; k < n.delta_n.size(); ++k)
    dat += fmt::format("{:.6g} {:.10g} {:.4g} {:.10g} {:.4g} {:.10g} {:.4g} {}\n", n.delta_n[k], n.Fn[k].mean, n.Fn[k].error,
                       n.Ft_parallel[k].mean, n.Ft_parallel[k].error, n.Ft_perpendicular[k].mean, n.Ft_perpendicular[k].error,
                       n.seeds);
  write_file_atomically(path("normal-" + p.scene + ".dat"), dat);
  if (!tangential) return;  // a normal-only profile
  const TangentialAverage& t = *tangential;

  dat = header("tangential force", p, p.tangential_inputs) +
        "# one block per delta_n (gnuplot index); columns: delta_n alpha_deg ht[m] Ft_parallel_mean[N] Ft_parallel_stderr "
        "Ft_perpendicular_mean Ft_perpendicular_stderr Fn_mean Fn_stderr\n";
  for (std::size_t k = 0; k < t.delta_n.size(); ++k) {
    if (k > 0 && t.delta_n[k] != t.delta_n[k - 1]) dat += "\n\n";
    dat += fmt::format("{:.6g} {:.6g} {:.10g} {:.10g} {:.4g} {:.10g} {:.4g} {:.10g} {:.4g}\n", t.delta_n[k], t.alpha_deg[k],
                       t.ht[k], t.Ft_parallel[k].mean, t.Ft_parallel[k].error, t.Ft_perpendicular[k].mean,
                       t.Ft_perpendicular[k].error, t.Fn[k].mean, t.Fn[k].error);
  }
  write_file_atomically(path("tangential-" + p.scene + ".dat"), dat);

  dat = header("tangential spring constant kt (slope of Ft_parallel against ht)", p, p.tangential_inputs) +
        "# columns: delta_n kt_mean[N/m] kt_stderr seeds\n";
  for (std::size_t k = 0; k < t.kt_delta_n.size(); ++k)
    dat += fmt::format("{:.6g} {:.10g} {:.4g} {}\n", t.kt_delta_n[k], t.kt[k].mean, t.kt[k].error, t.seeds);
  write_file_atomically(path("kt-" + p.scene + ".dat"), dat);
}

// The means and the standard errors of `v` as two columns, or as `mean` and `stderr`.
void put_pairs(h5::File& f, const std::vector<MeanError>& v, const std::string& mean, const std::string& stderr_) {
  std::vector<double> m, e;
  for (const auto& x : v) m.push_back(x.mean), e.push_back(x.error);
  put(f, mean, m);
  put(f, stderr_, e);
}
void put_pairs(h5::File& f, const std::string& name, const std::vector<MeanError>& v) {
  put_pairs(f, v, name + kMean, name + kStderr);
}

// [point][seed] as one row-major array (points x seeds values).
void put_per_seed(h5::File& f, const std::string& name, const std::vector<std::vector<double>>& v) {
  std::vector<double> flat;
  for (const auto& row : v) flat.insert(flat.end(), row.begin(), row.end());
  put(f, name, flat);
}
std::vector<std::vector<double>> get_per_seed(const h5::File& f, const std::string& name, std::size_t points,
                                              std::int64_t seeds) {
  std::vector<double> flat;
  get(f, name, flat);
  const std::size_t n = static_cast<std::size_t>(seeds);
  if (flat.size() != points * n)
    throw InputError(fmt::format("{}: /{}: {} values; allowed: {} points x {} seeds = {}", f.path(), name, flat.size(), points, n,
                                 points * n));
  check_finite(f, name, flat);
  std::vector<std::vector<double>> v(points);
  for (std::size_t k = 0; k < points; ++k) v[k].assign(flat.begin() + static_cast<std::ptrdiff_t>(k * n),
                                                       flat.begin() + static_cast<std::ptrdiff_t>((k + 1) * n));
  return v;
}

// Columns of one table: all finite, as long as the first.
void read_columns(const h5::File& f, std::initializer_list<std::pair<std::string, std::vector<double>*>> columns) {
  for (const auto& [name, v] : columns) get(f, name, *v);
  const auto& [ref, first] = *columns.begin();
  for (const auto& [name, v] : columns) {
    same_length(f, name, v->size(), ref, first->size());
    check_finite(f, name, *v);
  }
}

}  // namespace

void write_average_files(const std::string& dir, const NormalAverage& n, const TangentialAverage* tangential,
                         const AverageProvenance& p) {
  write_dat_files(dir, n, tangential, p);
  h5::AtomicH5 out((std::filesystem::path(dir) / (p.scene + ".h5")).string());
  h5::File& f = out.file();
  put(f, kNormalDeltaN, n.delta_n);
  put_pairs(f, kNormalFn, n.Fn);
  put_pairs(f, "normal/Ft_parallel", n.Ft_parallel);
  put_pairs(f, "normal/Ft_perpendicular", n.Ft_perpendicular);
  put(f, kSeeds, n.seeds);
  put_per_seed(f, kNormalFnPerSeed, n.Fn_per_seed);
  if (tangential) {
    const TangentialAverage& t = *tangential;
    put(f, "tangential/delta_n", t.delta_n);
    put(f, "tangential/alpha_deg", t.alpha_deg);
    put(f, "tangential/ht", t.ht);
    put_pairs(f, "tangential/Ft_parallel", t.Ft_parallel);
    put_pairs(f, "tangential/Ft_perpendicular", t.Ft_perpendicular);
    put_pairs(f, "tangential/Fn", t.Fn);
    put(f, kKtDeltaN, t.kt_delta_n);
    put_pairs(f, t.kt, kKtMean, kKtStderr);
    put_per_seed(f, kKtPerSeed, t.kt_per_seed);
  }
  put(f, kScene, p.scene);
  put(f, kProfile, p.profile);
  put(f, kCodeVersion, p.code_version);
  std::string inputs;
  for (const auto& in : p.normal_inputs) inputs += in + "\n";
  for (const auto& in : p.tangential_inputs) inputs += in + "\n";
  put(f, "provenance/inputs", inputs);
  put(f, "provenance/seconds", p.seconds);
  put(f, "provenance/cpu_seconds", p.cpu_seconds);
  put(f, kProvenanceStamp, p.stamp);
  out.commit();
}

AverageFile read_average_file(const std::string& path) {
  const h5::File in = h5::File::open(path);
  expect_layout(in, "average", kAverageLayout);
  AverageFile a;
  a.path = path;
  get(in, kScene, a.scene);
  if (a.scene != "soft-solid" && a.scene != "soft-soft")
    throw InputError(fmt::format("{}: /{}: '{}' is not allowed; allowed: soft-solid, soft-soft", path, kScene, a.scene));
  get(in, kProfile, a.profile);
  get(in, kCodeVersion, a.code_version);
  if (in.exists(kProvenanceStamp)) get(in, kProvenanceStamp, a.stamp);
  a.seeds = in.read_scalar_int64(kSeeds);
  if (a.seeds < 1) throw InputError(fmt::format("{}: /{}: {} is not allowed; allowed: >= 1", path, kSeeds, a.seeds));
  read_columns(in, {{kNormalDeltaN, &a.delta_n}, {kNormalFn + kMean, &a.Fn}, {kNormalFn + kStderr, &a.Fn_stderr}});
  a.has_kt = in.exists(kKt);
  if (a.has_kt) read_columns(in, {{kKtDeltaN, &a.kt_delta_n}, {kKtMean, &a.kt}, {kKtStderr, &a.kt_stderr}});
  if (in.exists(kNormalFnPerSeed)) a.Fn_per_seed = get_per_seed(in, kNormalFnPerSeed, a.delta_n.size(), a.seeds);
  if (a.has_kt && in.exists(kKtPerSeed)) a.kt_per_seed = get_per_seed(in, kKtPerSeed, a.kt_delta_n.size(), a.seeds);
  if (in.exists("provenance/seconds") && in.exists("provenance/cpu_seconds")) {
    Elapsed e;
    get(in, "provenance/seconds", e.wall);
    get(in, "provenance/cpu_seconds", e.cpu);
    a.time = e;
  }
  return a;
}

std::string describe_average_file(const h5::File& f) {
  return has_layout(f, kAverageLayout) ? "an average file (softpack-average)" : "";
}

}  // namespace softpack
