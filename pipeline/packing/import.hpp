// Packings made elsewhere (LAMMPS, LIGGGHTS, a user's generator), measured like generated ones:
// the profile's `packing.import` section names a source file per seed (docs/import.md), and
// softpack-import turns it into a packing file every stage accepts. The spheres are scaled to
// metres, moved so that the shell's centre is the origin, and checked like a generated packing:
// inside the shell, no overlap beyond a tolerance.
#pragma once
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "config/yaml_node.hpp"
#include "core/types.hpp"
#include "io/particle_import.hpp"

namespace softpack {

/// Where the rigid shell comes from: given in the profile (radius and centre, in the file's
/// unit), read from the file's box (LAMMPS box, extended XYZ Lattice and Origin: it must be a
/// cube; the shell is the sphere inscribed in it), or the enclosing sphere (centred on the
/// middle of the grains' bounding box, touching the farthest grain).
enum class ShellSource { given, read, enclosing };
const char* name(ShellSource s);

struct ImportSpec {
  std::map<std::uint64_t, std::string> files;  ///< seed -> source file (relative to the working directory)
  std::optional<ForeignFormat> format;         ///< from each file's extension when absent
  double length_unit = 1.0;                    ///< metres per length unit of the files
  ShellSource shell = ShellSource::read;
  double shell_radius = 0.0;                   ///< given: in the file's unit
  Vec3 shell_centre = Vec3::Zero();            ///< given: in the file's unit
  double overlap_tolerance = 1e-6;             ///< largest overlap allowed, over the smaller radius
  /// The largest gap allowed between the outermost grain and a shell read from the box or
  /// enclosing the seeds, over Rs: a wider one means the box is not the shell (a LAMMPS box around
  /// a wall region is often larger). A given shell is the user's word: its gap is reported only.
  double max_shell_gap = 0.02;
  /// The file's density column: taken (times density_unit, kg/m^3 per the file's density unit)
  /// and checked against the profile's material.density by the stages that use it, or ignored
  /// (`density: ignore`: the profile's applies, said in the packing file).
  bool density_ignored = false;
  double density_unit = 1.0;
  /// The face of the file's packing the wall presses (the soft-solid wall comes from +x): "+x"
  /// keeps the file's axes; another face is turned onto +x by a proper rotation about the shell's
  /// centre (+y: (x,y,z) -> (y,-x,z); +z: (z,y,-x); -x: (-x,-y,z); -y: (-y,x,z); -z: (-z,y,x)).
  std::string pressed_face = "+x";
  /// A file of several atom types is refused (softpack's grains share the profile's material)
  /// unless `atom_types: one-material` takes every type as that material.
  bool types_one_material = false;
  /// A file whose grains move (LAMMPS's Velocities, an XYZ velocity column) is refused unless
  /// `velocities: rest` starts them at rest, as every packing starts.
  bool velocities_rest = false;
};

/// Reads `packing.import` (file, line and column in messages); every seed of the profile must
/// have a file, and every file a seed of the profile.
ImportSpec parse_import(const ConfigNode& import, const std::vector<std::uint64_t>& seeds);

struct ImportedPacking {
  std::vector<Vec3> centres;  ///< [m], the shell's centre at the origin
  std::vector<double> radii;  ///< [m]
  double Rs = 0.0;            ///< shell radius [m]
  Vec3 shell_centre_in_file = Vec3::Zero();  ///< where the shell's centre was, in the file's unit
  ForeignFormat format = ForeignFormat::text;
  std::string source, sha256;  ///< the source file and the SHA-256 of its bytes
  double largest_overlap = 0.0;  ///< deepest overlap between two grains, over the smaller radius
  double shell_gap = 0.0;        ///< 1 - (outermost grain's reach) / Rs: the gap to the shell, over Rs
  std::size_t moved_in = 0;      ///< grains pressing into the shell (within overlap_tolerance), moved in to touch it
  double largest_move = 0.0;     ///< the largest such move, over the grain's radius
  /// The grains' density [kg/m^3] from the file's column (one value: the grains share one
  /// material); NaN when the file has none or the profile ignores it.
  double density = std::numeric_limits<double>::quiet_NaN();
  /// What the file holds and the import does not use, with what applies instead ("" for nothing):
  /// atom types taken as one material, velocities set to rest, sections and columns not read.
  std::string not_used;
};

/// Imports the source file of `seed`: InputError naming the file, its line and what is wrong
/// (a grain beyond the shell by more than overlap_tolerance of its radius -- within it, the grain is
/// moved in to touch the shell, and counted --, two grains overlapping beyond the tolerance, a shell read or
/// enclosing that leaves a gap wider than max_shell_gap, a bad file).
ImportedPacking import_packing(const ImportSpec& spec, std::uint64_t seed);

/// The proper rotation that turns `face` (+x, -x, +y, -y, +z, -z) onto +x.
Eigen::Matrix3d face_onto_x(const std::string& face);

/// One line per seed, "seed <seed> <file> sha256 <digest>": what the stages' stamps add to the
/// profile's text, so that a changed source file reruns its packing and everything after.
std::string import_sources_text(const ImportSpec& spec);

}  // namespace softpack
