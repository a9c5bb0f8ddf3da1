// softpack-average: mean and standard error over the seeds of one scene's sweep results, to
// HDF5 (for softpack-fit) and to plain columns (for gnuplot).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "analysis/average.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace {

using namespace softpack;

std::string header(const std::string& what, const std::string& scene, const std::string& profile,
                   const std::vector<std::string>& inputs) {
  std::string h = fmt::format("# softpack-average {}: {} of scene {} (profile {}), mean and standard error over {} seeds\n",
                              code_version(), what, scene, profile, inputs.size());
  for (const auto& in : inputs) h += "#   from " + in + "\n";
  return h;
}

void write_pairs(h5::File& f, const std::string& name, const std::vector<MeanError>& v) {
  std::vector<double> m, e;
  for (const auto& x : v) m.push_back(x.mean), e.push_back(x.error);
  f.write(name + "_mean", m);
  f.write(name + "_stderr", e);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"softpack-average: average the sweep results of one scene over the seeds"};
  std::string scene, profile, out_dir;
  std::vector<std::string> normal, tangential;
  app.add_option("--scene", scene, "soft-solid or soft-soft (recorded)")->required();
  app.add_option("--profile", profile, "profile name (recorded)")->required();
  app.add_option("--normal", normal, "normal results of every seed")->required();
  app.add_option("--tangential", tangential, "tangential results of every seed")->required();
  app.add_option("--out-dir", out_dir, "writes <scene>.h5, normal-<scene>.dat, tangential-<scene>.dat, kt-<scene>.dat")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const auto start = std::chrono::steady_clock::now();
    std::vector<SweepResults> ns, ts;
    if (scene != "soft-solid" && scene != "soft-soft")
      throw InputError(fmt::format("--scene: '{}' is not allowed; allowed: soft-solid, soft-soft", scene));
    for (const auto& p : normal) ns.push_back(read_sweep_results_file(p, "normal", scene));
    for (const auto& p : tangential) ts.push_back(read_sweep_results_file(p, "tangential", scene));
    const NormalAverage n = average_normal(ns);
    const TangentialAverage t = average_tangential(ts);
    namespace fs = std::filesystem;
    const auto path = [&](const std::string& name) { return (fs::path(out_dir) / name).string(); };

    std::string dat = header("normal force", scene, profile, normal) +
                      "# columns: delta_n Fn_mean[N] Fn_stderr Ft_parallel_mean Ft_parallel_stderr Ft_perpendicular_mean "
                      "Ft_perpendicular_stderr seeds\n";
    for (std::size_t k = 0; k < n.delta_n.size(); ++k)
      dat += fmt::format("{:.6g} {:.10g} {:.4g} {:.10g} {:.4g} {:.10g} {:.4g} {}\n", n.delta_n[k], n.Fn[k].mean, n.Fn[k].error,
                         n.Ft_parallel[k].mean, n.Ft_parallel[k].error, n.Ft_perpendicular[k].mean,
                         n.Ft_perpendicular[k].error, n.seeds);
    write_file_atomically(path("normal-" + scene + ".dat"), dat);

    dat = header("tangential force", scene, profile, tangential) +
          "# one block per delta_n (gnuplot index); columns: delta_n alpha_deg ht[m] Ft_parallel_mean[N] Ft_parallel_stderr "
          "Ft_perpendicular_mean Ft_perpendicular_stderr Fn_mean Fn_stderr\n";
    for (std::size_t k = 0; k < t.delta_n.size(); ++k) {
      if (k > 0 && t.delta_n[k] != t.delta_n[k - 1]) dat += "\n\n";
      dat += fmt::format("{:.6g} {:.6g} {:.10g} {:.10g} {:.4g} {:.10g} {:.4g} {:.10g} {:.4g}\n", t.delta_n[k], t.alpha_deg[k],
                         t.ht[k], t.Ft_parallel[k].mean, t.Ft_parallel[k].error, t.Ft_perpendicular[k].mean,
                         t.Ft_perpendicular[k].error, t.Fn[k].mean, t.Fn[k].error);
    }
    write_file_atomically(path("tangential-" + scene + ".dat"), dat);

    dat = header("tangential spring constant kt (slope of Ft_parallel against ht)", scene, profile, tangential) +
          "# columns: delta_n kt_mean[N/m] kt_stderr seeds\n";
    for (std::size_t k = 0; k < t.kt_delta_n.size(); ++k)
      dat += fmt::format("{:.6g} {:.10g} {:.4g} {}\n", t.kt_delta_n[k], t.kt[k].mean, t.kt[k].error, t.seeds);
    write_file_atomically(path("kt-" + scene + ".dat"), dat);

    h5::AtomicH5 out(path(scene + ".h5"));
    h5::File& f = out.file();
    f.write("normal/delta_n", n.delta_n);
    write_pairs(f, "normal/Fn", n.Fn);
    write_pairs(f, "normal/Ft_parallel", n.Ft_parallel);
    write_pairs(f, "normal/Ft_perpendicular", n.Ft_perpendicular);
    f.write_scalar("normal/seeds", static_cast<std::int64_t>(n.seeds));
    f.write("tangential/delta_n", t.delta_n);
    f.write("tangential/alpha_deg", t.alpha_deg);
    f.write("tangential/ht", t.ht);
    write_pairs(f, "tangential/Ft_parallel", t.Ft_parallel);
    write_pairs(f, "tangential/Ft_perpendicular", t.Ft_perpendicular);
    write_pairs(f, "tangential/Fn", t.Fn);
    f.write("kt/delta_n", t.kt_delta_n);
    std::vector<double> m, e;
    for (const auto& x : t.kt) m.push_back(x.mean), e.push_back(x.error);
    f.write("kt/mean", m);
    f.write("kt/stderr", e);
    f.write_string("provenance/scene", scene);
    f.write_string("provenance/profile", profile);
    f.write_string("provenance/code_version", code_version());
    std::string inputs;
    for (const auto& p : normal) inputs += p + "\n";
    for (const auto& p : tangential) inputs += p + "\n";
    f.write_string("provenance/inputs", inputs);
    f.write_scalar("provenance/seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    out.commit();
    return 0;
  } catch (...) {
    return exit_on_error("softpack-average");
  }
}
