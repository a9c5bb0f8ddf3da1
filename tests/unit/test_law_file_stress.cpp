// The law file's soft-soft stress term (version 4, many_body.soft_soft.stress; formats/law_file.hpp):
// a version 4 file with it goes round exactly and reaches the engine's law; an unknown form, a
// kappa out of [0, 10] and the key in a file of an earlier version are refused naming the key;
// files of every earlier version still read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "support/temp_dir.hpp"

namespace law_file_stress {  // a name of its own: the unity build puts the unit tests in one file
namespace {

using namespace softpack;
using json = nlohmann::ordered_json;

using softpack::testing::TempDir;

const std::string kThirdVersion = std::string(SOFTPACK_SOURCE_DIR) + "/data/many-body/report/laws.json";

// The third version's law file (version 3) with the stress term.
LawFile with_stress(const std::string& form, double kappa) {
  LawFile f = read_law_file(kThirdVersion);
  f.version = kLawFileVersion;
  f.many_body->soft_stress = ManyBodyStressFit{form, {kappa, 0.07}};
  return f;
}

TEST(LawFileStress, AVersion4FileGoesRoundAndReachesTheEngine) {
  const TempDir dir("law-file-stress");
  EXPECT_EQ(kLawFileVersion, 4);
  using Form = ManyBodyLaw::SoftStress::Form;
  for (const auto& [form, engine] : {std::pair{"mean", Form::mean}, std::pair{"normal", Form::normal}, std::pair{"lateral", Form::lateral}}) {
    write_law_file(dir / "law.json", with_stress(form, 1.2345678901234567));
    const LawFile g = read_law_file(dir / "law.json");
    EXPECT_EQ(g.version, 4);
    ASSERT_TRUE(g.many_body && g.many_body->soft_stress) << form;
    EXPECT_EQ(g.many_body->soft_stress->form, form);
    EXPECT_EQ(g.many_body->soft_stress->kappa.value, 1.2345678901234567);
    EXPECT_EQ(g.many_body->soft_stress->kappa.error, 0.07);
    const SoftParticleLaws laws = soft_particle_laws(g, "law.json");
    ASSERT_TRUE(laws.many_body->soft_stress) << form;
    EXPECT_EQ(laws.many_body->soft_stress->form, engine);
    EXPECT_EQ(laws.many_body->soft_stress->kappa, 1.2345678901234567);
    std::ifstream in(dir / "law.json");
    const json j = json::parse(in);
    EXPECT_EQ(j["many_body"]["soft_soft"]["stress"]["kappa"]["unit"], "1");
    EXPECT_NE(j["models"]["many_body"].get<std::string>().find(std::string(form) + ": p_i"), std::string::npos) << j["models"]["many_body"];
  }
  // Without the key, no term (and the models' text says none).
  const LawFile third = read_law_file(kThirdVersion);
  EXPECT_FALSE(third.many_body->soft_stress);
  EXPECT_FALSE(soft_particle_laws(third, "laws.json").many_body->soft_stress);
}

TEST(LawFileStress, EveryEarlierVersionStillReads) {
  const LawFile v1 = read_law_file(SOFTPACK_SOURCE_DIR "/data/radius/report/laws.json");
  EXPECT_EQ(v1.version, 1);
  const LawFile v2 = read_law_file(SOFTPACK_SOURCE_DIR "/data/many-body/report/laws-v2.json");
  EXPECT_EQ(v2.version, 2);
  ASSERT_TRUE(v2.many_body);
  const LawFile v3 = read_law_file(kThirdVersion);
  EXPECT_EQ(v3.version, 3);
  ASSERT_TRUE(v3.many_body && v3.many_body->soft_beta);
  EXPECT_FALSE(v3.many_body->soft_stress);
}

void expect_refused(const std::string& path, const std::vector<std::string>& message) {
  try {
    read_law_file(path);
    ADD_FAILURE() << path << ": read without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    for (const std::string& part : message) EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' not in: " << msg;
  }
}

TEST(LawFileStress, MistakesAreRefusedNamingTheKey) {
  const TempDir dir("law-file-stress-mistakes");
  const std::string path = dir / "law.json";
  struct Mistake {
    const char* name;
    void (*edit)(json&);
    std::vector<std::string> message;
  };
  const std::vector<Mistake> mistakes = {
      {"UnknownForm", [](json& j) { j["many_body"]["soft_soft"]["stress"]["form"] = "deviatoric"; },
       {"many_body.soft_soft.stress.form: 'deviatoric' is not allowed", "allowed: 'mean', 'normal', 'lateral'"}},
      {"KappaAbove", [](json& j) { j["many_body"]["soft_soft"]["stress"]["kappa"]["value"] = 10.5; },
       {"many_body.soft_soft.stress.kappa.value: 10.5 is not allowed", "allowed: 0 <= kappa <= 10"}},
      {"KappaNegative", [](json& j) { j["many_body"]["soft_soft"]["stress"]["kappa"]["value"] = -0.1; },
       {"many_body.soft_soft.stress.kappa.value: -0.1 is not allowed", "allowed: 0 <= kappa <= 10"}},
      {"KappaUnit", [](json& j) { j["many_body"]["soft_soft"]["stress"]["kappa"]["unit"] = "Pa"; },
       {"many_body.soft_soft.stress.kappa.unit: 'Pa' is not allowed", "allowed: '1'"}},
      {"NoForm", [](json& j) { j["many_body"]["soft_soft"]["stress"].erase("form"); },
       {"many_body.soft_soft.stress.form: missing", "allowed: 'mean', 'normal', 'lateral'"}},
      {"UnknownKey", [](json& j) { j["many_body"]["soft_soft"]["stress"]["kapa"] = 1.0; },
       {"many_body.soft_soft.stress.kapa: unknown key", "did you mean 'kappa'?"}},
      {"InVersion3", [](json& j) { j["version"] = 3; },
       {"many_body.soft_soft.stress: not allowed in a version 3 file", "allowed: version 4 or later"}},
  };
  for (const Mistake& m : mistakes) {
    write_law_file(path, with_stress("normal", 2.0));
    std::ifstream in(path);
    json j = json::parse(in);
    in.close();
    m.edit(j);
    std::ofstream(path) << j.dump(2);
    SCOPED_TRACE(m.name);
    expect_refused(path, m.message);
  }
  // The writer refuses what it could not read back: a stress term without soft_soft.beta.
  LawFile f = with_stress("mean", 1.0);
  f.many_body->soft_beta.reset();
  EXPECT_THROW(write_law_file(path, f), InputError);
}

}  // namespace
}  // namespace law_file_stress
