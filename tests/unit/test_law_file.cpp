// The law file (formats/law_file.hpp): a full file round-trips exactly (NaN errors stay NaN,
// absent parts stay absent), the JSON has the documented layout, and every mistake of a
// hand-edited file is refused with an InputError naming the file, the field and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "formats/law_file.hpp"
#include "support/temp_dir.hpp"

namespace {

using namespace softpack;
using json = nlohmann::ordered_json;


using softpack::testing::TempDir;

// Every field set, with odd doubles (exactness), NaN errors and a null c; soft-soft without its
// optional parts.
LawFile full_file() {
  LawFile f;
  f.reference_radius = 0.016;
  SceneLaws solid;
  solid.normal = {{12.345678901234567, 0.1}, {2.5, kNaN}, {-0.0123, 1e-4}, {0.071, 0.003}, 0.05, 0.5};
  solid.tangential = LawFit{{1234.5, 10.0}, {1.7, 0.02}, {-16.1, kNaN}, {0.071, kNaN}, 0.1, 0.5};
  solid.friction = FrictionLaw{{0.3, 0.4, 0.5}, {{0.31, 0.01}, {0.29, kNaN}, {0.275, 0.02}}};
  solid.normal_scaling = RadiusScaling{{1.98, 0.05}, 0.008, 0.032, "fixed"};
  solid.tangential_scaling = RadiusScaling{{kNaN, kNaN}, 0.008, 0.064, "self-similar"};
  f.scenes["soft-solid"] = solid;
  SceneLaws soft;
  soft.normal = {{3.0, kNaN}, {1.0 / 3.0, 0.01}, {kNaN, kNaN}, {kNaN, kNaN}, 0.0, 0.45};
  f.scenes["soft-soft"] = soft;
  f.mixing = MixingRule{"reduced-radius", 0.5, {0.042, 0.011}};
  f.provenance = {"experiments/radius-study.yaml", "0.6.0-3-gabcdef", "2024-05-01T12:00:00Z", {101, 102, 18446744073709551615u},
                  "notes with \"quotes\" and ünïcode"};
  return f;
}

bool same(double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; }
void expect_same(const LawValue& x, const LawValue& y, const std::string& what) {
  EXPECT_TRUE(same(x.value, y.value)) << what << ".value: " << x.value << " vs " << y.value;
  EXPECT_TRUE(same(x.error, y.error)) << what << ".error: " << x.error << " vs " << y.error;
}
void expect_same(const LawFit& x, const LawFit& y, const std::string& what) {
  expect_same(x.a, y.a, what + ".a");
  expect_same(x.b, y.b, what + ".b");
  expect_same(x.c, y.c, what + ".c");
  expect_same(x.delta, y.delta, what + ".delta");
  EXPECT_TRUE(same(x.delta_n_min, y.delta_n_min)) << what;
  EXPECT_TRUE(same(x.delta_n_max, y.delta_n_max)) << what;
}
void expect_same(const std::optional<RadiusScaling>& x, const std::optional<RadiusScaling>& y, const std::string& what) {
  ASSERT_EQ(x.has_value(), y.has_value()) << what;
  if (!x) return;
  expect_same(x->exponent, y->exponent, what + ".exponent");
  EXPECT_TRUE(same(x->R_min, y->R_min) && same(x->R_max, y->R_max)) << what;
  EXPECT_EQ(x->variant, y->variant) << what;
}

json load(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}
void save(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(LawFile, FullFileRoundTripsExactly) {
  const TempDir dir("law-file");
  const LawFile f = full_file();
  write_law_file(dir / "law.json", f);
  const LawFile g = read_law_file(dir / "law.json");
  EXPECT_EQ(g.version, kLawFileVersion);
  EXPECT_EQ(g.reference_radius, f.reference_radius);
  ASSERT_EQ(g.scenes.size(), 2u);
  for (const auto& [name, s] : f.scenes) {
    ASSERT_TRUE(g.scenes.contains(name)) << name;
    const SceneLaws& t = g.scenes.at(name);
    expect_same(s.normal, t.normal, name + ".normal");
    ASSERT_EQ(s.tangential.has_value(), t.tangential.has_value()) << name;
    if (s.tangential) expect_same(*s.tangential, *t.tangential, name + ".tangential");
    ASSERT_EQ(s.friction.has_value(), t.friction.has_value()) << name;
    if (s.friction) {
      EXPECT_EQ(s.friction->delta_n, t.friction->delta_n);
      ASSERT_EQ(s.friction->mu.size(), t.friction->mu.size());
      for (std::size_t i = 0; i < s.friction->mu.size(); ++i) expect_same(s.friction->mu[i], t.friction->mu[i], "mu");
    }
    expect_same(s.normal_scaling, t.normal_scaling, name + ".normal_scaling");
    expect_same(s.tangential_scaling, t.tangential_scaling, name + ".tangential_scaling");
  }
  EXPECT_FALSE(g.scenes.at("soft-soft").tangential || g.scenes.at("soft-soft").friction ||
               g.scenes.at("soft-soft").normal_scaling || g.scenes.at("soft-soft").tangential_scaling);
  ASSERT_TRUE(g.mixing);
  EXPECT_EQ(g.mixing->rule, "reduced-radius");
  EXPECT_EQ(g.mixing->checked_ratio, 0.5);
  expect_same(g.mixing->deviation, f.mixing->deviation, "mixing.deviation");
  EXPECT_EQ(g.provenance.study, f.provenance.study);
  EXPECT_EQ(g.provenance.code_version, f.provenance.code_version);
  EXPECT_EQ(g.provenance.created, f.provenance.created);
  EXPECT_EQ(g.provenance.seeds, f.provenance.seeds);
  EXPECT_EQ(g.provenance.notes, f.provenance.notes);

  // Written again, the same text: nothing lost or changed on the way.
  write_law_file(dir / "again.json", g);
  std::stringstream a, b;
  a << std::ifstream(dir / "law.json").rdbuf();
  b << std::ifstream(dir / "again.json").rdbuf();
  EXPECT_EQ(a.str(), b.str());
}

TEST(LawFile, AbsentOptionalPartsStayAbsent) {
  const TempDir dir("law-file-min");
  LawFile f;
  f.reference_radius = 0.016;
  f.scenes["soft-soft"].normal = {{3.0, kNaN}, {1.5, kNaN}, {-0.1, kNaN}, {0.2, kNaN}, 0.0, 0.5};
  write_law_file(dir / "law.json", f);
  const json j = load(dir / "law.json");
  EXPECT_FALSE(j.contains("mixing"));
  EXPECT_FALSE(j["scenes"].contains("soft-solid"));
  EXPECT_EQ(j["scenes"]["soft-soft"].size(), 1u);  // normal only
  const LawFile g = read_law_file(dir / "law.json");
  EXPECT_FALSE(g.mixing);
  EXPECT_EQ(g.scenes.size(), 1u);
  EXPECT_TRUE(g.provenance.seeds.empty());
  EXPECT_TRUE(std::isnan(g.scenes.at("soft-soft").normal.a.error));
}

// Version 2's many-body law (issue 33) goes round, reaches the simulation's laws, and a version 1
// file (every file before it: data/radius/report/laws.json) still reads, without one.
TEST(LawFile, TheManyBodyLawOfVersion2GoesRoundAndVersion1StillReads) {
  const TempDir dir("law-file-many-body");
  LawFile f = full_file();
  f.many_body = ManyBodyFit{"volumetric", {0.896, 0.006}, "experiments/many-body.yaml"};
  write_law_file(dir / "law.json", f);
  const LawFile g = read_law_file(dir / "law.json");
  EXPECT_EQ(g.version, kLawFileVersion);
  ASSERT_TRUE(g.many_body);
  EXPECT_EQ(g.many_body->beta.value, 0.896);
  EXPECT_EQ(g.many_body->beta.error, 0.006);
  EXPECT_EQ(g.many_body->source, "experiments/many-body.yaml");
  ASSERT_TRUE(soft_particle_laws(g, "law.json").many_body);
  EXPECT_EQ(soft_particle_laws(g, "law.json").many_body->beta, 0.896);
  EXPECT_EQ(g.many_body->tangential, "pairwise");
  EXPECT_FALSE(soft_particle_laws(g, "law.json").many_body->tangential_gain);
  f.many_body->tangential = "gain";
  write_law_file(dir / "law.json", f);
  EXPECT_EQ(read_law_file(dir / "law.json").many_body->tangential, "gain");
  EXPECT_TRUE(soft_particle_laws(read_law_file(dir / "law.json"), "law.json").many_body->tangential_gain);
  const LawFile old = read_law_file(SOFTPACK_SOURCE_DIR "/data/radius/report/laws.json");
  EXPECT_EQ(old.version, 1);
  EXPECT_FALSE(old.many_body);
  EXPECT_FALSE(soft_particle_laws(old, "laws.json").many_body);
}

TEST(LawFile, JsonHasTheDocumentedLayout) {
  const TempDir dir("law-file-layout");
  write_law_file(dir / "law.json", full_file());
  const json j = load(dir / "law.json");
  EXPECT_EQ(j["format"], "softpack-laws");
  EXPECT_EQ(j["version"], kLawFileVersion);
  EXPECT_EQ(j["reference_radius"], json({{"value", 0.016}, {"unit", "m"}}));
  for (const char* m : {"normal", "tangential", "friction", "radius_scaling", "mixing"}) EXPECT_TRUE(j["models"][m].is_string()) << m;
  const json& s = j["scenes"]["soft-solid"];
  EXPECT_EQ(s["normal"]["a"]["unit"], "N");
  EXPECT_EQ(s["normal"]["c"]["unit"], "N");
  EXPECT_EQ(s["normal"]["b"]["unit"], "1");
  EXPECT_TRUE(s["normal"]["b"]["error"].is_null());  // NaN error
  EXPECT_EQ(s["normal"]["delta_n_range"], json::array({0.05, 0.5}));
  EXPECT_EQ(s["tangential"]["a"]["unit"], "N/m");
  EXPECT_EQ(s["tangential"]["c"]["unit"], "N/m");
  EXPECT_EQ(s["friction"]["delta_n"], json::array({0.3, 0.4, 0.5}));
  EXPECT_EQ(s["friction"]["mu"][1], json({{"value", 0.29}, {"error", nullptr}, {"unit", "1"}}));
  EXPECT_EQ(s["normal_scaling"]["radius_range"], json({{"value", {0.008, 0.032}}, {"unit", "m"}}));
  EXPECT_EQ(s["normal_scaling"]["variant"], "fixed");
  EXPECT_TRUE(s["tangential_scaling"]["exponent"]["value"].is_null());
  EXPECT_TRUE(j["scenes"]["soft-soft"]["normal"]["c"]["value"].is_null());
  EXPECT_EQ(j["mixing"]["rule"], "reduced-radius");
  EXPECT_EQ(j["mixing"]["deviation"]["unit"], "1");
  EXPECT_EQ(j["provenance"]["seeds"], json::array({101, 102, 18446744073709551615u}));
}

TEST(LawFile, WriterRefusesWhatCouldNotBeReadBack) {
  const TempDir dir("law-file-write");
  LawFile f = full_file();
  f.reference_radius = kNaN;
  EXPECT_THROW(write_law_file(dir / "law.json", f), InputError);
  f = full_file();
  f.scenes["soft-solid"].normal.a.value = std::numeric_limits<double>::infinity();
  try {
    write_law_file(dir / "law.json", f);
    ADD_FAILURE() << "an infinite a was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scenes.soft-solid.normal.a.value"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path));  // nothing written, no temporary left
}

// ---- one mistake per case, made by editing a good file's JSON ----

struct Mistake {
  const char* name;
  std::function<void(json&)> edit;
  std::vector<std::string> message;  // what the message must contain (besides the file's path)
};
void PrintTo(const Mistake& m, std::ostream* os) { *os << m.name; }

json& solid(json& j) { return j["scenes"]["soft-solid"]; }

const std::vector<Mistake> kMistakes = {
    {"WrongUnit", [](json& j) { solid(j)["normal"]["a"]["unit"] = "N/m"; },
     {"scenes.soft-solid.normal.a.unit: 'N/m' is not allowed", "allowed: 'N'"}},
    {"WrongTangentialUnit", [](json& j) { solid(j)["tangential"]["c"]["unit"] = "N"; },
     {"scenes.soft-solid.tangential.c.unit", "allowed: 'N/m'"}},
    {"MissingUnit", [](json& j) { solid(j)["friction"]["mu"][2].erase("unit"); },
     {"scenes.soft-solid.friction.mu[2].unit: missing", "allowed: '1'"}},
    {"WrongFormat", [](json& j) { j["format"] = "softpack-fit"; }, {"format: 'softpack-fit'", "allowed: 'softpack-laws'"}},
    {"NoFormat", [](json& j) { j.erase("format"); }, {"format: missing", "allowed: 'softpack-laws'"}},
    {"Version5", [](json& j) { j["version"] = 5; }, {"version: 5 is newer than this build reads", "allowed: 4"}},
    {"Version0", [](json& j) { j["version"] = 0; }, {"version: 0 is not allowed", "allowed: 1 to 4"}},
    {"ManyBodyUnionInVersion2", [](json& j) { j["version"] = 2, j["many_body"] = {{"form", "volumetric-union"}, {"beta", {{"value", 0.6}, {"unit", "1"}}}}; },
     {"many_body.form: 'volumetric-union' is not allowed in a version 2 file", "allowed: 'volumetric'"}},
    {"ManyBodyGrainInVersion2", [](json& j) { j["version"] = 2, j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", 0.6}, {"unit", "1"}}}, {"grain", json::object()}}; },
     {"many_body.grain: not allowed in a version 2 file", "allowed: version 3"}},
    {"ManyBodyGrainExponent", [](json& j) { j["version"] = 3, j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", 0.6}, {"unit", "1"}}}, {"grain", {{"exponent", {{"value", -1}, {"unit", "1"}}}, {"beta", {{"value", 0.7}, {"unit", "1"}}}}}}; },
     {"many_body.grain.exponent.value: -1 is not allowed", "allowed: 0 <= exponent <= 10"}},
    {"ManyBodyTangentialUnknown", [](json& j) { j["version"] = 2, j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", 0.9}, {"error", 0.01}, {"unit", "1"}}}, {"tangential", "twice"}}; },
     {"many_body.tangential: 'twice' is not allowed", "gain"}},
    {"ManyBodyGainBelowTheNormalOnset",
     [](json& j) {
       j["version"] = 2, j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", 0.9}, {"error", 0.01}, {"unit", "1"}}}, {"tangential", "gain"}};
       solid(j)["tangential"]["delta"]["value"] = 0.5 * solid(j)["normal"]["delta"]["value"].get<double>();
     },
     {"many_body.tangential: 'gain' is not allowed with scenes.soft-solid.tangential.delta", "allowed: pairwise"}},
    {"ManyBodyInVersion1", [](json& j) { j["version"] = 1, j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", 0.9}, {"error", 0.01}, {"unit", "1"}}}}; },
     {"many_body: not allowed in a version 1 file", "allowed: version 2"}},
    {"ManyBodyForm", [](json& j) { j["many_body"] = {{"form", "ratio"}, {"beta", {{"value", 0.9}, {"error", 0.01}, {"unit", "1"}}}}; },
     {"many_body.form: 'ratio' is not allowed", "allowed: 'volumetric'"}},
    {"ManyBodyBeta", [](json& j) { j["many_body"] = {{"form", "volumetric"}, {"beta", {{"value", -0.5}, {"error", 0.01}, {"unit", "1"}}}}; },
     {"many_body.beta.value: -0.5 is not allowed", "allowed: 0 <= beta <= 10"}},
    {"MissingNormalA", [](json& j) { solid(j)["normal"].erase("a"); },
     {"scenes.soft-solid.normal.a: missing", "allowed: {\"value\", \"error\", \"unit\": 'N'}"}},
    {"MissingNormal", [](json& j) { solid(j).erase("normal"); }, {"scenes.soft-solid.normal: missing", "allowed: the Eq. 7"}},
    {"MissingDeltaNRange", [](json& j) { j["scenes"]["soft-soft"]["normal"].erase("delta_n_range"); },
     {"scenes.soft-soft.normal.delta_n_range: missing", "allowed: [lo, hi] with 0 <= lo < hi"}},
    {"UnknownKeyInLaw", [](json& j) { solid(j)["normal"]["delta_n_rnage"] = json::array({0.0, 0.5}); },
     {"scenes.soft-solid.normal.delta_n_rnage: unknown key", "allowed: a, b, c, delta, delta_n_range",
      "did you mean 'delta_n_range'"}},
    {"UnknownKeyInScene", [](json& j) { solid(j)["tangental"] = solid(j)["tangential"]; },
     {"scenes.soft-solid.tangental: unknown key", "allowed: normal, tangential, friction", "did you mean 'tangential'"}},
    {"UnknownKeyInValue", [](json& j) { solid(j)["normal"]["b"]["err"] = 0.1; },
     {"scenes.soft-solid.normal.b.err: unknown key", "allowed: value, error, unit"}},
    {"UnknownTopKey", [](json& j) { j["mixng"] = j["mixing"]; }, {"mixng: unknown key", "allowed: format, version"}},
    {"UnknownScene", [](json& j) { j["scenes"]["soft-wall"] = solid(j); },
     {"scenes.soft-wall: unknown scene", "allowed: soft-solid, soft-soft"}},
    {"NoScene", [](json& j) { j["scenes"] = json::object(); }, {"scenes: {} is not allowed", "allowed: an object with at least one of"}},
    {"NegativeReferenceRadius", [](json& j) { j["reference_radius"]["value"] = -0.016; },
     {"reference_radius.value: -0.016 is not allowed", "allowed: a finite number > 0"}},
    {"NullReferenceRadius", [](json& j) { j["reference_radius"]["value"] = nullptr; },
     {"reference_radius.value: null is not allowed", "allowed: a finite number"}},
    {"MissingReferenceRadius", [](json& j) { j.erase("reference_radius"); },
     {"reference_radius: missing", "allowed: {\"value\": a number > 0, \"unit\": 'm'}"}},
    {"ReferenceRadiusInMillimetres", [](json& j) { j["reference_radius"]["unit"] = "mm"; },
     {"reference_radius.unit: 'mm' is not allowed", "allowed: 'm'"}},
    {"DeltaNRangeReversed", [](json& j) { solid(j)["normal"]["delta_n_range"] = json::array({0.5, 0.05}); },
     {"scenes.soft-solid.normal.delta_n_range: [0.5,0.05] is not allowed", "allowed: [lo, hi] with 0 <= lo < hi"}},
    {"DeltaNRangeNegative", [](json& j) { solid(j)["tangential"]["delta_n_range"] = json::array({-0.1, 0.5}); },
     {"scenes.soft-solid.tangential.delta_n_range", "allowed: [lo, hi] with 0 <= lo < hi"}},
    {"NullA", [](json& j) { solid(j)["normal"]["a"]["value"] = nullptr; },
     {"scenes.soft-solid.normal.a.value: null is not allowed", "allowed: a finite number"}},
    {"TextForB", [](json& j) { solid(j)["normal"]["b"]["value"] = "2.5"; },
     {"scenes.soft-solid.normal.b.value: '2.5' is not allowed", "allowed: a finite number"}},
    {"FrictionLengthsDiffer", [](json& j) { solid(j)["friction"]["mu"].erase(2); },
     {"scenes.soft-solid.friction.mu: 2 values for 3 delta_n", "allowed: one per delta_n (3)"}},
    {"FrictionNotIncreasing", [](json& j) { solid(j)["friction"]["delta_n"][2] = 0.4; },
     {"scenes.soft-solid.friction.delta_n[2]: 0.4 is not allowed", "allowed: a number > 0.4"}},
    {"FrictionNullMu", [](json& j) { solid(j)["friction"]["mu"][0]["value"] = nullptr; },
     {"scenes.soft-solid.friction.mu[0].value: null", "allowed: a finite number"}},
    {"ScalingVariant", [](json& j) { solid(j)["normal_scaling"]["variant"] = "self_similar"; },
     {"scenes.soft-solid.normal_scaling.variant: 'self_similar' is not allowed", "allowed: 'fixed', 'self-similar'"}},
    {"RadiusRangeReversed", [](json& j) { solid(j)["tangential_scaling"]["radius_range"]["value"] = {0.064, 0.008}; },
     {"scenes.soft-solid.tangential_scaling.radius_range.value", "allowed: [R_min, R_max] with 0 < R_min <= R_max"}},
    {"MixingRule", [](json& j) { j["mixing"]["rule"] = "harmonic"; },
     {"mixing.rule: 'harmonic' is not allowed", "allowed: 'reduced-radius'"}},
    {"NegativeSeed", [](json& j) { j["provenance"]["seeds"][0] = -1; },
     {"provenance.seeds[0]: -1 is not allowed", "allowed: an integer >= 0"}},
    {"NotAnObject", [](json& j) { j = json::array({1, 2}); }, {"[1,2] is not allowed", "allowed: a JSON object"}},
};

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

class LawFileMistake : public ::testing::TestWithParam<Mistake> {};

TEST_P(LawFileMistake, IsRefusedWithFieldAndAllowedValue) {
  const Mistake& m = GetParam();
  const TempDir dir(std::string("law-file-") + m.name);
  const std::string path = dir / "law.json";
  write_law_file(path, full_file());
  json j = load(path);
  m.edit(j);
  save(path, j.dump(2));
  expect_refused(path, m.message);
}

INSTANTIATE_TEST_SUITE_P(LawFile, LawFileMistake, ::testing::ValuesIn(kMistakes),
                         [](const ::testing::TestParamInfo<Mistake>& i) { return std::string(i.param.name); });

// What JSON cannot hold or what is not JSON: the text itself edited.
TEST(LawFile, NonFiniteNumberOrNotJsonIsRefused) {
  const TempDir dir("law-file-text");
  const std::string path = dir / "law.json";
  write_law_file(path, full_file());
  json j = load(path);
  j["reference_radius"]["value"] = 7.25;
  std::string text = j.dump(2);
  text.replace(text.find("7.25"), 4, "1e999");  // +inf: beyond a double
  save(path, text);
  expect_refused(path, {"not a JSON file", "number overflow"});
  save(path, j.dump(2).substr(0, 100));  // cut short
  expect_refused(path, {"not a JSON file"});
}

// Issue 28, defect 13: what release 0.5.0 read as valid or blamed on another key.
TEST(LawFile, ReferenceRadiusOutsideItsScalingRangeIsRefused) {
  const TempDir dir("law-file-r0");
  const std::string path = dir / "law.json";
  write_law_file(path, full_file());
  json j = load(path);
  j["reference_radius"]["value"] = 0.1;  // beyond the soft-solid normal scaling's [0.008, 0.032] m
  save(path, j.dump(2));
  expect_refused(path, {"reference_radius.value", "radius_range [0.008, 0.032]"});
}

TEST(LawFile, AKeyTwiceInOneObjectIsRefused) {
  const TempDir dir("law-file-twice");
  const std::string path = dir / "law.json";
  write_law_file(path, full_file());
  std::string text = load(path).dump(2);
  text.replace(text.find("\"reference_radius\""), 0, "\"format\": \"x\",\n  ");  // "format" given twice
  save(path, text);
  expect_refused(path, {"the key \"format\" is given twice in one object"});
}

TEST(LawFile, ALawTooLargeForTheSimulationIsRefusedByItsOwnKey) {
  const TempDir dir("law-file-huge");
  const std::string path = dir / "law.json";
  write_law_file(path, full_file());
  json j = load(path);
  j["scenes"]["soft-solid"]["normal"]["a"]["value"] = 1e308;
  save(path, j.dump(2));
  expect_refused(path, {"scenes.soft-solid.normal.a", "stays within 1e+15 N"});
}

TEST(LawFile, AFolderIsAnInputError) {
  const TempDir dir("law-file-folder");
  std::filesystem::create_directories(dir.path);
  expect_refused(dir.path.string(), {"is a directory"});
}

TEST(LawFile, MissingFileIsAnInputError) {
  EXPECT_THROW(read_law_file("/nonexistent/softpack/law.json"), InputError);
}

}  // namespace
