// The contents of a level packing's sites, made once and kept (formats/contents_file.hpp): what
// is read back is, bit for bit, what the seeds give; a file of another packing, or one that
// cannot be read, is made again; a packing made in memory has its contents made, none kept.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "formats/contents_file.hpp"
#include "formats/packing_file.hpp"
#include "packing/nested.hpp"
#include "packing/statistics.hpp"
#include "io/sha256.hpp"
#include "support/level_packing.hpp"
#include "support/temp_dir.hpp"

namespace softpack {
namespace {

std::string write_level(const testing::TempDir& dir, const std::string& name, std::uint64_t seed) {
  const PackingParameters p = testing::level_packing(300);  // three levels, a cheap insertion
  const LevelPacking l = generate_level(p, 2, seed);
  PackingProvenance prov;
  prov.program = "softpack-pack";
  prov.seed = seed;
  const PackingSites sites{3, l.site_radius, l.sites, l.sites_drawn, l.sites_discarded};
  write_packing_file(dir / name, p, l.grains, packing_statistics(l.grains.centres, l.grains.radii, p.Rs, p.r_max, 10), prov, sites);
  return dir / name;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every field of every level packing, down the tree.
void expect_same(const std::vector<SiteContent>& a, const std::vector<SiteContent>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const LevelPacking &x = a[k].level, &y = b[k].level;
    EXPECT_TRUE(same_bits(x.grains.centres, y.grains.centres));
    EXPECT_TRUE(same_bits(x.grains.radii, y.grains.radii));
    EXPECT_TRUE(same_bits(x.grains.radii_inserted, y.grains.radii_inserted));
    EXPECT_EQ(x.grains.sampled, y.grains.sampled);
    EXPECT_EQ(x.grains.discarded, y.grains.discarded);
    EXPECT_EQ(x.grains.grown, y.grains.grown);
    EXPECT_EQ(x.site_radius, y.site_radius);
    EXPECT_TRUE(same_bits(x.sites, y.sites));
    EXPECT_EQ(x.sites_drawn, y.sites_drawn);
    EXPECT_EQ(x.sites_discarded, y.sites_discarded);
    expect_same(a[k].sites, b[k].sites);
  }
}

std::size_t nodes(const std::vector<SiteContent>& c) {
  std::size_t n = c.size();
  for (const SiteContent& s : c) n += nodes(s.sites);
  return n;
}

TEST(ContentsFile, TheKeptContentsAreWhatTheSeedsGive) {
  const testing::TempDir dir("contents-file");
  const PackingFile p = read_packing_file(write_level(dir, "seed-71.h5", 71));
  const std::vector<SiteContent> made = generate_contents(p.parameters, 2, 71, p.sites.centres.size());
  ASSERT_GT(nodes(made), made.size());  // sites with sites of their own: the tree is walked
  const std::string kept = p.path + ".contents.h5";
  EXPECT_FALSE(std::filesystem::exists(kept));
  expect_same(packing_contents(p), made);  // made, and kept
  ASSERT_TRUE(std::filesystem::exists(kept));
  const auto read = read_contents_file(kept, sha256_of_file(p.path), 2, p.sites.centres.size());
  ASSERT_TRUE(read);
  expect_same(*read, made);
  expect_same(packing_contents(p), made);  // read
  EXPECT_FALSE(read_contents_file(kept, "another packing", 2, p.sites.centres.size()));
  EXPECT_FALSE(read_contents_file(kept, sha256_of_file(p.path), 1, p.sites.centres.size()));
}

TEST(ContentsFile, MakingThemSaysEachSiteDoneWithTheSameBits) {
  // The line per site packing_contents prints while it makes them (minutes at the chain's level 0)
  // comes from this callback: once per site of the packing, in order, and the contents unchanged.
  const testing::TempDir dir("contents-file-progress");
  const PackingFile p = read_packing_file(write_level(dir, "seed-75.h5", 75));
  const std::size_t sites = p.sites.centres.size();
  ASSERT_GT(sites, 1u);
  std::vector<std::size_t> done;
  const auto made = generate_contents(p.parameters, 2, 75, sites, [&](const std::string& phase, std::size_t k, std::size_t n) {
    EXPECT_EQ(phase, "contents");
    EXPECT_EQ(n, sites);
    done.push_back(k);
  });
  std::vector<std::size_t> expected(sites);
  for (std::size_t k = 0; k < sites; ++k) expected[k] = k + 1;
  EXPECT_EQ(done, expected);
  expect_same(made, generate_contents(p.parameters, 2, 75, sites));
  ::testing::internal::CaptureStderr();
  expect_same(packing_contents(p), made);  // made: a line per site
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find(fmt::format("contents: site {}/{} made", sites, sites)), std::string::npos) << said;
  ::testing::internal::CaptureStderr();
  expect_same(packing_contents(p), made);  // read: nothing to say
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(ContentsFile, AnotherPackingsOrAnUnreadableFileIsMadeAgain) {
  const testing::TempDir dir("contents-file-again");
  const std::string path = write_level(dir, "seed.h5", 72);
  EXPECT_FALSE(packing_contents(read_packing_file(path)).empty());
  // The packing made again from another seed: the kept file is another packing's.
  write_level(dir, "seed.h5", 73);
  const PackingFile q = read_packing_file(path);
  expect_same(packing_contents(q), generate_contents(q.parameters, 2, 73, q.sites.centres.size()));
  // A file that is no HDF5 at all.
  std::ofstream(path + ".contents.h5", std::ios::trunc) << "not a contents file";
  expect_same(packing_contents(q), generate_contents(q.parameters, 2, 73, q.sites.centres.size()));
  EXPECT_TRUE(read_contents_file(path + ".contents.h5", sha256_of_file(path), 2, q.sites.centres.size()));
}

TEST(ContentsFile, APackingMadeInMemoryHasItsContentsMadeNoneKept) {
  const testing::TempDir dir("contents-file-memory");
  PackingFile p = read_packing_file(write_level(dir, "seed-74.h5", 74));
  const std::string kept = p.path + ".contents.h5";
  p.path.clear();
  expect_same(packing_contents(p), generate_contents(p.parameters, 2, 74, p.sites.centres.size()));
  EXPECT_FALSE(std::filesystem::exists(kept));
}

}  // namespace
}  // namespace softpack
