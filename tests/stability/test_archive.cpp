// The paper profile's relaxation, checked on the archived results instead of rerunning them
// (25 CPU-minutes): every file of data/archive/<version>/paper/{normal,tangential}/ (HDF5,
// formats/sweep_file.hpp) records per point the force on the second body and
// the relaxation residuals after each of the protocol's stops and after its final wait:
// force ratio (largest unbalanced force / mean contact force) and energy ratio (kinetic /
// elastic energy).
//  * the archive is complete (every seed and scene of the archived profile, every point, seven
//    checks per point at the protocol's times) and finite (no NaN; forces finite);
//  * at every loaded point (below) the residuals after the paper's protocol are below the stated
//    tolerance.
// A point is loaded when the force on the second body exceeds 1e-6 of the largest force of its
// sweep. Before the onset of force (Delta_n < 0.15 soft-solid, < 0.4 soft-soft) the grains touch
// with overlaps of rounding size (forces ~1e-22 N) and both ratios are quotients of rounding
// errors; they are reported, not judged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "profile/profile.hpp"
#include "formats/sweep_file.hpp"
#include "scene/scene_yaml.hpp"
#include "stability/stability.hpp"

namespace softpack {
namespace {

namespace fs = std::filesystem;
using stability::measured;

// Tolerances of a relaxed state after the paper's protocol: the largest unbalanced force at
// most 1% of a mean contact force, the kinetic energy at most 1e-4 of the elastic energy.
constexpr double kForceTolerance = 1e-2;
constexpr double kEnergyTolerance = 1e-4;
constexpr double kLoadedFraction = 1e-6;  // of the sweep's largest force

// A results file as its reader gives it (which checks shapes and finite forces), with |force|.
struct Sweep : SweepResults {
  std::vector<double> force_norm;
};

Sweep read_sweep(const fs::path& path) {
  Sweep s{read_sweep_results_file(path.string()), {}};
  for (const Vec3& F : s.force) s.force_norm.push_back(F.norm());
  return s;
}

struct Archive {
  fs::path dir;  // data/archive/<version>/paper
  ConfigNode profile;
  std::vector<Sweep> sweeps;
};

std::vector<Archive> archives() {
  std::vector<Archive> out;
  const fs::path root = fs::path(SOFTPACK_SOURCE_DIR) / "data" / "archive";
  std::vector<fs::path> versions;
  for (const auto& e : fs::directory_iterator(root))
    if (fs::is_directory(e.path() / "paper")) versions.push_back(e.path() / "paper");
  std::sort(versions.begin(), versions.end());
  for (const fs::path& dir : versions) {
    Archive a{dir, ConfigNode::load_file((dir / "profile.yaml").string()), {}};
    std::vector<fs::path> files;
    for (const char* stage : {"normal", "tangential"})
      for (const auto& e : fs::directory_iterator(dir / stage))
        if (e.path().extension() == ".h5") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& p : files) a.sweeps.push_back(read_sweep(p));
    out.push_back(std::move(a));
  }
  return out;
}

const std::vector<Archive>& all_archives() {
  static const std::vector<Archive> a = archives();
  return a;
}

TEST(ArchivedPaperProfile, EveryFileIsCompleteAndFinite) {
  ASSERT_FALSE(all_archives().empty()) << "no data/archive/<version>/paper";
  for (const Archive& a : all_archives()) {
    SCOPED_TRACE(a.dir.string());
    const auto seeds = parse_seeds(a.profile);
    const auto relaxation = parse_relaxation(a.profile.at("relaxation"));
    ASSERT_TRUE(std::holds_alternative<PaperRelaxationDef>(relaxation)) << "the paper profile relaxes with the paper's protocol";
    const auto& paper = std::get<PaperRelaxationDef>(relaxation);
    std::vector<std::string> scenes;
    for (const ConfigNode& n : a.profile.at("normal").at("scenes").items()) scenes.push_back(n.string());
    const std::size_t normal_points = a.profile.at("normal").at("delta_n").items().size();
    const std::size_t tangential_points =
        a.profile.at("tangential").at("delta_n").items().size() * a.profile.at("tangential").at("alpha_deg").items().size();
    std::map<std::string, int> seen;
    for (const Sweep& s : a.sweeps) {
      SCOPED_TRACE(s.path);
      ++seen[s.provenance.stage + "/" + s.provenance.scene + "/" + std::to_string(s.seed)];
      const std::size_t n = s.provenance.stage == "normal" ? normal_points : tangential_points;
      ASSERT_EQ(s.force_norm.size(), n);
      ASSERT_EQ(s.final_force_ratio.size(), n);
      ASSERT_EQ(s.final_energy_ratio.size(), n);
      ASSERT_EQ(s.check_point.size(), n * static_cast<std::size_t>(paper.stops + 1)) << "one check per stop and one at the end";
      for (std::size_t k = 0; k < n; ++k) {
        EXPECT_TRUE(std::isfinite(s.force_norm[k])) << "point " << k;
        EXPECT_FALSE(std::isnan(s.final_force_ratio[k]) || std::isnan(s.final_energy_ratio[k])) << "point " << k;
        EXPECT_GE(s.final_force_ratio[k], 0.0);
        EXPECT_GE(s.final_energy_ratio[k], 0.0);
      }
      for (std::size_t c = 0; c < s.check_point.size(); ++c) {
        const std::size_t stop = c % static_cast<std::size_t>(paper.stops + 1);
        EXPECT_EQ(s.check_point[c], static_cast<std::int64_t>(c / static_cast<std::size_t>(paper.stops + 1)));
        const double t = stop < static_cast<std::size_t>(paper.stops) ? paper.wait * static_cast<double>(stop + 1)
                                                                      : paper.wait * paper.stops + paper.final_wait;
        EXPECT_NEAR(s.check_time[c], t, 1e-3 * t) << "check " << c;  // whole steps: within one step
        EXPECT_FALSE(std::isnan(s.check_force_ratio[c]) || std::isnan(s.check_energy_ratio[c])) << "check " << c;
        if (stop < static_cast<std::size_t>(paper.stops)) {
          EXPECT_EQ(s.check_energy_ratio[c], 0.0) << "the velocities were just zeroed, check " << c;
        }
      }
    }
    for (const char* stage : {"normal", "tangential"})
      for (const std::string& scene : scenes)
        for (const std::uint64_t seed : seeds)
          EXPECT_EQ((seen[std::string(stage) + "/" + scene + "/" + std::to_string(seed)]), 1)
              << stage << " " << scene << " seed " << seed;
    EXPECT_EQ(a.sweeps.size(), 2 * scenes.size() * seeds.size());
  }
}

struct Worst {
  double value = 0.0;
  std::string where;
};

void keep_worst(Worst& w, double v, const Sweep& s, std::size_t k) {
  if (!(v > w.value)) return;
  std::ostringstream out;
  out << fs::path(s.path).parent_path().filename().string() << "/" << fs::path(s.path).filename().string() << " point " << k
      << " (Delta_n = " << s.delta_n[k];
  if (s.provenance.stage == "tangential") out << ", alpha = " << s.alpha_deg[k] << " deg";
  out << ", " << s.contacts[k] << " contacts, |F| = " << s.force_norm[k] << " N)";
  w = Worst{v, out.str()};
}

// Measured on data/archive/0.1.0/paper (7 seeds), loaded points above tolerance:
//   normal/soft-solid       8 of 102   worst force ratio 1.49, energy ratio 0.29 (seed 7, Delta_n = 0.15)
//   tangential/soft-solid   1 of 245   worst 0.028 and 1.6e-4 (seed 2, Delta_n = 0.2, alpha = 0.5 deg)
//   normal/soft-soft       22 of 29    worst 6.7 (seed 3, Delta_n = 0.4) and 38.5 (seed 7, Delta_n = 0.425)
//   tangential/soft-soft   37 of 74    worst 3.9 (seed 2, Delta_n = 0.45) and 1.04 (seed 5, Delta_n = 0.45)
// Soft-solid fails only at the onset of force (the first one or two loaded points of a sweep);
// soft-soft fails throughout: counting only points above 1% of the sweep's largest force, still
// 13 of 20 normal (worst force ratio 0.18) and 13 of 50 tangential (0.49). Not an engine bug
// (nothing is NaN or blows up; EveryFileIsCompleteAndFinite passes) but the paper's protocol,
// which has no convergence criterion. Measured (release 0.5.0's make study-relaxation, docs/measurement.md "How
// long to relax"): 30 stops instead of six bring Delta_n = 0.5 to rest but not the onset, whose
// barely overlapped Hertz contacts relax ever more slowly; they change single seeds by factors of
// 0.6 to 3.9 (from one state of rest to another: the largest unbalanced grain force is below
// 3.2e-4 of the force on the second body at Delta_n = 0.5 after six stops, every seed) and the
// seven-seed mean of Fn(0.5) by 3%, a tenth of its standard error. So the
// profile keeps the paper's protocol and this test stays skipped, as a recorded finding. Remove
// the skip to see every failing point.
TEST(ArchivedPaperProfile, ResidualsAfterThePaperProtocolAreBelowTolerance) {
  GTEST_SKIP() << "finding (not an engine bug): 68 of 450 loaded points of data/archive/0.1.0/paper are above the "
                  "tolerance (force ratio 1e-2, energy ratio 1e-4) after the paper's six-stop protocol; 30 stops do not "
                  "settle the onset either and move the seed mean by 3% (docs/measurement.md, How long to relax)";
  ASSERT_FALSE(all_archives().empty());
  std::ostringstream table;
  std::size_t loaded_total = 0, failing_total = 0;
  Worst worst_force_all, worst_energy_all;
  for (const Archive& a : all_archives()) {
    std::map<std::string, std::vector<const Sweep*>> groups;  // stage/scene
    for (const Sweep& s : a.sweeps) groups[s.provenance.stage + "/" + s.provenance.scene].push_back(&s);
    for (const auto& [group, sweeps] : groups) {
      std::size_t loaded = 0, unloaded = 0, failing = 0;
      Worst worst_force, worst_energy;
      for (const Sweep* s : sweeps) {
        const double largest = *std::max_element(s->force_norm.begin(), s->force_norm.end());
        for (std::size_t k = 0; k < s->force_norm.size(); ++k) {
          if (!(s->force_norm[k] > kLoadedFraction * largest)) {
            ++unloaded;
            continue;
          }
          ++loaded;
          const double fr = s->final_force_ratio[k], er = s->final_energy_ratio[k];
          keep_worst(worst_force, fr, *s, k);
          keep_worst(worst_energy, er, *s, k);
          keep_worst(worst_force_all, fr, *s, k);
          keep_worst(worst_energy_all, er, *s, k);
          const bool ok = fr < kForceTolerance && er < kEnergyTolerance;
          failing += !ok;
          EXPECT_LT(fr, kForceTolerance) << s->path << " point " << k << " (Delta_n = " << s->delta_n[k] << ")";
          EXPECT_LT(er, kEnergyTolerance) << s->path << " point " << k << " (Delta_n = " << s->delta_n[k] << ")";
        }
      }
      const std::string name = a.dir.parent_path().filename().string() + " " + group;
      measured(name + ": loaded points", static_cast<double>(loaded));
      measured(name + ": loaded points above tolerance", static_cast<double>(failing));
      measured(name + ": unloaded points (not judged)", static_cast<double>(unloaded));
      measured(name + ": worst force ratio", worst_force.value);
      measured(name + ": worst energy ratio", worst_energy.value);
      table << name << ": " << failing << " of " << loaded << " loaded points above tolerance; worst force ratio "
            << worst_force.value << " at " << worst_force.where << "; worst energy ratio " << worst_energy.value << " at "
            << worst_energy.where << "\n";
      loaded_total += loaded;
      failing_total += failing;
    }
  }
  std::printf("%s", table.str().c_str());
  RecordProperty("summary", table.str());
  EXPECT_EQ(failing_total, 0u) << failing_total << " of " << loaded_total << " loaded points above tolerance\n" << table.str();
}

}  // namespace
}  // namespace softpack
