// How the workflow uses law files (formats/law_file.hpp). A section's laws (`content` of a nested
// measurement, `soft_particle` of a coarse-grain medium; read_soft_particle_laws): `laws`' pairwise
// laws with the many-body law of the file `many_body` names, or `laws`' own; every refusal names
// the section's key. A report's law file (write_law_file_if_changed) is rewritten only for other
// laws, so the stages that read it keep their stamps when the report is made again.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"
#include "support/temp_dir.hpp"

namespace softpack {
namespace {

// a nested level's measured laws (pairwise only) and the probe's latest, with a many-body law
const std::string kPairwise = SOFTPACK_SOURCE_DIR "/data/nested/level-2/report/reference/laws.json";
const std::string kManyBody = SOFTPACK_SOURCE_DIR "/data/many-body/report/laws-v6.json";

void expect_refused(const std::function<void()>& f, const std::string& what) {
  try {
    f();
    ADD_FAILURE() << "not refused: " << what;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(SectionLaws, TheManyBodyLawIsTheNamedFilesAndThePairwiseLawsAreLaws) {
  const SoftParticleLaws own = soft_particle_laws(read_law_file(kPairwise), kPairwise);
  const SoftParticleLaws other = soft_particle_laws(read_law_file(kManyBody), kManyBody);
  const SoftParticleLaws l = read_soft_particle_laws("soft_particle", kPairwise, kManyBody);
  ASSERT_TRUE(l.many_body && other.many_body);
  EXPECT_EQ(l.many_body->beta, other.many_body->beta);
  ASSERT_TRUE(l.soft_solid && own.soft_solid && other.soft_solid);
  EXPECT_GT(l.soft_solid->normal(0.4), 0.0);
  EXPECT_EQ(l.soft_solid->normal(0.4), own.soft_solid->normal(0.4));
  EXPECT_NE(l.soft_solid->normal(0.4), other.soft_solid->normal(0.4));  // not the many-body file's pairwise law
  EXPECT_FALSE(read_soft_particle_laws("soft_particle", kPairwise, "").many_body);
}

TEST(SectionLaws, AFileWithoutAManyBodyLawOrNoFileIsRefusedNamingTheKey) {
  expect_refused([] { read_soft_particle_laws("content", kPairwise, kPairwise); }, "content.many_body: " + kPairwise + " has no many-body law");
  expect_refused([] { read_soft_particle_laws("content", "/nonexistent/laws.json", ""); }, "content.laws: ");
  expect_refused([] { read_soft_particle_laws("content", kPairwise, "/nonexistent/mb.json"); }, "content.many_body: ");
}

TEST(LawFileRewrite, OnlyOtherLawsRewriteTheFileNotAnotherCodeVersionOrTime) {
  const testing::TempDir dir("law-file-rewrite");
  const std::string path = dir / "laws.json";
  LawFile f = read_law_file(kManyBody);
  EXPECT_TRUE(write_law_file_if_changed(path, f));  // no file yet
  const std::string first = read_text_file(path);
  f.provenance.code_version = "9.9.9 (0000000)", f.provenance.created = "2099-01-01T00:00:00Z";
  f.many_body->source = "another version's report";
  EXPECT_FALSE(write_law_file_if_changed(path, f));
  EXPECT_EQ(read_text_file(path), first);
  f.provenance.seeds.push_back(999);  // other seeds: other laws' provenance
  EXPECT_TRUE(write_law_file_if_changed(path, f));
  EXPECT_EQ(read_law_file(path).provenance.code_version, "9.9.9 (0000000)");
  f.scenes.begin()->second.normal.a.value *= 1.01;  // another law
  EXPECT_TRUE(write_law_file_if_changed(path, f));
  EXPECT_EQ(read_law_file(path).scenes.begin()->second.normal.a.value, f.scenes.begin()->second.normal.a.value);
}

}  // namespace
}  // namespace softpack
