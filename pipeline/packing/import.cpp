#include "packing/import.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <map>
#include <unordered_map>

#include "core/error.hpp"
#include "core/random.hpp"
#include "io/sha256.hpp"
#include "scene/limits.hpp"

namespace softpack {
namespace {

// The deepest overlap between two grains, over the smaller radius, and the pair: a hashed grid of
// cells as wide as the largest diameter (each grain looks at the 27 cells around its own).
struct Overlap {
  double fraction = 0.0;
  std::size_t i = 0, j = 0;
};
Overlap deepest_overlap(const std::vector<Vec3>& x, const std::vector<double>& r) {
  const double cell = 2.0 * *std::max_element(r.begin(), r.end());
  const auto coord = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  const auto key = [](std::int64_t a, std::int64_t b, std::int64_t c) {
    return (static_cast<std::uint64_t>(a) * 73856093u) ^ (static_cast<std::uint64_t>(b) * 19349663u) ^
           (static_cast<std::uint64_t>(c) * 83492791u);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < x.size(); ++i) cells[key(coord(x[i].x()), coord(x[i].y()), coord(x[i].z()))].push_back(i);
  Overlap deepest;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::int64_t cx = coord(x[i].x()), cy = coord(x[i].y()), cz = coord(x[i].z());
    for (std::int64_t a = cx - 1; a <= cx + 1; ++a)
      for (std::int64_t b = cy - 1; b <= cy + 1; ++b)
        for (std::int64_t c = cz - 1; c <= cz + 1; ++c) {
          const auto it = cells.find(key(a, b, c));
          if (it == cells.end()) continue;
          for (const std::size_t j : it->second) {
            if (j <= i) continue;
            const double h = r[i] + r[j] - (x[i] - x[j]).norm();  // overlap (Eq. 3's h)
            const double f = h / std::min(r[i], r[j]);
            if (f > deepest.fraction) deepest = {f, i, j};
          }
        }
  }
  return deepest;
}

}  // namespace

const char* name(ShellSource s) {
  switch (s) {
    case ShellSource::given: return "given";
    case ShellSource::read: return "read";
    case ShellSource::enclosing: return "enclosing";
  }
  return "?";
}

ImportSpec parse_import(const ConfigNode& n, const std::vector<std::uint64_t>& seeds) {
  n.allow_only({"files", "format", "length_unit", "shell", "overlap_tolerance", "max_shell_gap", "density", "density_unit",
                "pressed_face", "atom_types", "velocities"});
  ImportSpec s;
  const ConfigNode files = n.at("files");
  if (!files.yaml().IsMap()) files.fail("expected a map of seed: file, like {1: packings/run-1.data}");
  for (const std::string& k : files.keys()) {
    std::string error;
    const auto seed = parse_seed(k, error);
    const ConfigNode file = files.at(k);
    if (!seed) file.fail(fmt::format("'{}' is not a seed: {}", k, error));
    if (std::find(seeds.begin(), seeds.end(), *seed) == seeds.end())
      file.fail(fmt::format("seed {} is not in the profile's seeds", *seed));
    // Relative to the profile's folder (a profile travels with its packings; make runs anywhere).
    std::filesystem::path p = file.string();
    if (p.is_relative() && std::filesystem::is_regular_file(n.file()))
      p = (std::filesystem::path(n.file()).parent_path() / p).lexically_normal();
    s.files[*seed] = p.string();
  }
  for (const std::uint64_t seed : seeds)
    if (!s.files.count(seed)) files.fail(fmt::format("no file for seed {} of the profile's seeds", seed));
  if (const auto f = n.find("format")) {
    try {
      s.format = parse_foreign_format(f->string());
    } catch (const InputError& e) {
      f->fail(e.what());
    }
  } else {
    for (const auto& [seed, path] : s.files) {
      try {
        foreign_format_of(path);
      } catch (const InputError& e) {
        files.at(std::to_string(seed)).fail(e.what());
      }
    }
  }
  if (const auto u = n.find("length_unit")) {
    s.length_unit = u->number();
    if (!(s.length_unit > 0.0 && std::isfinite(s.length_unit)))
      u->fail(fmt::format("{} is not allowed; allowed: metres per length unit of the files, > 0 (1 for SI, 1e-3 for mm)", s.length_unit));
  }
  const ConfigNode shell = n.at("shell");
  if (shell.yaml().IsMap()) {
    shell.allow_only({"radius", "centre"});
    s.shell = ShellSource::given;
    s.shell_radius = shell.at("radius").number();
    if (!(s.shell_radius > 0.0 && std::isfinite(s.shell_radius)))
      shell.at("radius").fail(fmt::format("{} is not allowed; allowed: a radius > 0 (in the file's unit)", s.shell_radius));
    s.shell_centre = shell.at("centre").vec3();
  } else {
    s.shell = shell.choice({"read", "enclosing"}) == "read" ? ShellSource::read : ShellSource::enclosing;
  }
  if (const auto t = n.find("overlap_tolerance")) {
    s.overlap_tolerance = t->number();
    if (!(s.overlap_tolerance >= 0.0 && s.overlap_tolerance <= 0.5))
      t->fail(fmt::format("{} is not allowed; allowed: 0 <= tolerance <= 0.5 (overlap over the smaller radius)", s.overlap_tolerance));
  }
  if (const auto g = n.find("max_shell_gap")) {
    s.max_shell_gap = g->number();
    if (!(s.max_shell_gap >= 0.0 && s.max_shell_gap < 1.0))
      g->fail(fmt::format("{} is not allowed; allowed: 0 <= gap < 1 (the gap between the outermost grain and the shell, over Rs)",
                          s.max_shell_gap));
  }
  if (const auto f = n.find("pressed_face")) s.pressed_face = f->choice({"+x", "-x", "+y", "-y", "+z", "-z"});
  if (const auto t = n.find("atom_types")) s.types_one_material = t->choice({"one-material"}) == "one-material";
  if (const auto v = n.find("velocities")) s.velocities_rest = v->choice({"rest"}) == "rest";
  if (const auto d = n.find("density")) s.density_ignored = d->choice({"take", "ignore"}) == "ignore";
  if (const auto u = n.find("density_unit")) {
    s.density_unit = u->number();
    if (!(s.density_unit > 0.0 && std::isfinite(s.density_unit)))
      u->fail(fmt::format("{} is not allowed; allowed: kg/m^3 per density unit of the files, > 0 (1 for SI, 1000 for g/cm^3)",
                          s.density_unit));
  }
  return s;
}

namespace {

struct Shell {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;  ///< in the file's unit
};

ForeignFormat format_of(const ImportSpec& spec, const std::string& path) { return spec.format ? *spec.format : foreign_format_of(path); }

// The shell of one file, in its unit: given, the sphere inscribed in its cubic box, or the
// sphere about the middle of the grains' bounding box through the farthest grain.
Shell shell_of(const ImportSpec& spec, const std::string& path, const ForeignSpheres& s) {
  if (spec.shell == ShellSource::given) return {spec.shell_centre, spec.shell_radius};
  if (spec.shell == ShellSource::read) {
    if (!s.box)
      throw InputError(fmt::format("{}: packing.import.shell: read, but the file gives no box{}; give shell: {{radius: R, centre: "
                                   "[x, y, z]}} or shell: enclosing",
                                   path, s.no_box_reason.empty() ? "" : " (" + s.no_box_reason + ")"));
    const Vec3 edge = s.box->hi - s.box->lo;
    if (!(edge.minCoeff() > 0.0) || edge.maxCoeff() - edge.minCoeff() > 1e-9 * edge.maxCoeff())
      throw InputError(fmt::format("{}: packing.import.shell: read needs a cubic box (the shell is the sphere inscribed in it); the box "
                                   "is {} x {} x {}; give shell: {{radius: R, centre: [x, y, z]}} or shell: enclosing",
                                   path, edge.x(), edge.y(), edge.z()));
    return {0.5 * (s.box->lo + s.box->hi), 0.5 * edge.x()};
  }
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t i = 0; i < s.radii.size(); ++i) {
    lo = lo.cwiseMin(s.centres[i] - Vec3::Constant(s.radii[i]));
    hi = hi.cwiseMax(s.centres[i] + Vec3::Constant(s.radii[i]));
  }
  Shell shell{0.5 * (lo + hi), 0.0};
  for (std::size_t i = 0; i < s.radii.size(); ++i) shell.radius = std::max(shell.radius, (s.centres[i] - shell.centre).norm() + s.radii[i]);
  return shell;
}

}  // namespace

ImportedPacking import_packing(const ImportSpec& spec, std::uint64_t seed) {
  const auto it = spec.files.find(seed);
  if (it == spec.files.end()) throw InputError(fmt::format("packing.import.files: no file for seed {}", seed));
  const std::string& path = it->second;
  ImportedPacking out;
  out.source = path;
  out.format = format_of(spec, path);
  out.sha256 = sha256_of_file(path);
  const ForeignSpheres s = read_foreign_spheres(path, out.format);
  const auto line = [&](std::size_t i) { return fmt::format("{}:{}", path, s.lines[i]); };

  // The shell, in the file's unit. Every seed's packing has the same shell radius (soft-soft
  // pairs two seeds, and the averages are over one Rs): read from the boxes, they must agree;
  // enclosing, the largest seed's radius serves all (each seed keeps its own centre).
  Shell shell = shell_of(spec, path, s);
  if (spec.shell != ShellSource::given)
    for (const auto& [other_seed, other] : spec.files) {
      if (other_seed == seed) continue;
      const Shell o = shell_of(spec, other, read_foreign_spheres(other, format_of(spec, other)));
      if (spec.shell == ShellSource::enclosing) {
        shell.radius = std::max(shell.radius, o.radius);
      } else if (std::abs(o.radius - shell.radius) > 1e-12 * shell.radius) {
        throw InputError(fmt::format("{} and {}: the shells read from their boxes differ (radius {} and {} in the file's unit); the "
                                     "packings of a profile share one shell radius; give shell: {{radius: R, centre: [x, y, z]}} or "
                                     "shell: enclosing",
                                     path, other, shell.radius, o.radius));
      }
    }
  const Vec3 c = shell.centre;
  const double R = shell.radius;
  out.shell_centre_in_file = c;
  out.Rs = R * spec.length_unit;
  if (const std::string why = limits::refusal(out.Rs, limits::kPackingRs); !why.empty())
    throw InputError(fmt::format("{}: the shell radius {} (in the file's unit) times packing.import.length_unit = {}: {}", path, R,
                                 spec.length_unit, why));

  // To metres, the shell's centre at the origin, the pressed face turned onto +x; every grain
  // inside the shell.
  const Eigen::Matrix3d turn = face_onto_x(spec.pressed_face);
  double reach = 0.0;  // of the outermost grain, in the file's unit
  std::size_t outermost = 0;
  for (std::size_t i = 0; i < s.radii.size(); ++i) {
    Vec3 x = turn * (s.centres[i] - c) * spec.length_unit;
    const double r = s.radii[i] * spec.length_unit;
    if (const std::string why = limits::refusal(r, limits::kRadius); !why.empty())
      throw InputError(fmt::format("{}: the radius times packing.import.length_unit = {}: {}", line(i), spec.length_unit, why));
    // A grain may press into the shell as into another grain, by overlap_tolerance of its radius
    // (a packing compacted against a wall does; a file of few digits rounds a touching grain out).
    if (!(x.norm() + r <= out.Rs * (1.0 + 1e-9) + spec.overlap_tolerance * r))
      throw InputError(fmt::format("{}: this grain reaches {} from the shell's centre, beyond the shell (radius {}, {}; in the file's unit) "
                                   "by {:.3g} of its radius; allowed: packing.import.overlap_tolerance = {} (raise it only if the "
                                   "overlap is meant: ASE's extended XYZ keeps positions to 1e-8)",
                                   line(i), x.norm() / spec.length_unit + s.radii[i], R, name(spec.shell),
                                   (x.norm() + r - out.Rs) / r, spec.overlap_tolerance));
    if (const double d = (s.centres[i] - c).norm() + s.radii[i]; d > reach) reach = d, outermost = i;
    // Pressing into the shell (within the tolerance): moved in to touch it, as a packing file
    // holds its grains inside the shell; counted and reported.
    if (const double excess = x.norm() + r - out.Rs; excess > 0.0) {
      x *= (out.Rs - r) / x.norm();
      ++out.moved_in;
      out.largest_move = std::max(out.largest_move, excess / r);
    }
    out.centres.push_back(x);
    out.radii.push_back(r);
  }
  out.shell_gap = std::max(0.0, 1.0 - reach / R);
  if (spec.shell != ShellSource::given && out.shell_gap > spec.max_shell_gap)
    throw InputError(fmt::format(
        "{}: the outermost grain reaches {:.4g} from the shell's centre: a gap of {:.1f} % of the shell's radius {:.4g} ({}; in the "
        "file's unit), more than packing.import.max_shell_gap = {} allows: the {} is not the packing's shell. Give the shell, "
        "shell: {{radius: R, centre: [x, y, z]}}{}, or raise max_shell_gap if the gap is meant",
        line(outermost), reach, 100.0 * out.shell_gap, R, name(spec.shell), spec.max_shell_gap,
        spec.shell == ShellSource::read ? "file's box" : "largest seed's enclosing sphere",
        spec.shell == ShellSource::read ? ", or shell: enclosing" : ""));
  // The density column: one value for every grain (softpack's grains share one material), which
  // the stages compare with the profile's material.density (measure/stage.cpp).
  if (!s.densities.empty() && !spec.density_ignored) {
    for (std::size_t i = 1; i < s.densities.size(); ++i)
      if (std::abs(s.densities[i] - s.densities[0]) > 1e-9 * s.densities[0])
        throw InputError(fmt::format("{} and {}: densities {} and {}: softpack's grains share one material (the profile's "
                                     "material.density); give a file of one density, or packing.import.density: ignore",
                                     line(0), line(i), s.densities[0], s.densities[i]));
    out.density = s.densities[0] * spec.density_unit;
  }
  // Every other column: used, or refused with what would apply, or named as not read.
  std::vector<std::string> not_used;
  if (s.types.size() > 1) {
    if (!spec.types_one_material)
      throw InputError(fmt::format("{}:{}: atom type {}, after {} (the file's types: {}): softpack's grains share one material, the "
                                   "profile's `material`; give packing.import.atom_types: one-material to take every type as it, "
                                   "or a file of one type",
                                   path, s.type_line, s.types[1], s.types[0], fmt::join(s.types, " ")));
    not_used.push_back(fmt::format("atom types {} (one material: the profile's)", fmt::join(s.types, " ")));
  }
  if (s.max_speed.value_or(0.0) > 0.0 || s.max_spin.value_or(0.0) > 0.0) {
    const std::string motion = fmt::format("the grains move ({}: |v| up to {:.3g}{}, in the file's units)", s.motion_source,
                                           s.max_speed.value_or(0.0),
                                           s.max_spin ? fmt::format(", |omega| up to {:.3g}", *s.max_spin) : std::string());
    if (!spec.velocities_rest)
      throw InputError(fmt::format("{}:{}: {}: softpack starts every packing at rest; give packing.import.velocities: rest to start "
                                   "this one at rest, or a packing at rest",
                                   path, s.motion_line, motion));
    not_used.push_back(motion + ", started at rest");
  }
  not_used.insert(not_used.end(), s.not_read.begin(), s.not_read.end());
  out.not_used = fmt::format("{}", fmt::join(not_used, "; "));
  const Overlap o = deepest_overlap(out.centres, out.radii);
  out.largest_overlap = o.fraction;
  if (o.fraction > spec.overlap_tolerance)
    throw InputError(fmt::format("{} and {}: these grains overlap by {:.3g} of the smaller radius; allowed: "
                                 "packing.import.overlap_tolerance = {} (a packing starts without overlaps; raise the tolerance "
                                 "only if the overlap is meant)",
                                 line(o.i), line(o.j), o.fraction, spec.overlap_tolerance));
  return out;
}

Eigen::Matrix3d face_onto_x(const std::string& face) {
  Eigen::Matrix3d m;
  if (face == "+x") m << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  else if (face == "-x") m << -1, 0, 0, 0, -1, 0, 0, 0, 1;
  else if (face == "+y") m << 0, 1, 0, -1, 0, 0, 0, 0, 1;
  else if (face == "-y") m << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  else if (face == "+z") m << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  else if (face == "-z") m << 0, 0, -1, 0, 1, 0, 1, 0, 0;
  else throw InputError(fmt::format("pressed_face: '{}' is not allowed; allowed: +x, -x, +y, -y, +z, -z", face));
  return m;
}

std::string import_sources_text(const ImportSpec& spec) {
  std::string text;
  std::map<std::string, std::pair<std::uint64_t, std::string>> first;  // digest -> the first seed with it, its file
  for (const auto& [seed, path] : spec.files) {
    const std::string digest = sha256_of_file(path);
    // Identity by content: two seeds of one packing would enter the average twice and shrink
    // its standard error (to 0 for two), whatever the files are called.
    if (const auto [it, fresh] = first.emplace(digest, std::pair{seed, path}); !fresh)
      throw InputError(fmt::format("packing.import.files: seeds {} ({}) and {} ({}) are one packing (the same bytes, SHA-256 {}); "
                                   "each seed must be a different packing",
                                   it->second.first, it->second.second, seed, path, digest));
    text += fmt::format("seed {} {} sha256 {}\n", seed, path, digest);
  }
  return text;
}

}  // namespace softpack
