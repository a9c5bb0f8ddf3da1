// softpack-fit: the contact laws of one scene fitted to the seed averages (paper §5): Eq. 7 to
// the normal force Fn(Δn), giving a, b, c and δ, then Eq. 8 to the tangential spring constant
// kt(Δn) with that δ. Reads the average file of softpack-average (HDF5), writes the fit file
// (JSON, formats/fit_file.hpp). The normal fit is essential: if it fails, exit 2 and no file; a
// tangential fit that cannot be done is written as null with the reason. With --config, the
// profile's `fit` section says how (analysis/fit_options.hpp, docs/fit.md); without it, or without
// the section, the fit is that of releases up to 0.4.0.
#include <CLI/CLI.hpp>
#include <fmt/format.h>


#include "analysis/fit_options.hpp"
#include "analysis/fit_selection.hpp"
#include "analysis/power_fit.hpp"
#include "profile/profile.hpp"
#include "config/yaml_node.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "core/stopwatch.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/average_file.hpp"
#include "formats/fit_file.hpp"
#include "packing/packing_profile.hpp"

namespace softpack::apps::fit_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-fit: fit Eq. 7 to the normal force and Eq. 8 to the tangential spring constant of one scene"};
  std::string average_path, out_path, gnuplot_path, config_path, criteria_path;
  bool quiet = false;
  app.add_option("--average", average_path, "seed averages of one scene (HDF5), e.g. data/paper/average/soft-solid.h5")
      ->required();
  app.add_option("--out", out_path, "fit file to write (JSON), e.g. data/paper/fit/soft-solid.json")->required();
  app.add_option("--gnuplot", gnuplot_path,
                 "also write the coefficients as gnuplot variables (a_solid=...; kt_a_solid=...; NaN when missing) for figures/*.gp");
  app.add_option("--config", config_path,
                 "the profile the averages were made with (experiments/<name>.yaml): its `fit` section says how to fit "
                 "(weighting, onset_force, delta_n_max, compare; docs/fit.md)");
  app.add_option("--criteria", criteria_path,
                 "the preregistered criteria (experiments/criteria.yaml): also judge the profile's fit and every candidate "
                 "of its `fit` section (chi2 over every point, runs, leave-one-seed-out jackknife; paper/preregistration.md)");
  app.add_flag("--quiet", quiet, "no summary line on stderr");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-fit")) return *code;

  try {
    const Stopwatch watch;
    const AverageFile in = read_average_file(average_path);
    fit::FitSection section;
    std::string stamp;
    if (!config_path.empty()) {
      const ConfigNode root = ConfigNode::load_file(config_path);
      section = fit::parse_fit_section(root);
      if (const auto name = root.find("profile"); name && name->string() != in.profile)
        throw InputError(fmt::format("{}: profile '{}', but {} was averaged for profile '{}'; give the profile it was made with",
                                     config_path, name->string(), average_path, in.profile));      // One configuration per result: averages that record a stamp must be of this profile as it
      // is now. A profile of the fit's options alone (no stages) has no stamp to record.
      try {
        stamp = profile_stamp(root, "average");
      } catch (const InputError&) {
        if (!in.stamp.empty()) throw;
      }
      check_stamp(average_path, "average", in.stamp, stamp, config_path);
    }
    FitFile out;
    out.scene = in.scene;
    out.stamp = stamp;
    out.input = {average_path, in.profile, in.code_version, in.seeds};
    const fit::FitOptions options = section.options_for(in.scene);  // with the scene's delta_n_max
    if (section.given) out.options = options;
    try {
      out.normal = fit::fit_normal_law(in.delta_n, in.Fn, in.Fn_stderr, options);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: /normal: {}", average_path, e.what()));
    }
    if (!in.has_kt) {
      out.tangential_reason = fmt::format("{} has no /kt group (no tangential sweep averaged)", average_path);
    } else {
      try {
        out.tangential = fit::fit_tangential_law(in.kt_delta_n, in.kt, in.kt_stderr, out.normal.delta, options);
      } catch (const InputError& e) {
        out.tangential_reason = fmt::format("/kt: {}", e.what());
      }
    }
    // fit.compare: the same points with every weighting, side by side (the chosen one included).
    if (section.compare)
      for (const auto w : {fit::FitOptions::Weighting::standard_error, fit::FitOptions::Weighting::unweighted,
                           fit::FitOptions::Weighting::relative}) {
        fit::FitOptions o = options;
        o.weighting = w;
        FitFile::Alternative alt{fit::weighting_name(w), std::nullopt, std::nullopt, ""};
        try {
          alt.normal = fit::fit_normal_law(in.delta_n, in.Fn, in.Fn_stderr, o);
          if (in.has_kt) alt.tangential = fit::fit_tangential_law(in.kt_delta_n, in.kt, in.kt_stderr, alt.normal->delta, o);
        } catch (const InputError& e) {
          alt.reason = e.what();
        }
        out.weightings.push_back(std::move(alt));
      }
    if (!criteria_path.empty()) {
      const fit::FitCriteria criteria = fit::parse_fit_criteria(ConfigNode::load_file(criteria_path));
      const fit::SceneCurves curves{in.delta_n,    in.Fn, in.Fn_stderr, in.Fn_per_seed,
                                    in.kt_delta_n, in.kt, in.kt_stderr, in.kt_per_seed};
      // The profile's own fit, judged alike (and jackknifed with its own options).
      const fit::CandidateFit own = fit::fit_candidate({"profile", options}, curves, criteria);
      out.judged = own.judged;
      out.jackknife = own.jackknife;
      for (const fit::Candidate& c : criteria.candidates) {
        if (!quiet) fmt::print(stderr, "softpack-fit {}: candidate {} (jackknife over {} seeds)\n", in.scene, c.name, in.seeds);
        out.candidates.push_back(fit::fit_candidate(c, curves, criteria));
      }
    }
    out.code_version = code_version();
    out.seconds = watch.elapsed().wall;
    out.cpu_seconds = process_cpu_seconds();
    // The fit file last: it is the stage's result, so a failed write leaves none beside a missing .gp.
    if (!gnuplot_path.empty()) write_fit_gnuplot_file(gnuplot_path, out);
    write_fit_file(out_path, out);

    if (!quiet) {
      const fit::PowerLawFit& n = out.normal;
      fmt::print(stderr, "softpack-fit {}: Fn = a dn^b + c: a = {:.5g} +- {:.2g}, b = {:.4g} +- {:.2g}, c = {:.4g} +- {:.2g}, "
                         "delta = {:.4g} ({} points)\n",
                 out.scene, n.a, n.a_error, n.b, n.b_error, n.c, n.c_error, n.delta, n.points);
      if (!out.tangential)
        fmt::print(stderr, "softpack-fit {}: no tangential fit: {}\n", out.scene, out.tangential_reason);
      else
        fmt::print(stderr, "softpack-fit {}: kt = a dn^b + c: a = {:.5g} +- {:.2g}, b = {:.4g} +- {:.2g}, c = {:.4g} ({} points)\n",
                   out.scene, out.tangential->a, out.tangential->a_error, out.tangential->b, out.tangential->b_error,
                   out.tangential->c, out.tangential->points);
      fmt::print(stderr, "softpack-fit {}: -> {}\n", out.scene, out_path);
    }
    return 0;
  } catch (...) {
    return exit_on_error("softpack-fit");
  }
}

}  // namespace softpack::apps::fit_app
