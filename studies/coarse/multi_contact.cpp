#include "coarse/multi_contact.hpp"

#include <fmt/format.h>

#include "coarse/medium.hpp"
#include "core/error.hpp"
#include "packing/generator.hpp"
#include "relax/relaxation.hpp"

namespace softpack {

std::vector<MultiContactPoint> measure_multi_contact(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                                     const std::vector<int>& walls, const std::vector<double>& delta_n,
                                                     const std::function<void(const MultiContactPoint&)>& progress) {
  const Packing packing = generate_packing(s.packing, packing_seed);
  const double Rs = s.packing.Rs;
  const SimulationSettings& sim = s.simulation;
  const Vec3 directions[6] = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
  std::vector<MultiContactPoint> out;
  for (const int k : walls) {
    if (k != 1 && k != 2 && k != 6) throw InputError(fmt::format("walls: {} is not allowed; allowed: 1, 2, 6", k));
    SceneDef scene = engine_scene(s);
    for (std::size_t i = 0; i < packing.radii.size(); ++i) {
      ParticleDef p;
      p.x = packing.centres[i], p.r = packing.radii[i], p.body = 0;
      scene.particles.push_back(p);
    }
    scene.shells.push_back(ShellDef{"shell", 0, Vec3::Zero(), Rs, 1, sim.shell_contact_radius, std::nullopt});
    for (int w = 0; w < k; ++w)  // each wall touching the shell from outside, its normal towards the centre
      scene.planes.push_back(PlaneDef{fmt::format("wall{}", w), Rs * directions[w], -directions[w], 1});
    Simulation simulation(scene);
    double at = 0.0;
    for (const double dn : delta_n) {
      const double step = (dn - at) * Rs;
      if (step > 0.0) {
        for (int w = 0; w < k; ++w)
          simulation.add_driver(MoveWallDef{fmt::format("wall{}", w), -s.normal_speed * directions[w], step, std::nullopt});
        while (simulation.drivers_moving()) simulation.run_steps(100);
        simulation.release_drivers();
      }
      at = dn;
      relax(simulation, s.relaxation, {}, [&] { return -simulation.plane_loads()[0].force; });
      out.push_back({k, dn, simulation.plane_loads()[0].force.dot(directions[0])});
      if (progress) progress(out.back());
    }
  }
  return out;
}

}  // namespace softpack
