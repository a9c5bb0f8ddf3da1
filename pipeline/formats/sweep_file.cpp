#include "formats/sweep_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "formats/file_kind.hpp"
#include "formats/h5_fields.hpp"
#include "formats/state_fields.hpp"

namespace softpack {
namespace {

using namespace formats;

// Both files: f(dataset, member) for each field of their PointProvenance.
constexpr const char *kPointStage = "provenance/stage", *kPointScene = "provenance/scene";
template <class P, class F>
void each_provenance_field(P& p, F&& f) {
  f(kPointStage, p.stage);
  f(kPointScene, p.scene);
  f("provenance/config", p.config);
  f("provenance/code_version", p.code_version);
}
// Since stamps (issue 28) and threads (issue 32): written always, read when there.
constexpr const char *kPackingSha256 = "provenance/packing_sha256", *kThreads = "provenance/threads";

// --- The point file ---------------------------------------------------------------------------

constexpr const char* kResult = "result";
constexpr std::array kPointLayout{kResult, kPointStage};  // what makes a file a point file

// /result: f(dataset, member) for each field of the PointResult but its checks, in the file's order.
template <class R, class F>
void each_result_field(R& r, F&& f) {
  f("result/delta_n", r.delta_n);
  f("result/hn", r.hn);
  f("result/alpha_deg", r.alpha_deg);
  f("result/ht", r.ht);
  f("result/force", r.force);
  f("result/force_first", r.force_first);
  f("result/force_between", r.force_between);
  f("result/contacts", r.contacts);
  f("result/overlap_max", r.overlap_max);
  f("result/overlap_q99", r.overlap_q99);
  f("result/relax_steps", r.relax_steps);
  f("result/relax_time", r.relax_time);
  f("result/steps", r.steps);
}

// /result/timing, written last (the output phase is the writing of the file up to them):
// f(dataset, member) for the wall-clock and CPU time of each phase.
template <class R, class F>
void each_timing_field(R& r, F&& f) {
  const auto phase = [&](const char* name, auto& e) {
    f(fmt::format("result/timing/{}/wall", name), e.wall);
    f(fmt::format("result/timing/{}/cpu", name), e.cpu);
  };
  phase("loading", r.timing.loading);
  phase("relaxation", r.timing.relaxation);
  phase("output", r.timing.output);
}

// /result/checks: one value per relaxation check. force_ratio and energy_ratio are written for
// the file's readers; the resume reads the residuals they come from.
const std::string kChecks = "result/checks/";
constexpr std::pair<const char*, double Measurement::*> kResiduals[] = {
    {"kinetic_energy", &Measurement::kinetic_energy},
    {"elastic_energy", &Measurement::elastic_energy},
    {"max_unbalanced_force", &Measurement::max_unbalanced_force},
    {"mean_contact_force", &Measurement::mean_contact_force}};


void write_checks(h5::File& f, const std::vector<RelaxationCheck>& checks) {
  std::vector<double> t, fr, er, contacts;
  std::vector<std::vector<double>> residuals(std::size(kResiduals));
  for (const auto& c : checks) {
    t.push_back(c.time), fr.push_back(c.residuals.force_ratio()), er.push_back(c.residuals.energy_ratio());
    for (std::size_t k = 0; k < residuals.size(); ++k) residuals[k].push_back(c.residuals.*kResiduals[k].second);
    contacts.push_back(static_cast<double>(c.residuals.contacts));
  }
  f.write(kChecks + "time", t);
  f.write(kChecks + "force_ratio", fr);
  f.write(kChecks + "energy_ratio", er);
  for (std::size_t k = 0; k < residuals.size(); ++k) f.write(kChecks + kResiduals[k].first, residuals[k]);
  f.write(kChecks + "contacts", contacts);
}

std::vector<RelaxationCheck> read_checks(const h5::File& f) {
  const auto t = f.read_doubles(kChecks + "time");
  std::vector<RelaxationCheck> checks(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) checks[k].time = t[k];
  for (const auto& [name, member] : kResiduals) {
    const auto v = f.read_doubles(kChecks + name);
    same_length(f, kChecks + name, v.size(), kChecks + "time", t.size());
    for (std::size_t k = 0; k < t.size(); ++k) checks[k].residuals.*member = v[k];
  }
  const auto nc = f.read_doubles(kChecks + "contacts");
  same_length(f, kChecks + "contacts", nc.size(), kChecks + "time", t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!(nc[k] >= 0.0 && nc[k] <= 9007199254740992.0 && nc[k] == std::floor(nc[k])))
      throw InputError(fmt::format("{}: /{}contacts: value {} = {} is not allowed; allowed: a count of contacts", f.path(),
                                   kChecks, k, nc[k]));
    checks[k].residuals.contacts = static_cast<std::size_t>(nc[k]);
  }
  return checks;
}


// --- The results file -------------------------------------------------------------------------

constexpr const char *kDeltaN = "delta_n", *kFn = "Fn", *kCheckPoint = "relaxation/checks/point";
constexpr std::array kResultsLayout{kDeltaN, kFn, kPointStage};  // what makes a file a results file

// The phases of a point's time (PointTiming), as columns timing/<phase>/{wall, cpu} [s].
constexpr std::array<const char*, 3> kPhases{"loading", "relaxation", "output"};
constexpr std::array<const char*, 3> kPhaseWall{"timing/loading/wall", "timing/relaxation/wall", "timing/output/wall"};
constexpr std::array<const char*, 3> kPhaseCpu{"timing/loading/cpu", "timing/relaxation/cpu", "timing/output/cpu"};
constexpr std::array<const char*, 3> kPhaseDescription{
    "moving the second body (normal) or turning the first soft-particle (tangential), with the restore of its start state",
    "the relaxation protocol", "writing the point file"};
constexpr const char *kReused = "timing/reused", *kCpuSeconds = "provenance/cpu_seconds", *kOverlap = "overlap_max";
Elapsed PointTiming::*const kPhaseMember[] = {&PointTiming::loading, &PointTiming::relaxation, &PointTiming::output};

// The first release whose results files have a column.
enum class Since { always, release_0_4, release_0_5 };

struct Column {
  const char* name;
  const char* unit = "";              ///< attribute "unit"
  const char* description = nullptr;  ///< attribute "description"
  bool per_check = false;             ///< one value per relaxation check (else per point)
  bool finite = true;                 ///< numbers: the reader refuses NaN and infinities
  Since since = Since::always;        ///< absent from the files of older releases (read as empty)
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
  f({.name = kOverlap,
     .description = "largest overlap at the end of the point over the smaller radius of its contact (a sphere's own "
                    "radius against a wall); the Hertz law holds for overlaps << 1",
     .since = Since::release_0_5},
    s.overlap_max);
  f({.name = "overlap_q99",
     .description = "99th percentile of the closed contacts' overlaps over the smaller radius at the end of the point",
     .since = Since::release_0_5},
    s.overlap_q99);
  f({"steps"}, s.steps);
  f({"relaxation/steps"}, s.relax_steps);
  f({"relaxation/time"}, s.relax_time);
  f({.name = "relaxation/final_force_ratio", .finite = false}, s.final_force_ratio);
  f({.name = "relaxation/final_energy_ratio", .finite = false}, s.final_energy_ratio);
  f({.name = kCheckPoint, .per_check = true}, s.check_point);
  f({.name = "relaxation/checks/time", .per_check = true}, s.check_time);
  f({.name = "relaxation/checks/force_ratio", .per_check = true, .finite = false}, s.check_force_ratio);
  f({.name = "relaxation/checks/energy_ratio", .per_check = true, .finite = false}, s.check_energy_ratio);
  f({.name = "seconds", .description = "wall-clock time of each point's loading and relaxation"}, s.seconds);
  for (std::size_t k = 0; k < kPhases.size(); ++k) {
    f({.name = kPhaseWall[k], .unit = "s", .description = kPhaseDescription[k], .since = Since::release_0_4}, s.phase_wall[k]);
    f({.name = kPhaseCpu[k], .unit = "s", .description = kPhaseDescription[k], .since = Since::release_0_4}, s.phase_cpu[k]);
  }
  f({.name = kReused,
     .description = "1: this run took the point from its checkpoint, its timing is that of the run that computed it",
     .since = Since::release_0_4},
    s.reused);
}

// f(dataset, member) for each provenance field of `s`.
template <class S, class F>
void each_sweep_provenance(S& s, F&& f) {
  each_provenance_field(s.provenance, f);
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
    s.overlap_max.push_back(r.overlap_max), s.overlap_q99.push_back(r.overlap_q99);
    s.relax_time.push_back(r.relax_time), s.seconds.push_back(r.seconds());
    for (std::size_t p = 0; p < kPhases.size(); ++p) {
      s.phase_wall[p].push_back((r.timing.*kPhaseMember[p]).wall);
      s.phase_cpu[p].push_back((r.timing.*kPhaseMember[p]).cpu);
    }
    s.reused.push_back(r.reused ? 1 : 0);
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

void write_point_file(const std::string& path, PointResult& r, const SimulationState& s, const PointProvenance& prov) {
  Stopwatch watch;
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  each_result_field(r, writer(f));
  write_checks(f, r.checks);
  write_state(f, s);
  each_provenance_field(prov, writer(f));
  put(f, kProvenanceStamp, prov.stamp);
  put(f, kThreads, prov.threads);
  r.timing.output = watch.elapsed();
  each_timing_field(r, writer(f));
  out.commit();
}

PointFile read_point_file(const std::string& path, bool with_state) {
  const h5::File f = h5::File::open(path);
  expect_layout(f, "sweep point", kPointLayout);
  PointFile p;
  each_provenance_field(p.provenance, reader(f));
  if (f.exists(kProvenanceStamp)) get(f, kProvenanceStamp, p.provenance.stamp);
  if (f.exists(kThreads)) get(f, kThreads, p.provenance.threads);
  if (p.provenance.stage != "normal" && p.provenance.stage != "tangential" && p.provenance.stage != "sliding")
    throw InputError(
        fmt::format("{}: /{}: '{}' is not allowed; allowed: normal, tangential, sliding", path, kPointStage, p.provenance.stage));
  each_result_field(p.result, reader(f));
  each_timing_field(p.result, reader(f));
  p.result.checks = read_checks(f);
  if (with_state) p.state = read_state(f);
  return p;
}

std::string describe_point_file(const h5::File& f) {
  return has_layout(f, kPointLayout) ? "a sweep point file (a checkpoint of softpack-" + f.read_string(kPointStage) + ")" : "";
}

void write_sweep_results_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                              const std::string& packings, const std::string& packing_sha256, std::uint64_t seed,
                              const Elapsed& stage_time) {
  SweepResults s = columns(points);
  s.provenance = prov;
  s.packings = packings;
  s.packing_sha256 = packing_sha256;
  s.seed = seed;
  s.total_seconds = stage_time.wall;
  s.total_cpu_seconds = stage_time.cpu;
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  each_column(s, [&](const Column& c, const auto& column) { put(f, c.name, column); });
  // The attributes: the units N, then m, then s, then the descriptions.
  for (const std::string unit : {"N", "m", "s"})
    each_column(s, [&](const Column& c, const auto&) {
      if (c.unit == unit) f.set_attribute(c.name, "unit", unit);
    });
  each_column(s, [&](const Column& c, const auto&) {
    if (c.description) f.set_attribute(c.name, "description", std::string(c.description));
  });
  each_sweep_provenance(s, writer(f));
  put(f, kCpuSeconds, s.total_cpu_seconds);
  put(f, kProvenanceStamp, s.provenance.stamp);
  put(f, kPackingSha256, s.packing_sha256);
  put(f, kThreads, s.provenance.threads);
  out.commit();
}

SweepResults read_sweep_results_file(const std::string& path, const std::string& stage, const std::string& scene) {
  const h5::File f = h5::File::open(path);
  expect_layout(f, "sweep results", kResultsLayout);
  SweepResults s;
  s.path = path;
  each_sweep_provenance(s, reader(f));
  if (f.exists(kProvenanceStamp)) get(f, kProvenanceStamp, s.provenance.stamp);
  if (f.exists(kThreads)) get(f, kThreads, s.provenance.threads);
  if (f.exists(kPackingSha256)) get(f, kPackingSha256, s.packing_sha256);
  // The timings (release 0.4.0 on): all of them or none.
  s.has_timing = f.exists(kReused);
  if (s.has_timing) get(f, kCpuSeconds, s.total_cpu_seconds);
  s.has_overlap = f.exists(kOverlap);  // release 0.5.0 on
  if (!stage.empty() && s.provenance.stage != stage)
    throw InputError(
        fmt::format("{}: /{}: these are {} results, {} ones are expected here", path, kPointStage, s.provenance.stage, stage));
  if (!scene.empty() && s.provenance.scene != scene)
    throw InputError(
        fmt::format("{}: /{}: these are results of the {} scene, not of {}", path, kPointScene, s.provenance.scene, scene));
  each_column(s, [&](const Column& c, auto& column) {
    if (c.since == Since::release_0_4 && !s.has_timing) return;
    if (c.since == Since::release_0_5 && !s.has_overlap) return;
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
  if (!has_layout(f, kResultsLayout)) return "";
  const std::string stage = f.read_string(kPointStage);
  return "a " + stage + " sweep results file (softpack-" + stage + ")";
}

}  // namespace softpack
