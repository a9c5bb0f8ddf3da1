// The law file: the measured soft-particle contact laws in one versioned JSON file that a
// simulation can read (a soft-particle as one sphere with these laws). Version 2 (issue 33) adds
// the many-body law (contact/soft_particle_law.hpp ManyBodyLaw), version 3 its third version's
// keys, version 4 the soft-soft stress term; earlier files are read as they were. JSON:
//
//   {"format": "softpack-laws", "version": 4,
//    "reference_radius": {"value": R0, "unit": "m"},
//    "models": {"normal", "tangential", "friction", "radius_scaling", "mixing"}  (texts; not read),
//    "scenes": {"soft-solid": {                       (and/or "soft-soft"; at least one)
//        "normal": {"a": {"value", "error", "unit": "N"}, "b": {…, "unit": "1"},
//                   "c": {…, "unit": "N"}, "delta": {…, "unit": "1"}, "delta_n_range": [lo, hi]},
//        "tangential": {"a": {…, "unit": "N/m"}, "b": {…, "unit": "1"}, "c": {…, "unit": "N/m"},
//                       "delta": {…, "unit": "1"}, "delta_n_range": [lo, hi]},       (optional)
//        "friction": {"delta_n": [...], "mu": [{"value", "error", "unit": "1"}, ...]}, (optional)
//        "normal_scaling": {"exponent": {…, "unit": "1"},
//                           "radius_range": {"value": [R_min, R_max], "unit": "m"},
//                           "variant": "fixed" | "self-similar"},                      (optional)
//        "tangential_scaling": {the same}},                                           (optional)
//      "soft-soft": {…}},
//    "mixing": {"rule": "reduced-radius", "checked_ratio", "deviation": {…, "unit": "1"}} (optional),
//    "many_body": {"form": "volumetric" | "volumetric-union", "beta": {…, "unit": "1"},
//                  "tangential": "pairwise" | "gain", "source": text,
//                  "grain": {"exponent": {…, "unit": "1"}, "beta": {…, "unit": "1"}},
//                  "soft_soft": {"beta": {…, "unit": "1"},
//                                "stress": {"form": "mean" | "normal" | "lateral", "kappa": {…, "unit": "1"}}}}
//                  (optional; version 2: form volumetric, no grain, no soft_soft; version 3 (the
//                  third version, paper/many-body.md): all but stress; version 4: stress too (the
//                  soft-soft stress term, ManyBodyLaw::SoftStress); tangential absent: pairwise),
//    "provenance": {"study", "seeds": [...], "code_version", "created", "notes"}}
//
// NaN is written as null and read back as NaN: an "error" may always be null (not known), a
// "value" may be null except for a law's a and b and a friction mu. The reader refuses, with an
// InputError naming the file, the field (e.g. `scenes.soft-solid.normal.a.unit`), what it found
// and what is allowed: another format or version, a missing required field, a key it does not
// know (in any object but "models"), a unit other than the one above, a non-finite number,
// reference_radius <= 0, a delta_n_range not 0 <= lo < hi, friction delta_n not increasing or of
// another length than mu (or empty), a variant or rule not listed above, a radius_range not
// 0 < R_min <= R_max, a checked_ratio <= 0, a many_body in a version 1 file, a form other than
// "volumetric" (version 2) or "volumetric-union" (version 3), a beta outside 0 <= beta <= 10, a grain
// exponent outside 0 <= p <= 10, grain or soft_soft in a version 2 file, a stress in a file before
// version 4, a stress form not listed above, a kappa outside 0 <= kappa <= 10.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contact/soft_particle_law.hpp"
#include "core/types.hpp"

namespace softpack {

/// The version of the law file this build writes; it reads this one and every earlier one.
inline constexpr int kLawFileVersion = 4;

/// A measured value and its standard error (NaN: not known).
struct LawValue {
  double value = kNaN;
  double error = kNaN;  ///< NaN = not known
};

/// Eq. 7 (normal: Fn = a dn^b + c for dn >= delta, 0 below, c = -a delta^b) or Eq. 8
/// (tangential stiffness kt, the same form), with dn = hn / R.
struct LawFit {
  LawValue a, b, c, delta;
  double delta_n_min = kNaN;  ///< the delta_n range the law
  double delta_n_max = kNaN;  ///< was measured on
};

/// The soft-particle friction coefficient mu_soft = Ft/Fn while the contact slides, per delta_n
/// (delta_n increasing, one mu each).
struct FrictionLaw {
  std::vector<double> delta_n;
  std::vector<LawValue> mu;
};

/// X(R) = X(R0) (R/R0)^exponent at fixed delta_n.
struct RadiusScaling {
  LawValue exponent;
  double R_min = kNaN;  ///< [m], the radii it was measured at
  double R_max = kNaN;  ///< [m]
  std::string variant;  ///< "fixed" (same grains, more of them) or "self-similar"
};

/// The laws of one scene ("soft-solid" or "soft-soft").
struct SceneLaws {
  LawFit normal;                     ///< Eq. 7; a, c in N
  std::optional<LawFit> tangential;  ///< Eq. 8; a, c in N/m (kt per metre of displacement ht)
  std::optional<FrictionLaw> friction;
  std::optional<RadiusScaling> normal_scaling, tangential_scaling;
};

/// Two soft-particles of radii R1 != R2.
struct MixingRule {
  /// The only allowed value: the soft-soft law at R_eq = 2 R1 R2 / (R1 + R2).
  std::string rule = "reduced-radius";
  double checked_ratio = kNaN;  ///< R2/R1 at which it was checked
  LawValue deviation;  ///< mean relative deviation measured/predicted of Fn over the checked points
};

/// The many-body law's grain factor (version 3): a solid sphere of radius r presses with g(r/R) =
/// ((r/R) / (1 + r/R))^exponent of the single-contact law, its contacts' β their own.
struct ManyBodyGrainFit {
  LawValue exponent, beta;
};

/// The soft-soft stress term (version 4; contact/soft_particle_law.hpp ManyBodyLaw::SoftStress):
/// the stress of each soft-particle's other contacts, by `form`, pushing on the contact's cap.
struct ManyBodyStressFit {
  std::string form = "mean";  ///< "mean", "normal" (along the contact) or "lateral" (across it)
  LawValue kappa;             ///< κ, 0 <= κ <= 10
};

/// The many-body law (version 2; version 3 adds the union form, the grains' and the
/// soft-particles' own; version 4 the soft-soft stress term): the volumetric form's β, fitted on
/// the many-body probe.
struct ManyBodyFit {
  std::string form = "volumetric";      ///< "volumetric-union": E the union of the caps (version 3)
  LawValue beta;                        ///< the walls' (and every contact's without its own)
  std::string source;                   ///< where it was fitted (the probe's plan and report)
  std::string tangential = "pairwise";  ///< "gain": kt times the normal gain (absent: pairwise)
  std::optional<ManyBodyGrainFit> grain{};  ///< none: a grain as a wall, the walls' β
  std::optional<LawValue> soft_beta{};    ///< β of soft-soft contacts; none: the walls'
  std::optional<ManyBodyStressFit> soft_stress{};  ///< the soft-soft stress term (with soft_beta); none: no term
};

struct LawFileProvenance {
  std::string study, code_version, created;
  std::vector<std::uint64_t> seeds;
  std::string notes;
};

struct LawFile {
  int version = kLawFileVersion;
  double reference_radius = kNaN;  ///< R0 [m]: the shell radius a, c were measured at
  std::map<std::string, SceneLaws> scenes;  ///< keys "soft-solid", "soft-soft" (at least one)
  std::optional<MixingRule> mixing;
  std::optional<ManyBodyFit> many_body;  ///< version 2 and later
  LawFileProvenance provenance;
};

/// Writes the law file atomically. Throws InputError (the same messages as read_law_file, naming
/// `path`) and writes nothing when `f` would not be read back: the file is always readable.
void write_law_file(const std::string& path, const LawFile& f);

/// write_law_file, unless `path` holds the same laws: only the provenance's code_version and
/// created, and many_body.source, differ. A report made again by other code then leaves its law
/// file, and so the stamps of every stage that reads it (a nested level above, a medium), as
/// they were. Returns whether it wrote.
bool write_law_file_if_changed(const std::string& path, const LawFile& f);

/// Reads a law file; InputError naming the file and the field on every rule above.
LawFile read_law_file(const std::string& path);

/// What a simulation's soft-particle contacts run on (contact/soft_particle_law.hpp): the laws'
/// values (their errors are not used), δ where the file has none from (-c/a)^(1/b) (0 for
/// c >= 0), the radius exponents with their measured radii, μ_soft per Δn. `source` names the
/// file in messages. The scaling is used whatever its variant: with "fixed" a larger
/// soft-particle holds more grains of the same size, with "self-similar" larger grains; the
/// many-body law (version 2 on; its stress term, version 4). Defined with the scene files' laws,
/// formats/scene_laws.cpp.
SoftParticleLaws soft_particle_laws(const LawFile& f, const std::string& source);

/// The laws a soft-particle follows as `key` (a settings section: `content` of a nested
/// measurement, `soft_particle` of a coarse-grain medium) names them: `key.laws`' file, and when
/// `many_body` is not empty the many-body law of that file instead of `laws`' own (the parameters
/// are dimensionless: paper/many-body.md). InputError naming `key.laws` or `key.many_body`; a
/// `many_body` file without a many-body law is refused.
SoftParticleLaws read_soft_particle_laws(const std::string& key, const std::string& laws, const std::string& many_body);

}  // namespace softpack
