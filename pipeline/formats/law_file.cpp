#include "formats/law_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <nlohmann/json.hpp>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/suggest.hpp"
#include "core/types.hpp"
#include "formats/json_input.hpp"
#include "formats/law_file_json.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

using json = nlohmann::ordered_json;
using Keys = std::vector<std::string>;

using law_json::kFormat, law_json::kForce, law_json::kStiffness, law_json::kOne, law_json::kMetre;
const Keys kTopKeys = {"format", "version", "reference_radius", "models", "scenes", "mixing", "many_body", "provenance"};
const Keys kManyBodyKeys = {"form", "beta", "tangential", "source", "grain", "soft_soft"};
const Keys kManyBodyForms = {"volumetric", "volumetric-union"};
const Keys kGrainKeys = {"exponent", "beta"};
const Keys kSoftSoftKeys = {"beta", "stress"};
const Keys kStressKeys = {"form", "kappa"};
const Keys kStressForms = {"mean", "normal", "lateral"};
const Keys kManyBodyTangential = {"pairwise", "gain"};
const Keys kSceneNames = {"soft-solid", "soft-soft"};
const Keys kSceneKeys = {"normal", "tangential", "friction", "normal_scaling", "tangential_scaling"};
const Keys kLawKeys = {"a", "b", "c", "delta", "delta_n_range"};
const Keys kValueKeys = {"value", "error", "unit"};
const Keys kQuantityKeys = {"value", "unit"};  // reference_radius, radius_range: no error
const Keys kFrictionKeys = {"delta_n", "mu"};
const Keys kScalingKeys = {"exponent", "radius_range", "variant"};
const Keys kVariants = {"fixed", "self-similar"};
const Keys kMixingKeys = {"rule", "checked_ratio", "deviation"};
const Keys kRules = {"reduced-radius"};
const Keys kProvenanceKeys = {"study", "seeds", "code_version", "created", "notes"};

// ---- reading: every refusal "<file>: <field>: <what was found> ...; allowed: <what is>" ----

std::string shown(const json& j) { return j.is_string() ? fmt::format("'{}'", j.get<std::string>()) : j.dump(); }

std::string quoted(const Keys& keys) {
  std::vector<std::string> q;
  for (const std::string& k : keys) q.push_back(fmt::format("'{}'", k));
  return fmt::format("{}", fmt::join(q, ", "));
}

std::string child(const std::string& field, const std::string& key) { return field.empty() ? key : field + "." + key; }
std::string item(const std::string& field, std::size_t i) { return fmt::format("{}[{}]", field, i); }

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(field.empty() ? fmt::format("{}: {}", file_, what) : fmt::format("{}: {}: {}", file_, field, what));
  }
  [[noreturn]] void refuse(const std::string& field, const json& found, const std::string& allowed) const {
    fail(field, fmt::format("{} is not allowed; allowed: {}", shown(found), allowed));
  }

  /// `j` as an object whose keys are all among `keys`.
  const json& object(const json& j, const std::string& field, const Keys& keys) const {
    if (!j.is_object()) refuse(field, j, fmt::format("an object with {}", fmt::join(keys, ", ")));
    for (const auto& [key, v] : j.items()) {
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
      const std::string near = closest_match(key, keys);
      fail(child(field, key),
           fmt::format("unknown key; allowed: {}{}", fmt::join(keys, ", "), near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
    }
    return j;
  }
  /// The member `key` of the object `j`: nullptr when it is absent or null (an optional part).
  const json* find(const json& j, const std::string& key) const {
    const auto it = j.find(key);
    return it == j.end() || it->is_null() ? nullptr : &*it;
  }
  const json& need(const json& j, const std::string& field, const std::string& key, const std::string& allowed) const {
    const auto it = j.find(key);
    if (it == j.end()) fail(child(field, key), "missing; allowed: " + allowed);
    return *it;
  }

  /// A finite number; null is NaN when `null_ok`.
  double number(const json& j, const std::string& field, bool null_ok) const {
    const std::string allowed = null_ok ? "a finite number or null" : "a finite number";
    if (j.is_null() && null_ok) return kNaN;
    if (!j.is_number() || !std::isfinite(j.get<double>())) refuse(field, j, allowed);
    return j.get<double>();
  }
  std::string text(const json& j, const std::string& field) const {
    if (!j.is_string()) refuse(field, j, "a string");
    return j.get<std::string>();
  }
  std::string literal(const json& j, const std::string& field, const Keys& allowed) const {
    if (!j.is_string() || std::find(allowed.begin(), allowed.end(), j.get<std::string>()) == allowed.end()) refuse(field, j, quoted(allowed));
    return j.get<std::string>();
  }
  void check_unit(const json& j, const std::string& field, const char* unit) const {
    const std::string f = child(field, "unit");
    const json& u = need(j, field, "unit", quoted({unit}));
    if (!u.is_string() || u.get<std::string>() != unit) refuse(f, u, quoted({unit}));
  }

  LawValue value(const json& j, const std::string& field, const char* unit, bool value_null_ok) const {
    object(j, field, kValueKeys);
    LawValue v;
    v.value = number(need(j, field, "value", value_null_ok ? "a finite number or null" : "a finite number"), child(field, "value"), value_null_ok);
    if (const json* e = find(j, "error")) v.error = number(*e, child(field, "error"), true);
    check_unit(j, field, unit);
    return v;
  }

  /// [lo, hi] with `lo_min <= lo < hi` (`closed`) or `0 < lo <= hi`; `allowed` says which.
  std::pair<double, double> range(const json& j, const std::string& field, bool closed, const std::string& allowed) const {
    if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) refuse(field, j, allowed);
    const double lo = number(j[0], item(field, 0), false), hi = number(j[1], item(field, 1), false);
    if (closed ? !(lo >= 0.0 && lo < hi) : !(lo > 0.0 && lo <= hi)) refuse(field, j, allowed);
    return {lo, hi};
  }

  /// A dimensionless {"value", "error", "unit": '1'} `key` of `parent` with lo <= value <= hi.
  LawValue bounded(const json& parent, const std::string& field, const std::string& key, double lo, double hi) const {
    const std::string allowed = fmt::format("{} <= {} <= {}", lo, key, hi);
    const json& j = need(parent, field, key, fmt::format("{{\"value\": {}, \"error\", \"unit\": '1'}}", allowed));
    const LawValue v = value(j, child(field, key), kOne, false);
    if (!(v.value >= lo && v.value <= hi)) refuse(child(child(field, key), "value"), j["value"], allowed);
    return v;
  }

  ManyBodyFit many_body(const json& m, const LawFile& f) const {
    if (f.version < 2) fail("many_body", "not allowed in a version 1 file; allowed: version 2 or later (the many-body law)");
    object(m, "many_body", kManyBodyKeys);
    ManyBodyFit mb;
    mb.form = literal(need(m, "many_body", "form", quoted(kManyBodyForms)), "many_body.form", kManyBodyForms);
    if (f.version < 3 && mb.form != "volumetric")
      fail("many_body.form",
           fmt::format("'{}' is not allowed in a version {} file; allowed: 'volumetric' (version 3 adds 'volumetric-union')", mb.form, f.version));
    for (const char* key : {"grain", "soft_soft"})
      if (f.version < 3 && find(m, key))
        fail(child("many_body", key), fmt::format("not allowed in a version {} file; allowed: version 3 or later", f.version));
    mb.beta = bounded(m, "many_body", "beta", 0.0, 10.0);
    if (const json* t = find(m, "tangential")) mb.tangential = literal(*t, "many_body.tangential", kManyBodyTangential);
    // the gain Fn / Eq. 7 grows without bound as Eq. 7 falls to 0 at its onset: kt stays finite
    // only where Eq. 8 has fallen to 0 by then
    for (const auto& [name, laws] : f.scenes)
      if (mb.tangential == "gain" && laws.tangential && laws.tangential->delta.value < laws.normal.delta.value)
        fail("many_body.tangential", fmt::format("'gain' is not allowed with scenes.{}.tangential.delta ({}) below its normal delta ({}); allowed: "
                                                 "pairwise, or a tangential onset at or above the normal one",
                                                 name, laws.tangential->delta.value, laws.normal.delta.value));
    if (const json* s = find(m, "source")) mb.source = text(*s, "many_body.source");
    if (const json* g = find(m, "grain"))
      object(*g, "many_body.grain", kGrainKeys),
          mb.grain = ManyBodyGrainFit{bounded(*g, "many_body.grain", "exponent", 0.0, 10.0), bounded(*g, "many_body.grain", "beta", 0.0, 10.0)};
    if (const json* ss = find(m, "soft_soft")) {
      object(*ss, "many_body.soft_soft", kSoftSoftKeys), mb.soft_beta = bounded(*ss, "many_body.soft_soft", "beta", 0.0, 10.0);
      if (const json* st = find(*ss, "stress")) mb.soft_stress = stress(*st, f);
    }
    return mb;
  }

  ManyBodyStressFit stress(const json& st, const LawFile& f) const {
    const std::string field = "many_body.soft_soft.stress";
    if (f.version < 4) fail(field, fmt::format("not allowed in a version {} file; allowed: version 4 or later (the soft-soft stress term)", f.version));
    object(st, field, kStressKeys);
    ManyBodyStressFit s;
    s.form = literal(need(st, field, "form", quoted(kStressForms)), child(field, "form"), kStressForms);
    s.kappa = bounded(st, field, "kappa", 0.0, 10.0);
    return s;
  }

  LawFit law(const json& j, const std::string& field, const char* unit) const {
    object(j, field, kLawKeys);
    const std::string dimensional = fmt::format("{{\"value\", \"error\", \"unit\": '{}'}}", unit);
    const std::string dimensionless = "{\"value\", \"error\", \"unit\": '1'}";
    LawFit f;
    f.a = value(need(j, field, "a", dimensional), child(field, "a"), unit, false);
    f.b = value(need(j, field, "b", dimensionless), child(field, "b"), kOne, false);
    f.c = value(need(j, field, "c", dimensional), child(field, "c"), unit, true);
    f.delta = value(need(j, field, "delta", dimensionless), child(field, "delta"), kOne, true);
    const std::string allowed = "[lo, hi] with 0 <= lo < hi";
    std::tie(f.delta_n_min, f.delta_n_max) = range(need(j, field, "delta_n_range", allowed), child(field, "delta_n_range"), true, allowed);
    // What the law gives over its range must be a number the simulation can add and multiply:
    // a = 1e308 was read, then overflowed in a later stage that blamed another key.
    constexpr double kLargest = 1e15;  // [N] or [N/m], far beyond any soft-particle's contact
    for (const double dn : {f.delta_n_min, f.delta_n_max}) {
      const double v = f.a.value * std::pow(dn, f.b.value) + (std::isnan(f.c.value) ? 0.0 : f.c.value);  // c may be left out (null)
      if (!(std::abs(v) <= kLargest))
        refuse(child(field, "a"), j.at("a"),
               fmt::format("a law whose value a dn^b + c stays within {:g} {} over its delta_n_range (it is {:g} at delta_n = "
                           "{})",
                           kLargest, unit, v, dn));
    }
    return f;
  }

  FrictionLaw friction(const json& j, const std::string& field) const {
    object(j, field, kFrictionKeys);
    const std::string dn_field = child(field, "delta_n"), mu_field = child(field, "mu");
    const json& dn = need(j, field, "delta_n", "an array of increasing numbers");
    const json& mu = need(j, field, "mu", "an array of {\"value\", \"error\", \"unit\": '1'}");
    if (!dn.is_array() || dn.empty()) refuse(dn_field, dn, "a non-empty array of increasing numbers");
    if (!mu.is_array()) refuse(mu_field, mu, "an array of {\"value\", \"error\", \"unit\": '1'}");
    FrictionLaw f;
    for (std::size_t i = 0; i < dn.size(); ++i) {
      f.delta_n.push_back(number(dn[i], item(dn_field, i), false));
      if (i > 0 && !(f.delta_n[i] > f.delta_n[i - 1]))
        refuse(item(dn_field, i), dn[i], fmt::format("a number > {} (delta_n increasing)", f.delta_n[i - 1]));
    }
    if (mu.size() != dn.size())
      fail(mu_field, fmt::format("{} values for {} delta_n is not allowed; allowed: one per delta_n ({})", mu.size(), dn.size(), dn.size()));
    for (std::size_t i = 0; i < mu.size(); ++i) f.mu.push_back(value(mu[i], item(mu_field, i), kOne, false));
    return f;
  }

  RadiusScaling scaling(const json& j, const std::string& field) const {
    object(j, field, kScalingKeys);
    RadiusScaling s;
    s.exponent = value(need(j, field, "exponent", "{\"value\", \"error\", \"unit\": '1'}"), child(field, "exponent"), kOne, true);
    const std::string rr = child(field, "radius_range");
    const std::string allowed = "[R_min, R_max] with 0 < R_min <= R_max";
    const json& r = object(need(j, field, "radius_range", "{\"value\": " + allowed + ", \"unit\": 'm'}"), rr, kQuantityKeys);
    std::tie(s.R_min, s.R_max) = range(need(r, rr, "value", allowed), child(rr, "value"), false, allowed);
    check_unit(r, rr, kMetre);
    s.variant = literal(need(j, field, "variant", quoted(kVariants)), child(field, "variant"), kVariants);
    return s;
  }

  SceneLaws scene(const json& j, const std::string& field) const {
    object(j, field, kSceneKeys);
    SceneLaws s;
    s.normal = law(need(j, field, "normal", "the Eq. 7 law {a, b, c, delta, delta_n_range}"), child(field, "normal"), kForce);
    if (const json* t = find(j, "tangential")) s.tangential = law(*t, child(field, "tangential"), kStiffness);
    if (const json* fr = find(j, "friction")) s.friction = friction(*fr, child(field, "friction"));
    if (const json* n = find(j, "normal_scaling")) s.normal_scaling = scaling(*n, child(field, "normal_scaling"));
    if (const json* t = find(j, "tangential_scaling")) s.tangential_scaling = scaling(*t, child(field, "tangential_scaling"));
    return s;
  }

  MixingRule mixing(const json& j, const std::string& field) const {
    object(j, field, kMixingKeys);
    MixingRule m;
    m.rule = literal(need(j, field, "rule", quoted(kRules)), child(field, "rule"), kRules);
    if (const json* r = find(j, "checked_ratio")) {
      m.checked_ratio = number(*r, child(field, "checked_ratio"), true);
      if (!(m.checked_ratio > 0.0)) refuse(child(field, "checked_ratio"), *r, "a number > 0 (R2/R1) or null");
    }
    if (const json* d = find(j, "deviation")) m.deviation = value(*d, child(field, "deviation"), kOne, true);
    return m;
  }

  LawFileProvenance provenance(const json& j, const std::string& field) const {
    object(j, field, kProvenanceKeys);
    LawFileProvenance p;
    for (auto [key, out] :
         {std::pair{"study", &p.study}, std::pair{"code_version", &p.code_version}, std::pair{"created", &p.created}, std::pair{"notes", &p.notes}})
      if (const json* s = find(j, key)) *out = text(*s, child(field, key));
    if (const json* seeds = find(j, "seeds")) {
      const std::string sf = child(field, "seeds");
      if (!seeds->is_array()) refuse(sf, *seeds, "an array of integers >= 0");
      for (std::size_t i = 0; i < seeds->size(); ++i) {
        if (!(*seeds)[i].is_number_unsigned()) refuse(item(sf, i), (*seeds)[i], "an integer >= 0");
        p.seeds.push_back((*seeds)[i].get<std::uint64_t>());
      }
    }
    return p;
  }

  LawFile file(const json& j) const {
    if (!j.is_object()) fail("", fmt::format("{} is not allowed; allowed: a JSON object (a {} file)", shown(j), kFormat));
    const json& format = need(j, "", "format", quoted({kFormat}));
    if (!format.is_string() || format.get<std::string>() != kFormat) refuse("format", format, quoted({kFormat}));
    const json& version = need(j, "", "version", std::to_string(kLawFileVersion));
    const bool above = version.is_number_unsigned() ? version.get<std::uint64_t>() > kLawFileVersion
                                                    : version.is_number_integer() && version.get<std::int64_t>() > kLawFileVersion;
    if (above)
      fail("version", fmt::format("{} is newer than this build reads; allowed: {} (this build reads version {})", version.dump(), kLawFileVersion,
                                  kLawFileVersion));
    if (!version.is_number_integer() || version.get<std::int64_t>() < 1) refuse("version", version, fmt::format("1 to {}", kLawFileVersion));
    object(j, "", kTopKeys);
    LawFile f;
    f.version = static_cast<int>(version.get<std::int64_t>());
    const std::string allowed = "{\"value\": a number > 0, \"unit\": 'm'}";
    const json& r = object(need(j, "", "reference_radius", allowed), "reference_radius", kQuantityKeys);
    const json& rv = need(r, "reference_radius", "value", "a finite number > 0");
    f.reference_radius = number(rv, "reference_radius.value", false);
    if (!(f.reference_radius > 0.0)) refuse("reference_radius.value", rv, "a finite number > 0");
    check_unit(r, "reference_radius", kMetre);
    if (const json* m = find(j, "models"); m && !m->is_object()) refuse("models", *m, "an object of texts");
    const json& scenes = need(j, "", "scenes", "an object with " + fmt::format("{}", fmt::join(kSceneNames, ", ")));
    if (!scenes.is_object() || scenes.empty())
      refuse("scenes", scenes, fmt::format("an object with at least one of {}", fmt::join(kSceneNames, ", ")));
    for (const auto& [name, s] : scenes.items()) {
      if (std::find(kSceneNames.begin(), kSceneNames.end(), name) == kSceneNames.end())
        fail(child("scenes", name), fmt::format("unknown scene; allowed: {}", fmt::join(kSceneNames, ", ")));
      f.scenes[name] = scene(s, child("scenes", name));
    }
    // The laws are measured at reference_radius; a scaling carries them to other radii within the
    // range it was measured over, which must hold R0 itself (else every law would be rescaled).
    using Scaling = std::pair<const char*, const std::optional<RadiusScaling>*>;
    for (const auto& [name, laws] : f.scenes)
      for (const auto& [which, scaling] :
           std::array<Scaling, 2>{Scaling{"normal_scaling", &laws.normal_scaling}, Scaling{"tangential_scaling", &laws.tangential_scaling}})
        if (*scaling && !(f.reference_radius >= (*scaling)->R_min && f.reference_radius <= (*scaling)->R_max))
          refuse("reference_radius.value", rv,
                 fmt::format("a radius within scenes.{}.{}.radius_range [{}, {}] m (the laws are measured at it)", name, which, (*scaling)->R_min,
                             (*scaling)->R_max));
    if (const json* m = find(j, "mixing")) f.mixing = mixing(*m, "mixing");
    if (const json* m = find(j, "many_body")) f.many_body = many_body(*m, f);
    if (const json* p = find(j, "provenance")) f.provenance = provenance(*p, "provenance");
    return f;
  }

 private:
  std::string file_;
};

}  // namespace

void write_law_file(const std::string& path, const LawFile& f) {
  const json j = law_json::file(f);
  Reader(path).file(j);  // what would not be read back is refused before anything is written
  write_file_atomically(path, j.dump(2) + "\n");
}

LawFile read_law_file(const std::string& path) { return Reader(path).file(read_json_input(path, "a law file (JSON)")); }

bool write_law_file_if_changed(const std::string& path, const LawFile& f) {
  // What names the code that wrote the laws, not the laws: when the time of writing, the code
  // version and the many-body law's source (which names the version) are all that differ, the
  // file stays as it is.
  const auto laws_only = [](json j) {
    if (j.contains("provenance")) j["provenance"].erase("code_version"), j["provenance"].erase("created");
    if (j.contains("many_body")) j["many_body"].erase("source");
    return j;
  };
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const json old = json::parse(read_text_file(path), nullptr, /*allow_exceptions=*/false);
    if (!old.is_discarded() && laws_only(old) == laws_only(law_json::file(f))) return false;
  }
  write_law_file(path, f);
  return true;
}

}  // namespace softpack
