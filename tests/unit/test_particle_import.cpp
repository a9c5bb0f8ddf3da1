// The readers of other programs' packings (io/particle_import.hpp) and the import's checks
// (packing/import.hpp): what each format says is what is read, and what is wrong is refused
// with the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/error.hpp"
#include "io/sha256.hpp"
#include "io/particle_import.hpp"
#include "packing/import.hpp"

namespace softpack {
namespace {

std::string write(const std::string& name, const std::string& text) {
  // One folder per process: two builds' suites may run at once.
  const auto dir = std::filesystem::temp_directory_path() / ("softpack-test-import-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& path, ForeignFormat f) {
  try {
    read_foreign_spheres(path, f);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kLammps =
    "LAMMPS data file via write_data\n\n2 atoms\n1 atom types\n\n"
    "-1 1 xlo xhi\n-1 1 ylo yhi\n0 4 zlo zhi\n\n"
    "Masses\n\n1 1.0\n\n"
    "Atoms # sphere\n\n"
    "7 1 0.5 2500 0.1 0.2 0.3 0 0 0\n"
    "8 1 0.25 2500 0.5 0.5 0.5 1 0 -1  # image flags\n\n"
    "Velocities\n\n7 0 0 0 0 0 0\n8 0 0 0 0 0 0\n";

TEST(ParticleImport, LammpsDataFileWithImageFlags) {
  const ForeignSpheres s = read_foreign_spheres(write("a.data", kLammps), ForeignFormat::lammps);
  ASSERT_EQ(s.radii.size(), 2u);
  EXPECT_DOUBLE_EQ(s.radii[0], 0.25);  // half the diameter
  EXPECT_DOUBLE_EQ(s.radii[1], 0.125);
  EXPECT_EQ(s.centres[0], Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(s.centres[1], Vec3(0.5 + 2.0, 0.5, 0.5 - 4.0));  // unwrapped through the box
  EXPECT_EQ(s.lines[1], 17);
  ASSERT_TRUE(s.box);
  EXPECT_EQ(s.box->lo, Vec3(-1, -1, 0));
  EXPECT_EQ(s.box->hi, Vec3(1, 1, 4));
  EXPECT_EQ(s.densities.size(), 2u);  // the density column, read (the stages compare it with material.density)
}

TEST(ParticleImport, LammpsRefusesWhatItCannotRead) {
  std::string t = kLammps;
  EXPECT_NE(error_of(write("b.data", t.replace(t.find("# sphere"), 8, "# atomic")), ForeignFormat::lammps)
                .find("b.data:14: atom_style atomic"),
            std::string::npos);
  t = kLammps;
  EXPECT_NE(error_of(write("c.data", t.replace(t.find("2 atoms"), 7, "3 atoms")), ForeignFormat::lammps)
                .find("the header says 3 atoms, the Atoms section holds 2"),
            std::string::npos);
  t = kLammps;
  EXPECT_NE(error_of(write("d.data", t.replace(t.find("0.25 2500"), 4, "0.00")), ForeignFormat::lammps).find("d.data:17: radius 0"),
            std::string::npos);
  // A triclinic box: read as no box (the shell must then be given or enclosing); image flags
  // cannot be unwrapped through it.
  t = kLammps;
  t.replace(t.find("\n\nMasses"), 0, "\n0.5 0 0 xy xz yz");
  EXPECT_NE(error_of(write("e.data", t), ForeignFormat::lammps).find("e.data:18: a non-zero image flag needs an orthogonal box"),
            std::string::npos);
  t.replace(t.find("1 0 -1"), 6, "0 0 0");
  const ForeignSpheres s = read_foreign_spheres(write("f.data", t), ForeignFormat::lammps);
  EXPECT_FALSE(s.box);
  EXPECT_EQ(s.no_box_reason, "a triclinic box");
  EXPECT_NE(error_of(write("g.data", std::string(kLammps).replace(std::string(kLammps).find("2 atoms"), 7, "inf atoms")),
                     ForeignFormat::lammps)
                .find("g.data:3: the count of atoms 'inf' is not allowed"),
            std::string::npos);
}

TEST(ParticleImport, ExtendedXyzWithDiameterAndOrigin) {
  const std::string path = write("a.xyz",
                                 "2\nLattice=\"2 0 0 0 2 0 0 0 2\" Origin=\"-1 -1 -1\" "
                                 "Properties=species:S:1:pos:R:3:Diameter:R:1 pbc=\"F F F\"\n"
                                 "X 0.1 0.2 0.3 0.5\nX -0.5 0 0.5 0.25\n");
  const ForeignSpheres s = read_foreign_spheres(path, ForeignFormat::xyz);
  ASSERT_EQ(s.radii.size(), 2u);
  EXPECT_DOUBLE_EQ(s.radii[1], 0.125);
  EXPECT_EQ(s.centres[1], Vec3(-0.5, 0, 0.5));
  ASSERT_TRUE(s.box);
  EXPECT_EQ(s.box->lo, Vec3(-1, -1, -1));
  EXPECT_EQ(s.box->hi, Vec3(1, 1, 1));
  EXPECT_TRUE(s.densities.empty());  // no density property
  const ForeignSpheres d = read_foreign_spheres(write("d.xyz", "1\nProperties=species:S:1:pos:R:3:radius:R:1:density:R:1\nX 0 0 0 1 2500\n"),
                                                ForeignFormat::xyz);
  EXPECT_EQ(d.densities, std::vector<double>{2500.0});
  EXPECT_NE(error_of(write("b.xyz", "1\nProperties=species:S:1:pos:R:3\nX 0 0 0\n"), ForeignFormat::xyz).find("no radius"),
            std::string::npos);
  EXPECT_NE(error_of(write("c.xyz", "1\nProperties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 1\n1\n\nX 0 0 0 1\n"), ForeignFormat::xyz)
                .find("c.xyz:4: a second frame"),
            std::string::npos);
}

TEST(ParticleImport, TextAndFormatNames) {
  const ForeignSpheres s = read_foreign_spheres(write("a.txt", "# x y z r\n0 0 0 1\n\n3 0 0 2 # big\n"), ForeignFormat::text);
  ASSERT_EQ(s.radii.size(), 2u);
  EXPECT_EQ(s.lines[1], 4);
  EXPECT_FALSE(s.box);
  EXPECT_EQ(foreign_format_of("x/run.lmp"), ForeignFormat::lammps);
  EXPECT_EQ(foreign_format_of("run.EXTXYZ"), ForeignFormat::xyz);
  EXPECT_THROW(foreign_format_of("run.h5"), InputError);
  EXPECT_NE(error_of(write("b.txt", "0 0 0\n"), ForeignFormat::text).find("b.txt:1: 3 values; expected 4"), std::string::npos);
}

TEST(ParticleImport, ShellEnclosingAndOverlapTolerance) {
  ImportSpec spec;
  spec.files[1] = write("two.txt", "0 0 0 1\n3 0 0 2\n");  // touching: |x1 - x2| = r1 + r2
  spec.shell = ShellSource::enclosing;
  spec.length_unit = 0.5;
  const ImportedPacking p = import_packing(spec, 1);
  // Bounding box x in [-1, 5]: centre x = 2, the shell through the far side of both grains.
  EXPECT_DOUBLE_EQ(p.shell_centre_in_file.x(), 2.0);
  EXPECT_DOUBLE_EQ(p.Rs, 3.0 * 0.5);
  EXPECT_DOUBLE_EQ(p.centres[0].x(), -1.0);  // (0 - 2) * 0.5
  EXPECT_DOUBLE_EQ(p.radii[1], 1.0);
  EXPECT_EQ(p.sha256, sha256_of_file(spec.files[1]));
  EXPECT_EQ(p.sha256.size(), 64u);
  spec.files[1] = write("overlap.txt", "0 0 0 1\n2.9 0 0 2\n");  // overlap 0.1 of the smaller radius
  spec.overlap_tolerance = 0.2;
  EXPECT_NEAR(import_packing(spec, 1).largest_overlap, 0.1, 1e-12);
  spec.overlap_tolerance = 0.05;
  try {
    import_packing(spec, 1);
    FAIL() << "an overlap of 0.1 passed a tolerance of 0.05";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("overlap.txt:1 and "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("overlap.txt:2: these grains overlap by 0.1"), std::string::npos) << e.what();
  }
}

TEST(ParticleImport, Sha256OfKnownText) {
  // sha256("abc"), FIPS 180-2 appendix B.1.
  EXPECT_EQ(sha256_of_file(write("abc.txt", "abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// A shell read from the box or enclosing the seeds must hold the grains without a wide gap (a
// LAMMPS box around a wall region is often larger than the wall: the shell came out 10 % too big,
// with no word); a shell the user gives is the user's word, its gap reported.
TEST(ParticleImport, AShellThatLeavesAWideGapIsRefusedUnlessGiven) {
  // A grain of radius 1 touching a sphere of radius 2 about the origin; the box is +-2.2.
  const std::string path = write("wide.xyz", "2\nProperties=species:S:1:pos:R:3:radius:R:1 Lattice=\"4.4 0 0 0 4.4 0 0 0 4.4\" "
                                             "Origin=\"-2.2 -2.2 -2.2\"\nX 1 0 0 1\nX -1 0 0 1\n");
  ImportSpec spec;
  spec.files[1] = path;
  spec.shell = ShellSource::read;
  try {
    import_packing(spec, 1);
    FAIL() << "a box 10 % wider than the grains' reach was taken for the shell";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wide.xyz:3: the outermost grain reaches 2 from the shell's centre: a gap of 9.1 %"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("max_shell_gap = 0.02"), std::string::npos) << e.what();
  }
  spec.max_shell_gap = 0.1;
  EXPECT_NEAR(import_packing(spec, 1).shell_gap, 1.0 - 2.0 / 2.2, 1e-12);
  spec.max_shell_gap = 0.02;
  spec.shell = ShellSource::given;
  spec.shell_radius = 2.2;
  EXPECT_NEAR(import_packing(spec, 1).shell_gap, 1.0 - 2.0 / 2.2, 1e-12);  // given: reported, not refused
  spec.shell = ShellSource::enclosing;  // the largest seed's sphere: the smaller seed is refused
  spec.files[2] = write("small.txt", "0 0 0 1\n");
  EXPECT_NEAR(import_packing(spec, 1).shell_gap, 0.0, 1e-12);
  EXPECT_THROW(import_packing(spec, 2), InputError);
}

// The wall presses +x: a packing whose pressed face was another is turned onto it by a proper
// rotation about the shell's centre (issue 31: a LAMMPS wall came down on +z).
TEST(ParticleImport, ThePressedFaceIsTurnedOntoPlusX) {
  for (const std::string face : {"+x", "-x", "+y", "-y", "+z", "-z"}) {
    const Eigen::Matrix3d m = face_onto_x(face);
    Vec3 n = Vec3::Zero();
    n[face[1] - 'x'] = face[0] == '+' ? 1.0 : -1.0;
    EXPECT_EQ(m * n, Vec3(1, 0, 0)) << face;
    EXPECT_DOUBLE_EQ(m.determinant(), 1.0) << face << ": not a proper rotation";
    EXPECT_TRUE((m * m.transpose()).isIdentity(0.0)) << face;
  }
  ImportSpec spec;
  spec.files[1] = write("face.txt", "0 0 1 1\n0 0 -1 1\n");  // two grains along z, touching the shell of radius 2 at z = +-2
  spec.shell = ShellSource::given;
  spec.shell_radius = 2.0;
  spec.pressed_face = "+z";
  const ImportedPacking p = import_packing(spec, 1);
  EXPECT_EQ(p.centres[0], Vec3(1, 0, 0));  // the grain at +z now faces the wall
  EXPECT_EQ(p.centres[1], Vec3(-1, 0, 0));
  EXPECT_THROW(face_onto_x("+w"), InputError);
}

std::string import_error(const ImportSpec& spec) {
  try {
    import_packing(spec, 1);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every column is used, refused with what would apply, or named (issue 31: a column read and
// dropped is a value silently assumed): several atom types and moving grains are refused unless
// the profile says how to take them; other sections and columns are named in not_used.
TEST(ParticleImport, TypesAndVelocitiesAreRefusedUnlessTheProfileSaysHowToTakeThem) {
  std::string t = kLammps;  // at rest, one type: nothing to say but the Masses section
  t.replace(t.find("8 1 0.25"), 8, "8 1 0.25").replace(t.find("1 0 -1  #"), 6, "0 0 0 ");
  ImportSpec spec;
  spec.files[1] = write("rest.data", t);
  spec.shell = ShellSource::given;
  spec.shell_radius = 10.0;
  EXPECT_EQ(import_packing(spec, 1).not_used, "section Masses");
  const ForeignSpheres rest = read_foreign_spheres(spec.files[1], ForeignFormat::lammps);
  EXPECT_EQ(rest.max_speed, 0.0);
  EXPECT_EQ(rest.types, std::vector<std::string>{"1"});

  std::string two = t;
  spec.files[1] = write("types.data", two.replace(two.find("8 1 0.25"), 8, "8 2 0.25"));
  EXPECT_NE(import_error(spec).find("types.data:17: atom type 2, after 1 (the file's types: 1 2): softpack's grains share one material"),
            std::string::npos) << import_error(spec);
  spec.types_one_material = true;
  EXPECT_EQ(import_packing(spec, 1).not_used, "atom types 1 2 (one material: the profile's); section Masses");

  std::string moving = t;
  spec.files[1] = write("moving.data", moving.replace(moving.find("8 0 0 0 0 0 0"), 13, "8 0 3 4 0 0 1"));
  EXPECT_NE(import_error(spec).find("moving.data:22: the grains move (its Velocities section: |v| up to 5, |omega| up to 1, in the "
                                    "file's units): softpack starts every packing at rest; give packing.import.velocities: rest"),
            std::string::npos) << import_error(spec);
  spec.velocities_rest = true;
  EXPECT_EQ(import_packing(spec, 1).not_used,
            "the grains move (its Velocities section: |v| up to 5, |omega| up to 1, in the file's units), started at rest; section Masses");

  // Extended XYZ: species, vel and omega read; other columns named.
  spec = ImportSpec{};
  spec.shell = ShellSource::given;
  spec.shell_radius = 10.0;
  spec.files[1] = write("cols.xyz", "2\nProperties=species:S:1:pos:R:3:radius:R:1:vel:R:3:forces:R:3:id:I:1\n"
                                    "H 0 0 0 1 0 0 0 1 1 1 7\nH 3 0 0 1 0 0 0.5 0 0 0 8\n");
  EXPECT_NE(import_error(spec).find("cols.xyz:4: the grains move (its vel column: |v| up to 0.5, in the file's units)"),
            std::string::npos) << import_error(spec);
  spec.velocities_rest = true;
  EXPECT_EQ(import_packing(spec, 1).not_used, "the grains move (its vel column: |v| up to 0.5, in the file's units), started at rest; "
                                             "column forces; column id");
}

}  // namespace
}  // namespace softpack
