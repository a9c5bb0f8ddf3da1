#include "integrate/velocity_verlet.hpp"

namespace softpack {

namespace {

// The free spheres an integration phase moves: neither driven nor asleep.
struct Free {
  const std::uint8_t* driven;
  const std::uint8_t* asleep;
  bool operator()(std::size_t i) const { return (!driven || !driven[i]) && (!asleep || !asleep[i]); }
};

}  // namespace

void half_kick(Particles& p, double dt, const std::uint8_t* asleep) {
  const std::size_t n = p.size();
  const double half = 0.5 * dt;
  const Free free{p.driven.empty() ? nullptr : p.driven.data(), asleep};
  Vec3* const v = p.v.data();
  const Vec3* const F = p.F.data();
  const double* const inv_m = p.inv_m.data();
  for (std::size_t i = 0; i < n; ++i)
    if (free(i)) v[i] += (half * inv_m[i]) * F[i];
  if (p.rotates()) {
    Vec3* const w = p.w.data();
    const Vec3* const T = p.T.data();
    const double* const inv_I = p.inv_I.data();
    for (std::size_t i = 0; i < n; ++i)
      if (free(i)) w[i] += (half * inv_I[i]) * T[i];
  }
}

void drift(Particles& p, double dt, Neighbours& neighbours, const std::uint8_t* asleep) {
  const std::size_t n = p.size();
  const Free free{p.driven.empty() ? nullptr : p.driven.data(), asleep};
  Vec3* const x = p.x.data();
  const Vec3* const v = p.v.data();
  const Vec3* const x0 = neighbours.x_at_build().data();
  Neighbours::LargestTwo moved;
  for (std::size_t i = 0; i < n; ++i) {
    if (!free(i)) {
      // A sleeping sphere stands still, but its displacement since the last build still counts
      // towards the skin (the drivers report the driven ones').
      if (asleep && asleep[i]) moved.add((x[i] - x0[i]).squaredNorm());
      continue;
    }
    x[i] += dt * v[i];
    moved.add((x[i] - x0[i]).squaredNorm());
  }
  neighbours.set_moved(moved);
}

void quench(Particles& p) {
  const std::size_t n = p.size();
  const std::uint8_t* const driven = p.driven.empty() ? nullptr : p.driven.data();
  Vec3* const v = p.v.data();
  const Vec3* const F = p.F.data();
  for (std::size_t i = 0; i < n; ++i)
    if ((!driven || !driven[i]) && F[i].dot(v[i]) < 0.0) v[i].setZero();
  if (p.rotates()) {
    Vec3* const w = p.w.data();
    const Vec3* const T = p.T.data();
    for (std::size_t i = 0; i < n; ++i)
      if ((!driven || !driven[i]) && T[i].dot(w[i]) < 0.0) w[i].setZero();
  }
}

}  // namespace softpack
