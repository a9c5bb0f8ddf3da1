// softpack-import: one imported packing of the DAG, in place of softpack-pack. Reads the
// `packing.import` section of a profile (a LAMMPS data file, extended XYZ or "x y z r" text per
// seed; packing/import.hpp), checks the spheres like a generated packing (inside the shell, no
// overlap beyond the tolerance) and writes a packing file every stage accepts, marked as imported
// with the source file's SHA-256 and the import options; on request pictures for ParaView and OVITO.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/version.hpp"
#include "formats/packing_file.hpp"
#include "io/particle_export.hpp"
#include "packing/packing_profile.hpp"
#include "packing/statistics.hpp"

namespace softpack::apps::import_app {

int main(int argc, char** argv) {
  CLI::App app{
      "softpack-import: import the packing of one seed from another program (LAMMPS data file with atom_style sphere, "
      "extended XYZ, or x y z r text), as the profile's packing.import section says (docs/import.md)"};
  std::string config_path, out_path, vtp_path, xyz_path;
  long long seed = -1;
  bool quiet = false;
  app.add_option("--config", config_path, "profile file whose `packing` section holds `import` (files per seed, shell, unit)")->required();
  app.add_option("--seed", seed, "the seed the packing is filed under (a key of packing.import.files)")->required()->check(seed_check());
  app.add_option("--out", out_path, "packing file to write (HDF5), e.g. data/<profile>/packings/seed-1.h5")->required();
  app.add_option("--vtp", vtp_path, "also write the spheres for ParaView (VTK PolyData)");
  app.add_option("--xyz", xyz_path, "also write the spheres for OVITO (extended XYZ)");
  std::string planned_stamp;
  app.add_option("--stamp", planned_stamp,
                 "the packing stage's stamp make planned this run with (softpack-config PROFILE stamp packing): refused "
                 "when the profile has changed since");
  app.add_flag("--quiet", quiet, "no summary line on stderr");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-import")) return *code;

  try {
    const Stopwatch watch;
    if (seed < 0) throw InputError(fmt::format("--seed: {} is not allowed; allowed: a seed >= 0", seed));
    const ConfigNode root = ConfigNode::load_file(config_path);
    PackingProfile profile;
    try {
      profile = parse_packing(root);
    } catch (const InputError& e) {
      throw in_file(config_path, e);
    }
    // One configuration per result: refused before anything is computed when the profile changed
    // since make planned this run.
    const std::string stamp = profile_stamp(root, "packing");
    check_planned_stamp(config_path, "packing", planned_stamp, stamp);
    if (!profile.import)
      throw InputError(fmt::format("{}: packing: no `import` section; this profile's packings are generated (softpack-pack)", config_path));
    const ImportSpec& spec = *profile.import;
    // An output never overwrites an input: the source is named by the profile, not the command line.
    if (const auto source = spec.files.find(static_cast<std::uint64_t>(seed)); source != spec.files.end())
      for (const std::string& out : {out_path, vtp_path, xyz_path}) {
        std::error_code ec;
        if (!out.empty() && (out == source->second || std::filesystem::equivalent(out, source->second, ec)))
          throw InputError(fmt::format("{}: the same file as the source of seed {} (packing.import.files in {}), which this "
                                       "command reads; an output never overwrites an input: give it another name",
                                       out, seed, config_path));
      }
    const ImportedPacking imported = import_packing(spec, static_cast<std::uint64_t>(seed));
    double r_max = 0.0;
    for (const double r : imported.radii) r_max = std::max(r_max, r);
    const PackingStatistics stats = packing_statistics(imported.centres, imported.radii, imported.Rs, r_max, profile.profile_bins);

    ImportRecord record;
    record.source_file = imported.source;
    record.source_sha256 = imported.sha256;
    record.format = name(imported.format);
    record.shell = name(spec.shell);
    record.shell_centre_in_file = imported.shell_centre_in_file;
    record.length_unit = spec.length_unit;
    record.overlap_tolerance = spec.overlap_tolerance;
    record.largest_overlap = imported.largest_overlap;
    record.density = imported.density;
    record.pressed_face = spec.pressed_face;
    record.not_used = imported.not_used;
    PackingProvenance prov;
    prov.program = "softpack-import";
    prov.code_version = code_version();
    prov.config_file = config_path;
    prov.config = section_text(root, "packing");
    prov.stamp = stamp;
    prov.seed = static_cast<std::uint64_t>(seed);
    prov.seconds = watch.elapsed().wall;
    prov.cpu_seconds = process_cpu_seconds();
    const std::string line = fmt::format("softpack-import {} seed {} from {} (sha256 {}), profile {}", prov.code_version, seed,
                                         imported.source, imported.sha256, config_path);
    write_packing_pictures(vtp_path, xyz_path, imported.centres, imported.radii, imported.Rs, line);
    write_imported_packing_file(out_path, record, imported.centres, imported.radii, imported.Rs, stats, prov);
    if (!quiet)
      fmt::print(stderr,
                 "softpack-import seed {}: {} spheres from {} ({}), shell {} m ({}; the outermost grain {:.2g} % of it inside), "
                 "largest overlap {:.2g} of a radius{}, solid fraction {:.4f}, {}{}, {:.2f} s -> {}\n",
                 seed, imported.radii.size(), imported.source, name(imported.format), imported.Rs, name(spec.shell),
                 100.0 * imported.shell_gap, imported.largest_overlap,
                 imported.moved_in ? fmt::format(", {} grains pressing into the shell moved in by up to {:.2g} of their radius",
                                                 imported.moved_in, imported.largest_move)
                                   : std::string(),
                 stats.solid_fraction,
                 std::isfinite(imported.density) ? fmt::format("density {:.6g} kg/m^3 (the file's)", imported.density)
                 : spec.density_ignored      ? std::string("the file's density ignored (the profile's material.density applies)")
                                             : std::string("no density in the file (the profile's material.density applies)"),
                 imported.not_used.empty() ? std::string() : fmt::format(", not used: {}", imported.not_used), watch.elapsed().wall,
                 out_path);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-import");
  }
}

}  // namespace softpack::apps::import_app
