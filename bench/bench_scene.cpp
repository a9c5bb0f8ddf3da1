// softpack-bench-scene: the softpack side of the LAMMPS comparison. Runs the benchmark
// packing (bench/support/confined_packing.hpp) for a number of steps and prints the loop time
// and throughput, plus the parameters LAMMPS must be given to compute the same physics; or, with
// --lattice N, the scaling scene of about N spheres (lattice_cube there), and the memory the
// simulation takes per sphere.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "contact/viscous_damping.hpp"
#include "core/cpu_features.hpp"
#include "core/material.hpp"
#include "core/stopwatch.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/confined_packing.hpp"

namespace {

// The process's resident memory [bytes] (/proc/self/statm), 0 where it cannot be read.
double resident_bytes() {
  std::ifstream in("/proc/self/statm");
  double size = 0.0, resident = 0.0;
  if (!(in >> size >> resident)) return 0.0;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

}  // namespace

int main(int argc, char** argv) {
  using namespace softpack;
  CLI::App app{"softpack-bench-scene: time softpack on the benchmark packing (make bench)"};
  std::string packing_path;
  long steps = 2000;
  bool frictionless = false, parameters_only = false, digest = false;
  int n = 5000;
  long lattice = 0;
  std::string order = "spatial";
  auto* packing_opt = app.add_option("--packing", packing_path, "x y z r file; made (about --spheres spheres) when missing and --spheres is given");
  app.add_option("--lattice", lattice, "instead of --packing: about N equal spheres on a lattice, 12 persistent contacts each")
      ->check(CLI::Range(1L, 100000000L))
      ->excludes(packing_opt);
  app.add_option("--order", order, "the spheres' order in memory: spatial (Z-order, as the engine is meant to get them) or given")
      ->check(CLI::IsMember({"spatial", "given"}));
  auto* spheres_opt = app.add_option("--spheres", n, "sphere count when the packing has to be made")->check(CLI::Range(1, 100000000));
  app.add_option("--steps", steps, "velocity-Verlet steps to time (with --lattice, after one untimed set-up step)");
  app.add_flag("--frictionless", frictionless, "Hertz + damping only (no friction, no rotation)");
  app.add_flag("--parameters", parameters_only, "print the physical parameters (for LAMMPS) and exit");
  app.add_flag("--digest", digest, "also print a digest of the final state's bits (x, v, w, F, T, springs)");
  std::string isa = "best";
  app.add_option("--isa", isa, "instruction set of the force loops: best, avx512, portable (both give the same bits)")
      ->check(CLI::IsMember({"best", "avx512", "portable"}));
  CLI11_PARSE(app, argc, argv);

  if (packing_path.empty() && lattice == 0) {
    fmt::print(stderr, "softpack-bench-scene: give --packing FILE or --lattice N\n");
    return 2;
  }
  // A missing file is made only when asked: made at the default size, a file named for another
  // (confined-1600.txt) held 5 000 spheres and every later run timed the wrong scene.
  if (lattice == 0 && !std::filesystem::exists(packing_path) && spheres_opt->count() == 0) {
    fmt::print(stderr, "softpack-bench-scene: {}: no such packing; give --spheres N to make one of about N spheres there\n", packing_path);
    return 2;
  }
  if (isa == "portable") cpu::limit_vector_isa(cpu::VectorIsa::portable);
  const bench::BenchParameters p;
  const bench::Lattice grid = lattice > 0 ? bench::lattice_cube(lattice, 0.5e-3, 1e-2) : bench::Lattice{};
  const auto spheres = lattice > 0 ? grid.spheres : bench::confined_packing(n, p, packing_path);
  const SceneDef scene =
      lattice > 0 ? bench::lattice_scene(grid, p, !frictionless, order == "spatial") : bench::bench_scene(spheres, p, !frictionless, order == "spatial");
  const double rss_before = resident_bytes();
  Simulation sim(scene);
  const Material& m = scene.materials[0];
  const double alpha = damping::zeta_from_restitution(p.restitution);  // LAMMPS calls the damping coefficient alpha
  // LAMMPS damps the tangential direction with xgammat * gamma_n; ours uses the sliding-rolling
  // mode's own stiffness and mass (contact/viscous_damping.hpp): the ratio is constant,
  // sqrt(Dt D / 3.5) for rotating solid spheres.
  const double xgammat = scene.effects.tangential_damping_ratio * std::sqrt(tsuji_Dt(m, m) * hertz_D(m, m) / 3.5);
  double r_min = spheres[0].r, r_max = spheres[0].r;
  for (const auto& s : spheres) r_min = std::min(r_min, s.r), r_max = std::max(r_max, s.r);
  fmt::print("spheres={} r_min={:.6g} r_max={:.6g} Rs={:.6g} dt={:.9g} alpha={:.12g} xgammat={:.12g} skin={:.6g}\n",
             spheres.size(), r_min, r_max, p.Rs, sim.dt(), alpha, xgammat, p.skin * r_min);
  if (parameters_only) return 0;

  // The scaling scene times the steady state: its set-up (the first neighbour list, the first
  // touch of the contact arrays' pages) is one step timed apart, else it weighs on the 20 steps
  // of 10^6 spheres and not on the 20 000 of 10^3. The packing scene (the LAMMPS comparison,
  // whose timings include LAMMPS's own set-up, and the digests) times every step.
  double setup_seconds = 0.0;
  if (lattice > 0) {
    const Stopwatch setup;
    sim.run_steps(1);
    setup_seconds = setup.elapsed().wall;
  }
  const auto t0 = std::chrono::steady_clock::now();
  sim.run_steps(steps);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto meas = sim.residuals();
  fmt::print("softpack_loop_time_s={:.6g} particle_steps_per_s={:.4g} contacts={} listed_pairs={} rebuilds={} friction={} isa={}\n", seconds,
             static_cast<double>(spheres.size()) * static_cast<double>(steps) / seconds, meas.contacts, sim.pair_list().size(),
             sim.neighbour_rebuilds(), frictionless ? 0 : 1, cpu::name(cpu::vector_isa()));
  if (digest) fmt::print("state_digest={:016x}\n", state_digest(sim.state()));
  if (lattice > 0)
    fmt::print("ns_per_sphere_step={:.4g} setup_s={:.4g} contacts_per_sphere={:.3g} memory_per_sphere_B={:.0f}\n",
               1e9 * seconds / (static_cast<double>(spheres.size()) * static_cast<double>(steps)), setup_seconds,
               2.0 * static_cast<double>(meas.contacts) / static_cast<double>(spheres.size()),
               (resident_bytes() - rss_before) / static_cast<double>(spheres.size()));
  return 0;
}
