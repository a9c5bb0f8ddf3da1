// Simulation::state() and restore(): the saved form of a run (state/simulation_state.hpp), from
// the world and the springs of the contact lists, and back.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/error.hpp"
#include "sim/simulation.hpp"

namespace softpack {
namespace {

// The non-zero springs of wall k's lists of every family, by sphere (a sphere is in one family).
std::vector<std::vector<SimulationState::WallSpring>> wall_springs(const ContactLists& lists, bool shells, std::size_t walls) {
  std::vector<std::vector<SimulationState::WallSpring>> out(walls);
  for (std::size_t w = 0; w < walls; ++w) {
    for (const ContactFamily& f : lists.family) {
      const WallList& l = (shells ? f.shells : f.planes)[w];
      for (std::size_t k = 0; k < l.spring.size(); ++k)
        if (l.spring[k] != Vec3::Zero()) out[w].push_back({l.i[k], l.spring[k]});
    }
    std::sort(out[w].begin(), out[w].end(), [](const auto& a, const auto& b) { return a.i < b.i; });
  }
  return out;
}

// Installs saved wall springs; a saved spring whose sphere is not listed cannot be: it touched.
void install(std::vector<WallList>& lists, const std::vector<std::vector<SimulationState::WallSpring>>& saved) {
  for (std::size_t w = 0; w < lists.size() && w < saved.size(); ++w) {
    std::size_t a = 0;
    for (const auto& sp : saved[w]) {
      while (a < lists[w].size() && lists[w].i[a] < sp.i) ++a;
      if (a == lists[w].size() || lists[w].i[a] != sp.i)
        throw InputError(fmt::format("the saved state has a wall spring for sphere {}, which is off the wall", sp.i));
      lists[w].spring[a] = sp.xi;
    }
  }
}

// Installs saved pair springs; a saved spring whose pair is not listed cannot be: it was touching.
void install(PairList& pl, const std::vector<SimulationState::PairSpring>& saved) {
  std::size_t a = 0;
  for (const auto& sp : saved) {
    while (a < pl.size() && std::pair(pl.i[a], pl.j[a]) < std::pair(sp.i, sp.j)) ++a;
    if (a == pl.size() || pl.i[a] != sp.i || pl.j[a] != sp.j)
      throw InputError(fmt::format("the saved state has a spring for spheres {} and {}, which are apart", sp.i, sp.j));
    pl.spring[a] = sp.xi;
  }
}

}  // namespace

SimulationState Simulation::state() const {
  if (drivers_moving()) throw std::logic_error("Simulation::state: a driver is still moving");
  const Particles& p = world_.p;
  const ContactLists& lists = neighbours_.lists();
  SimulationState s;
  s.time = world_.time;
  s.steps = world_.steps;
  s.x = p.x, s.v = p.v, s.w = p.w, s.F = p.F, s.T = p.T;
  for (const auto& pl : world_.planes) s.plane_points.push_back(pl.point);
  for (const auto& sh : world_.shells) s.shell_centres.push_back(sh.centre);
  if (free_shells_)
    for (std::size_t k = 0; k < world_.shells.size(); ++k) {
      s.shell_velocities.push_back(world_.shells[k].velocity), s.shell_spins.push_back(world_.shells[k].spin);
      s.shell_forces.push_back(world_.shell_loads[k].force), s.shell_torques.push_back(world_.shell_loads[k].torque);
    }
  // The springs of every family (a pair or a sphere on a wall is in one), by spheres.
  for (const ContactFamily& f : lists.family)
    for (std::size_t k = 0; k < f.pairs.spring.size(); ++k)
      if (f.pairs.spring[k] != Vec3::Zero()) s.pair_springs.push_back({f.pairs.i[k], f.pairs.j[k], f.pairs.spring[k]});
  std::sort(s.pair_springs.begin(), s.pair_springs.end(), [](const auto& a, const auto& b) { return std::pair(a.i, a.j) < std::pair(b.i, b.j); });
  if (!lists.family.empty()) {
    s.plane_springs = wall_springs(lists, false, world_.planes.size());
    s.shell_springs = wall_springs(lists, true, world_.shells.size());
  }
  return s;
}

void Simulation::restore(const SimulationState& s) {
  Particles& p = world_.p;
  const std::size_t n = p.size();
  if (s.x.size() != n || s.v.size() != n || s.F.size() != n || s.w.size() != p.w.size() || s.T.size() != p.T.size() ||
      s.plane_points.size() != world_.planes.size() || s.shell_centres.size() != world_.shells.size() ||
      s.shell_velocities.size() != (free_shells_ ? world_.shells.size() : 0) || s.shell_spins.size() != s.shell_velocities.size() ||
      s.shell_forces.size() != s.shell_velocities.size() || s.shell_torques.size() != s.shell_velocities.size())
    throw InputError(fmt::format("the saved state does not fit this scene ({} spheres saved, {} in the scene)", s.x.size(), n));
  if (active_) active_->wake_all(neighbours_.lists());
  world_.time = s.time;
  world_.steps = s.steps;
  p.x = s.x, p.v = s.v, p.w = s.w, p.F = s.F, p.T = s.T;
  for (std::size_t k = 0; k < world_.planes.size(); ++k) world_.planes[k].point = s.plane_points[k];
  for (std::size_t k = 0; k < world_.shells.size(); ++k) world_.shells[k].centre = s.shell_centres[k];
  for (std::size_t k = 0; k < s.shell_velocities.size(); ++k) {
    world_.shells[k].velocity = s.shell_velocities[k], world_.shells[k].spin = s.shell_spins[k];
    world_.shell_loads[k] = WallLoad{s.shell_forces[k], s.shell_torques[k]};
  }
  rebuild_neighbours();
  // Install the springs; a saved spring whose pair is not listed cannot be: it was touching.
  if (scene_.effects.friction && !neighbours_.lists().family.empty()) {
    ContactLists& lists = neighbours_.lists();
    // Each saved spring to the family of its spheres (neighbor/contact_list.hpp ContactLists).
    const auto family = [&](int i) {
      if (i < 0 || static_cast<std::size_t>(i) >= n)
        throw InputError(fmt::format("the saved state has a spring for sphere {}, which this scene of {} spheres does not have", i, n));
      return p.family_of(static_cast<std::size_t>(i));
    };
    for (std::size_t f = 0; f < lists.family.size(); ++f) {
      ContactFamily& l = lists.family[f];
      std::fill(l.pairs.spring.begin(), l.pairs.spring.end(), Vec3::Zero());
      for (auto* walls : {&l.planes, &l.shells})
        for (WallList& wl : *walls) std::fill(wl.spring.begin(), wl.spring.end(), Vec3::Zero());
      std::vector<SimulationState::PairSpring> pairs;
      for (const auto& sp : s.pair_springs)
        if (std::max(family(sp.i), family(sp.j)) == f) pairs.push_back(sp);
      const auto walls = [&](const std::vector<std::vector<SimulationState::WallSpring>>& saved) {
        std::vector<std::vector<SimulationState::WallSpring>> mine(saved.size());
        for (std::size_t w = 0; w < saved.size(); ++w)
          for (const auto& sp : saved[w])
            if (family(sp.i) == f) mine[w].push_back(sp);
        return mine;
      };
      install(l.pairs, pairs);
      install(l.planes, walls(s.plane_springs));
      install(l.shells, walls(s.shell_springs));
    }
  }
  watchdog_.start(world_, residuals());
  since_check_ = 0;
}

}  // namespace softpack
