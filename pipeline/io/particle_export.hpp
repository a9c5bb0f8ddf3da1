// Sphere snapshots for visualisation: VTK PolyData (.vtp) for ParaView and extended XYZ for
// OVITO and ASE. Text, full precision (%.17g), written atomically. Lengths in metres.
#pragma once
#include <array>
#include <optional>
#include <span>
#include <string>

#include "core/types.hpp"

namespace softpack {

/// An extra per-sphere array for the .vtp file: `components` values per sphere, row-major.
struct PointField {
  std::string name;
  std::span<const double> values;
  int components = 1;
};

/// The simulation box [lo, hi] of an extended-XYZ file (its Lattice, Origin and pbc keys).
struct ExportBox {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  std::array<bool, 3> periodic{false, false, false};
};

/// VTK XML PolyData, ASCII: one point and one vertex cell per sphere (ParaView draws them;
/// Glyph > Sphere scaled by "radius" shows the spheres), point data "radius" and "diameter"
/// (Float64) and the extra fields. The provenance goes into an XML comment.
/// Throws std::invalid_argument when array sizes disagree, InputError when it cannot write.
void write_vtp(const std::string& path, std::span<const Vec3> centres,
               std::span<const double> radii, std::span<const PointField> extra_point_fields = {},
               const std::string& provenance = {});

/// Extended XYZ: the count, then "Properties=species:S:1:pos:R:3:radius:R:1", the box (when
/// given) and provenance="..." on one line, then one "X x y z r" line per sphere. The
/// provenance is made one line without double quotes or backslashes, which readers differ on.
void write_extended_xyz(const std::string& path, std::span<const Vec3> centres,
                        std::span<const double> radii,
                        const std::optional<ExportBox>& box = std::nullopt,
                        const std::string& provenance = {});

/// The pictures of a packing in its shell (radius Rs, centred at the origin), each when its path
/// is not empty: .vtp, and extended XYZ with the shell's cube as its (non-periodic) box.
void write_packing_pictures(const std::string& vtp_path, const std::string& xyz_path, std::span<const Vec3> centres,
                            std::span<const double> radii, double Rs, const std::string& provenance);

}  // namespace softpack
