// The profile's optional `fit` section: how softpack-fit fits Eq. 7 and Eq. 8 (docs/fit.md).
//
//   fit:
//     weighting: relative     # stderr (1/stderr^2), unweighted, relative (1/value^2)
//     onset_force: 1.0e-2     # Eq. 7's loaded points: Fn > this x the curve's largest force
//     delta_n_max: 0.5        # fit only delta_n <= this; or per scene, {soft-solid: 0.5, soft-soft: 0.35}
//     compare: true           # also fit with every other weighting, side by side in the fit file
//     form: clamped           # loaded (default) or clamped: max(0, a dn^b + c) over every point, delta free
//     sigma_floor: 1.0e-3     # clamped: stderr floored at this x the curve's largest force
//
// Every key may be left out (its default is the fit of releases up to 0.4.0: stderr, 1e-9, no
// bound, no comparison); a profile without the section fits as those releases did.
#pragma once
#include <limits>
#include <map>
#include <string>

#include "config/yaml_node.hpp"

namespace softpack::fit {

/// A force below this fraction of the largest |F| of the curve is round-off, i.e. zero.
inline constexpr double kZeroForceRelative = 1e-9;

/// How a law is fitted (the profile's `fit` section; docs/fit.md). The defaults are the fit of
/// releases up to 0.4.0.
struct FitOptions {
  enum class Weighting { standard_error, unweighted, relative };
  Weighting weighting = Weighting::standard_error;
  /// Eq. 7's form: `loaded`, a Δn^b + c fitted to the loaded points (onset_force); `clamped`,
  /// max(0, a Δn^b + c) fitted to every point up to delta_n_max, δ free (issue 29; weighting
  /// stderr with σ floored at sigma_floor × the curve's largest force, or unweighted).
  enum class Form { loaded, clamped };
  Form form = Form::loaded;
  double sigma_floor = 1e-3;  ///< clamped form, and the judgement of every form: σ >= this × the largest |F|
  double onset_force = kZeroForceRelative;  ///< Eq. 7: loaded when F > onset_force × the curve's largest |F|
  double delta_n_max = std::numeric_limits<double>::infinity();  ///< fit only Δn <= this
};

/// "stderr", "unweighted", "relative"; InputError naming the allowed values otherwise.
FitOptions::Weighting parse_weighting(const std::string& name);
/// Reads a candidate's or a section's keys (weighting, onset_force, form, sigma_floor) into `o`;
/// InputError at the key for a value not allowed.
void parse_fit_keys(const ConfigNode& node, FitOptions& o);
const char* weighting_name(FitOptions::Weighting w);



struct FitSection {
  FitOptions options;
  /// delta_n_max per scene ("soft-solid", "soft-soft") when the section gives a map; a scene
  /// left out has options.delta_n_max (no bound).
  std::map<std::string, double> delta_n_max_of;
  bool compare = false;  ///< also fit with the other weightings (the fit file's "weightings")
  bool given = false;    ///< the profile has a `fit` section
  /// The options of one scene's fit: `options` with its delta_n_max.
  FitOptions options_for(const std::string& scene) const;
};

/// Reads `fit` of a profile root (defaults when it has none). InputError at the key's line and
/// column: an unknown key, a weighting not allowed, onset_force outside [0, 1), delta_n_max <= 0
/// or a map of it with a key other than soft-solid and soft-soft.
FitSection parse_fit_section(const ConfigNode& root);

}  // namespace softpack::fit
