// softpack-pack: one packing of the DAG. Reads the `packing` section of a profile, generates
// the packing of one seed (packing/generator.hpp) and writes the packing file (HDF5), and on
// request pictures for ParaView (.vtp) and OVITO (extended XYZ).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

#include "packing/packing_profile.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "profile/profile.hpp"
#include "core/stopwatch.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/packing_file.hpp"
#include "io/particle_export.hpp"
#include "packing/nested.hpp"
#include "packing/statistics.hpp"

namespace softpack::apps::pack_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-pack: generate the soft-particle packing of one seed (paper §3)"};
  std::string config_path, out_path, vtp_path, xyz_path;
  long long seed = -1;
  bool quiet = false;
  app.add_option("--config", config_path, "profile file, e.g. experiments/paper.yaml (its `packing` section)")->required();
  app.add_option("--seed", seed, "seed of the random numbers, 0 <= seed <= 2^63 - 1; the same seed gives the same packing")
      ->required()
      ->check(seed_check());
  app.add_option("--out", out_path, "packing file to write (HDF5), e.g. data/paper/packings/seed-1.h5")->required();
  app.add_option("--vtp", vtp_path, "also write the spheres for ParaView (VTK PolyData)");
  app.add_option("--xyz", xyz_path, "also write the spheres for OVITO (extended XYZ)");
  std::string planned_stamp;
  app.add_option("--stamp", planned_stamp,
                 "the packing stage's stamp make planned this run with (softpack-config PROFILE stamp packing): refused "
                 "when the profile has changed since");
  app.add_flag("--quiet", quiet, "no progress lines on stderr");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-pack")) return *code;

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
    if (profile.import)
      throw InputError(fmt::format("{}: packing.import: this profile's packings are imported, not generated; make them with "
                                   "softpack-import (make packings does)",
                                   config_path));
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    double last = -1.0;  // redraw at most 10 times a second on a terminal, once a second in a log
    const auto progress = [&](const std::string& phase, std::size_t done, std::size_t total) {
      if (quiet) return;
      const double elapsed = watch.elapsed().wall;
      if (elapsed - last < (tty ? 0.1 : 1.0) && done != total) return;
      last = elapsed;
      fmt::print(stderr, "{}softpack-pack seed {}: {} {}/{} ({:.0f}%), {:.1f} s{}", tty ? "\r\033[K" : "", seed, phase, done,
                 total, 100.0 * static_cast<double>(done) / static_cast<double>(total), elapsed, tty ? "" : "\n");
    };
    // A packing of nested soft-particles (packing.levels > 1): its grains and the sites of the
    // level below (packing/nested.hpp); levels 1 gives generate_packing's bits.
    const LevelPacking level = generate_level(profile.parameters, profile.levels - 1, static_cast<std::uint64_t>(seed), progress);
    const Packing& packing = level.grains;
    PackingSites sites;
    sites.levels = profile.levels;
    sites.radius = level.site_radius;
    sites.centres = level.sites;
    sites.drawn = level.sites_drawn;
    sites.discarded = level.sites_discarded;
    if (!quiet && tty) fmt::print(stderr, "\n");
    const PackingParameters& p = profile.parameters;
    const PackingStatistics stats = packing_statistics(packing.centres, packing.radii, p.Rs, p.r_max, profile.profile_bins);

    PackingProvenance prov;
    prov.program = "softpack-pack";
    prov.code_version = code_version();
    prov.config_file = config_path;
    prov.config = section_text(root, "packing");
    prov.stamp = stamp;
    prov.seed = static_cast<std::uint64_t>(seed);
    prov.seconds = watch.elapsed().wall;
    prov.cpu_seconds = process_cpu_seconds();
    // The packing file last: it is what make (and the sweeps) take as the stage's result, so a
    // write that fails (a full disk) leaves no packing file beside missing pictures.
    const std::string line = fmt::format("softpack-pack {} seed {} from {}", prov.code_version, seed, config_path);
    write_packing_pictures(vtp_path, xyz_path, packing.centres, packing.radii, p.Rs, line);
    write_packing_file(out_path, p, packing, stats, prov, sites);
    if (!quiet)
      fmt::print(stderr,
                 "softpack-pack seed {}: {} spheres inserted of {} sampled ({} discarded, {} grown), solid fraction "
                 "{:.4f}, fitted exponent {:.3f} +- {:.3f}, {:.1f} s -> {}\n",
                 seed, packing.radii.size(), packing.sampled, packing.discarded, packing.grown, stats.solid_fraction,
                 stats.exponent.b, stats.exponent.b_error, prov.seconds, out_path);
    if (!quiet && sites.levels > 1)
      fmt::print(stderr, "softpack-pack seed {}: {} soft-particles of the level below (radius {:.4g} m) placed of {} drawn ({} "
                 "discarded); {} levels\n",
                 seed, sites.centres.size(), sites.radius, sites.drawn, sites.discarded, sites.levels);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-pack");
  }
}

}  // namespace softpack::apps::pack_app
