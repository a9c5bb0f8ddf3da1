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
};

/// Reads the file. InputError with file, line and what is wrong: unreadable, not the format,
/// a count that disagrees with the header, a non-finite value, a radius <= 0, a density <= 0, image flags in a
/// triclinic box, a LAMMPS atom style other than sphere, an XYZ file without positions or
/// radii. A triclinic box or a non-orthogonal Lattice is read as no box (no_box_reason says so).
ForeignSpheres read_foreign_spheres(const std::string& path, ForeignFormat format);

}  // namespace softpack
