// softpack-fit: the contact laws of one scene fitted to the seed averages (paper §5): Eq. 7 to
// the normal force Fn(Δn), giving a, b, c and δ, then Eq. 8 to the tangential spring constant
// kt(Δn) with that δ. Reads the average file of softpack-average (HDF5), writes JSON
// (analysis/fit_json.hpp). The normal fit is essential: if it fails, exit 2 and no file; a
// tangential fit that cannot be done is written as null with the reason.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/fit_json.hpp"
#include "analysis/power_fit.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/average_file.hpp"
#include "io/atomic_file.hpp"

namespace {

using namespace softpack;
using json = nlohmann::ordered_json;

}  // namespace

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  CLI::App app{"softpack-fit: fit Eq. 7 to the normal force and Eq. 8 to the tangential spring constant of one scene"};
  std::string average_path, out_path, gnuplot_path;
  bool quiet = false;
  app.add_option("--average", average_path, "seed averages of one scene (HDF5), e.g. data/paper/average/soft-solid.h5")
      ->required();
  app.add_option("--out", out_path, "fit file to write (JSON), e.g. data/paper/fit/soft-solid.json")->required();
  app.add_option("--gnuplot", gnuplot_path,
                 "also write the coefficients as gnuplot variables (a_solid=...; kt_a_solid=...; NaN when missing) for figures/*.gp");
  app.add_flag("--quiet", quiet, "no summary line on stderr");
  CLI11_PARSE(app, argc, argv);

  try {
    const auto start = Clock::now();
    const AverageFile in = read_average_file(average_path);
    const std::string& scene = in.scene;
    const std::int64_t seeds = in.seeds;
    fit::PowerLawFit normal;
    try {
      normal = fit::fit_normal_law(in.delta_n, in.Fn, in.Fn_stderr);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: /normal: {}", average_path, e.what()));
    }

    json tangential = nullptr;
    std::string reason;
    fit::PowerLawFit kt_fit;
    if (!in.has_kt) {
      reason = fmt::format("{} has no /kt group (no tangential sweep averaged)", average_path);
    } else {
      try {
        kt_fit = fit::fit_tangential_law(in.kt_delta_n, in.kt, in.kt_stderr, normal.delta);
        tangential = fit::to_json(kt_fit, false);
      } catch (const InputError& e) {
        reason = fmt::format("/kt: {}", e.what());
      }
    }

    json out;
    out["scene"] = scene;
    out["normal"] = fit::to_json(normal, true);
    out["tangential"] = tangential;
    if (tangential.is_null()) out["tangential_reason"] = reason;
    out["errors"] =
        "standard errors from s^2 (J^T W J)^-1 with s^2 = chi2/(n - p) (chi2_per_dof; W = 1/stderr^2 when weighted, else 1); "
        "delta_error by first-order propagation with the full covariance of (a, b, c); tangential c = -a delta^b with delta "
        "treated as exact";
    out["models"] = {{"normal", "Fn = a dn^b + c for dn >= delta, 0 below (Eq. 7); delta = (-c/a)^(1/b)"},
                     {"tangential", "kt = a dn^b + c for dn >= delta, 0 below (Eq. 8); c = -a delta^b, delta from the normal fit"}};
    out["provenance"] = {
        {"program", "softpack-fit"},
        {"code_version", code_version()},
        {"inputs", json::array({{{"path", average_path},
                                 {"scene", scene},
                                 {"profile", in.profile},
                                 {"code_version", in.code_version},
                                 {"seeds", seeds}}})},
        {"seconds", std::chrono::duration<double>(Clock::now() - start).count()}};
    write_file_atomically(out_path, out.dump(2) + "\n");
    if (!gnuplot_path.empty()) {
      // Suffix of the figure scripts' variables: soft-solid -> _solid, soft-soft -> _soft.
      const std::string sfx = scene == "soft-solid" ? "solid" : "soft";
      const bool has_kt = !tangential.is_null();
      const auto num = [](bool known, double x) { return known && std::isfinite(x) ? fmt::format("{}", x) : "NaN"; };
      std::string gp = fmt::format("# softpack-fit {} of {} ({}): Eq. 7 and Eq. 8 coefficients for gnuplot\n", code_version(),
                                   average_path, scene);
      gp += fmt::format("a_{0}={1}; b_{0}={2}; c_{0}={3}; delta_{0}={4}\n", sfx, num(true, normal.a), num(true, normal.b),
                        num(true, normal.c), num(true, normal.delta));
      gp += fmt::format("kt_a_{0}={1}; kt_b_{0}={2}; kt_c_{0}={3}; kt_delta_{0}={4}\n", sfx, num(has_kt, kt_fit.a),
                        num(has_kt, kt_fit.b), num(has_kt, kt_fit.c), num(has_kt, kt_fit.delta));
      write_file_atomically(gnuplot_path, gp);
    }

    if (!quiet) {
      fmt::print(stderr, "softpack-fit {}: Fn = a dn^b + c: a = {:.5g} +- {:.2g}, b = {:.4g} +- {:.2g}, c = {:.4g} +- {:.2g}, "
                         "delta = {:.4g} ({} points)\n",
                 scene, normal.a, normal.a_error, normal.b, normal.b_error, normal.c, normal.c_error, normal.delta, normal.points);
      if (tangential.is_null())
        fmt::print(stderr, "softpack-fit {}: no tangential fit: {}\n", scene, reason);
      else
        fmt::print(stderr, "softpack-fit {}: kt = a dn^b + c: a = {:.5g} +- {:.2g}, b = {:.4g} +- {:.2g}, c = {:.4g} ({} points)\n",
                   scene, kt_fit.a, kt_fit.a_error, kt_fit.b, kt_fit.b_error, kt_fit.c, kt_fit.points);
      fmt::print(stderr, "softpack-fit {}: -> {}\n", scene, out_path);
    }
    return 0;
  } catch (...) {
    return exit_on_error("softpack-fit");
  }
}
