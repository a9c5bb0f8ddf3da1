// report/stage_timing: the time a profile's outputs record, gathered per stage and phase.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "core/error.hpp"
#include "formats/sweep_file.hpp"
#include "report/stage_timing.hpp"

namespace softpack {
namespace {

namespace fs = std::filesystem;

PointResult point(double delta_n, Elapsed loading, Elapsed relaxation, Elapsed output, bool reused) {
  PointResult r;
  r.delta_n = delta_n;
  r.timing = {loading, relaxation, output};
  r.reused = reused;
  return r;
}

TEST(StageTiming, SweepsCostTheSumOfTheirPointsPhasesAndMissingFilesAreListed) {
  const fs::path dir = fs::temp_directory_path() / ("softpack-timing-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string a = (dir / "soft-solid-seed-1.h5").string(), b = (dir / "soft-solid-seed-2.h5").string();
  write_sweep_results_file(a,
                           {point(0.0, {1, 0.5}, {2, 1.5}, {0.25, 0.125}, false), point(0.1, {1, 1}, {4, 3}, {0.5, 0.25}, true)},
                           PointProvenance{"normal", "soft-solid", "cfg", "test", "0123456789abcdef"}, "p", "", 1,
                           Elapsed{10, 2.5});
  TimingInputs in;
  in.normal = {a, b};  // b is not there
  const ProfileTiming t = collect_timing(in);
  ASSERT_EQ(t.stages.size(), 1u);
  const StageTiming& s = t.stages[0];
  EXPECT_EQ(s.stage, "normal");
  EXPECT_EQ(s.scene, "soft-solid");
  EXPECT_EQ(s.files, 1u);
  EXPECT_EQ(s.points, 2u);
  EXPECT_EQ(s.reused, 1u);
  EXPECT_DOUBLE_EQ(s.phases.loading.cpu, 1.5);
  EXPECT_DOUBLE_EQ(s.phases.relaxation.cpu, 4.5);
  EXPECT_DOUBLE_EQ(s.phases.output.cpu, 0.375);
  EXPECT_DOUBLE_EQ(s.cost.cpu, 6.375);
  EXPECT_DOUBLE_EQ(s.cost.wall, 8.75);
  EXPECT_DOUBLE_EQ(s.process.cpu, 2.5);  // the process of the last run, beside the cost
  EXPECT_DOUBLE_EQ(t.total().cpu, 6.375);
  ASSERT_EQ(s.missing.size(), 1u);
  EXPECT_EQ(s.missing[0], b);
  EXPECT_FALSE(t.complete());
  EXPECT_NE(timing_table(t, "T").find("Missing (not run yet)"), std::string::npos);
  // A file of another stage is refused with its name, not counted.
  in.normal.clear();
  in.tangential = {a};
  EXPECT_THROW(collect_timing(in), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace softpack
