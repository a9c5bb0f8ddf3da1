#include "analysis/fit_options.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace softpack::fit {

FitOptions::Weighting parse_weighting(const std::string& name) {
  if (name == "stderr") return FitOptions::Weighting::standard_error;
  if (name == "unweighted") return FitOptions::Weighting::unweighted;
  if (name == "relative") return FitOptions::Weighting::relative;
  throw InputError(fmt::format("weighting '{}' is not allowed; allowed: stderr, unweighted, relative", name));
}

const char* weighting_name(FitOptions::Weighting w) {
  switch (w) {
    case FitOptions::Weighting::standard_error: return "stderr";
    case FitOptions::Weighting::unweighted: return "unweighted";
    case FitOptions::Weighting::relative: return "relative";
  }
  return "?";
}

void parse_fit_keys(const ConfigNode& node, FitOptions& o) {
  if (const auto w = node.find("weighting")) o.weighting = parse_weighting(w->choice({"stderr", "unweighted", "relative"}));
  if (const auto f = node.find("onset_force")) {
    const double v = f->number();
    if (!(v >= 0.0 && v < 1.0))
      f->fail(fmt::format("{} is not allowed; allowed: 0 <= onset_force < 1 (a fraction of the curve's largest force)", v));
    o.onset_force = v;
  }
  if (const auto f = node.find("form"))
    o.form = f->choice({"loaded", "clamped"}) == "clamped" ? FitOptions::Form::clamped : FitOptions::Form::loaded;
  if (const auto f = node.find("sigma_floor")) {
    const double v = f->number();
    if (!(v > 0.0 && v < 1.0))
      f->fail(fmt::format("{} is not allowed; allowed: 0 < sigma_floor < 1 (a fraction of the curve's largest force)", v));
    o.sigma_floor = v;
  }
  if (o.form == FitOptions::Form::clamped && o.weighting == FitOptions::Weighting::relative)
    node.fail("form clamped with weighting relative is not allowed (a point of zero force has no relative deviation); "
              "allowed: stderr or unweighted");
}

FitOptions FitSection::options_for(const std::string& scene) const {
  FitOptions o = options;
  if (const auto it = delta_n_max_of.find(scene); it != delta_n_max_of.end()) o.delta_n_max = it->second;
  return o;
}

FitSection parse_fit_section(const ConfigNode& root) {
  FitSection out;
  const std::optional<ConfigNode> section = root.find("fit");
  if (!section) return out;
  out.given = true;
  section->allow_only({"weighting", "onset_force", "delta_n_max", "compare", "form", "sigma_floor"});
  parse_fit_keys(*section, out.options);
  if (const auto m = section->find("delta_n_max")) {
    const auto bound = [](const ConfigNode& n) {
      const double v = n.number();
      if (!(v > 0.0)) n.fail(fmt::format("{} is not allowed; allowed: delta_n_max > 0", v));
      return v;
    };
    if (m->yaml().IsMap()) {  // per scene
      m->allow_only({"soft-solid", "soft-soft"});
      for (const char* scene : {"soft-solid", "soft-soft"})
        if (const auto v = m->find(scene)) out.delta_n_max_of[scene] = bound(*v);
    } else {
      out.options.delta_n_max = bound(*m);
    }
  }
  if (const auto c = section->find("compare")) out.compare = c->boolean();
  return out;
}

}  // namespace softpack::fit
