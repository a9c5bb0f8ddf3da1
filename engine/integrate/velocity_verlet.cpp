#include "integrate/velocity_verlet.hpp"

#include "core/parallel.hpp"

namespace softpack {

namespace {

// Calls f(i) for the free spheres (not driven) among [begin, end).
template <class F>
[[gnu::always_inline]] inline void for_free_in(const Particles& p, std::size_t begin, std::size_t end, F&& f) {
  const std::uint8_t* const driven = p.driven.empty() ? nullptr : p.driven.data();
  for (std::size_t i = begin; i < end; ++i)
    if (!driven || !driven[i]) f(i);
}

// Calls f(i) for every free sphere, on the threads by shares (core/parallel.hpp), or for the
// listed ones only.
template <class F>
[[gnu::always_inline]] inline void for_free(const Particles& p, const Movers* movers, F&& f) {
  if (movers) {
    const std::uint8_t* const driven = p.driven.empty() ? nullptr : p.driven.data();
    for (const std::int32_t k : *movers->awake) {
      const auto i = static_cast<std::size_t>(k);
      if (!driven || !driven[i]) f(i);
    }
    return;
  }
  parallel::for_each_share(p.size(), [&](std::size_t begin, std::size_t end) { for_free_in(p, begin, end, f); });
}

// The half kick of sphere i: v += F/m dt/2, and w += T/I dt/2 with rotation.
struct Kick {
  double half;
  Vec3* v;
  const Vec3* F;
  const double* inv_m;
  Vec3* w;  ///< null without rotation
  const Vec3* T;
  const double* inv_I;
  Kick(Particles& p, double dt)
      : half(0.5 * dt), v(p.v.data()), F(p.F.data()), inv_m(p.inv_m.data()), w(p.rotates() ? p.w.data() : nullptr),
        T(p.rotates() ? p.T.data() : nullptr), inv_I(p.rotates() ? p.inv_I.data() : nullptr) {}
  [[gnu::always_inline]] void operator()(std::size_t i) const {
    v[i] += (half * inv_m[i]) * F[i];
    if (w) w[i] += (half * inv_I[i]) * T[i];
  }
};

}  // namespace

void half_kick(Particles& p, double dt, const Movers* movers, bool then_quench) {
  if (then_quench && movers) {  // the quench is of every free sphere, not only the movers
    half_kick(p, dt, movers, false);
    return quench(p);
  }
  // Sphere by sphere, as the separate passes would: the kick, then the quench of what it gave.
  const Kick kick(p, dt);
  if (!then_quench) return for_free(p, movers, kick);
  for_free(p, movers, [&](std::size_t i) {
    kick(i);
    if (kick.F[i].dot(kick.v[i]) < 0.0) kick.v[i].setZero();
    if (kick.w && kick.T[i].dot(kick.w[i]) < 0.0) kick.w[i].setZero();
  });
}

void kick_drift(Particles& p, double dt, Neighbours& neighbours, const Movers* movers) {
  // Sphere by sphere: v(t + dt/2), then x(t + dt) from it, then |x - x_at_build|^2 recorded: for
  // the listed movers on this thread, else by shares on the threads, each share's two largest,
  // then theirs (the same two values whatever the cut).
  const Kick kick(p, dt);
  Vec3* const x = p.x.data();
  const Vec3* const x0 = neighbours.x_at_build().data();
  const auto move = [&](std::size_t i, Neighbours::LargestTwo& m) {
    kick(i);
    x[i] += dt * kick.v[i];
    m.add((x[i] - x0[i]).squaredNorm());
  };
  Neighbours::LargestTwo moved = movers ? movers->asleep_moved : Neighbours::LargestTwo{};
  if (movers) {
    for_free(p, movers, [&](std::size_t i) { move(i, moved); });
    return neighbours.set_moved(moved);
  }
  const std::size_t n = p.size(), parts = static_cast<std::size_t>(parallel::threads_for(n));
  std::vector<Neighbours::LargestTwo> of_share(parts);
  parallel::for_each_block(parts, [&](std::size_t t) {
    Neighbours::LargestTwo m;  // a local: the shares' records share a cache line
    for_free_in(p, parallel::share_begin(n, t, parts), parallel::share_begin(n, t + 1, parts), [&](std::size_t i) { move(i, m); });
    of_share[t] = m;
  });
  for (const Neighbours::LargestTwo& m : of_share) moved.add(m.first), moved.add(m.second);
  neighbours.set_moved(moved);
}

void half_kick_shells(std::vector<SphericalShell>& shells, const std::vector<WallLoad>& loads, double dt, bool rotation) {
  for (std::size_t k = 0; k < shells.size(); ++k) {
    SphericalShell& s = shells[k];
    if (!s.free()) continue;
    s.velocity += (0.5 * dt / s.mass) * loads[k].force;
    if (rotation) s.spin += (0.5 * dt / (2.0 / 3.0 * s.mass * s.radius * s.radius)) * loads[k].torque;
  }
}

void drift_shells(std::vector<SphericalShell>& shells, double dt) {
  for (SphericalShell& s : shells)
    if (s.free()) s.centre += dt * s.velocity;
}

void quench(Particles& p) {
  const std::uint8_t* const driven = p.driven.empty() ? nullptr : p.driven.data();
  Vec3* const v = p.v.data();
  const Vec3* const F = p.F.data();
  Vec3* const w = p.rotates() ? p.w.data() : nullptr;
  const Vec3* const T = p.rotates() ? p.T.data() : nullptr;
  parallel::for_each_share(p.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if ((!driven || !driven[i]) && F[i].dot(v[i]) < 0.0) v[i].setZero();
    if (w)
      for (std::size_t i = begin; i < end; ++i)
        if ((!driven || !driven[i]) && T[i].dot(w[i]) < 0.0) w[i].setZero();
  });
}

}  // namespace softpack
