// The contents of a level packing's sites, made once and kept (formats/contents_file.hpp): what
// is read back is, bit for bit, what the seeds give; a file of another packing, or one that
// cannot be read, is made again; a packing made in memory has its contents made, none kept.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <atomic>
#include <fstream>
#include <future>
#include <optional>
#include <thread>

#include <unistd.h>

#include "formats/contents_file.hpp"
#include "formats/packing_file.hpp"
#include "packing/nested.hpp"
#include "packing/statistics.hpp"
#include "io/file_lock.hpp"
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

// The lock (io/file_lock.hpp) is the file's, not the thread's: a second holder waits, says so once
// before it waits, and has it when the first lets go. (flock locks belong to an open file, so two
// in one process exclude each other as two processes do.)
TEST(FileLock, ASecondHolderWaitsForTheFirstAndSaysSo) {
  const testing::TempDir dir("file-lock");
  const std::string path = (dir.path / "x.lock").string();
  std::optional<FileLock> first(std::in_place, path);
  ASSERT_TRUE(first->held());
  std::promise<void> waiting;
  std::atomic<int> said{0};
  std::atomic<bool> had{false};
  std::thread second([&] {
    const FileLock lock(path, [&] {
      ++said;
      waiting.set_value();
    });
    had = lock.held();
  });
  waiting.get_future().wait();  // the second is about to wait: the first still holds it
  EXPECT_FALSE(had);
  first.reset();
  second.join();
  EXPECT_TRUE(had);
  EXPECT_EQ(said, 1);
  const FileLock third(path, [] { ADD_FAILURE() << "nobody holds it: no wait"; });
  EXPECT_TRUE(third.held());
  EXPECT_FALSE(FileLock((dir.path / "no such folder" / "x.lock").string()).held()) << "a lock that cannot be had is not taken";
}

// A scene that finds another making its packing's contents waits, then reads what that one kept:
// here the holder keeps the contents of another seed under this packing's key, which only a read
// returns.
TEST(ContentsFile, AProcessThatFindsThemBeingMadeWaitsAndReadsThem) {
  const testing::TempDir dir("contents-file-lock");
  const PackingFile p = read_packing_file(write_level(dir, "seed-76.h5", 76));
  const std::size_t sites = p.sites.centres.size();
  const std::string kept = p.path + ".contents.h5";
  std::optional<FileLock> maker(std::in_place, kept + ".lock");
  std::vector<SiteContent> other = generate_contents(p.parameters, 2, 77, sites);
  ASSERT_NE(other.at(0).solid_volume(), generate_contents(p.parameters, 2, 76, sites).at(0).solid_volume())
      << "the two seeds' contents must differ";
  std::vector<SiteContent> got;
  // Its standard error into a pipe, read until the line that says it waits: past its first look,
  // it is at the lock (no timing).
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const int saved = ::dup(2);
  ::dup2(pipe_fds[1], 2);
  std::thread scene([&] {
    got = packing_contents(p);
    [[maybe_unused]] const auto n = ::write(pipe_fds[1], "\ndone\n", 6);  // (a maker that never waited ends the read)
  });
  std::string said;
  char c;
  while (said.find("waiting for it\n") == std::string::npos && said.find("\ndone\n") == std::string::npos &&
         ::read(pipe_fds[0], &c, 1) == 1)
    said += c;
  ::dup2(saved, 2);
  ::close(saved);
  EXPECT_NE(said.find("contents: another process is making those of " + p.path), std::string::npos) << said;
  write_contents_file(kept, sha256_of_file(p.path), 2, other);
  maker.reset();
  scene.join();
  ::close(pipe_fds[1]), ::close(pipe_fds[0]);
  expect_same(got, other);
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
