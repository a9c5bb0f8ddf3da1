#include "coarse/compression.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "forces/contact_walk.hpp"

namespace softpack {

CurveRow curve_row(const Simulation& sim, const Medium& m, const std::vector<int>& body_of, double H0, int phase) {
  CurveRow row;
  const auto& planes = sim.planes();
  const auto& loads = sim.plane_loads();
  const double H = planes[1].point.z() - planes[0].point.z();
  const double area = m.L * m.L;
  const auto pressure = [&](std::size_t k) { return -loads[k].force.dot(planes[k].normal); };
  row.strain = (H0 - H) / H0;
  row.phase = phase;
  row.sigma_bottom = pressure(0) / area;
  row.sigma_top = pressure(1) / area;
  row.shear = planes[1].point.x() / H0;  // the top plane starts at x = 0
  row.tau = -loads[1].force.x() / area;
  row.sigma_lateral = (pressure(2) + pressure(3) + pressure(4) + pressure(5)) / (4.0 * m.L * H);
  row.fraction = m.solid_volume() / (area * H);
  // Bodies in contact: distinct pairs of bodies with a loaded contact between them.
  const int grains = static_cast<int>(m.grain_x.size());
  std::vector<std::pair<int, int>> touching;
  const ForceField& ff = sim.force_field();
  for_each_closed_contact(sim.world(), sim.contact_lists(), ff, [&](const ClosedContact& c) {
    if (c.kind != ClosedContact::Kind::pair || !(c.Fn() > 0.0)) return;
    const int a = body_of[static_cast<std::size_t>(c.i)], b = body_of[static_cast<std::size_t>(c.j)];
    if (a != b) touching.emplace_back(std::min(a, b), std::max(a, b));
  });
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  for (const auto& [a, b] : touching) {
    const int soft = (a >= grains) + (b >= grains);
    (soft == 0 ? row.grain_grain : soft == 1 ? row.grain_soft : row.soft_soft) += 1;
  }
  row.Z = 2.0 * static_cast<double>(touching.size()) / static_cast<double>(m.bodies());
  const Measurement r = sim.residuals();
  row.kinetic = r.kinetic_energy, row.elastic = r.elastic_energy;
  return row;
}

double strain_within_laws(const std::vector<CurveRow>& rows) {
  double within = std::numeric_limits<double>::quiet_NaN();
  for (const CurveRow& row : rows) {
    if (row.phase != 1) continue;
    if (row.beyond_range < 0) return std::numeric_limits<double>::quiet_NaN();
    if (row.beyond_range > 0) return std::isnan(within) ? -1.0 : within;
    within = row.strain;
  }
  return within;
}

CompressionRun run_compression(const SceneDef& scene, const Medium& m, CoarseModel model, const CoarseGrainSettings& s,
                               const std::function<void(double, double, const CurveRow&)>& progress,
                               const std::function<void(const Simulation&, const CurveRow&)>& observe) {
  Stopwatch clock;
  CompressionRun run;
  Simulation sim(scene);
  run.dt = sim.dt();
  run.spheres = sim.particles().size();
  run.bodies = m.bodies();
  const std::vector<int> body_of = sphere_bodies(m, model);
  const double H0 = m.H;
  const double total = s.strain + s.unload_strain + s.shear;
  // A row, with the soft contacts beyond the laws' range so far (soft model).
  const auto record = [&](int sign) {
    run.rows.push_back(curve_row(sim, m, body_of, H0, sign));
    if (model == CoarseModel::soft) {
      const RangeStats range = sim.force_field().range();
      run.rows.back().beyond_range = range.beyond_range, run.rows.back().max_dn = range.max_dn;
    }
    if (observe) observe(sim, run.rows.back());
  };
  record(1);
  // Each row: the wall moves by record_strain (the last one by what is left), then, with
  // `relax`, stands while the medium comes to rest under the quench; then the row is recorded.
  const auto phase = [&](double strain, int sign) {
    const double every = sign == 2 ? s.record_shear : s.record_strain;
    const long rows = std::max(1L, std::lround(strain / every));
    const Vec3 direction = sign == 2 ? Vec3(Vec3::UnitX()) : Vec3(0.0, 0.0, sign > 0 ? -1.0 : 1.0);
    for (long k = 0; k < rows; ++k) {
      const double d = std::min(every, strain - static_cast<double>(k) * every) * H0;
      if (!(d > 0.0)) break;
      sim.add_driver(MoveWallDef{"top", s.speed * direction, d, std::nullopt});
      sim.run_steps(std::max(1L, std::lround(d / (s.speed * sim.dt()))));
      while (sim.drivers_moving()) sim.run_steps(1);
      sim.release_drivers();
      if (s.relax > 0.0) {
        sim.set_quench(true);
        sim.run_for(s.relax);
        sim.set_quench(false);
      }
      record(sign);
      const double done = sign == 2 ? s.strain + s.unload_strain + run.rows.back().shear
                          : sign > 0 ? run.rows.back().strain
                                     : s.strain + (s.strain - run.rows.back().strain);
      if (progress) progress(done, total, run.rows.back());
    }
  };
  phase(s.strain, 1);
  phase(s.unload_strain, -1);
  phase(s.shear, 2);
  run.steps = sim.step_count();
  run.soft = sim.force_field().range();
  run.time = clock.elapsed();
  return run;
}

}  // namespace softpack
