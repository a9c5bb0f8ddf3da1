#include "formats/sweep_results_file.hpp"

#include <fmt/format.h>

#include <array>
#include <type_traits>

#include "core/error.hpp"
#include "formats/file_kind.hpp"
#include "formats/h5_fields.hpp"

namespace softpack {
namespace {

using namespace formats;
using sweep_names::kScene;
using sweep_names::kStage;

constexpr const char *kDeltaN = "delta_n", *kFn = "Fn", *kCheckPoint = "relaxation/checks/point";
constexpr std::array kLayout{kDeltaN, kFn, kStage};  // what makes a file a results file

struct Column {
  const char* name;
  const char* unit = "";               ///< attribute "unit"
  const char* description = nullptr;   ///< attribute "description"
  bool per_check = false;              ///< one value per relaxation check (else per point)
  bool finite = true;                  ///< numbers: the reader refuses NaN and infinities
};

// f(column, member) for each column of `s`, in the file's order.
template <class S, class F>
void each_column(S& s, F&& f) {
  f({kDeltaN}, s.delta_n);
  f({"hn", "m"}, s.hn);
  f({"alpha_deg"}, s.alpha_deg);
  f({"ht", "m"}, s.ht);
  f({kFn, "N"}, s.Fn);
  f({"Ft_parallel", "N"}, s.Ft_parallel);
  f({"Ft_perpendicular", "N"}, s.Ft_perpendicular);
  f({"force", "N"}, s.force);
  f({"force_first", "N"}, s.force_first);
  f({"force_between", "N"}, s.force_between);
  f({"contacts"}, s.contacts);
  f({"steps"}, s.steps);
  f({"relaxation/steps"}, s.relax_steps);
  f({"relaxation/time"}, s.relax_time);
  f({.name = "relaxation/final_force_ratio", .finite = false}, s.final_force_ratio);
  f({.name = "relaxation/final_energy_ratio", .finite = false}, s.final_energy_ratio);
  f({.name = kCheckPoint, .per_check = true}, s.check_point);
  f({.name = "relaxation/checks/time", .per_check = true}, s.check_time);
  f({.name = "relaxation/checks/force_ratio", .per_check = true, .finite = false}, s.check_force_ratio);
  f({.name = "relaxation/checks/energy_ratio", .per_check = true, .finite = false}, s.check_energy_ratio);
  f({.name = "seconds", .description = "wall-clock time of each point"}, s.seconds);
}

// f(dataset, member) for each provenance field of `s`.
template <class S, class F>
void each_provenance(S& s, F&& f) {
  sweep_names::each_provenance_field(s.provenance, f);
  f("provenance/packings", s.packings);
  f("provenance/seed", s.seed);
  f("provenance/seconds", s.total_seconds);
}

SweepResults columns(const std::vector<PointResult>& points) {
  SweepResults s;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const PointResult& r = points[k];
    s.delta_n.push_back(r.delta_n), s.hn.push_back(r.hn), s.alpha_deg.push_back(r.alpha_deg), s.ht.push_back(r.ht);
    s.Fn.push_back(r.force.x()), s.Ft_parallel.push_back(r.force.y()), s.Ft_perpendicular.push_back(r.force.z());
    s.force.push_back(r.force), s.force_first.push_back(r.force_first), s.force_between.push_back(r.force_between);
    s.contacts.push_back(r.contacts), s.steps.push_back(r.steps), s.relax_steps.push_back(r.relax_steps);
    s.relax_time.push_back(r.relax_time), s.seconds.push_back(r.seconds);
    s.final_force_ratio.push_back(r.checks.empty() ? 0.0 : r.checks.back().residuals.force_ratio());
    s.final_energy_ratio.push_back(r.checks.empty() ? 0.0 : r.checks.back().residuals.energy_ratio());
    for (const auto& c : r.checks) {
      s.check_point.push_back(static_cast<std::int64_t>(k));
      s.check_time.push_back(c.time);
      s.check_force_ratio.push_back(c.residuals.force_ratio());
      s.check_energy_ratio.push_back(c.residuals.energy_ratio());
    }
  }
  return s;
}

}  // namespace

void write_sweep_results_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                              const std::string& packings, std::uint64_t seed, double seconds) {
  SweepResults s = columns(points);
  s.provenance = prov;
  s.packings = packings;
  s.seed = seed;
  s.total_seconds = seconds;
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  each_column(s, [&](const Column& c, const auto& column) { put(f, c.name, column); });
  // The attributes in the order of the first files: the units N, then m, then descriptions.
  for (const std::string unit : {"N", "m"})
    each_column(s, [&](const Column& c, const auto&) {
      if (c.unit == unit) f.set_attribute(c.name, "unit", unit);
    });
  each_column(s, [&](const Column& c, const auto&) {
    if (c.description) f.set_attribute(c.name, "description", std::string(c.description));
  });
  each_provenance(s, writer(f));
  out.commit();
}

SweepResults read_sweep_results_file(const std::string& path, const std::string& stage, const std::string& scene) {
  const h5::File f = h5::File::open(path);
  expect_layout(f, "sweep results", kLayout);
  SweepResults s;
  s.path = path;
  each_provenance(s, reader(f));
  if (!stage.empty() && s.provenance.stage != stage)
    throw InputError(
        fmt::format("{}: /{}: these are {} results, {} ones are expected here", path, kStage, s.provenance.stage, stage));
  if (!scene.empty() && s.provenance.scene != scene)
    throw InputError(
        fmt::format("{}: /{}: these are results of the {} scene, not of {}", path, kScene, s.provenance.scene, scene));
  each_column(s, [&](const Column& c, auto& column) {
    get(f, c.name, column);
    if (c.per_check) same_length(f, c.name, column.size(), kCheckPoint, s.check_point.size());
    else same_length(f, c.name, column.size(), kDeltaN, s.delta_n.size());
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(column)>, std::vector<double>>)
      if (c.finite) check_finite(f, c.name, column);
  });
  if (s.delta_n.empty()) throw InputError(fmt::format("{}: /{}: the sweep holds no points", path, kDeltaN));
  return s;
}

std::string describe_sweep_results_file(const h5::File& f) {
  if (!has_layout(f, kLayout)) return "";
  const std::string stage = f.read_string(kStage);
  return "a " + stage + " sweep results file (softpack-" + stage + ")";
}

}  // namespace softpack
