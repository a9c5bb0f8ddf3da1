#include "coarse/lammps_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "contact/viscous_damping.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"
#include "sim/simulation.hpp"

namespace softpack {

double lammps_tsuji_alpha(double e) {
  const double c[] = {1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218};
  double a = 0.0;
  for (int k = 6; k >= 0; --k) a = a * e + c[k];
  return a;
}

double lammps_tsuji_code(double alpha) {
  double lo = -0.2, hi = 1.05;  // alpha_L decreases strictly here
  if (!(alpha <= lammps_tsuji_alpha(lo) && alpha >= lammps_tsuji_alpha(hi)))
    throw InputError(fmt::format("damping: LAMMPS's damping tsuji reaches a damping coefficient from {:.4g} to {:.4g}, not {:.6g}",
                                 lammps_tsuji_alpha(hi), lammps_tsuji_alpha(lo), alpha));
  for (int k = 0; k < 200 && hi - lo > 1e-16; ++k) {
    const double mid = 0.5 * (lo + hi);
    (lammps_tsuji_alpha(mid) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

LammpsGranular lammps_granular(const Material& grain, const Material& wall, double restitution, double tangential_ratio) {
  if (grain.E != wall.E || grain.nu != wall.nu)
    throw InputError(fmt::format("material.wall: E {} and nu {} against the grains' {} and {}: LAMMPS's fix wall/gran takes one E and nu "
                                 "for the contact (bench/lammps/README.md C1), so the export needs a wall of the grains' E and nu",
                                 wall.E, wall.nu, grain.E, grain.nu));
  LammpsGranular g;
  g.E = grain.E, g.nu = grain.nu;
  g.E_wall = grain.E / (1.0 + grain.nu);
  g.damping_code = lammps_tsuji_code(damping::zeta_from_restitution(restitution));
  g.Dt = tsuji_Dt(grain, grain);
  g.xgammat = tangential_ratio * std::sqrt(g.Dt * hertz_D(grain, grain) / 3.5);  // rotating solid spheres: m_t = m12 / 3.5
  g.mu = contact_mu(grain, grain), g.mu_wall = contact_mu(grain, wall);
  return g;
}

namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

std::string data_file(const CoarseGrainSettings& s, const MediumFile& mf, const SceneDef& scene) {
  const Medium& m = mf.medium;
  const double margin = 0.1 * m.L;  // the box holds the walls with room to spare (boundary f f f)
  std::string out = fmt::format("LAMMPS data file: coarse-grain medium seed {} (soft model), softpack-coarse export --lammps, softpack {}\n\n",
                                mf.seed, code_version());
  out += fmt::format("{} atoms\n2 atom types\n\n", scene.particles.size());
  out += fmt::format("{:.17g} {:.17g} xlo xhi\n{:.17g} {:.17g} ylo yhi\n{:.17g} {:.17g} zlo zhi\n\n", -margin, m.L + margin, -margin, m.L + margin,
                     -margin, m.H + margin);
  out += "Atoms # sphere\n\n";
  for (std::size_t k = 0; k < scene.particles.size(); ++k) {
    const ParticleDef& p = scene.particles[k];
    const double density = p.mass ? *p.mass / sphere_volume(p.r) : s.simulation.material.density;
    out += fmt::format("{} {} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", k + 1, p.soft ? 2 : 1, 2.0 * p.r, density, p.x.x(), p.x.y(), p.x.z());
  }
  return out;
}

// The walls: softpack/wall for the soft-particles, fix wall/gran for the grains, one pair per plane.
std::string walls() {
  return R"LMP(# -- The six walls. A soft-particle meets softpack/wall (the soft-solid law); a grain meets LAMMPS's
# fix wall/gran (group grains) with the corrections of bench/lammps/README.md. The top wall's grain side is
# a region that follows softpack/wall's position (f_top[4..6]): one wall, one motion.
fix             bottom all softpack/wall z lo 0
fix             top all softpack/wall z hi ${H0}
fix             x0 all softpack/wall x lo 0
fix             x1 all softpack/wall x hi ${L}
fix             y0 all softpack/wall y lo 0
fix             y1 all softpack/wall y hi ${L}
variable        top_dx equal f_top[4]
variable        top_dz equal f_top[6]-${H0}
region          top_plane plane 0 0 ${H0} 0 0 -1 move v_top_dx NULL v_top_dz units box
fix             g_bottom grains wall/gran granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji zplane 0 NULL contacts
fix             g_top grains wall/gran/region granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji region top_plane contacts
fix             g_x0 grains wall/gran granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji xplane 0 NULL contacts
fix             g_x1 grains wall/gran granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji xplane NULL ${L} contacts
fix             g_y0 grains wall/gran granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji yplane 0 NULL contacts
fix             g_y1 grains wall/gran granular hertz/material ${E_wall} ${damping_code} ${nu} tangential mindlin ${Dt} ${xgammat} ${mu_wall} damping tsuji yplane NULL ${L} contacts
# the force of each wall on the grains (columns 2-4 of wall/gran's per-atom contacts)
compute         g_bottom grains reduce sum f_g_bottom[2] f_g_bottom[3] f_g_bottom[4]
compute         g_top grains reduce sum f_g_top[2] f_g_top[3] f_g_top[4]
compute         g_x0 grains reduce sum f_g_x0[2] f_g_x0[3] f_g_x0[4]
compute         g_x1 grains reduce sum f_g_x1[2] f_g_x1[3] f_g_x1[4]
compute         g_y0 grains reduce sum f_g_y0[2] f_g_y0[3] f_g_y0[4]
compute         g_y1 grains reduce sum f_g_y1[2] f_g_y1[3] f_g_y1[4]
)LMP";
}

// A row of the curve (coarse/compression.hpp CurveRow): the stresses on the walls from both sides
// of each (softpack/wall's load is the force on the wall, wall/gran's the force on the grains).
std::string row_variables() {
  return R"LMP(# -- A row of the curve (studies/coarse/compression.hpp): the load on each wall from the soft-particles
# (softpack/wall: the force on the wall) and from the grains (minus wall/gran's force on them)
variable        H equal f_top[6]
variable        strain_now equal (${H0}-v_H)/${H0}
variable        sigma_top equal (f_top[3]-c_g_top[3])/(${L}*${L})
variable        sigma_bottom equal (c_g_bottom[3]-f_bottom[3])/(${L}*${L})
variable        sigma_lateral equal ((c_g_x0[1]-f_x0[1])+(f_x1[1]-c_g_x1[1])+(c_g_y0[2]-f_y0[2])+(f_y1[2]-c_g_y1[2]))/(4*${L}*v_H)
variable        shear_now equal f_top[4]/${H0}
variable        tau equal -(f_top[1]-c_g_top[1])/(${L}*${L})
variable        fraction equal ${solid_volume}/(${L}*${L}*v_H)
compute         ke all ke
compute         erot all erotate/sphere
variable        kinetic equal c_ke+c_erot
# the computes a row reads are made current at each run's last step by the thermo output
thermo_style    custom step v_strain_now v_sigma_top v_sigma_lateral c_g_bottom[3] c_g_top[3] c_g_x0[1] c_g_x1[1] c_g_y0[2] c_g_y1[2] c_ke c_erot
thermo_modify   norm no lost error
)LMP";
}

const char* kIncrement = R"LMP(# One increment of the compression (studies/coarse/compression.hpp), included by phase.in: the top wall
# moves by d = min(every, total - k every) H0 along (dir_x, 0, dir_z) in the engine's count of steps
# (d / (speed dt) rounded up), stands relax_steps steps under the per-grain quench, then a row of curve.dat.
variable        left equal ${total}-${k}*${every}
variable        d equal (v_left*(v_left<${every})+${every}*(v_left>=${every}))*${H0}
variable        n equal ceil(v_d/(${speed}*${time_step})-1e-9)
variable        v equal v_d/(v_n*${time_step})
fix_modify      top velocity $(v_dir_x*v_v:%.17g) 0 $(v_dir_z*v_v:%.17g)
run             ${n} pre no post no
fix_modify      top velocity 0 0 0
if "${relax_steps} > 0" then "fix_modify quench quench yes" "run ${relax_steps} pre no post no" "fix_modify quench quench no"
print           "$(v_strain_now:%.17g) ${phase} $(v_shear_now:%.17g) $(v_tau:%.17g) $(v_sigma_top:%.17g) $(v_sigma_bottom:%.17g) $(v_sigma_lateral:%.17g) $(v_fraction:%.17g) $(v_kinetic:%.17g) $(step)" append curve.dat screen no
)LMP";

const char* kPhase = R"LMP(# One phase of the compression, included by in.compression: the increments of `every` of H0 up to
# `total` of H0 (their count rounded, at least one, as the engine's; none when total is 0).
variable        rows equal (${total}>0)*(round(${total}/${every})+(round(${total}/${every})<1)*(1-round(${total}/${every})))
variable        k equal 0
label           next_increment
if "${k} >= ${rows}" then "jump SELF phase_done"
include         increment.in
variable        k equal ${k}+1
jump            SELF next_increment
label           phase_done
)LMP";

std::string input_script(const CoarseGrainSettings& s, const std::string& config, const MediumFile& mf, const Simulation& sim,
                         const LammpsGranular& g, double skin) {
  const Medium& m = mf.medium;
  const EffectsDef& fx = s.simulation.effects;
  std::string out = fmt::format(
      R"LMP(# The oedometric compression of a coarse-grain medium's soft model in LAMMPS (issue 34, docs/lammps.md),
# written by softpack-coarse export --lammps (softpack {version}) from
#   settings  {config} (its coarse_grain section: settings.yaml)
#   medium    seed {seed}: {grains} grains (type 1), {sites} soft-particles (type 2), box {L:.6g} x {L:.6g} x {H:.6g} m
#   laws      {laws} (copied to laws.json)
# Run it in this folder (it writes curve.dat, a row per increment as softpack-coarse run's curve, and
# log.lammps; softpack-coarse lammps-curve reads them back):
#   softpack-lammps -in in.compression
#   mpirun -np 2 softpack-lammps -in in.compression
# Every run after the first is `pre no` (it continues the last step; a command that makes LAMMPS init
# again between runs, write_restart or write_data, makes fix wall/gran convert its damping again:
# bench/lammps/README.md C5).

# -- The protocol (docs/coarse-grain.md; string variables: ${{X}} puts in their text, every digit): the top wall moves down by `strain` of H0 at `speed`, an
# increment every `record_strain`, each followed by `relax` s at rest under the per-grain quench;
# then up by `unload_strain`; then along x by `shear`, an increment every `record_shear`.
variable        speed string {speed:.17g}
variable        strain string {strain:.17g}
variable        unload_strain string {unload:.17g}
variable        record_strain string {record:.17g}
variable        shear string {shear:.17g}
variable        record_shear string {record_shear:.17g}
variable        relax string {relax:.17g}
# The medium (medium.data) and the engine's time step for it (integrate/time_step.hpp)
variable        L string {L:.17g}
variable        H0 string {H:.17g}
variable        solid_volume string {solid:.17g}
variable        time_step string {dt:.17g}
variable        relax_steps equal (${{relax}}>0)*(1+(round(${{relax}}/${{time_step}})-1)*(round(${{relax}}/${{time_step}})>1))
# The grains' contact in LAMMPS's terms (bench/lammps/README.md): E, nu, mu of the grains; the wall's E
# is E/(1+nu) (C1); kt = Dt (C2); the tangential damping xgammat (C3); e' such that LAMMPS's tsuji
# polynomial gives the engine's damping coefficient for the restitution {restitution} (C4)
variable        E string {E:.17g}
variable        nu string {nu:.17g}
variable        mu string {mu:.17g}
variable        E_wall string {E_wall:.17g}
variable        mu_wall string {mu_wall:.17g}
variable        Dt string {Dt:.17g}
variable        xgammat string {xgammat:.17g}
variable        damping_code string {code:.17g}

units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off             # softpack/soft: a contact across two ranks keeps its spring on both
comm_modify     vel yes
read_data       medium.data
group           grains type 1
group           soft type 2
pair_style      hybrid granular softpack/soft laws.json grain_contact {grain_contact} restitution {restitution:.17g} tangential_ratio {ratio:.17g} history_update {history}
pair_coeff      1 1 granular hertz/material ${{E}} ${{damping_code}} ${{nu}} tangential mindlin ${{Dt}} ${{xgammat}} ${{mu}} damping tsuji
pair_coeff      1 2 softpack/soft grain soft
pair_coeff      2 2 softpack/soft soft soft
neighbor        {skin:.17g} bin
neigh_modify    delay 0 every 1 check yes
timestep        ${{time_step}}
fix             integrate all nve/sphere
fix             quench all softpack/quench no

)LMP",
      fmt::arg("version", code_version()), fmt::arg("config", config), fmt::arg("seed", mf.seed), fmt::arg("grains", m.grain_x.size()),
      fmt::arg("sites", m.sites.size()), fmt::arg("L", m.L), fmt::arg("H", m.H), fmt::arg("laws", s.laws), fmt::arg("speed", s.speed),
      fmt::arg("strain", s.strain), fmt::arg("unload", s.unload_strain), fmt::arg("record", s.record_strain), fmt::arg("shear", s.shear),
      fmt::arg("record_shear", s.record_shear > 0.0 ? s.record_shear : s.record_strain), fmt::arg("relax", s.relax), fmt::arg("solid", m.solid_volume()),
      fmt::arg("dt", sim.dt()), fmt::arg("restitution", *fx.restitution), fmt::arg("E", g.E), fmt::arg("nu", g.nu), fmt::arg("mu", g.mu),
      fmt::arg("E_wall", g.E_wall), fmt::arg("mu_wall", g.mu_wall), fmt::arg("Dt", g.Dt), fmt::arg("xgammat", g.xgammat), fmt::arg("code", g.damping_code),
      fmt::arg("grain_contact", s.grain_contact == GrainContactRule::wall ? "wall" : "reduced-radius"), fmt::arg("ratio", fx.tangential_damping_ratio),
      fmt::arg("history", s.simulation.integration.history_update == HistoryUpdate::synchronized ? "synchronized" : "standard"), fmt::arg("skin", skin));
  out += walls() + "\n" + row_variables();
  out += R"LMP(
# -- The compression. The first run computes the forces of the medium at rest (a row at strain 0) and
# is the one whose init converts fix wall/gran's damping (C5).
run             0
print           "# strain phase shear tau sigma_top sigma_bottom sigma_lateral fraction kinetic step" file curve.dat screen no
print           "$(v_strain_now:%.17g) 1 $(v_shear_now:%.17g) $(v_tau:%.17g) $(v_sigma_top:%.17g) $(v_sigma_bottom:%.17g) $(v_sigma_lateral:%.17g) $(v_fraction:%.17g) $(v_kinetic:%.17g) $(step)" append curve.dat screen no
# loading (phase 1), unloading (-1), platen shear (2)
variable        phase equal 1
variable        dir_x equal 0
variable        dir_z equal -1
variable        total string ${strain}
variable        every string ${record_strain}
include         phase.in
variable        phase equal -1
variable        dir_z equal 1
variable        total string ${unload_strain}
include         phase.in
variable        phase equal 2
variable        dir_x equal 1
variable        dir_z equal 0
variable        total string ${shear}
variable        every string ${record_shear}
include         phase.in
print           "softpack-coarse export: the compression ended at step $(step)"
)LMP";
  return out;
}

}  // namespace

void write_lammps_export(const CoarseGrainSettings& s, const std::string& config, const MediumFile& mf, const std::string& out_dir) {
  if (s.spin_locked)
    throw InputError("coarse_grain.soft_particle.rotation: locked is not exported (LAMMPS's fix nve/sphere turns every sphere); allowed: free");
  const EffectsDef& fx = s.simulation.effects;
  if (fx.normal != "hertz" || !fx.friction || !fx.rotation || !fx.damping())
    throw InputError(fmt::format("{}: simulation.effects: the export writes Hertz, Tsuji friction, rotation and damping (the coarse-grain "
                                 "profiles'); these settings have normal '{}', friction {}, rotation {}, damping {}",
                                 s.profile, fx.normal, fx.friction, fx.rotation, fx.damping()));
  if (fx.gravity) throw InputError(fmt::format("{}: simulation.effects.gravity is not exported (the input has none)", s.profile));
  if (s.beyond_range == SoftParticlesDef::BeyondRange::stop)
    throw InputError("coarse_grain.soft_particle.beyond_range: stop is not exported (softpack/soft does not count the contacts beyond the laws' range); allowed: report");
  const LammpsGranular g = lammps_granular(s.simulation.material, s.simulation.wall_material, *fx.restitution, fx.tangential_damping_ratio);
  if (!s.many_body.empty())  // the pair style reads one law file, copied below
    throw InputError("coarse_grain.soft_particle.many_body is not exported (softpack/soft reads the one law file `laws`); allowed: no many_body");
  const SoftParticleLaws laws = read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body);
  Medium medium = mf.medium;
  medium_contents(s, medium);  // nested: the sites' contents weigh the soft-particles, as in softpack-coarse run
  const SceneDef scene = medium_scene(s, medium, CoarseModel::soft, laws);
  const Simulation sim(scene);  // the engine's time step for this medium
  double r_min = scene.particles.front().r;
  for (const ParticleDef& p : scene.particles) r_min = std::min(r_min, p.r);
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(fmt::format("{}: cannot make the folder: {}", out_dir, ec.message()));
  std::ifstream law_in(s.laws, std::ios::binary);
  std::stringstream law_text;
  law_text << law_in.rdbuf();
  write_files_atomically({{out_dir + "/medium.data", data_file(s, mf, scene)},
                          {out_dir + "/laws.json", law_text.str()},
                          {out_dir + "/in.compression", input_script(s, config, mf, sim, g, s.simulation.neighbor.skin * r_min)},
                          {out_dir + "/phase.in", kPhase},
                          {out_dir + "/increment.in", kIncrement},
                          {out_dir + "/settings.yaml", s.section_text}});
}

LammpsRun read_lammps_run(const std::string& dir, const CoarseGrainSettings& s, const MediumFile& mf) {
  LammpsRun out;
  CompressionRun& run = out.run;
  const std::string curve = dir + "/curve.dat", log = dir + "/log.lammps";
  std::ifstream in(curve);
  if (!in) throw InputError(fmt::format("{}: no such file (run softpack-lammps -in in.compression in {})", curve, dir));
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row_in(line);
    CurveRow r;
    double step = 0.0;
    if (!(row_in >> r.strain >> r.phase >> r.shear >> r.tau >> r.sigma_top >> r.sigma_bottom >> r.sigma_lateral >> r.fraction >> r.kinetic >> step))
      throw InputError(fmt::format("{}:{}: expected 10 numbers (strain phase shear tau sigma_top sigma_bottom sigma_lateral fraction kinetic step)",
                                   curve, number));
    r.Z = std::nan(""), r.elastic = std::nan("");  // not measured by the LAMMPS input
    run.rows.push_back(r);
    run.steps = static_cast<long>(step);
  }
  // The engine's rows (coarse/compression.cpp): a phase of `total` has max(1, lround(total / every))
  // increments, none when total is 0; and the input's settings must be these.
  const auto increments = [](double total, double every) { return total > 0.0 ? std::max(1L, std::lround(total / every)) : 0L; };
  const long expected = 1 + increments(s.strain, s.record_strain) + increments(s.unload_strain, s.record_strain) +
                        increments(s.shear, s.record_shear > 0.0 ? s.record_shear : s.record_strain);
  if (static_cast<long>(run.rows.size()) != expected)
    throw InputError(fmt::format("{}: {} rows where the settings give {}: the run did not end, or ran other settings (see {})", curve,
                                 run.rows.size(), expected, log));
  std::ifstream settings_in(dir + "/settings.yaml");
  std::stringstream settings_text;
  settings_text << settings_in.rdbuf();
  if (settings_text.str() != s.section_text)
    throw InputError(fmt::format("{}/settings.yaml: not the coarse_grain section of the settings given: the run was exported from other settings", dir));
  std::ifstream log_in(log);
  if (!log_in) throw InputError(fmt::format("{}: no such file (the run's log)", log));
  // "Loop time of T on N procs for S steps with A atoms", one per run
  double seconds = 0.0;
  long steps = 0;
  bool ended = false;
  while (std::getline(log_in, line)) {
    ended = ended || line.rfind("softpack-coarse export: the compression ended", 0) == 0;
    if (line.rfind("Loop time of ", 0) != 0) continue;
    std::istringstream words(line.substr(13));
    double t = 0.0;
    int ranks = 0;
    long n = 0;
    std::string on, procs, for_, steps_word;
    if (!(words >> t >> on >> ranks >> procs >> for_ >> n >> steps_word) || on != "on" || for_ != "for" || steps_word != "steps")
      throw InputError(fmt::format("{}: '{}' is not LAMMPS's 'Loop time of T on N procs for S steps'", log, line));
    seconds += t, out.ranks = ranks, steps += n;
  }
  if (!ended) throw InputError(fmt::format("{}: no line 'softpack-coarse export: the compression ended': the run did not end", log));
  if (out.ranks == 0) throw InputError(fmt::format("{}: no 'Loop time' line: not the log of a LAMMPS run", log));
  if (steps != run.steps) throw InputError(fmt::format("{}: {} steps, but {} ends at step {}: not the log of this run", log, steps, curve, run.steps));
  const SoftParticleLaws laws = read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body);
  Medium medium = mf.medium;
  medium_contents(s, medium);  // nested: the sites' contents weigh the soft-particles, as in softpack-coarse run
  const SceneDef scene = medium_scene(s, medium, CoarseModel::soft, laws);
  run.dt = Simulation(scene).dt();
  run.spheres = scene.particles.size(), run.bodies = mf.medium.bodies();
  run.time.wall = seconds, run.time.cpu = seconds * out.ranks;
  return out;
}

}  // namespace softpack
