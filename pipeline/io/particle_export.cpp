#include "io/particle_export.hpp"

#include <fmt/format.h>

#include <iterator>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace softpack {
namespace {

void check_sizes(const std::string& path, std::span<const Vec3> centres,
                 std::span<const double> radii) {
  if (centres.size() != radii.size())
    throw std::invalid_argument(fmt::format("{}: {} centres but {} radii", path, centres.size(),
                                            radii.size()));
}

// For XML attribute values.
std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// An XML comment may not contain "--" nor end with "-".
std::string xml_comment_text(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '-' && !out.empty() && out.back() == '-') out += ' ';
    out += c;
  }
  return out;
}

// One line, no double quotes or backslashes: extended-XYZ readers disagree on escapes.
std::string xyz_value(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"') out += '\'';
    else if (c == '\\') out += '/';
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += ' ';
    else out += c;
  }
  return out;
}

using Out = std::back_insert_iterator<fmt::memory_buffer>;

void scalar_array(Out out, const std::string& name, std::span<const double> values,
                  double factor) {
  fmt::format_to(out, "        <DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n",
                 xml_escape(name));
  for (double v : values) fmt::format_to(out, "          {:.17g}\n", factor * v);
  fmt::format_to(out, "        </DataArray>\n");
}

}  // namespace

void write_vtp(const std::string& path, std::span<const Vec3> centres,
               std::span<const double> radii, std::span<const PointField> extra_point_fields,
               const std::string& provenance) {
  check_sizes(path, centres, radii);
  const std::size_t n = centres.size();
  for (const PointField& f : extra_point_fields) {
    if (f.name.empty() || f.components < 1 ||
        f.values.size() != n * static_cast<std::size_t>(f.components))
      throw std::invalid_argument(fmt::format(
          "{}: point field '{}': {} values for {} spheres of {} components", path, f.name,
          f.values.size(), n, f.components));
  }

  fmt::memory_buffer buf;
  const Out out(buf);
  fmt::format_to(out, "<?xml version=\"1.0\"?>\n");
  if (!provenance.empty()) fmt::format_to(out, "<!-- {} -->\n", xml_comment_text(provenance));
  fmt::format_to(out,
                 "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                 "header_type=\"UInt64\">\n"
                 "  <PolyData>\n"
                 "    <Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" NumberOfLines=\"0\" "
                 "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                 "      <PointData Scalars=\"radius\">\n",
                 n);
  scalar_array(out, "radius", radii, 1.0);
  scalar_array(out, "diameter", radii, 2.0);
  for (const PointField& f : extra_point_fields) {
    fmt::format_to(out,
                   "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                   "format=\"ascii\">\n",
                   xml_escape(f.name), f.components);
    const auto c = static_cast<std::size_t>(f.components);
    for (std::size_t i = 0; i < n; ++i) {
      fmt::format_to(out, "         ");
      for (std::size_t k = 0; k < c; ++k) fmt::format_to(out, " {:.17g}", f.values[i * c + k]);
      fmt::format_to(out, "\n");
    }
    fmt::format_to(out, "        </DataArray>\n");
  }
  fmt::format_to(out,
                 "      </PointData>\n"
                 "      <Points>\n"
                 "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                 "format=\"ascii\">\n");
  for (const Vec3& x : centres)
    fmt::format_to(out, "          {:.17g} {:.17g} {:.17g}\n", x.x(), x.y(), x.z());
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "      </Points>\n"
                 "      <Verts>\n"
                 "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < n; ++i) fmt::format_to(out, "          {}\n", i);
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (std::size_t i = 0; i < n; ++i) fmt::format_to(out, "          {}\n", i + 1);
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "      </Verts>\n"
                 "    </Piece>\n"
                 "  </PolyData>\n"
                 "</VTKFile>\n");
  write_file_atomically(path, fmt::to_string(buf));
}

void write_extended_xyz(const std::string& path, std::span<const Vec3> centres,
                        std::span<const double> radii, const std::optional<ExportBox>& box,
                        const std::string& provenance) {
  check_sizes(path, centres, radii);
  fmt::memory_buffer buf;
  const Out out(buf);
  fmt::format_to(out, "{}\nProperties=species:S:1:pos:R:3:radius:R:1", centres.size());
  if (box) {
    const Vec3 l = box->hi - box->lo;
    fmt::format_to(out,
                   " Lattice=\"{:.17g} 0 0 0 {:.17g} 0 0 0 {:.17g}\""
                   " Origin=\"{:.17g} {:.17g} {:.17g}\" pbc=\"{} {} {}\"",
                   l.x(), l.y(), l.z(), box->lo.x(), box->lo.y(), box->lo.z(),
                   box->periodic[0] ? 'T' : 'F', box->periodic[1] ? 'T' : 'F',
                   box->periodic[2] ? 'T' : 'F');
  }
  if (!provenance.empty()) fmt::format_to(out, " provenance=\"{}\"", xyz_value(provenance));
  fmt::format_to(out, "\n");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3& x = centres[i];
    fmt::format_to(out, "X {:.17g} {:.17g} {:.17g} {:.17g}\n", x.x(), x.y(), x.z(), radii[i]);
  }
  write_file_atomically(path, fmt::to_string(buf));
}

void write_packing_pictures(const std::string& vtp_path, const std::string& xyz_path, std::span<const Vec3> centres,
                            std::span<const double> radii, double Rs, const std::string& provenance) {
  if (!vtp_path.empty()) write_vtp(vtp_path, centres, radii, {}, provenance);
  if (!xyz_path.empty())
    write_extended_xyz(xyz_path, centres, radii, ExportBox{Vec3::Constant(-Rs), Vec3::Constant(Rs), {false, false, false}}, provenance);
}

}  // namespace softpack
