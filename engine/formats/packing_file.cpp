#include "formats/packing_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "core/error.hpp"
#include "formats/file_kind.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {

void write_packing_file(const std::string& path, const PackingParameters& p, const Packing& packing,
                        const PackingStatistics& stats, const PackingProvenance& provenance) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  const std::size_t n = packing.radii.size();
  std::vector<double> centres;
  centres.reserve(3 * n);
  for (const Vec3& x : packing.centres) centres.insert(centres.end(), {x.x(), x.y(), x.z()});
  f.write("centres", centres, {n, 3});
  f.write("radii", packing.radii);
  f.write("radii_inserted", packing.radii_inserted);
  f.set_attribute("centres", "unit", std::string("m"));
  f.set_attribute("radii", "unit", std::string("m"));
  f.write_scalar("shell/radius", p.Rs);
  f.write("shell/centre", std::vector<double>{0.0, 0.0, 0.0});

  f.write_scalar("parameters/Rs", p.Rs);
  f.write_scalar("parameters/r_max", p.r_max);
  f.write_scalar("parameters/polydispersity", p.polydispersity);
  f.write_scalar("parameters/exponent", p.exponent);
  f.write_scalar("parameters/beta", p.beta);
  f.write_scalar("parameters/trials", static_cast<std::int64_t>(p.trials));
  f.write_scalar("parameters/shell_is_neighbour", static_cast<std::int64_t>(p.shell_is_neighbour));
  f.write_scalar("parameters/level_ratio", p.level_ratio);

  f.write_scalar("stats/sampled", static_cast<std::int64_t>(packing.sampled));
  f.write_scalar("stats/inserted", static_cast<std::int64_t>(n));
  f.write_scalar("stats/discarded", static_cast<std::int64_t>(packing.discarded));
  f.write_scalar("stats/grown", static_cast<std::int64_t>(packing.grown));
  f.write_scalar("stats/solid_fraction", stats.solid_fraction);
  f.write_scalar("stats/bulk_fraction", stats.bulk_fraction);
  f.write_scalar("stats/depletion_length", stats.depletion_length);
  f.write_scalar("stats/min_shell_gap", stats.min_shell_gap);
  f.write_scalar("stats/exponent", stats.exponent.b);
  f.write_scalar("stats/exponent_error", stats.exponent.b_error);
  f.write_scalar("stats/exponent_r_min", stats.exponent.r_min);
  f.write_scalar("stats/exponent_r_max", stats.exponent.r_max);
  f.write("stats/radial_profile/r_inner", stats.profile.r_inner);
  f.write("stats/radial_profile/r_outer", stats.profile.r_outer);
  f.write("stats/radial_profile/solid_fraction", stats.profile.solid_fraction);

  f.write_string("provenance/program", provenance.program);
  f.write_string("provenance/code_version", provenance.code_version);
  f.write_string("provenance/config_file", provenance.config_file);
  f.write_string("provenance/config", provenance.config);
  f.write_scalar("provenance/seed", static_cast<std::int64_t>(provenance.seed));
  f.write_scalar("provenance/seconds", provenance.seconds);
  out.commit();
}

PackingFile read_packing_file(const std::string& path) {
  const h5::File f = h5::File::open(path);
  if (!f.exists("centres") || !f.exists("radii") || !f.exists("provenance/program")) {
    const std::string kind = kind_of(f);
    throw InputError(fmt::format("{}: not a softpack packing file ({})", path,
                                 kind.empty() ? "no /centres, /radii or /provenance/program" : "it is " + kind));
  }
  PackingFile out;
  PackingProvenance& v = out.provenance;
  v.program = f.read_string("provenance/program");
  if (v.program != "softpack-pack")
    throw InputError(fmt::format("{}: not a softpack packing file (/provenance/program is '{}', not 'softpack-pack')", path,
                                 v.program));
  std::vector<std::size_t> dims;
  const std::vector<double> c = f.read_doubles("centres", &dims);
  if (dims.size() != 2 || dims[1] != 3)
    throw InputError(fmt::format("{}: /centres must be (N, 3), found ({})", path, fmt::join(dims, ", ")));
  out.radii = f.read_doubles("radii");
  if (out.radii.size() != dims[0])
    throw InputError(fmt::format("{}: /centres has {} rows but /radii {} values", path, dims[0], out.radii.size()));
  if (out.radii.empty()) throw InputError(fmt::format("{}: /radii: the packing holds no spheres", path));
  for (std::size_t i = 0; i < dims[0]; ++i) out.centres.emplace_back(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
  out.Rs = f.read_scalar_double("shell/radius");
  PackingParameters& p = out.parameters;
  p.Rs = f.read_scalar_double("parameters/Rs");
  p.r_max = f.read_scalar_double("parameters/r_max");
  p.polydispersity = f.read_scalar_double("parameters/polydispersity");
  p.exponent = f.read_scalar_double("parameters/exponent");
  p.beta = f.read_scalar_double("parameters/beta");
  p.trials = f.read_scalar_int64("parameters/trials");
  const std::int64_t shell_is_neighbour = f.read_scalar_int64("parameters/shell_is_neighbour");
  if (shell_is_neighbour != 0 && shell_is_neighbour != 1)
    throw InputError(fmt::format("{}: /parameters/shell_is_neighbour: {} is not allowed; allowed: 0 or 1", path,
                                 shell_is_neighbour));
  p.shell_is_neighbour = shell_is_neighbour == 1;
  p.level_ratio = f.read_scalar_double("parameters/level_ratio");
  try {
    validate(p);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: /parameters: {}", path, e.what()));
  }
  if (out.Rs != p.Rs)
    throw InputError(fmt::format("{}: /shell/radius = {} differs from /parameters/Rs = {}", path, out.Rs, p.Rs));
  // The spheres: finite, of positive radius, inside the shell (the generator's guarantee; the
  // sweeps would otherwise start from overlaps with the shell).
  const double reach = out.Rs * (1.0 + 1e-9);
  for (std::size_t i = 0; i < out.radii.size(); ++i) {
    const double r = out.radii[i];
    const Vec3& x = out.centres[i];
    if (!(std::isfinite(r) && r > 0.0))
      throw InputError(fmt::format("{}: /radii[{}] = {} is not allowed; allowed: a finite radius > 0", path, i, r));
    if (!x.allFinite())
      throw InputError(fmt::format("{}: /centres[{}] = ({}, {}, {}) is not finite", path, i, x.x(), x.y(), x.z()));
    if (!(x.norm() + r <= reach))
      throw InputError(fmt::format("{}: sphere {} (/centres[{}], /radii[{}]) reaches {} m from the centre, beyond the shell "
                                   "(/shell/radius = {} m)",
                                   path, i, i, i, x.norm() + r, out.Rs));
  }
  v.code_version = f.read_string("provenance/code_version");
  v.config_file = f.read_string("provenance/config_file");
  v.config = f.read_string("provenance/config");
  const std::int64_t seed = f.read_scalar_int64("provenance/seed");
  if (seed < 0) throw InputError(fmt::format("{}: /provenance/seed: {} is not allowed; allowed: a seed >= 0", path, seed));
  v.seed = static_cast<std::uint64_t>(seed);
  v.seconds = f.read_scalar_double("provenance/seconds");
  return out;
}

}  // namespace softpack
