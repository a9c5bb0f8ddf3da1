// Google Benchmark programs of `make bench`:
//  * Confined/{frictional,frictionless}: velocity-Verlet steps of a ~5000-sphere packing
//    (polydispersity 10) compressed in a shell, Hertz + Tsuji friction + damping + rotation,
//    or Hertz + damping only; counters: particle steps and contacts per second;
//  * SameState/{frictional,frictionless}: the same first steps from the same state, for the
//    price of friction on identical contacts;
//  * ContactDetection/Pi: hierarchical-grid neighbour search (build + every pair) per sphere
//    at equal N and solid fraction for polydispersity 1, 10, 100, 1000.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "neighbor/hierarchical_grid.hpp"
#include "sim/simulation.hpp"
#include "support/confined_packing.hpp"
#include "support/scenes.hpp"

namespace {

using namespace softpack;

const std::vector<bench::Sphere>& packing() {
  static const std::vector<bench::Sphere> spheres = [] {
    const char* cache = std::getenv("SOFTPACK_BENCH_PACKING");
    return bench::confined_packing(5000, bench::BenchParameters{}, cache ? cache : "");
  }();
  return spheres;
}

void Confined(benchmark::State& state, bool friction) {
  Simulation sim(bench::bench_scene(packing(), bench::BenchParameters{}, friction));
  sim.run_steps(200);  // past the first neighbour builds
  const long steps = 200;
  double contacts = 0.0;
  for (auto _ : state) {
    sim.run_steps(steps);
    state.PauseTiming();
    contacts += static_cast<double>(sim.residuals().contacts) * steps;
    state.ResumeTiming();
  }
  const double n = static_cast<double>(sim.particles().size());
  state.counters["particle_steps_per_s"] = benchmark::Counter(n * steps * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["contacts_per_s"] = benchmark::Counter(contacts, benchmark::Counter::kIsRate);
  state.counters["spheres"] = n;
  state.counters["contacts"] = contacts / (steps * state.iterations());
}
BENCHMARK_CAPTURE(Confined, frictional, true)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(Confined, frictionless, false)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// What friction costs on identical contacts: the first steps from the packing's initial state,
// restored (untimed) before every iteration. Confined and the whole runs of `make bench` let each
// scene evolve, and from this jammed frictional packing the frictionless one flows at once: its
// lists are rebuilt every ~7 steps at first and 86 times in 2000 steps, against 14, so those
// compare different work. Here both scenes step the same spheres with the same contacts, from
// lists built once, for fewer steps than the first rebuild takes (rebuilds_per_step must be 0).
// step() rather than run_steps(): no watchdog check at the end of each iteration.
void SameState(benchmark::State& state, bool friction) {
  Simulation sim(bench::bench_scene(packing(), bench::BenchParameters{}, friction));
  const SimulationState start = sim.state();
  const long steps = 5;
  double contacts = 0.0;
  long rebuilds = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sim.restore(start);
    const long before = sim.neighbour_rebuilds();
    state.ResumeTiming();
    for (long s = 0; s < steps; ++s) sim.step();
    state.PauseTiming();
    rebuilds += sim.neighbour_rebuilds() - before;
    contacts += static_cast<double>(sim.residuals().contacts) * steps;
    state.ResumeTiming();
  }
  const double n = static_cast<double>(sim.particles().size());
  state.counters["particle_steps_per_s"] = benchmark::Counter(n * steps * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["contacts"] = contacts / (steps * state.iterations());
  state.counters["rebuilds_per_step"] = static_cast<double>(rebuilds) / (steps * state.iterations());
}
BENCHMARK_CAPTURE(SameState, frictional, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(SameState, frictionless, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);

// About N spheres from the power law b = 3.5 on [r_max / Pi, r_max], placed without overlap
// (random sequential addition) in a ball sized for a solid fraction of 0.30, whatever Pi.
struct Configuration {
  std::vector<Vec3> x;
  std::vector<double> r;
};

Configuration configuration(double Pi) {
  const int n = 20000;
  const double r_max = 1.0, r_min = r_max / Pi;
  testing::Random sizes(static_cast<std::uint64_t>(Pi));
  double volume = 0.0;
  for (int k = 0; k < n; ++k) volume += std::pow(Pi == 1 ? r_max : testing::power_law_radius(sizes, r_min, r_max, 3.5), 3);
  const double R = std::cbrt(volume / 0.30);
  testing::Random rng(static_cast<std::uint64_t>(Pi));  // the same radii as above
  Configuration c;
  for (const auto& p : testing::random_spheres_in_shell(rng, n, R, Pi == 1 ? r_max : r_min, r_max, 3.5, 1000, kNoBody)) {
    c.x.push_back(p.x);
    c.r.push_back(p.r);
  }
  return c;
}

void ContactDetection(benchmark::State& state) {
  const double Pi = static_cast<double>(state.range(0));
  const Configuration c = configuration(Pi);
  double r_min = c.r[0];
  for (double r : c.r) r_min = std::min(r_min, r);
  const double skin = 0.2 * r_min;
  HierarchicalGrid grid;
  std::size_t pairs = 0;
  for (auto _ : state) {
    grid.build(c.x, c.r, skin, 4.0);
    pairs = 0;
    grid.for_each_pair([&](int, int) { ++pairs; });
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["s_per_sphere"] =
      benchmark::Counter(static_cast<double>(c.x.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["pairs_per_sphere"] = static_cast<double>(pairs) / static_cast<double>(c.x.size());
  state.counters["levels"] = static_cast<double>(grid.level_count());
  state.counters["spheres"] = static_cast<double>(c.x.size());
}
BENCHMARK(ContactDetection)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
