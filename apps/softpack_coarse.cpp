// softpack-coarse: the coarse-grain validation (issue 17, docs/coarse-grain.md).
//
//   softpack-coarse medium --config experiments/coarse-grain.yaml --seed S --out medium-S.h5
//       builds the medium of seed S: grains, sites and their packings (coarse/medium_file.hpp);
//   softpack-coarse run --config ... --model resolved|soft --medium medium-S.h5 --out F.h5
//       runs its oedometric compression with that model, writes the curve (coarse/result_file.hpp);
//   softpack-coarse stamp --config ... --release V: the stages' stamps, for make (coarse/settings.hpp);
//   softpack-coarse export --lammps, lammps-curve: the soft model in LAMMPS (apps/coarse_lammps_cli.hpp).
// The comparison of the two models is a study's report (`make coarse-grain`, softpack-study
// report: report kind `coarse`).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "apps/coarse_estimate_cli.hpp"
#include "apps/coarse_lammps_cli.hpp"
#include "apps/coarse_medium_cli.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "coarse/compression.hpp"
#include "coarse/medium_file.hpp"
#include "coarse/multi_contact.hpp"
#include "coarse/probe_report.hpp"
#include "coarse/probe_settings.hpp"
#include "coarse/soft_census.hpp"
#include "coarse/validation.hpp"
#include "coarse/in_place.hpp"
#include "coarse/speed.hpp"
#include "coarse/kinematics.hpp"
#include "coarse/result_file.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"

namespace softpack::apps::coarse_app {
namespace {

struct RunOptions {
  std::string config, model, medium, out;
  std::uint64_t seed = 0;
  bool quiet = false;
};

int medium(const RunOptions& o, const std::string& program) {
  const CoarseGrainSettings s = read_coarse_grain_settings(o.config);
  const Lines l;
  Stopwatch clock, phase_clock;  // the ETA of each phase (sampled contents, sites) from its own pace
  MediumFile mf;
  std::string phase;
  mf.medium = build_medium(s, o.seed, [&](const char* what, std::size_t k, std::size_t n) {
    if (phase != what) phase = what, phase_clock = Stopwatch();
    const double t = phase_clock.elapsed().wall;
    if (!o.quiet)
      fmt::print(stderr, "{}{} medium seed {}: {} packing {} of {} ({:.0f} s, ETA {:.0f} s){}", l.cr(), program, o.seed,
                 phase == "sample" ? "sampled content" : "site", k, n, clock.elapsed().wall,
                 n > k ? t / static_cast<double>(k) * static_cast<double>(n - k) : 0.0, l.nl());
  });
  mf.seed = o.seed, mf.settings = s.medium_text, mf.code_version = code_version(), mf.time = clock.elapsed();
  write_medium_file(o.out, mf);
  const Medium& m = mf.medium;
  double packed = 0.0, error = 0.0;  // expected, with its error, when the contents are sampled
  std::size_t inner = 0;
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const SiteInside in = site_inside(m, k);
    packed += static_cast<double>(m.packings[k].radii.size()) + in.grains, error += in.grains_error;
    inner += m.levels > 1 ? m.inner_sites[k].size() : 0;
  }
  const std::string nested = fmt::format("{}, at {} levels, {} soft-particles of level 1 among them{}", error > 0.0 ? fmt::format(" ± {:.0f}", error) : "",
                                         m.levels, inner, m.content_mean.sample > 0 ? fmt::format(", their contents sampled ({} per level)", m.content_mean.sample) : "");
  if (!o.quiet)
    fmt::print(stderr, "{}{} medium seed {}: {} grains, {} sites ({:.0f} grains in their packings{}), box {:.4g} x {:.4g} x {:.4g} m, {:.1f} s -> {}\n",
               l.cr(), program, o.seed, m.grain_x.size(), m.sites.size(), packed, m.levels > 1 ? nested : "", m.L, m.L, m.H, mf.time.wall, o.out);
  return 0;
}

int run(const RunOptions& o, const std::string& program) {
  const CoarseGrainSettings s = read_coarse_grain_settings(o.config);
  const CoarseModel model = parse_coarse_model(o.model);
  const Lines l;
  const MediumFile mf = read_medium_file(o.medium);
  Medium m = medium_with_contents(s, o.config, mf, o.medium, fmt::format("{} seed {} {}", program, mf.seed, o.model), o.quiet);
  const SoftParticleLaws laws = read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body);
  const SceneDef scene = medium_scene(s, m, model, laws);
  if (!o.quiet)
    fmt::print(stderr, "{} seed {} {}: {} grains, {} sites, {} spheres in a box {:.4g} x {:.4g} x {:.4g} m\n", program, mf.seed, o.model,
               m.grain_x.size(), m.sites.size(), scene.particles.size(), m.L, m.L, m.H);
  Stopwatch clock;
  const CompressionRun r = run_compression(scene, m, model, s, [&](double done, double total, const CurveRow& row) {
    if (o.quiet) return;
    const double elapsed = clock.elapsed().wall;
    fmt::print(stderr, "{}{} seed {} {}: strain {:.4f} ({:.0f}%), sigma_zz {:.4g} Pa, K0 {:.3f}, fraction {:.4f}, Z {:.2f}, ETA {:.0f} s{}",
               l.cr(), program, mf.seed, o.model, row.strain, 100.0 * done / total, row.sigma_top,
               row.sigma_top > 0.0 ? row.sigma_lateral / row.sigma_top : 0.0, row.fraction, row.Z,
               done > 0.0 ? elapsed * (total - done) / done : 0.0, l.nl());
  });
  write_coarse_result(o.out, coarse_result(r, m, model, mf.seed, s));
  if (!o.quiet)
    fmt::print(stderr, "{}{} seed {} {}: {} steps of {:.3g} s in {:.1f} s (CPU {:.1f} s) -> {}\n", l.cr(), program, mf.seed, o.model,
               r.steps, r.dt, r.time.wall, r.time.cpu, o.out);
  return 0;
}

// multi-contact --part shear: the confined shear's runs, a block per arrangement and Δn.
int confined_shear(const std::string& program, const CoarseGrainSettings& s, std::uint64_t seed, const std::vector<std::string>& names,
                   const std::vector<double>& delta_n, const std::vector<double>& ht, const std::string& source, const std::string& out,
                   const std::string& stamp) {
  std::vector<ProbeArrangement> arrangements;
  for (const std::string& name : names) arrangements.push_back(builtin_arrangement(name, seed));
  const Stopwatch clock;
  std::size_t done = 0;
  const std::size_t points = arrangements.size() * delta_n.size() * (ht.size() + 1);
  const auto sheared = measure_confined_shear(s, seed, arrangements, delta_n, ht, [&](const ShearPoint& p) {
    const double t = clock.elapsed().wall;
    ++done;
    if (!p.failed.empty())
      fmt::print(stderr, "{} multi-contact: {}, delta_n {:.3f}, ht/Rs {}: not measured, nor its larger ht: {}\n", program, p.arrangement, p.delta_n, p.ht,
                 p.failed);
    else
      fmt::print(stderr, "{} multi-contact: {}, delta_n {:.3f}, ht/Rs {}: Fn {:.5g} N, Ft {:.5g} N ({}/{}, {:.0f} s, ETA {:.0f} s)\n", program,
                 p.arrangement, p.delta_n, p.ht, p.Fn, p.Ft, done, points, t, t / static_cast<double>(done) * static_cast<double>(points - done));
  });
  write_confined_shear(out, source, seed, sheared, clock.elapsed().cpu, stamp);
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string program = "softpack-coarse";
  CLI::App app{"softpack-coarse: the coarse-grain validation: a two-decade medium compressed resolved and with soft-particles"};
  app.require_subcommand(1);
  RunOptions o;
  CLI::App* medium_cmd = app.add_subcommand("medium", "one seed: the medium (grains, sites and their packings), for both models");
  medium_cmd->add_option("--config", o.config, "settings, e.g. experiments/coarse-grain.yaml")->required();
  medium_cmd->add_option("--seed", o.seed, "seed of the medium, 0 <= seed <= 2^63 - 1")->required()->check(seed_check());
  medium_cmd->add_option("--out", o.out, "medium file (HDF5)")->required();
  medium_cmd->add_flag("--quiet", o.quiet, "no progress lines");
  CLI::App* run_cmd = app.add_subcommand("run", "one model on one medium: compress it, write the curve");
  run_cmd->add_option("--config", o.config, "settings, e.g. experiments/coarse-grain.yaml")->required();
  run_cmd->add_option("--model", o.model, "resolved (every grain of both decades) or soft (soft-particles)")
      ->required()
      ->check(CLI::IsMember({"resolved", "soft"}));
  run_cmd->add_option("--medium", o.medium, "medium file (softpack-coarse medium)")->required();
  run_cmd->add_option("--out", o.out, "results file (HDF5)")->required();
  run_cmd->add_flag("--quiet", o.quiet, "no progress lines");
  add_threads_option(*run_cmd);
  coarse_app::EstimateCommand estimate;
  estimate.add(app);
  std::string probe_config, probe_out;
  std::uint64_t probe_seed = 0;
  std::vector<std::string> probe_arrangements{"one", "opposite", "cube"};
  std::vector<double> probe_dn{0.1, 0.2, 0.3, 0.4};
  CLI::App* probe_cmd =
      app.add_subcommand("multi-contact", "one resolved soft-particle pressed by several walls at once (arrangements: coarse/multi_contact.hpp)");
  std::string probe_plan, probe_radius;
  auto* probe_config_opt = probe_cmd->add_option("--config", probe_config, "settings, e.g. experiments/coarse-grain.yaml (or --probe)");
  auto* probe_plan_opt = probe_cmd->add_option("--probe", probe_plan,
                                               "the many-body probe's plan, e.g. experiments/many-body.yaml: its settings, arrangements and "
                                               "delta_n (coarse/probe_settings.hpp)")
                             ->excludes(probe_config_opt);
  probe_cmd->add_option("--radius", probe_radius, "with --probe: the name of one of its radii")->needs(probe_plan_opt);
  std::string probe_part = "walls";
  probe_cmd
      ->add_option("--part", probe_part,
                   "with --probe: walls (its arrangements), bodies (its bodies' arrangements with each kind) or shear (its confined shear)")
      ->check(CLI::IsMember({"walls", "bodies", "shear"}))
      ->needs(probe_plan_opt);
  std::string probe_kind;
  probe_cmd->add_option("--kind", probe_kind, "with --part bodies: which of the plan's pressing bodies (wall, grain-X, soft)")->needs(probe_plan_opt);
  probe_cmd->add_option("--packing-seed", probe_seed, "seed of the packing (and of random-N's directions)")->required()->check(seed_check());
  probe_cmd->add_option("--arrangements", probe_arrangements,
                        "one, opposite, orthogonal, triangle, tetrahedral, square, pyramid, cube, opposite-half, orthogonal-half, random-N (N = 2-12); "
                        "each may end in :BODY (wall, soft, grain-X: a grain of radius X Rs)");
  probe_cmd->add_option("--delta-n", probe_dn, "Delta_n of the arrangement, increasing (wall k's: w_k Delta_n)");
  probe_cmd->add_option("--out", probe_out, "text file: a block per arrangement, rows: walls delta_n Fn_1 ... Fn_walls")->required();
  add_threads_option(*probe_cmd);
  std::string report_plan, report_dir, report_out;
  CLI::App* report_cmd = app.add_subcommand("probe-report", "the many-body probe's analysis: candidate laws fitted and judged by the plan's rule (coarse/probe_fit.hpp)");
  report_cmd->add_option("--probe", report_plan, "the plan, e.g. experiments/many-body.yaml")->required();
  report_cmd->add_option("--dir", report_dir, "the probe files' folder (RADIUS/seed-S.dat), e.g. data/many-body/probe")->required();
  report_cmd->add_option("--out", report_out, "folder of probe.md, probe.json, probe.dat")->required();
  std::string val_plan, val_dir, val_out, val_against;
  std::vector<std::string> val_settings{"reference", "many-body"};
  CLI::App* val_cmd = app.add_subcommand("validation", "the many-body law's acceptance on media, by the plan's criterion (coarse/validation.hpp)");
  val_cmd->add_option("--probe", val_plan, "the plan, e.g. experiments/many-body.yaml")->required();
  val_cmd->add_option("--dir", val_dir, "the validation study's folder, e.g. data/many-body-validation")->required();
  val_cmd->add_option("--settings", val_settings, "its settings to judge");
  val_cmd->add_option("--out", val_out, "folder of validation.md and validation.json")->required();
  val_cmd->add_option("--against", val_against, "one of the settings: the others read against it too (a bound against the version it changes)");
  int law_version = 1;  // the version of the law whose media a command reads (one command runs)
  const auto add_law_version = [&](CLI::App& cmd) {  // the plan's validation.media_seeds for 1, vN_media_seeds for N
    return cmd.add_option("--law-version", law_version, "on the media of this version of the law")->check(CLI::Range(1, kLawVersions))->capture_default_str();
  };
  add_law_version(*val_cmd);
  std::string census_plan, census_config, census_media, census_out;
  CLI::App* census_cmd = app.add_subcommand(
      "soft-contacts", "where the media use the soft-particle law: every soft-particle contact of the soft model, against the probe's range (coarse/soft_census.hpp)");
  census_cmd->add_option("--probe", census_plan, "the plan (its media seeds and Delta_n range), e.g. experiments/many-body.yaml")->required();
  census_cmd->add_option("--config", census_config, "the soft model's settings, e.g. data/many-body-validation/profiles/many-body.yaml")->required();
  census_cmd->add_option("--media", census_media, "folder of the medium files seed-S.h5, e.g. data/many-body-validation/many-body/media")->required();
  census_cmd->add_option("--out", census_out, "folder of contacts.md and contacts.dat")->required();
  add_law_version(*census_cmd);
  std::string place_plan, place_config, place_media, place_out;
  std::uint64_t place_seed = 0;
  CLI::App* place_cmd = app.add_subcommand(
      "in-place", "the law in place: the resolved medium compressed again, each site's pushes against the law's from the same geometry (coarse/in_place.hpp)");
  place_cmd->add_option("--probe", place_plan, "the plan (its strain range), e.g. experiments/many-body.yaml")->required();
  place_cmd->add_option("--config", place_config, "the settings with the law file, e.g. data/many-body-v3/profiles/many-body.yaml")->required();
  place_cmd->add_option("--media", place_media, "folder of the medium files seed-S.h5, e.g. data/many-body-v3/reference/media")->required();
  place_cmd->add_option("--seed", place_seed, "the medium's seed")->required();
  place_cmd->add_option("--out", place_out, "folder of seed-S.dat")->required();
  std::string place_report_plan, place_report_dir;
  CLI::App* place_report_cmd = app.add_subcommand("in-place-report", "the law in place over the plan's media seeds: in-place.md from each seed-S.dat");
  place_report_cmd->add_option("--probe", place_report_plan, "the plan, e.g. experiments/many-body.yaml")->required();
  place_report_cmd->add_option("--dir", place_report_dir, "folder of seed-S.dat, where in-place.md goes")->required();
  add_law_version(*place_report_cmd);
  std::string speed_plan, speed_dir;
  std::uint64_t speed_seed = 0;
  int speed_repeats = 3;
  CLI::App* speed_cmd = app.add_subcommand("speed", "the speed-up side by side: one medium resolved, soft pairwise and soft many-body in one process (coarse/speed.hpp)");
  speed_cmd->add_option("--probe", speed_plan, "the plan (its media seeds), e.g. experiments/many-body.yaml")->required();
  speed_cmd->add_option("--dir", speed_dir, "the version's study folder (profiles/, reference/media/; writes speed/), e.g. data/many-body-v3")->required();
  add_law_version(*speed_cmd)->required();
  auto* speed_seed_opt = speed_cmd->add_option("--seed", speed_seed, "the medium's seed (one of the version's media seeds)");
  speed_cmd->add_option("--repeats", speed_repeats, "runs of each soft model (their least time)")->capture_default_str();
  bool speed_report = false;
  speed_cmd->add_flag("--report", speed_report, "instead: speed/speed.md from the seeds' speed/seed-S.dat")->excludes(speed_seed_opt);
  std::string kin_plan, kin_dir;
  CLI::App* kin_cmd = app.add_subcommand("kinematics", "the soft medium's geometry against the resolved one's (coarse/kinematics.hpp)");
  kin_cmd->add_option("--probe", kin_plan, "the plan (its media seeds), e.g. experiments/many-body.yaml")->required();
  kin_cmd->add_option("--dir", kin_dir, "the version's study folder (profiles/, report/contact-rows.dat, in-place/; writes report/kinematics.md)")->required();
  add_law_version(*kin_cmd)->required();
  std::string seeds_config;
  CLI::App* seeds_cmd = app.add_subcommand("seeds", "print the settings' seeds (for make)");
  std::string seeds_probe;
  auto* seeds_config_opt = seeds_cmd->add_option("--config", seeds_config, "settings, e.g. experiments/coarse-grain.yaml");
  seeds_cmd->add_option("--probe", seeds_probe, "instead: the many-body probe's runs, RADIUS/GROUP-S (GROUP: seed, bodies-KIND, shear; e.g. experiments/many-body.yaml)")
      ->excludes(seeds_config_opt);
  std::string runs_stamp_release;
  auto* runs_stamp_opt = seeds_cmd->add_option("--runs-stamp", runs_stamp_release, "with --probe: print GROUP=STAMP of its groups of runs for this release instead (for make)");
  int media_of = 0;
  seeds_cmd->add_option("--media-of", media_of, "with --probe: print the media seeds of this version of the law instead (for make)")->check(CLI::Range(1, kLawVersions));
  bool medium_text = false;  // what a medium depends on, as the medium file records it (maintenance)
  seeds_cmd->add_flag("--medium-text", medium_text)->group("");
  std::string stamp_config, release;
  CLI::App* stamp_cmd = app.add_subcommand("stamp", "print the stages' configuration stamps, medium=, resolved=, soft= (for make)");
  stamp_cmd->add_option("--config", stamp_config, "settings, e.g. experiments/coarse-grain.yaml")->required();
  stamp_cmd->add_option("--release", release, "the release the stamps are of (make passes CMakeLists.txt's)")->required();
  LammpsCommands lammps;
  lammps.add(app);
  if (const auto code = parse_command_line(app, argc, argv, program)) return *code;
  try {
    if (lammps.run(program)) return 0;
    if (*seeds_cmd) {
      if (seeds_probe.empty() == seeds_config.empty()) throw InputError("seeds: give --config or --probe");
      if (!seeds_probe.empty()) {
        const ManyBodyProbe plan = read_many_body_probe(seeds_probe);
        if (media_of > 0) {
          fmt::print("{}\n", fmt::join(plan.media_seeds_of(media_of), " "));
          return 0;
        }
        const bool stamps = runs_stamp_opt->count() > 0;
        if (stamps && runs_stamp_release.empty()) throw InputError("seeds: --runs-stamp '' is not allowed; allowed: the release, e.g. 0.6.1");
        const auto groups = plan.runs_stamps(stamps ? runs_stamp_release : "-");
        for (const auto& [group, stamp] : groups) {
          if (stamps) {
            fmt::print("{}={} ", group, stamp);
            continue;
          }
          for (const auto& [radius, Rs] : plan.radii)
            for (std::uint64_t seed : plan.seeds) fmt::print("{}/{}-{} ", radius, group, seed);
        }
        fmt::print("\n");
        return 0;
      }
      if (medium_text) {
        fmt::print("{}", read_coarse_grain_settings(seeds_config).medium_text);
        return 0;
      }
      for (std::uint64_t seed : read_coarse_grain_settings(seeds_config).seeds) fmt::print("{} ", seed);
      fmt::print("\n");
      return 0;
    }
    if (*stamp_cmd) {
      const CoarseStamps st = coarse_stamps(stamp_config, release);
      fmt::print("medium={}\nresolved={}\nsoft={}\n", st.medium, st.resolved, st.soft);
      return 0;
    }
    if (*place_cmd) {
      const Lines l;
      const Stopwatch clock;
      write_in_place_seed(read_many_body_probe(place_plan), place_config, place_media, place_seed, place_out, [&](double done, double total, const CurveRow& row) {
        fmt::print(stderr, "{}{} in-place seed {}: strain {:.4f} ({:.0f}%), ETA {:.0f} s{}", l.cr(), program, place_seed, row.strain, 100.0 * done / total,
                   done > 0.0 ? clock.elapsed().wall * (total - done) / done : 0.0, l.nl());
      });
      fmt::print(stderr, "{}{} in-place: {}/seed-{}.dat ({:.0f} CPU-s)\n", l.cr(), program, place_out, place_seed, clock.elapsed().cpu);
      return 0;
    }
    if (*speed_cmd) {
      const ManyBodyProbe plan = read_many_body_probe(speed_plan);
      if (speed_report) {
        write_speed_report(plan, speed_plan, speed_dir, law_version);
        fmt::print(stderr, "{} speed: {}/speed/speed.md\n", program, speed_dir);
        return 0;
      }
      const Lines l;
      std::pair<std::string, Stopwatch> run;  // the run under way and its clock
      const SpeedSeed r = write_speed_seed(plan, speed_plan, speed_dir, law_version, speed_seed, speed_repeats, [&](const std::string& model, int k, double done, double total) {
        if (run.first != model + std::to_string(k)) run = {model + std::to_string(k), Stopwatch()};
        fmt::print(stderr, "{}{} speed seed {}: {} run {}, {:.0f}%, ETA {:.0f} s{}", l.cr(), program, speed_seed, model, k + 1, 100.0 * done / total,
                   run.second.elapsed().wall * (total - done) / done, l.nl());
      });
      fmt::print(stderr, "{}{} speed seed {}: CPU resolved {:.1f} s, pairwise {:.3f} s, many-body {:.3f} s -> {}/seed-{}.dat\n", l.cr(), program, speed_seed,
                 r.resolved, r.pairwise, r.many_body, speed_dir + "/speed", speed_seed);
      return 0;
    }
    if (*kin_cmd) {
      const CoarseGrainSettings s = read_coarse_grain_settings(kin_dir + "/profiles/many-body.yaml");
      write_kinematics_report(read_many_body_probe(kin_plan), kin_plan, read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body), s.laws, kin_dir + "/report/contact-rows.dat",
                              kin_dir + "/in-place", kin_dir + "/report", law_version);
      fmt::print(stderr, "{} kinematics: {}/report/kinematics.md\n", program, kin_dir);
      return 0;
    }
    if (*place_report_cmd) {
      write_in_place_report(read_many_body_probe(place_report_plan), place_report_plan, place_report_dir, law_version);
      fmt::print(stderr, "{} in-place-report: {}/in-place.md\n", program, place_report_dir);
      return 0;
    }
    if (*census_cmd) {
      write_soft_census(read_many_body_probe(census_plan), census_plan, census_config, census_media, census_out, law_version);
      fmt::print(stderr, "{} soft-contacts: {}/contacts.md\n", program, census_out);
      return 0;
    }
    if (*val_cmd) {
      for (const ValidationVerdict& v : write_validation(read_many_body_probe(val_plan), val_plan, val_dir, val_settings, val_out, law_version, val_against))
        fmt::print(stderr, "{} validation: {}: {} of {} points within the bound, accepted: {}\n", program, v.setting, v.agreeing, v.points,
                   v.accepted ? "yes" : "no");
      return 0;
    }
    if (*report_cmd) {
      const ProbeAnalysis a = write_probe_report(read_many_body_probe(report_plan), report_plan, report_dir, report_out);
      fmt::print(stderr, "{} probe-report: chosen {}, enters the engine: {} -> {}/probe.md\n", program, a.chosen, a.enters_engine ? "yes" : "no", report_out);
      return 0;
    }
    if (*probe_cmd) {
      if (probe_plan.empty() == probe_config.empty()) throw InputError("multi-contact: give --config or --probe");
      CoarseGrainSettings s;
      std::string source = probe_config, stamp_line;
      if (!probe_plan.empty()) {
        if (probe_radius.empty()) throw InputError("multi-contact: --probe needs --radius (one of the plan's radii)");
        const ManyBodyProbe plan = read_many_body_probe(probe_plan);
        s = plan.settings_at(probe_radius);
        if ((probe_part == "bodies") == probe_kind.empty()) throw InputError("multi-contact: --kind goes with --part bodies, and only with it");
        probe_arrangements = probe_part == "walls" ? plan.arrangements() : probe_part == "bodies" ? plan.bodies(probe_kind) : plan.shear_arrangements;
        probe_dn = probe_part == "shear" ? plan.shear_delta_n : probe_part == "bodies" ? plan.delta_n_of(probe_kind) : plan.delta_n;
        source = fmt::format("{} (radius {}: Rs = {} m; part {}{})", probe_plan, probe_radius, s.packing.Rs, probe_part, probe_kind.empty() ? "" : " " + probe_kind);
        stamp_line = plan.stamp_line(probe_part, probe_kind, release_version());  // first: make compares it (workflow/coarse.mk)
        if (probe_part == "shear") return confined_shear(program, s, probe_seed, probe_arrangements, probe_dn, plan.shear_ht, source, probe_out, stamp_line);
      } else {
        s = read_coarse_grain_settings(probe_config);
      }
      std::vector<ProbeArrangement> arrangements;
      for (const std::string& name : probe_arrangements) {
        for (const ProbeArrangement& a : arrangements)
          if (a.name == name) throw InputError(fmt::format("--arrangements: '{}' is given twice", name));
        arrangements.push_back(builtin_arrangement(name, probe_seed));
      }
      const Stopwatch clock;
      std::size_t done = 0;
      const std::size_t points = arrangements.size() * probe_dn.size();
      const auto points_of = measure_multi_contact(s, probe_seed, arrangements, probe_dn, [&](const MultiContactPoint& p) {
        const double t = clock.elapsed().wall;
        ++done;
        if (!p.failed.empty()) {
          fmt::print(stderr, "{} multi-contact: {}, delta_n {:.3f}: not measured, and its larger delta_n not tried: {}\n", program, p.arrangement,
                     p.delta_n, p.failed);
          return;
        }
        fmt::print(stderr, "{} multi-contact: {} ({} walls), delta_n {:.3f}: Fn {:.5g} N on the first wall ({}/{}, {:.0f} s, ETA {:.0f} s)\n", program,
                   p.arrangement, p.Fn.size(), p.delta_n, p.Fn[0], done, points, t, t / static_cast<double>(done) * static_cast<double>(points - done));
      });
      write_multi_contact(probe_out, source, probe_seed, arrangements, points_of, clock.elapsed().cpu, stamp_line);
      return 0;
    }
    if (*medium_cmd) return medium(o, program);
    if (estimate.run()) return 0;
    return run(o, program);
  } catch (...) {
    return exit_on_error(program);
  }
}

}  // namespace softpack::apps::coarse_app
