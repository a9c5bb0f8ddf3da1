#include "formats/state_fields.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "formats/h5_fields.hpp"

namespace softpack {
namespace {

using namespace formats;

// /state: f(dataset, member) for each field of the SimulationState but its springs.
constexpr const char *kX = "state/x", *kV = "state/v", *kF = "state/F";
template <class S, class F>
void each_state_field(S& s, F&& f) {
  f("state/time", s.time);
  f("state/steps", s.steps);
  f(kX, s.x);
  f(kV, s.v);
  f("state/w", s.w);
  f(kF, s.F);
  f("state/T", s.T);
  f("state/plane_points", s.plane_points);
  f("state/shell_centres", s.shell_centres);
}
// Free shells' motion and last load (a nested soft-particle's content resolved, docs/nested.md):
// written when the scene has free shells, absent otherwise.
template <class S, class F>
void each_free_shell_field(S& s, F&& f) {
  f("state/shell_velocities", s.shell_velocities);
  f("state/shell_spins", s.shell_spins);
  f("state/shell_forces", s.shell_forces);
  f("state/shell_torques", s.shell_torques);
}
constexpr const char *kPairI = "state/pair_springs/i", *kPairJ = "state/pair_springs/j", *kPairXi = "state/pair_springs/xi";
constexpr const char *kPlaneSprings = "state/plane_springs", *kShellSprings = "state/shell_springs";
std::string wall_spring(const char* group, std::size_t wall, const char* field) { return fmt::format("{}/{}/{}", group, wall, field); }

// Sphere ids of springs: 0 <= id < the number of spheres of the state.
std::vector<int> read_ids(const h5::File& f, const std::string& name, std::size_t spheres) {
  const auto v = f.read_int64s(name);
  std::vector<int> out;
  out.reserve(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] < 0 || static_cast<std::uint64_t>(v[k]) >= spheres)
      throw InputError(fmt::format("{}: /{}: value {} = {} is not a sphere of the state (0 to {})", f.path(), name, k, v[k],
                                   spheres == 0 ? std::string("none") : std::to_string(spheres - 1)));
    out.push_back(static_cast<int>(v[k]));
  }
  return out;
}

void write_wall_springs(h5::File& f, const char* group, const std::vector<std::vector<SimulationState::WallSpring>>& walls) {
  for (std::size_t w = 0; w < walls.size(); ++w) {
    std::vector<std::int64_t> ids;
    std::vector<Vec3> xi;
    for (const auto& s : walls[w]) ids.push_back(s.i), xi.push_back(s.xi);
    put(f, wall_spring(group, w, "i"), ids);
    put(f, wall_spring(group, w, "xi"), xi);
  }
}

std::vector<std::vector<SimulationState::WallSpring>> read_wall_springs(const h5::File& f, const char* group, std::size_t spheres) {
  std::vector<std::vector<SimulationState::WallSpring>> out;
  for (std::size_t w = 0; f.exists(wall_spring(group, w, "i")); ++w) {
    const auto ids = read_ids(f, wall_spring(group, w, "i"), spheres);
    std::vector<Vec3> xi;
    get(f, wall_spring(group, w, "xi"), xi);
    same_length(f, wall_spring(group, w, "xi"), xi.size(), wall_spring(group, w, "i"), ids.size());
    out.emplace_back();
    for (std::size_t k = 0; k < ids.size(); ++k) out.back().push_back({ids[k], xi[k]});
  }
  return out;
}

}  // namespace

void write_state(h5::File& f, const SimulationState& s) {
  each_state_field(s, writer(f));
  if (!s.shell_velocities.empty()) each_free_shell_field(s, writer(f));
  std::vector<std::int64_t> pi, pj;
  std::vector<Vec3> pxi;
  for (const auto& sp : s.pair_springs) pi.push_back(sp.i), pj.push_back(sp.j), pxi.push_back(sp.xi);
  put(f, kPairI, pi);
  put(f, kPairJ, pj);
  put(f, kPairXi, pxi);
  write_wall_springs(f, kPlaneSprings, s.plane_springs);
  write_wall_springs(f, kShellSprings, s.shell_springs);
}

SimulationState read_state(const h5::File& f) {
  SimulationState s;
  each_state_field(s, reader(f));
  if (f.exists("state/shell_velocities")) each_free_shell_field(s, reader(f));
  const std::size_t n = s.x.size();
  same_length(f, kV, s.v.size(), kX, n);
  same_length(f, kF, s.F.size(), kX, n);
  const auto pi = read_ids(f, kPairI, n), pj = read_ids(f, kPairJ, n);
  std::vector<Vec3> pxi;
  get(f, kPairXi, pxi);
  same_length(f, kPairJ, pj.size(), kPairI, pi.size());
  same_length(f, kPairXi, pxi.size(), kPairI, pi.size());
  for (std::size_t k = 0; k < pi.size(); ++k) s.pair_springs.push_back({pi[k], pj[k], pxi[k]});
  s.plane_springs = read_wall_springs(f, kPlaneSprings, n);
  s.shell_springs = read_wall_springs(f, kShellSprings, n);
  return s;
}

}  // namespace softpack
