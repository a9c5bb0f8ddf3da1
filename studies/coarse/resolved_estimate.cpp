#include "coarse/resolved_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/version.hpp"
#include "integrate/time_step.hpp"

namespace softpack {
namespace {

struct Size {
  double spheres = 0.0, error = 0.0, smallest = std::numeric_limits<double>::infinity();
  double inside = 0.0;  ///< of those, the sites' sites' contents' (all of `error` is theirs)
};

// Spheres and smallest grain of the medium's resolved model: its sites' contents counted when
// made, expected from the sample when sampled (the same mean for every site: their errors add).
Size resolved_size(const Medium& m) {
  Size z;
  z.spheres = static_cast<double>(m.grain_r.size());
  for (double r : m.grain_r) z.smallest = std::min(z.smallest, r);
  for (const Packing& p : m.packings) {
    z.spheres += static_cast<double>(p.radii.size());
    for (double r : p.radii) z.smallest = std::min(z.smallest, r);
  }
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const SiteInside in = site_inside(m, k);  // InputError when nested and neither made nor sampled
    z.spheres += in.grains, z.error += in.grains_error, z.smallest = std::min(z.smallest, in.smallest_radius);
    z.inside += in.grains;
  }
  return z;
}

// The engine's step for a resolved scene whose smallest grain has radius r.
double resolved_step(const CoarseGrainSettings& s, double r) {
  SceneDef one = engine_scene(s);
  ParticleDef p;
  p.r = r, p.material = 0;
  one.particles.push_back(p);
  return choose_time_step(one);
}

// The header's plan: the sites' sites' contents a levels deeper.
DeeperPlan plan_deeper(const CoarseGrainSettings& s, const Medium& m, const Size& z, double simulated_time, double c, double c_error) {
  DeeperPlan d;
  d.levels_added = s.plan_levels_added;
  if (d.levels_added == 0 || m.levels == 1 || m.sites.empty()) return d;
  double sites = 0.0;
  for (const auto& inner : m.inner_sites) sites += static_cast<double>(inner.size());
  const double n = sites / static_cast<double>(m.sites.size());
  // A content of L levels holds x (1 + n + ... + n^(L-1)) grains: the ratio of L = D + a to L = D.
  const int D = m.levels - 1, a = d.levels_added;
  double deeper = 0.0, now = 0.0, level = 1.0;
  for (int k = 0; k < D + a; ++k, level *= n) (k < D ? now : deeper) += level;
  d.sites_per_packing = n;
  d.depth_ratio = (now + deeper) / now;
  d.spheres = z.spheres + (d.depth_ratio - 1.0) * z.inside;
  d.spheres_error = d.depth_ratio * z.error;
  d.smallest_radius = z.smallest / std::pow(s.packing.polydispersity, a);
  d.dt = resolved_step(s, d.smallest_radius);
  d.steps = simulated_time / d.dt;
  d.cpu = d.spheres * d.steps * c;
  d.cpu_error = d.cpu * std::hypot(d.spheres_error / d.spheres, c > 0.0 ? c_error / c : 0.0);
  return d;
}

}  // namespace

ResolvedEstimate estimate_resolved(const CoarseGrainSettings& s, const Medium& m, const CoarseResult& soft,
                                   const std::vector<CoarseResult>& measured) {
  if (soft.model != "soft") throw InputError(fmt::format("{}: a {} run; allowed: the medium's soft run", soft.path, soft.model));
  if (soft.sites != static_cast<std::int64_t>(m.sites.size()) || soft.grains != static_cast<std::int64_t>(m.grain_r.size()))
    throw InputError(fmt::format("{}: {} grains and {} sites, the medium {} and {}: not this medium's run", soft.path, soft.grains,
                                 soft.sites, m.grain_r.size(), m.sites.size()));
  if (measured.empty()) throw InputError("estimate_resolved: no measured resolved run to take the cost per sphere-step from");
  ResolvedEstimate e;
  e.content_sample = m.content_mean.sample;
  const Size z = resolved_size(m);
  e.spheres = z.spheres, e.spheres_error = z.error, e.smallest_radius = z.smallest;
  // The engine's step for the resolved scene: its smallest grain's (the shells and walls set none).
  e.dt = resolved_step(s, e.smallest_radius);
  e.simulated_time = static_cast<double>(soft.steps) * soft.dt;
  e.steps = e.simulated_time / e.dt;
  std::vector<double> c;
  for (const CoarseResult& r : measured) {
    if (r.model != "resolved") throw InputError(fmt::format("{}: a {} run; allowed: resolved runs (their cost per sphere-step)", r.path, r.model));
    if (!(r.cpu_seconds > 0.0 && r.spheres > 0 && r.steps > 0)) throw InputError(fmt::format("{}: no CPU time, spheres or steps", r.path));
    c.push_back(r.cpu_seconds / (static_cast<double>(r.spheres) * static_cast<double>(r.steps)));
  }
  double mean = 0.0, var = 0.0;
  for (double x : c) mean += x / static_cast<double>(c.size());
  for (double x : c) var += (x - mean) * (x - mean);
  e.measured_runs = c.size();
  e.cpu_per_sphere_step = mean;
  e.cpu_per_sphere_step_error = c.size() > 1 ? std::sqrt(var / static_cast<double>(c.size() - 1) / static_cast<double>(c.size())) : 0.0;
  e.cpu = e.spheres * e.steps * mean;
  e.cpu_error = e.cpu * std::hypot(e.spheres_error / e.spheres, mean > 0.0 ? e.cpu_per_sphere_step_error / mean : 0.0);
  e.soft_cpu = soft.cpu_seconds;
  e.deeper = plan_deeper(s, m, z, e.simulated_time, mean, e.cpu_per_sphere_step_error);
  return e;
}

namespace {

// The last loading row with no soft contact yet beyond the laws' range: its strain and σzz (null
// where the rows do not count them; strain -1 when the first row already does).
nlohmann::json within_laws_json(const CoarseResult& soft) {
  const double strain = strain_within_laws(soft.rows);
  nlohmann::json j = {{"strain", std::isnan(strain) ? nlohmann::json(nullptr) : nlohmann::json(strain)}, {"sigma_zz", nullptr}};
  for (const CurveRow& row : soft.rows)
    if (row.phase == 1 && row.strain == strain) j["sigma_zz"] = {{"value", row.sigma_top}, {"unit", "Pa"}};
  j["rule"] = "the last loading row whose /curve/beyond_range is 0 (coarse/compression.hpp strain_within_laws)";
  return j;
}

}  // namespace

std::string resolved_estimate_json(const ResolvedEstimate& e, const std::string& config, const std::string& medium, const CoarseResult& soft,
                                   const std::vector<CoarseResult>& measured) {
  using nlohmann::json;
  const auto q = [](double v, const char* unit) { return json{{"value", v}, {"unit", unit}}; };
  json runs = json::array();
  for (const CoarseResult& r : measured) runs.push_back(r.path);
  json j = {{"code_version", code_version()},
            {"config", config},
            {"medium", medium},
            {"soft_run", soft.path},
            {"seed", soft.seed},
            {"soft_cpu", q(e.soft_cpu, "s")},
            {"soft_spheres", soft.spheres},
            {"soft_steps", soft.steps},
            {"soft_dt", q(soft.dt, "s")},
            // the soft run's contacts beyond the laws' measured range (forces/contact_models.hpp RangeStats)
            {"soft_beyond_range", soft.beyond_range},
            {"soft_max_dn", soft.max_dn},
            // where its stress is still within the measured laws (experiments/three-decades.yaml)
            {"soft_within_laws", within_laws_json(soft)},
            {"resolved_spheres", {{"value", e.spheres}, {"error", e.spheres_error}}},
            {"contents", e.content_sample > 0 ? fmt::format("sampled: {} level packings per level below (medium.content_sample)", e.content_sample)
                                              : std::string("made")},
            {"smallest_radius", q(e.smallest_radius, "m")},
            {"resolved_dt", q(e.dt, "s")},
            {"simulated_time", q(e.simulated_time, "s")},
            {"resolved_steps", e.steps},
            {"cpu_per_sphere_step", {{"value", e.cpu_per_sphere_step}, {"error", e.cpu_per_sphere_step_error}, {"unit", "s"}}},
            {"measured_runs", runs},
            {"resolved_cpu_estimate", {{"value", e.cpu}, {"error", e.cpu_error}, {"unit", "s"}}},
            {"speed_up_estimate", {{"value", e.speed_up()}, {"error", e.cpu_error / e.soft_cpu}}},
            {"rule", "resolved CPU = spheres x (soft run's simulated time / resolved dt) x CPU per sphere-step of the measured "
                     "resolved runs (coarse/resolved_estimate.hpp)"}};
  if (const DeeperPlan& d = e.deeper; d.levels_added > 0)
    j["plan"] = {{"levels_added", d.levels_added},
                 {"sites_per_packing", d.sites_per_packing},
                 {"depth_ratio", d.depth_ratio},
                 {"resolved_spheres", {{"value", d.spheres}, {"error", d.spheres_error}}},
                 {"smallest_radius", q(d.smallest_radius, "m")},
                 {"resolved_dt", q(d.dt, "s")},
                 {"resolved_steps", d.steps},
                 {"resolved_cpu_estimate", {{"value", d.cpu}, {"error", d.cpu_error}, {"unit", "s"}}},
                 {"speed_up_estimate", {{"value", d.cpu / e.soft_cpu}, {"error", d.cpu_error / e.soft_cpu}}},
                 {"rule", "the same medium with each site's soft-particle levels_added levels deeper at the same Pi: the sites' sites' "
                          "grains times depth_ratio = (n^(D+a) - 1) / (n^D - 1), the step of the smallest grain / Pi^a, over the same "
                          "soft run's soft_cpu (coarse/resolved_estimate.hpp)"}};
  return j.dump(1) + "\n";
}

}  // namespace softpack
