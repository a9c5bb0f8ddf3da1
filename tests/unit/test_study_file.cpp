// The study files (experiments/studies/, docs/studies.md): every one loads, names a registered
// report kind and is its file's name (its make goal); the plan's defaults; what is refused.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "report/study_file.hpp"
#include "report/report_kinds.hpp"

namespace softpack {
namespace {

namespace fs = std::filesystem;

// Study files name their base profile and figures from the project's folder, as make runs them.
class StudyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    before_ = fs::current_path();
    fs::current_path(SOFTPACK_SOURCE_DIR);
    dir_ = fs::temp_directory_path() / ("softpack-study-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::current_path(before_);
    fs::remove_all(dir_);
  }
  // A study file named `name`.yaml with `plan` lines before a minimal body; InputError's message or "".
  std::string refusal(const std::string& name, const std::string& plan) const {
    const std::string path = (dir_ / (name + ".yaml")).string();
    std::ofstream(path) << plan
                        << "base: experiments/quick.yaml\nseeds: [101]\ncompare: {Fn_delta_n: [0.5], kt_delta_n: [0.6]}\n"
                           "reference: {seeds: [101]}\nsettings:\n  base: {}\n";
    try {
      read_study(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path before_, dir_;
};

TEST_F(StudyFile, EveryStudyOfTheProjectLoadsWithARegisteredKind) {
  int studies = 0;
  for (const auto& f : fs::directory_iterator("experiments/studies")) {
    SCOPED_TRACE(f.path().string());
    const Study s = read_study(f.path().string());
    EXPECT_EQ(s.name, f.path().stem().string());
    EXPECT_NO_THROW(report_kind(s.report));
    EXPECT_FALSE(s.stages.empty());
    for (const StudyFigure& fig : s.figures) EXPECT_TRUE(fs::is_regular_file(fig.script)) << fig.script;
    ++studies;
  }
  EXPECT_GE(studies, 5);
}

TEST_F(StudyFile, ThePlanHasDefaults) {
  ASSERT_EQ(refusal("plain", "study: plain\nreport: accuracy\n"), "");
  const Study s = read_study((dir_ / "plain.yaml").string());
  EXPECT_EQ(s.out, "studies/plain");
  EXPECT_EQ(s.stages, std::vector<std::string>{"tangential"});
  EXPECT_TRUE(s.figures.empty());
}

TEST_F(StudyFile, AMistakeInThePlanIsRefusedNamingTheKey) {
  EXPECT_NE(refusal("one", "study: other\nreport: accuracy\n").find("the study's name is its file's (one.yaml"), std::string::npos);
  EXPECT_NE(refusal("one", "study: one\nreport: sizes\n").find("report"), std::string::npos);
  EXPECT_NE(refusal("one", "study: one\nreport: accuracy\nstages: [tables]\n").find("stages"), std::string::npos);
  EXPECT_NE(refusal("one", "study: one\nreport: accuracy\nout: ../elsewhere\n").find("a folder under DATA"), std::string::npos);
  EXPECT_NE(refusal("one", "study: one\nreport: accuracy\nfigures: [{script: figures/none.gp, data: a.dat, name: a}]\n")
                .find("figures/none.gp: no such gnuplot script"),
            std::string::npos);
  EXPECT_THROW(report_kind("sizes"), InputError);
}

// The response kind (report/response_report.hpp) reads the value of the one key its settings set
// from each setting's profile, orders them by it and lists what has not run; two keys are refused.
TEST_F(StudyFile, AResponseStudyVariesOneKeyAndListsItsSettingsByItsValue) {
  const std::string body =
      "study: speeds\nreport: response\nstages: [normal]\nbase: experiments/quick.yaml\nseeds: [101, 102]\n"
      "compare: {Fn_delta_n: [0.5]}\nreference: {set: {normal.speed: 0.01}}\n";
  const std::string path = (dir_ / "speeds.yaml").string();
  std::ofstream(path) << body << "settings:\n  fast: {set: {normal.speed: 0.04}}\n  slow: {set: {normal.speed: 0.0025}}\n";
  const std::string table = report_kind("response").write(read_study(path), (dir_ / "runs").string(), dir_.string(), "T");
  const auto slow = table.find("| slow (not run in full) | 0.0025 |"), reference = table.find("| reference (not run in full) | 0.01 |"),
             fast = table.find("| fast (not run in full) | 0.04 |");
  ASSERT_NE(slow, std::string::npos) << table;
  ASSERT_NE(reference, std::string::npos) << table;
  ASSERT_NE(fast, std::string::npos) << table;
  EXPECT_LT(slow, reference);
  EXPECT_LT(reference, fast);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "response.dat"));

  std::ofstream(path) << body << "settings:\n  stiff: {set: {material.E: 1.0e6}}\n";
  try {
    report_kind("response").write(read_study(path), (dir_ / "runs").string(), dir_.string(), "T");
    ADD_FAILURE() << "a response study of two keys was not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("varies one key of the profile; its settings set 2 (material.E, normal.speed)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace softpack
