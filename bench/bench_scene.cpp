// softpack-bench-scene: the softpack side of the LAMMPS comparison. Runs the benchmark
// packing (bench/support/confined_packing.hpp) for a number of steps and prints the loop time
// and throughput, plus the parameters LAMMPS must be given to compute the same physics.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>

#include "contact/viscous_damping.hpp"
#include "core/cpu_features.hpp"
#include "core/material.hpp"
#include "sim/simulation.hpp"
#include "state/state_digest.hpp"
#include "support/confined_packing.hpp"

int main(int argc, char** argv) {
  using namespace softpack;
  CLI::App app{"softpack-bench-scene: time softpack on the benchmark packing (make bench)"};
  std::string packing_path;
  long steps = 2000;
  bool frictionless = false, parameters_only = false, digest = false;
  int n = 5000;
  app.add_option("--packing", packing_path, "x y z r file; made (about --spheres spheres) when missing")->required();
  app.add_option("--spheres", n, "sphere count when the packing has to be made");
  app.add_option("--steps", steps, "velocity-Verlet steps to time");
  app.add_flag("--frictionless", frictionless, "Hertz + damping only (no friction, no rotation)");
  app.add_flag("--parameters", parameters_only, "print the physical parameters (for LAMMPS) and exit");
  app.add_flag("--digest", digest, "also print a digest of the final state's bits (x, v, w, F, T, springs)");
  std::string isa = "best";
  app.add_option("--isa", isa, "instruction set of the force loops: best, avx512, portable (both give the same bits)")
      ->check(CLI::IsMember({"best", "avx512", "portable"}));
  CLI11_PARSE(app, argc, argv);

  if (isa == "portable") cpu::limit_vector_isa(cpu::VectorIsa::portable);
  const bench::BenchParameters p;
  const auto spheres = bench::confined_packing(n, p, packing_path);
  const SceneDef scene = bench::bench_scene(spheres, p, !frictionless);
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

  const auto t0 = std::chrono::steady_clock::now();
  sim.run_steps(steps);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto meas = sim.residuals();
  fmt::print("softpack_loop_time_s={:.6g} particle_steps_per_s={:.4g} contacts={} listed_pairs={} rebuilds={} friction={} isa={}\n", seconds,
             static_cast<double>(spheres.size()) * static_cast<double>(steps) / seconds, meas.contacts, sim.pair_list().size(),
             sim.neighbour_rebuilds(), frictionless ? 0 : 1, cpu::name(cpu::vector_isa()));
  if (digest) fmt::print("state_digest={:016x}\n", state_digest(sim.state()));
  return 0;
}
