// HDF5 result files (round trips, errors naming the file and dataset, byte-identical output,
// atomic commit) and the .vtp / extended-XYZ snapshot writers.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/error.hpp"
#include "io/hdf5_file.hpp"
#include "unit/io_fixture.hpp"

namespace softpack {
namespace {

using namespace io_test;

// Runs `f` and returns the InputError message (fails the test when none is thrown).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

// A small results file of every kind of object the wrapper writes.
void write_sample(h5::File& f, double scale) {
  std::vector<double> centres(12);
  for (std::size_t i = 0; i < centres.size(); ++i) centres[i] = scale * (0.1 * i - 0.3);
  f.write("particles/centres", centres, {4, 3});
  f.write("particles/ids", std::vector<std::int64_t>{3, 1, 4, 1});
  f.write("stats/radial_profile/r", std::vector<double>{0.0, 1e-3, 2e-3});
  f.write_scalar("stats/phi", 0.64 * scale);
  f.write_scalar("stats/n_contacts", std::int64_t{42});
  f.write_string("provenance", fmt::format("softpack test, scale {}", scale));
  f.set_attribute("/", "code_version", std::string("0.1.0 (test)"));
  f.set_attribute("particles/centres", "unit", std::string("m"));
  f.set_attribute("stats", "seed", std::string("7"));
}

// ---------------------------------------------------------------------------------------------

using H5RoundTrip = IoTest;

TEST_F(H5RoundTrip, EveryType) {
  const std::vector<double> reals = {0.0,
                                     -0.0,
                                     1.0 / 3.0,
                                     -2.5e-300,
                                     std::numeric_limits<double>::denorm_min(),
                                     std::numeric_limits<double>::max(),
                                     std::numeric_limits<double>::infinity()};
  const std::vector<std::int64_t> ints = {0, -1, std::numeric_limits<std::int64_t>::min(),
                                          std::numeric_limits<std::int64_t>::max()};
  const std::string text = "Hertz + Tsuji, r in µm\nline two";
  {
    h5::File f = h5::File::create(path("a.h5"));
    f.write("reals", reals);
    f.write("ints", ints);
    f.write("empty", std::vector<double>{});
    f.write_scalar("s/d", 2.718281828459045);
    f.write_scalar("s/i", std::int64_t{-123456789012345});
    f.write_string("s/text", text);
    f.write_string("s/empty_text", "");
    f.set_attribute("reals", "unit", std::string("m"));
    f.set_attribute("reals", "unit", std::string("N"));  // replaced: an attribute is set, not added twice
    f.close();
  }
  const h5::File f = h5::File::open(path("a.h5"));
  const std::vector<double> r = f.read_doubles("reals");
  ASSERT_EQ(r.size(), reals.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_EQ(std::memcmp(&r[i], &reals[i], sizeof(double)), 0) << i;  // bit for bit, -0.0 too
  }
  EXPECT_EQ(f.read_int64s("ints"), ints);
  EXPECT_TRUE(f.read_doubles("empty").empty());
  EXPECT_EQ(f.read_scalar_double("s/d"), 2.718281828459045);
  EXPECT_EQ(f.read_scalar_int64("/s/i"), -123456789012345);
  EXPECT_EQ(f.read_string("s/text"), text);
  EXPECT_EQ(f.read_string("s/empty_text"), "");
  EXPECT_TRUE(f.exists("/"));
  EXPECT_TRUE(f.exists("s"));
  EXPECT_TRUE(f.exists("/s/text"));
  EXPECT_FALSE(f.exists("s/missing"));
  EXPECT_FALSE(f.exists("reals/below_a_dataset"));
}

TEST_F(H5RoundTrip, DimsAndGroups) {
  {
    h5::File f = h5::File::create(path("d.h5"));
    write_sample(f, 1.0);
    f.write("grid", std::vector<std::int64_t>(24, 5), {2, 3, 4});
    f.write("none", std::vector<double>{}, {0, 3});
    EXPECT_THROW(f.write("bad", std::vector<double>(5), {2, 3}), std::invalid_argument);
    EXPECT_THROW(f.write("stats/phi", std::vector<double>{1.0}), std::runtime_error);
    EXPECT_THROW(f.write("stats/phi/below", std::vector<double>{1.0}), std::runtime_error);
    EXPECT_THROW(f.write("a//b", std::vector<double>{1.0}), std::invalid_argument);
  }
  const h5::File f = h5::File::open(path("d.h5"));
  std::vector<std::size_t> dims;
  const std::vector<double> c = f.read_doubles("particles/centres", &dims);
  EXPECT_EQ(dims, (std::vector<std::size_t>{4, 3}));
  ASSERT_EQ(c.size(), 12u);
  EXPECT_EQ(c[4], 0.1 * 4 - 0.3);  // row-major: row 1, column 1
  EXPECT_EQ(f.read_int64s("grid", &dims), std::vector<std::int64_t>(24, 5));
  EXPECT_EQ(dims, (std::vector<std::size_t>{2, 3, 4}));
  EXPECT_TRUE(f.read_doubles("none", &dims).empty());
  EXPECT_EQ(dims, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(f.read_doubles("stats/radial_profile/r", &dims).size(), 3u);
  EXPECT_EQ(dims, std::vector<std::size_t>{3});
  EXPECT_EQ(f.read_int64s("particles/ids"), (std::vector<std::int64_t>{3, 1, 4, 1}));
}

// A path of more than 1024 characters: no fixed-size buffer for names (the variable-length
// strings are read from the file by the layer itself, io/hdf5_quarantine.cpp).
TEST_F(H5RoundTrip, LongPath) {
  fs::path dir = dir_;
  while (dir.string().size() <= 1100) dir /= std::string(200, 'd');
  fs::create_directories(dir);
  const std::string p = (dir / "long.h5").string();
  ASSERT_GT(p.size(), 1024u);
  {
    h5::File f = h5::File::create(p);
    write_sample(f, 1.0);
  }
  const h5::File f = h5::File::open(p);
  EXPECT_EQ(f.read_string("provenance"), "softpack test, scale 1");
  EXPECT_EQ(input_error([&] { f.read_doubles("nope"); }), p + ": no dataset 'nope'");
}

// ---------------------------------------------------------------------------------------------

using H5Errors = IoTest;

TEST_F(H5Errors, MissingFile) {
  const std::string p = path("nope.h5");
  EXPECT_NE(input_error([&] { h5::File::open(p); }).find(p + ": no such file"),
            std::string::npos);
}

TEST_F(H5Errors, NotAnHdf5File) {
  const std::string p = path("garbage.h5");
  spit(p, std::string(4096, '\x5a') + "not hdf5 at all");
  EXPECT_EQ(input_error([&] { h5::File::open(p); }), p + ": not an HDF5 file");
  spit(p, "");
  EXPECT_EQ(input_error([&] { h5::File::open(p); }), p + ": not an HDF5 file");
}

TEST_F(H5Errors, TruncatedFile) {
  const std::string p = path("cut.h5");
  {
    h5::File f = h5::File::create(p);
    write_sample(f, 1.0);
    f.write("big", std::vector<double>(1000, 1.5));
  }
  const std::string bytes = slurp(p);
  spit(p, bytes.substr(0, bytes.size() / 2));
  const std::string msg = input_error([&] { h5::File::open(p); });
  EXPECT_EQ(msg.rfind(p + ": truncated or corrupt HDF5 file", 0), 0u) << msg;
}

TEST_F(H5Errors, DatasetsThatAreMissingOrOfTheWrongKind) {
  const std::string p = path("e.h5");
  {
    h5::File f = h5::File::create(p);
    write_sample(f, 1.0);
  }
  const h5::File f = h5::File::open(p);
  const auto expect = [&](auto&& call, const std::string& what) {
    const std::string msg = input_error(call);
    EXPECT_EQ(msg.rfind(p + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  };
  expect([&] { f.read_doubles("stats/missing"); }, "no dataset 'stats/missing'");
  expect([&] { f.read_doubles("nowhere/at/all"); }, "no dataset 'nowhere/at/all'");
  expect([&] { f.read_doubles("stats"); }, "'stats' is a group, not a dataset");
  expect([&] { f.read_int64s("stats/radial_profile/r"); },
         "dataset 'stats/radial_profile/r': expected integers that fit in 64-bit signed, found "
         "64-bit floating-point numbers");
  expect([&] { f.read_doubles("particles/ids"); },
         "expected floating-point numbers, found 64-bit signed integers");
  expect([&] { f.read_doubles("particles/centres"); },
         "dataset 'particles/centres': expected a 1-D array, found shape (4, 3)");
  expect([&] { f.read_doubles("stats/phi"); }, "expected a 1-D array, found a scalar");
  expect([&] { f.read_scalar_double("stats/radial_profile/r"); },
         "expected a scalar, found shape (3)");
  expect([&] { f.read_string("stats/phi"); }, "expected a string, found 64-bit floating-point");
}

TEST_F(H5Errors, CannotCreate) {
  const std::string p = path("no/such/dir/x.h5");
  EXPECT_EQ(input_error([&] { h5::File::create(p); }), p + ": cannot create the file: No such file or directory");
}

// ---------------------------------------------------------------------------------------------

using H5Determinism = IoTest;

// The same data gives the same bytes: no time stamps (the writes straddle a clock second), no
// uninitialised memory (different data written in between, and glibc told to poison freed and
// fresh blocks).
TEST_F(H5Determinism, SameContentSameBytes) {
  const auto write = [&](const std::string& name, double scale) {
    h5::File f = h5::File::create(path(name));
    write_sample(f, scale);
  };
  write("first.h5", 1.0);
  const std::time_t t0 = std::time(nullptr);
  while (std::time(nullptr) == t0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
#if defined(__GLIBC__)
  mallopt(M_PERTURB, 0xa5);
#endif
  write("other.h5", 3.0);
  write("second.h5", 1.0);
#if defined(__GLIBC__)
  mallopt(M_PERTURB, 0);
#endif
  const std::string a = slurp(path("first.h5"));
  EXPECT_FALSE(a.empty());
  EXPECT_TRUE(a == slurp(path("second.h5"))) << "the same content gave different bytes";
  EXPECT_FALSE(a == slurp(path("other.h5")));
}

// ---------------------------------------------------------------------------------------------

using H5Atomic = IoTest;

TEST_F(H5Atomic, NoFileUnlessCommitted) {
  const std::string p = path("out/results.h5");  // the directory is created
  std::string tmp;
  {
    h5::AtomicH5 out(p);
    tmp = out.temporary_path();
    EXPECT_TRUE(fs::exists(tmp));
    EXPECT_FALSE(fs::exists(p));
    write_sample(out.file(), 1.0);
  }  // no commit, e.g. an exception on the way
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_FALSE(fs::exists(p));

  try {
    h5::AtomicH5 out(p);
    out.file().write_scalar("x", 1.0);
    throw InputError("a failure half way");
  } catch (const InputError&) {
  }
  EXPECT_FALSE(fs::exists(p));
  EXPECT_TRUE(fs::is_empty(path("out")));

  {
    h5::AtomicH5 out(p);
    write_sample(out.file(), 1.0);
    out.commit();
    EXPECT_FALSE(fs::exists(out.temporary_path()));
  }
  EXPECT_EQ(h5::File::open(p).read_scalar_int64("stats/n_contacts"), 42);
}

TEST_F(H5Atomic, CommittedFileEqualsDirectWrite) {
  {
    h5::AtomicH5 out(path("atomic.h5"));
    write_sample(out.file(), 1.0);
    out.commit();
  }
  {
    h5::File f = h5::File::create(path("direct.h5"));
    write_sample(f, 1.0);
  }
  EXPECT_TRUE(slurp(path("atomic.h5")) == slurp(path("direct.h5")));
}

TEST_F(H5Atomic, ReadableByH5py) {
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed";
  const std::string p = path("py.h5");
  {
    h5::AtomicH5 out(p);
    write_sample(out.file(), 1.0);
    out.commit();
  }
  const std::string script = fmt::format(
      "import h5py, sys\n"
      "f = h5py.File('{}', 'r')\n"
      "ok = (f['particles/centres'].shape == (4, 3)\n"
      "      and f['particles/ids'][()].tolist() == [3, 1, 4, 1]\n"
      "      and f['stats/n_contacts'][()] == 42\n"
      "      and f['provenance'].asstr()[()] == 'softpack test, scale 1'\n"
      "      and f.attrs['code_version'].decode() == '0.1.0 (test)'\n"
      "      and f['particles/centres'].attrs['unit'].decode() == 'm'\n"
      "      and f['stats'].attrs['seed'].decode() == '7'\n"
      // Under a checksum h5py verifies: arrays by Fletcher-32, scalars and strings compact.
      "      and f['particles/centres'].fletcher32 and f['particles/ids'].fletcher32\n"
      "      and f['stats/n_contacts'].id.get_create_plist().get_layout() == h5py.h5d.COMPACT\n"
      "      and f['provenance'].id.get_create_plist().get_layout() == h5py.h5d.COMPACT)\n"
      "sys.exit(0 if ok else 1)\n",
      p);
  spit(path("check.py"), script);
  EXPECT_EQ(std::system(fmt::format("/usr/bin/python3 '{}'", path("check.py")).c_str()), 0);
}

// ---------------------------------------------------------------------------------------------

const std::vector<Vec3> kCentres = {Vec3(0, 0, 0), Vec3(1.0 / 3.0, -2e-3, 5e-4),
                                    Vec3(0.1, 0.2, 0.3)};
const std::vector<double> kRadii = {1e-3, 2.5e-4, 1.0 / 7.0};


}  // namespace
}  // namespace softpack
