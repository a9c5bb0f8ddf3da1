// Sphere packings written by other programs, read for softpack-import: a LAMMPS data file with
// atom_style sphere, an extended XYZ file (ASE, OVITO, our own export), or plain text "x y z r".
// Lengths in the file's own unit (the caller scales them). Each sphere keeps the line it came
// from, so that a message can point at it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace softpack {

enum class ForeignFormat { lammps, xyz, text };

/// "lammps", "xyz", "text".
const char* name(ForeignFormat f);
/// From a name above; InputError listing the allowed names.
ForeignFormat parse_foreign_format(const std::string& text);
/// From a file name: .data .lmp .lammps -> lammps, .xyz .extxyz -> xyz, .txt .xyzr -> text;
/// InputError naming the file and the extensions when none fits.
ForeignFormat foreign_format_of(const std::string& path);

/// An axis-aligned box [lo, hi] (LAMMPS's box, an extended XYZ file's orthogonal Lattice + Origin).
struct ForeignBox {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
};

struct ForeignSpheres {
  std::vector<Vec3> centres;
  std::vector<double> radii;
  std::vector<long> lines;        ///< 1-based line of each sphere in the file
  /// Each sphere's density, in the file's unit, when the file has the column (LAMMPS atom_style
  /// sphere; an extended XYZ `density` property); empty otherwise.
  std::vector<double> densities;
  std::optional<ForeignBox> box;  ///< when the file gives an orthogonal one
  std::string no_box_reason;      ///< why there is none, when the file has a box of another shape
  /// The atom types the file gives (LAMMPS's `type` column, an extended XYZ `species` or `type`
  /// column), distinct, in the order met; `type_line`: the line of a sphere of the second one.
  std::vector<std::string> types;
  long type_line = 0;
  /// The grains' motion, when the file gives it (LAMMPS's Velocities section, an extended XYZ
  /// `vel`/`velo`/`velocities`/`momenta` or `omega` column): the largest |v| and |omega|, in the file's
  /// units; `motion_line`: the line of the fastest grain; `motion_source`: where it was read.
  std::optional<double> max_speed, max_spin;
  long motion_line = 0;
  std::string motion_source;
  /// What the file holds that the import does not read (other LAMMPS sections, other XYZ columns),
  /// named for the summary and the packing file.
  std::vector<std::string> not_read;
};

/// Reads the file. InputError with file, line and what is wrong: unreadable, not the format,
/// a count that disagrees with the header, a non-finite value, a radius <= 0, a density <= 0, image flags in a
/// triclinic box, a LAMMPS atom style other than sphere, an XYZ file without positions or
/// radii. A triclinic box or a non-orthogonal Lattice is read as no box (no_box_reason says so).
ForeignSpheres read_foreign_spheres(const std::string& path, ForeignFormat format);

}  // namespace softpack
