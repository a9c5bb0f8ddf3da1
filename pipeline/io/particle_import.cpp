#include "io/particle_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace softpack {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A file's lines, and the place of a message: "FILE:LINE: ".
struct Lines {
  std::string path;
  std::vector<std::string> text;
  std::string at(std::size_t k) const { return fmt::format("{}:{}: ", path, k + 1); }
  [[noreturn]] void fail(std::size_t k, const std::string& why) const { throw InputError(at(k) + why); }
};

Lines read_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read this file", path));
  Lines l{path, {}};
  for (std::string s; std::getline(in, s);) {
    if (!s.empty() && s.back() == '\r') s.pop_back();
    l.text.push_back(s);
  }
  return l;
}

std::optional<double> to_number(const std::string& w) {
  double v = 0.0;
  const char* end = w.data() + w.size();
  const auto [p, ec] = std::from_chars(w.data(), end, v);
  if (ec != std::errc() || p != end) return std::nullopt;
  return v;
}

// A count: decimal digits only, at most 10^9 (a file of more spheres is not a packing we can run).
long count(const Lines& l, std::size_t k, const std::string& w, const char* what) {
  long long v = -1;
  const char* end = w.data() + w.size();
  const auto [p, ec] = std::from_chars(w.data(), end, v);
  if (ec != std::errc() || p != end || v < 0 || v > 1000000000LL)
    l.fail(k, fmt::format("{} '{}' is not allowed; allowed: a whole number from 0 to 1e9", what, w));
  return static_cast<long>(v);
}

double number(const Lines& l, std::size_t k, const std::string& w, const char* what) {
  const auto v = to_number(w);
  if (!v || !std::isfinite(*v)) l.fail(k, fmt::format("{} '{}' is not a finite number", what, w));
  return *v;
}

void add_sphere(ForeignSpheres& s, const Lines& l, std::size_t k, const Vec3& x, double r) {
  if (!(r > 0.0)) l.fail(k, fmt::format("radius {} is not allowed; allowed: a radius > 0 (a grain, not a point)", r));
  s.centres.push_back(x);
  s.radii.push_back(r);
  s.lines.push_back(static_cast<long>(k + 1));
}

std::string strip_comment(const std::string& s) { return s.substr(0, s.find('#')); }

// The entries of a LAMMPS section from line k: f(k, words) for each line that is not blank, up to
// the next keyword (a line whose first word is not a number), where k is left.
template <class F>
void each_entry(const Lines& l, std::size_t& k, F&& f) {
  for (; k < l.text.size(); ++k) {
    const std::vector<std::string> e = split(strip_comment(l.text[k]));
    if (e.empty()) continue;
    if (!to_number(e[0])) break;
    f(k, e);
  }
}

void add_type(ForeignSpheres& s, std::size_t k, const std::string& type) {
  if (std::find(s.types.begin(), s.types.end(), type) != s.types.end()) return;
  s.types.push_back(type);
  if (s.types.size() == 2) s.type_line = static_cast<long>(k + 1);
}

// A grain's velocity `v` or angular velocity `w` (whichever is given) on line k.
void add_motion(ForeignSpheres& s, std::size_t k, std::optional<Vec3> v, std::optional<Vec3> w) {
  const double speed = v ? v->norm() : 0.0, spin = w ? w->norm() : 0.0;
  if (v && (!s.max_speed || speed > *s.max_speed)) {
    s.max_speed = speed;
    if (speed > 0.0) s.motion_line = static_cast<long>(k + 1);
  }
  if (w && (!s.max_spin || spin > *s.max_spin)) {
    s.max_spin = spin;
    if (spin > 0.0 && !(s.max_speed && *s.max_speed > 0.0)) s.motion_line = static_cast<long>(k + 1);
  }
}

// --- LAMMPS data file (read_data): a title line, a header, then sections ------------------------
ForeignSpheres read_lammps(const Lines& l) {
  if (l.text.empty()) throw InputError(l.path + ": empty file; expected a LAMMPS data file (read_data)");
  ForeignSpheres s;
  long atoms = -1;
  bool triclinic = false;
  std::array<std::optional<std::pair<double, double>>, 3> bounds;
  std::size_t k = 1;  // line 1 is the title
  // The header: "N atoms", "lo hi xlo xhi", ...; it ends at the first section keyword.
  for (; k < l.text.size(); ++k) {
    const std::vector<std::string> w = split(strip_comment(l.text[k]));
    if (w.empty()) continue;
    if (!to_number(w[0])) break;  // a section keyword
    if (w.size() == 2 && w[1] == "atoms") {
      atoms = count(l, k, w[0], "the count of atoms");
    } else if (w.size() == 4 && w[2].size() == 3 && w[2][1] == 'l' && w[2][2] == 'o' && w[3] == std::string(1, w[2][0]) + "hi" &&
               w[2][0] >= 'x' && w[2][0] <= 'z') {
      bounds[static_cast<std::size_t>(w[2][0] - 'x')] = {number(l, k, w[0], "box bound"), number(l, k, w[1], "box bound")};
    } else if (w.size() == 6 && w[3] == "xy") {
      for (int i = 0; i < 3; ++i)
        if (number(l, k, w[static_cast<std::size_t>(i)], "tilt factor") != 0.0) triclinic = true;
    } else if (w.size() >= 4 && (w.back() == "avec" || w.back() == "bvec" || w.back() == "cvec")) {
      triclinic = true;  // a general triclinic box (LAMMPS 2024 on)
    }
  }
  if (atoms < 0) throw InputError(l.path + ": no 'N atoms' line in the header; is this a LAMMPS data file (read_data)?");
  if (triclinic)
    s.no_box_reason = "a triclinic box";
  else if (bounds[0] && bounds[1] && bounds[2])
    s.box = ForeignBox{{bounds[0]->first, bounds[1]->first, bounds[2]->first}, {bounds[0]->second, bounds[1]->second, bounds[2]->second}};
  // The sections: a keyword line, then the entries up to the next keyword.
  bool found = false;
  while (k < l.text.size()) {
    const std::string keyword_line = l.text[k];
    const std::vector<std::string> w = split(strip_comment(keyword_line));
    if (w.empty()) {
      ++k;
      continue;
    }
    const std::size_t section = k++;
    if (w[0] == "Velocities") {  // atom_style sphere: id vx vy vz wx wy wz
      s.motion_source = "its Velocities section";
      each_entry(l, k, [&](std::size_t k, const std::vector<std::string>& e) {
        if (e.size() != 7 && e.size() != 4)
          l.fail(k, fmt::format("{} columns; a Velocities line of atom_style sphere has 7 (id vx vy vz wx wy wz)", e.size()));
        const auto at = [&](std::size_t c) { return number(l, k, e[c], "velocity"); };
        add_motion(s, k, Vec3(at(1), at(2), at(3)), e.size() == 7 ? std::optional<Vec3>(Vec3(at(4), at(5), at(6))) : std::nullopt);
      });
      continue;
    }
    if (w[0] != "Atoms") {
      std::string keyword = w[0];
      for (std::size_t i = 1; i < w.size(); ++i) keyword += " " + w[i];
      s.not_read.push_back("section " + keyword);
      each_entry(l, k, [](std::size_t, const std::vector<std::string>&) {});  // skipped
      continue;
    }
    if (found) l.fail(section, "a second Atoms section");
    found = true;
    if (const std::size_t hash = keyword_line.find('#'); hash != std::string::npos) {
      const std::vector<std::string> style = split(keyword_line.substr(hash + 1));
      if (!style.empty() && style[0] != "sphere")
        l.fail(section, fmt::format("atom_style {}: softpack-import reads atom_style sphere (id type diameter density x y z)", style[0]));
    }
    each_entry(l, k, [&](std::size_t k, const std::vector<std::string>& e) {
      if (e.size() != 7 && e.size() != 10)
        l.fail(k, fmt::format("{} columns; atom_style sphere has 7 (id type diameter density x y z) or 10 (and ix iy iz)", e.size()));
      Vec3 x(number(l, k, e[4], "x"), number(l, k, e[5], "y"), number(l, k, e[6], "z"));
      if (e.size() == 10) {  // image flags: unwrap through the periodic box
        for (int i = 0; i < 3; ++i) {
          const double n = number(l, k, e[7 + static_cast<std::size_t>(i)], "image flag");
          if (n != 0.0) {
            if (!s.box) l.fail(k, "a non-zero image flag needs an orthogonal box (xlo xhi, ylo yhi, zlo zhi in the header)");
            x[i] += n * (s.box->hi[i] - s.box->lo[i]);
          }
        }
      }
      add_sphere(s, l, k, x, 0.5 * number(l, k, e[2], "diameter"));
      add_type(s, k, e[1]);
      s.densities.push_back(number(l, k, e[3], "density"));
      if (!(s.densities.back() > 0.0)) l.fail(k, fmt::format("density {}: allowed, > 0", s.densities.back()));
    });
  }
  if (!found) throw InputError(l.path + ": no Atoms section");
  if (static_cast<long>(s.radii.size()) != atoms)
    throw InputError(fmt::format("{}: the header says {} atoms, the Atoms section holds {}", l.path, atoms, s.radii.size()));
  return s;
}

// --- extended XYZ: count, a line of key=value pairs, one line per atom -----------------------------
std::map<std::string, std::string> key_values(const Lines& l, std::size_t k) {
  std::map<std::string, std::string> kv;
  const std::string& s = l.text[k];
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i == s.size()) break;
    std::size_t j = i;
    while (j < s.size() && s[j] != '=' && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    const std::string key = s.substr(i, j - i);
    std::string value;
    if (j < s.size() && s[j] == '=') {
      ++j;
      if (j < s.size() && s[j] == '"') {
        const std::size_t close = s.find('"', j + 1);
        if (close == std::string::npos) l.fail(k, fmt::format("the value of {} has no closing quote", key));
        value = s.substr(j + 1, close - j - 1);
        j = close + 1;
      } else {
        const std::size_t start = j;
        while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
        value = s.substr(start, j - start);
      }
    }
    kv[lower(key)] = value;
    i = j;
  }
  return kv;
}

ForeignSpheres read_xyz(const Lines& l) {
  if (l.text.size() < 2) throw InputError(l.path + ": expected an extended XYZ file (a count, a comment line, the atoms)");
  const std::vector<std::string> first = split(l.text[0]);
  if (first.empty()) l.fail(0, "expected the number of atoms on the first line");
  const auto n = static_cast<std::size_t>(count(l, 0, first[0], "the number of atoms"));
  const std::map<std::string, std::string> kv = key_values(l, 1);
  ForeignSpheres s;
  // Properties=name:type:columns:... (default species:S:1:pos:R:3)
  const std::string properties = kv.count("properties") ? kv.at("properties") : "species:S:1:pos:R:3";
  std::vector<std::string> p;
  for (std::size_t a = 0, b; a <= properties.size(); a = b + 1) {
    b = std::min(properties.find(':', a), properties.size());
    p.push_back(properties.substr(a, b - a));
  }
  if (p.size() % 3 != 0) l.fail(1, fmt::format("Properties={} is not name:type:columns triples", properties));
  long pos = -1, radius = -1, diameter = -1, density = -1, type = -1, velocity = -1, spin = -1, column = 0;
  for (std::size_t i = 0; i < p.size(); i += 3) {
    const long cols = count(l, 1, p[i + 2], "Properties: the column count");
    if (cols < 1 || cols > 1000) l.fail(1, fmt::format("Properties: '{}' is not allowed as a column count; allowed: 1 to 1000", p[i + 2]));
    const std::string name = lower(p[i]);
    const bool read = (name == "pos" && cols == 3) || ((name == "radius" || name == "radii") && cols == 1) ||
                      (name == "diameter" && cols == 1) || (name == "density" && cols == 1) ||
                      ((name == "species" || name == "type") && cols == 1) ||
                      ((name == "vel" || name == "velo" || name == "velocities" || name == "momenta") && cols == 3) ||
                      (name == "omega" && cols == 3);
    if (name == "pos" && cols == 3) pos = column;
    if ((name == "radius" || name == "radii") && cols == 1) radius = column;
    if (name == "diameter" && cols == 1) diameter = column;
    if (name == "density" && cols == 1) density = column;
    if ((name == "species" || name == "type") && cols == 1) type = column;
    if ((name == "vel" || name == "velo" || name == "velocities" || name == "momenta") && cols == 3) {
      velocity = column;
      s.motion_source = "its " + p[i] + " column";
    }
    if (name == "omega" && cols == 3) spin = column;
    if (!read) s.not_read.push_back("column " + p[i]);
    column += cols;
  }
  if (spin >= 0 && velocity < 0) s.motion_source = "its omega column";
  if (pos < 0) l.fail(1, fmt::format("Properties={} has no pos:R:3 column", properties));
  if (radius < 0 && diameter < 0) l.fail(1, fmt::format("Properties={} has no radius (radius:R:1) or diameter column", properties));
  if (kv.count("lattice")) {
    std::vector<double> c;
    for (const std::string& w : split(kv.at("lattice"))) c.push_back(number(l, 1, w, "Lattice entry"));
    if (c.size() != 9) l.fail(1, "Lattice must hold 9 numbers (three cell vectors)");
    Vec3 origin = Vec3::Zero();
    if (kv.count("origin")) {
      const std::vector<std::string> o = split(kv.at("origin"));
      if (o.size() != 3) l.fail(1, "Origin must hold 3 numbers");
      origin = Vec3(number(l, 1, o[0], "Origin"), number(l, 1, o[1], "Origin"), number(l, 1, o[2], "Origin"));
    }
    if (c[1] != 0.0 || c[2] != 0.0 || c[3] != 0.0 || c[5] != 0.0 || c[6] != 0.0 || c[7] != 0.0)
      s.no_box_reason = "a non-orthogonal Lattice";
    else
      s.box = ForeignBox{origin, origin + Vec3(c[0], c[4], c[8])};
  }
  if (l.text.size() < 2 + n) throw InputError(fmt::format("{}: the first line says {} atoms, the file holds {}", l.path, n, l.text.size() - 2));
  for (std::size_t k = 2; k < 2 + n; ++k) {
    const std::vector<std::string> w = split(l.text[k]);
    if (static_cast<long>(w.size()) != column) l.fail(k, fmt::format("{} columns; Properties={} gives {}", w.size(), properties, column));
    const auto at = [&](long c) { return number(l, k, w[static_cast<std::size_t>(c)], "value"); };
    add_sphere(s, l, k, Vec3(at(pos), at(pos + 1), at(pos + 2)), radius >= 0 ? at(radius) : 0.5 * at(diameter));
    if (type >= 0) add_type(s, k, w[static_cast<std::size_t>(type)]);
    const auto vec = [&](long c) { return c < 0 ? std::nullopt : std::optional<Vec3>(Vec3(at(c), at(c + 1), at(c + 2))); };
    if (velocity >= 0 || spin >= 0) add_motion(s, k, vec(velocity), vec(spin));
    if (density >= 0) {
      s.densities.push_back(at(density));
      if (!(s.densities.back() > 0.0)) l.fail(k, fmt::format("density {}: allowed, > 0", s.densities.back()));
    }
  }
  for (std::size_t k = 2 + n; k < l.text.size(); ++k)
    if (!split(l.text[k]).empty()) l.fail(k, "a second frame (or extra lines); give a file of one frame");
  return s;
}

// --- plain text: "x y z r" per line, '#' comments ----------------------------------------------------
ForeignSpheres read_text(const Lines& l) {
  ForeignSpheres s;
  for (std::size_t k = 0; k < l.text.size(); ++k) {
    const std::vector<std::string> w = split(strip_comment(l.text[k]));
    if (w.empty()) continue;
    if (w.size() != 4) l.fail(k, fmt::format("{} values; expected 4: x y z r", w.size()));
    add_sphere(s, l, k, Vec3(number(l, k, w[0], "x"), number(l, k, w[1], "y"), number(l, k, w[2], "z")), number(l, k, w[3], "r"));
  }
  return s;
}

}  // namespace

const char* name(ForeignFormat f) {
  switch (f) {
    case ForeignFormat::lammps: return "lammps";
    case ForeignFormat::xyz: return "xyz";
    case ForeignFormat::text: return "text";
  }
  return "?";
}

ForeignFormat parse_foreign_format(const std::string& text) {
  for (const ForeignFormat f : {ForeignFormat::lammps, ForeignFormat::xyz, ForeignFormat::text})
    if (text == name(f)) return f;
  throw InputError(fmt::format("'{}' is not allowed; allowed: lammps (a data file, atom_style sphere), xyz (extended XYZ), "
                               "text (x y z r per line)",
                               text));
}

ForeignFormat foreign_format_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : lower(path.substr(dot));
  if (ext == ".data" || ext == ".lmp" || ext == ".lammps") return ForeignFormat::lammps;
  if (ext == ".xyz" || ext == ".extxyz") return ForeignFormat::xyz;
  if (ext == ".txt" || ext == ".xyzr") return ForeignFormat::text;
  throw InputError(fmt::format("{}: cannot tell the format from the extension '{}' (.data .lmp .lammps: lammps; .xyz .extxyz: xyz; "
                               ".txt .xyzr: text); give `format`",
                               path, ext));
}

ForeignSpheres read_foreign_spheres(const std::string& path, ForeignFormat format) {
  const Lines l = read_lines(path);
  ForeignSpheres s = format == ForeignFormat::lammps ? read_lammps(l) : format == ForeignFormat::xyz ? read_xyz(l) : read_text(l);
  if (s.radii.empty()) throw InputError(path + ": no spheres");
  return s;
}

}  // namespace softpack
