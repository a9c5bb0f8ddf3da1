// The exports for viewers (io/particle_export.hpp): ParaView's VTK PolyData and OVITO's extended
// XYZ, their headers, full-precision values and refusals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/particle_export.hpp"
#include "unit/io_fixture.hpp"

namespace softpack {
namespace {

using namespace io_test;

using ExportVtp = IoTest;

TEST_F(ExportVtp, HeaderCellsAndPointData) {
  const std::string p = path("snap.vtp");
  const std::vector<double> v = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::vector<PointField> extra = {{"velocity", v, 3}};
  write_vtp(p, kCentres, kRadii, extra, "softpack 0.1.0 -- seed 7 <x>");
  const std::vector<std::string> lines = lines_of(p);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "<?xml version=\"1.0\"?>");
  EXPECT_EQ(lines[1], "<!-- softpack 0.1.0 - - seed 7 <x> -->");
  const std::string text = slurp(p);
  EXPECT_NE(text.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPoints=\"3\" NumberOfVerts=\"3\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"radius\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"diameter\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"velocity\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(text.find(fmt::format("{:.17g} {:.17g} {:.17g}", 1.0 / 3.0, -2e-3, 5e-4)),
            std::string::npos);
  // 6 opening lines, 6 arrays of (open, 3 rows, close), 8 other tags.
  EXPECT_EQ(lines.size(), 6u + 6u * 5u + 8u);
  if (python_has("xml.etree.ElementTree")) {  // well-formed XML
    EXPECT_EQ(std::system(fmt::format("/usr/bin/python3 -c \"import xml.etree.ElementTree as E; "
                                      "E.parse('{}')\"",
                                      p)
                              .c_str()),
              0);
  }
}

TEST_F(ExportVtp, RefusesMismatchedSizes) {
  EXPECT_THROW(write_vtp(path("x.vtp"), kCentres, std::vector<double>{1.0}),
               std::invalid_argument);
  const std::vector<double> two = {1, 2};
  const std::vector<PointField> extra = {{"short", two, 1}};
  EXPECT_THROW(write_vtp(path("x.vtp"), kCentres, kRadii, extra), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path("x.vtp")));
}

using ExportXyz = IoTest;

TEST_F(ExportXyz, HeaderAndFullPrecisionLines) {
  const std::string p = path("snap.xyz");
  ExportBox box;
  box.lo = Vec3(-1, -1, 0);
  box.hi = Vec3(1, 1, 2.5);
  write_extended_xyz(p, kCentres, kRadii, box, "softpack \"0.1.0\"\nseed\\7");
  const std::vector<std::string> lines = lines_of(p);
  ASSERT_EQ(lines.size(), 2u + kCentres.size());
  EXPECT_EQ(lines[0], "3");
  EXPECT_EQ(lines[1],
            "Properties=species:S:1:pos:R:3:radius:R:1 Lattice=\"2 0 0 0 2 0 0 0 2.5\" "
            "Origin=\"-1 -1 0\" pbc=\"F F F\" provenance=\"softpack '0.1.0' seed/7\"");
  for (std::size_t i = 0; i < kCentres.size(); ++i) {
    std::istringstream in(lines[2 + i]);
    std::string species;
    double x, y, z, r;
    in >> species >> x >> y >> z >> r;
    EXPECT_EQ(species, "X");
    EXPECT_EQ(x, kCentres[i].x());  // exact: %.17g round-trips
    EXPECT_EQ(y, kCentres[i].y());
    EXPECT_EQ(z, kCentres[i].z());
    EXPECT_EQ(r, kRadii[i]);
  }
}

TEST_F(ExportXyz, NoBoxNoProvenance) {
  const std::string p = path("bare.xyz");
  write_extended_xyz(p, kCentres, kRadii);
  const std::vector<std::string> lines = lines_of(p);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[1], "Properties=species:S:1:pos:R:3:radius:R:1");
}

}  // namespace
}  // namespace softpack
