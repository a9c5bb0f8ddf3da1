// The study files (experiments/studies/, docs/studies.md): every one loads, names a registered
// report kind and is its file's name (its make goal); the plan's defaults; what is refused.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "formats/packing_file.hpp"
#include "packing/packing_profile.hpp"
#include "report/study_file.hpp"
#include "report/report_kinds.hpp"
#include "report/study_runs.hpp"

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

// A base whose one key is coarse_grain is the coarse-grain settings' (report/study_base.hpp): a
// setting's seeds go into its section, ~ removes a key, and the reports say so.
TEST_F(StudyFile, ACoarseGrainBaseKeepsItsSeedsInItsSectionAndRemovesKeysWithNull) {
  const std::string path = (dir_ / "cg.yaml").string();
  std::ofstream(path) << "study: cg\nreport: coarse\nbase: tests/data/coarse-grain-tiny.yaml\nseeds: [901, 902]\n"
                         "settings:\n  still: {set: {coarse_grain.compression.shear: ~, coarse_grain.compression.record_shear: ~}, seeds: [902]}\n";
  const Study st = read_study(path);
  EXPECT_EQ(st.base_kind, StudyBase::coarse_grain);
  EXPECT_EQ(st.stages, std::vector<std::string>{"coarse-grain-runs"});
  const ConfigNode file = ConfigNode::load_string(setting_profile_text(st, st.setting("still")), "still");
  file.allow_only({"coarse_grain"});  // no profile name or description
  EXPECT_EQ(file.at("coarse_grain").at("seeds").items().size(), 1u);
  EXPECT_FALSE(file.at("coarse_grain").at("compression").has("shear"));
  EXPECT_TRUE(file.at("coarse_grain").at("compression").has("speed"));
  EXPECT_EQ(setting_changes(st, st.setting("still")),
            "coarse_grain.compression.shear removed, coarse_grain.compression.record_shear removed");
}

// A setting whose run failed is reported with the first line of its failed.txt (workflow/studies.mk).
TEST_F(StudyFile, AFailedSettingIsReadFromItsFailedFile) {
  fs::create_directories(dir_ / "a");
  fs::create_directories(dir_ / "b");
  std::ofstream(dir_ / "a" / "failed.txt") << "numerical error: the time step\nmore\n";
  std::ofstream(dir_ / "b" / "failed.txt");
  EXPECT_EQ(setting_failure(dir_.string(), "a"), "numerical error: the time step");
  EXPECT_EQ(setting_failure(dir_.string(), "b"), "its run failed (no message)");
  EXPECT_EQ(setting_failure(dir_.string(), "c"), std::nullopt);
}

TEST_F(StudyFile, AMistakeInThePlanIsRefusedNamingTheKey) {
  EXPECT_NE(refusal("one", "study: other\nreport: accuracy\n").find("the study's name is its file's (one.yaml"), std::string::npos);
  // nested.mu_seeds_loaded: 1 to the study's seeds.
  EXPECT_NE(refusal("one", "study: one\nreport: nested\ncriteria: experiments/nested.yaml\nnested: {against: reference, mu_from_ht_over_Rs: 0.2, mu_seeds_loaded: 2}\n")
                .find("allowed: 1 to 1"),
            std::string::npos);
  EXPECT_NE(refusal("one", "study: one\nreport: nested\ncriteria: experiments/nested.yaml\nnested: {against: reference, mu_from_ht_over_Rs: 0.2, mu_seeds_loaded: 0}\n")
                .find("mu_seeds_loaded"),
            std::string::npos);
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

// `vary`: a setting per value named <key>-<value>, the reference's own value the reference's results;
// `grid`: every combination, the last key fastest, its lists read from another file.
TEST_F(StudyFile, VaryAndGridGenerateTheirSettings) {
  const std::string head = "report: packings\nstages: [packings]\nbase: experiments/quick.yaml\nseeds: [101, 102]\n";
  std::ofstream((dir_ / "sizes.yaml").string()) << "study: sizes\n" << head
                                                << "vary:\n  packing.beta: [1.0, 2, 3.0]\n  packing.shell_is_neighbour: [false]\n";
  const Study v = read_study((dir_ / "sizes.yaml").string());
  ASSERT_EQ(v.vary.size(), 2u);
  EXPECT_EQ(v.vary[0].points, (std::vector<std::pair<std::string, std::string>>{{"1.0", "beta-1.0"}, {"2", "beta-2"}, {"3.0", "beta-3.0"}}));
  EXPECT_EQ(v.setting("beta-2").of, "reference");  // quick.yaml's beta is 2.0
  EXPECT_TRUE(v.setting("beta-3.0").runs());
  EXPECT_EQ(setting_number(v, v.setting("beta-3.0"), "packing.beta"), 3.0);
  EXPECT_EQ(setting_number(v, v.setting("shell-is-neighbour-false"), "packing.shell_is_neighbour"), 0.0);

  std::ofstream((dir_ / "lists.yaml").string()) << "held: [103, 104]\ngrid: {beta: [1.0, 2.0], trials: [30, 3000]}\n";
  const std::string lists = (dir_ / "lists.yaml").string();
  std::ofstream((dir_ / "rule.yaml").string())
      << "study: rule\nreport: density-rule\nstages: [packings]\nbase: experiments/quick.yaml\ncriteria: " << lists
      << "\nseeds: {file: " << lists << ", key: held}\ngrid:\n  packing.beta: {file: " << lists
      << ", key: grid.beta}\n  packing.trials: {file: " << lists << ", key: grid.trials}\n";
  const Study g = read_study((dir_ / "rule.yaml").string());
  EXPECT_EQ(g.seeds, (std::vector<std::uint64_t>{103, 104}));
  ASSERT_EQ(g.grid.size(), 2u);
  std::vector<std::string> names;
  for (const auto& [value, name] : g.grid[1].points) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"beta-1.0-trials-30", "beta-1.0-trials-3000", "beta-2.0-trials-30",
                                             "beta-2.0-trials-3000"}));
  EXPECT_EQ(g.setting("beta-2.0-trials-3000").of, "reference");
  EXPECT_EQ(g.grid[1].points[2].first, "30");
}

TEST_F(StudyFile, GeneratedSettingsAreRefusedWithTheKey) {
  const std::string head = "report: packings\nstages: [packings]\nbase: experiments/quick.yaml\nseeds: [101]\n";
  const auto refused = [&](const std::string& name, const std::string& body) {
    std::ofstream((dir_ / (name + ".yaml")).string()) << "study: " << name << "\n" << head << body;
    try {
      read_study((dir_ / (name + ".yaml")).string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused("both", "vary: {packing.beta: [1.0]}\ngrid: {packing.trials: [10]}\n").find("not both"), std::string::npos);
  EXPECT_NE(refused("none", "").find("`vary` is missing: the report kind 'packings' reads it"), std::string::npos);
  EXPECT_NE(refused("word", "vary: {packing.beta: [\"1 0\"]}\n").find("names its setting 'beta-1 0'"), std::string::npos);
  EXPECT_NE(refused("far", "vary: {packing.beta: {file: experiments/quick.yaml, key: packing.gamma}}\n").find("gamma"),
            std::string::npos);
  EXPECT_NE(refused("twice", "vary: {packing.beta: [3.0, 3.0]}\n").find("'beta-3.0' is a name already used"), std::string::npos);
  EXPECT_NE(refused("bad", "vary: {packing.beta: [-1.0]}\n").find("setting beta--1.0"), std::string::npos);
  EXPECT_NE(refused("around", "reference: {set: {packing.trials: 10}}\nvary: {packing.beta: [3.0]}\n").find("the reference sets no key"),
            std::string::npos);
}

// The density rule (report/packing_report.hpp) takes, among the settings within the criteria's
// margin of the densest mean solid fraction, the one of least mean generation time: the packings'
// times are planted, so the choice is known.
TEST_F(StudyFile, TheDensityRuleChoosesTheCheapestWithinTheMargin) {
  const std::string runs = (dir_ / "runs").string(), criteria = (dir_ / "criteria.yaml").string();
  std::ofstream(criteria) << "density: {solid_fraction_margin: 0.5}\n";
  std::ofstream((dir_ / "rule.yaml").string())
      << "study: rule\nreport: density-rule\nstages: [packings]\nbase: experiments/quick.yaml\ncriteria: " << criteria
      << "\nseeds: [101, 102]\ncommon: {packing.polydispersity: 1.5, packing.r_max_over_Rs: 0.35}\n"
         "grid: {packing.beta: [0.5, 2.0], packing.trials: [3000]}\n";
  const Study st = read_study((dir_ / "rule.yaml").string());
  // beta 0.5 is far less dense than beta 2.0 (the reference's own value); it is made the cheaper.
  for (const StudySetting* s : {&st.setting("beta-0.5-trials-3000"), &st.reference})
    for (std::uint64_t seed : st.seeds) {
      const ConfigNode profile = ConfigNode::load_string(setting_profile_text(st, *s), "profile");
      const PackingProfile pp = parse_packing(profile);
      const Packing pk = generate_packing(pp.parameters, seed);
      PackingProvenance prov;
      prov.program = "softpack-pack";
      prov.seconds = s->name == "reference" ? 10.0 : 1.0;
      fs::create_directories(runs + "/" + s->name + "/packings");
      write_packing_file(runs + "/" + s->name + "/packings/seed-" + std::to_string(seed) + ".h5", pp.parameters, pk,
                         packing_statistics(pk.centres, pk.radii, pp.parameters.Rs, pp.parameters.r_max, 10), prov);
    }
  for (const auto& [margin, chosen] : {std::pair{"0.5", "beta-0.5-trials-3000"}, std::pair{"0.001", "beta-2.0-trials-3000"}}) {
    std::ofstream(criteria) << "density: {solid_fraction_margin: " << margin << "}\n";
    const std::string table = report_kind("density-rule").write(st, runs, dir_.string(), "T");
    EXPECT_NE(table.find(std::string("(setting ") + chosen + ")"), std::string::npos) << table;
  }
}

}  // namespace
}  // namespace softpack
