#include "formats/packing_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "io/sha256.hpp"
#include "formats/file_kind.hpp"
#include "formats/h5_fields.hpp"
#include "packing/nested.hpp"

namespace softpack {
namespace {

using namespace formats;

constexpr const char *kCentres = "centres", *kRadii = "radii", *kShellRadius = "shell/radius";
constexpr const char *kProgram = "provenance/program", *kParameters = "parameters", *kRs = "parameters/Rs";
constexpr std::array kPackingLayout{kCentres, kRadii, kProgram};  // what makes a file a packing file
constexpr const char* kPack = "softpack-pack";              // the program that writes them
constexpr const char* kImport = "softpack-import";          // ... or imports them
constexpr const char* kNearest = "parameters/nearest_neighbour";  // since 0.5.0; absent: surface
constexpr const char *kLevels = "parameters/levels", *kSites = "sites/centres", *kSiteRadius = "sites/radius";

// /parameters: f(dataset, member) for each of the generator's parameters, in the file's order.
template <class P, class F>
void each_parameter(P& p, F&& f) {
  f(kRs, p.Rs);
  f("parameters/r_max", p.r_max);
  f("parameters/polydispersity", p.polydispersity);
  f("parameters/exponent", p.exponent);
  f("parameters/beta", p.beta);
  f("parameters/trials", p.trials);
  f("parameters/shell_is_neighbour", p.shell_is_neighbour);
  f("parameters/level_ratio", p.level_ratio);
}

// /provenance: f(dataset, member) for each field of the provenance.
template <class V, class F>
void each_packing_provenance(V& v, F&& f) {
  f(kProgram, v.program);
  f("provenance/code_version", v.code_version);
  f("provenance/config_file", v.config_file);
  f("provenance/config", v.config);
  f("provenance/seed", v.seed);
  f("provenance/seconds", v.seconds);
  f("provenance/cpu_seconds", v.cpu_seconds);
}

// /imported: f(dataset, member) for each field of an imported packing's record.
template <class R, class F>
void each_import_field(R& r, F&& f) {
  f("imported/source_file", r.source_file);
  f("imported/source_sha256", r.source_sha256);
  f("imported/format", r.format);
  f("imported/shell", r.shell);
  f("imported/shell_centre_in_file", r.shell_centre_in_file);
  f("imported/length_unit", r.length_unit);
  f("imported/overlap_tolerance", r.overlap_tolerance);
  f("imported/largest_overlap", r.largest_overlap);
}

void put_statistics(h5::File& f, const PackingStatistics& stats) {
  put(f, "stats/solid_fraction", stats.solid_fraction);
  put(f, "stats/bulk_fraction", stats.bulk_fraction);
  put(f, "stats/depletion_length", stats.depletion_length);
  put(f, "stats/min_shell_gap", stats.min_shell_gap);
  put(f, "stats/exponent", stats.exponent.b);
  put(f, "stats/exponent_error", stats.exponent.b_error);
  put(f, "stats/exponent_r_min", stats.exponent.r_min);
  put(f, "stats/exponent_r_max", stats.exponent.r_max);
  put(f, "stats/radial_profile/r_inner", stats.profile.r_inner);
  put(f, "stats/radial_profile/r_outer", stats.profile.r_outer);
  put(f, "stats/radial_profile/solid_fraction", stats.profile.solid_fraction);
}

void put_spheres(h5::File& f, const std::vector<Vec3>& centres, const std::vector<double>& radii, double Rs) {
  put(f, kCentres, centres);
  put(f, kRadii, radii);
  f.set_attribute(kCentres, "unit", std::string("m"));
  f.set_attribute(kRadii, "unit", std::string("m"));
  put(f, kShellRadius, Rs);
  put(f, "shell/centre", std::vector<double>{0.0, 0.0, 0.0});
}

// /parameters/levels and /sites: the model's levels, and each site inside the shell at Rs / Pi.
void read_sites(const h5::File& f, const std::string& path, PackingFile& out) {
  PackingSites& s = out.sites;
  long levels = 0;
  get(f, kLevels, levels);
  try {
    validate_levels(out.parameters, static_cast<int>(levels));
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: /{}: {}", path, kLevels, e.what()));
  }
  s.levels = static_cast<int>(levels);
  if (s.levels == 1) return;
  get(f, kSites, s.centres);
  get(f, kSiteRadius, s.radius);
  get(f, "stats/sites_drawn", s.drawn);
  get(f, "stats/sites_discarded", s.discarded);
  const double expected = out.Rs / out.parameters.polydispersity;
  if (!(std::abs(s.radius - expected) <= 1e-12 * expected))
    throw InputError(fmt::format("{}: /{} = {} m; allowed: Rs / Pi = {} m (packing/nested.hpp)", path, kSiteRadius, s.radius, expected));
  for (std::size_t i = 0; i < s.centres.size(); ++i)
    if (!(s.centres[i].norm() + s.radius <= out.Rs * (1.0 + 1e-9)))
      throw InputError(fmt::format("{}: site {} (/{}[{}]) reaches {} m from the centre, beyond the shell (/{} = {} m)", path, i,
                                   kSites, i, s.centres[i].norm() + s.radius, kShellRadius, out.Rs));
}

}  // namespace

void write_imported_packing_file(const std::string& path, const ImportRecord& record, const std::vector<Vec3>& centres,
                                 const std::vector<double>& radii, double Rs, const PackingStatistics& stats,
                                 const PackingProvenance& provenance) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  put_spheres(f, centres, radii, Rs);
  put(f, kRs, Rs);
  each_import_field(record, writer(f));
  if (std::isfinite(record.density)) put(f, "imported/density", record.density);  // none: absent
  put(f, "imported/pressed_face", record.pressed_face);
  put(f, "imported/not_used", record.not_used);
  put(f, "stats/inserted", radii.size());
  put_statistics(f, stats);
  each_packing_provenance(provenance, writer(f));
  put(f, kProvenanceStamp, provenance.stamp);
  out.commit();
}

void write_packing_file(const std::string& path, const PackingParameters& p, const Packing& packing,
                        const PackingStatistics& stats, const PackingProvenance& provenance, const PackingSites& sites) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  const std::size_t n = packing.radii.size();
  put_spheres(f, packing.centres, packing.radii, p.Rs);
  put(f, "radii_inserted", packing.radii_inserted);
  each_parameter(p, writer(f));
  put(f, kNearest, std::string(name(p.nearest_neighbour)));
  put(f, "stats/sampled", packing.sampled);
  put(f, "stats/inserted", n);
  put(f, "stats/discarded", packing.discarded);
  put(f, "stats/grown", packing.grown);
  put_statistics(f, stats);
  if (sites.levels > 1) {
    put(f, kLevels, static_cast<long>(sites.levels));
    put(f, kSites, sites.centres);
    f.set_attribute(kSites, "unit", std::string("m"));
    put(f, kSiteRadius, sites.radius);
    put(f, "stats/sites_drawn", sites.drawn);
    put(f, "stats/sites_discarded", sites.discarded);
  }

  each_packing_provenance(provenance, writer(f));
  put(f, kProvenanceStamp, provenance.stamp);
  out.commit();
}

PackingFile read_packing_file(const std::string& path) {
  const h5::File f = h5::File::open(path);
  expect_layout(f, "packing", kPackingLayout);
  PackingFile out;
  out.path = path;
  PackingProvenance& v = out.provenance;
  get(f, kProgram, v.program);
  if (v.program != kPack && v.program != kImport)
    throw InputError(fmt::format("{}: not a softpack packing file (/{} is '{}', not '{}' or '{}')", path, kProgram, v.program, kPack,
                                 kImport));
  get(f, kCentres, out.centres);  // shape (N, 3), finite
  get(f, kRadii, out.radii);
  same_length(f, kRadii, out.radii.size(), kCentres, out.centres.size());
  if (out.radii.empty()) throw InputError(fmt::format("{}: /{}: the packing holds no spheres", path, kRadii));
  get(f, kShellRadius, out.Rs);
  PackingParameters& p = out.parameters;
  if (v.program == kImport) {  // no generator: its shell, and the largest grain
    ImportRecord r;
    each_import_field(r, reader(f));
    if (f.exists("imported/density")) get(f, "imported/density", r.density);
    if (f.exists("imported/pressed_face")) get(f, "imported/pressed_face", r.pressed_face);
    if (f.exists("imported/not_used")) get(f, "imported/not_used", r.not_used);
    out.imported = r;
    get(f, kRs, p.Rs);
    p.r_max = 0.0;
    for (const double radius : out.radii) p.r_max = std::max(p.r_max, radius);
  } else {
    each_parameter(p, reader(f));
    try {
      if (f.exists(kNearest)) p.nearest_neighbour = parse_nearest_neighbour(f.read_string(kNearest));
      validate(p);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: /{}: {}", path, kParameters, e.what()));
    }
  }
  if (out.Rs != p.Rs)
    throw InputError(fmt::format("{}: /{} = {} differs from /{} = {}", path, kShellRadius, out.Rs, kRs, p.Rs));
  // The spheres: of finite positive radius, inside the shell (the generator's guarantee; the
  // sweeps would otherwise start from overlaps with the shell).
  const double reach = out.Rs * (1.0 + 1e-9);
  for (std::size_t i = 0; i < out.radii.size(); ++i) {
    const double r = out.radii[i];
    const Vec3& x = out.centres[i];
    if (!(std::isfinite(r) && r > 0.0))
      throw InputError(fmt::format("{}: /{}[{}] = {} is not allowed; allowed: a finite radius > 0", path, kRadii, i, r));
    if (!(x.norm() + r <= reach))
      throw InputError(fmt::format("{}: sphere {} (/{}[{}], /{}[{}]) reaches {} m from the centre, beyond the shell "
                                   "(/{} = {} m)",
                                   path, i, kCentres, i, kRadii, i, x.norm() + r, kShellRadius, out.Rs));
  }
  if (f.exists(kLevels)) read_sites(f, path, out);
  each_packing_provenance(v, reader(f));
  if (f.exists(kProvenanceStamp)) get(f, kProvenanceStamp, v.stamp);
  return out;
}

std::string packing_sha256(const PackingFile& p) {
  // The spheres sorted (by x, y, z, r): the same packing listed in another order is the same packing.
  std::vector<std::array<double, 4>> spheres;
  spheres.reserve(p.radii.size());
  for (std::size_t i = 0; i < p.radii.size(); ++i) spheres.push_back({p.centres[i].x(), p.centres[i].y(), p.centres[i].z(), p.radii[i]});
  std::sort(spheres.begin(), spheres.end());
  std::string bytes;
  const auto add = [&](double v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); };
  add(p.Rs);
  for (const auto& sphere : spheres)
    for (const double v : sphere) add(v);
  if (p.sites.levels > 1) {  // a packing without levels keeps the identity it had before them
    std::vector<std::array<double, 3>> sites;
    for (const Vec3& x : p.sites.centres) sites.push_back({x.x(), x.y(), x.z()});
    std::sort(sites.begin(), sites.end());
    add(static_cast<double>(p.sites.levels));
    add(p.sites.radius);
    for (const auto& site : sites)
      for (const double v : site) add(v);
  }
  return sha256_of_bytes(bytes);
}

std::string describe_packing_file(const h5::File& f) {
  if (!has_layout(f, kPackingLayout)) return "";
  const std::string program = f.read_string(kProgram);
  return program == kPack || program == kImport ? fmt::format("a packing file ({})", program) : "a packing file of another program";
}

}  // namespace softpack
