// The vectorised pair loop (sim/pair_forces.cpp) computes what the per-contact reference
// routine (contact/contact_force.hpp: advance_spring, then contact_force) computes, for every
// combination of effects, on random touching and non-touching pairs with loaded springs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "contact/contact_force.hpp"
#include "core/cpu_features.hpp"
#include "sim/pair_forces.hpp"
#include "sim/touching_pairs.hpp"
#include "support/effect_combinations.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kTolerance = 1e-12;  // relative to the largest force; only rounding differs

struct World {
  std::vector<Vec3> x, v, w, F, T;
  std::vector<double> r;
  PairList list;
};

World random_world(bool friction) {
  testing::Random rng(17);
  World wd;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    wd.x.push_back(rng.in_box(0.01));
    wd.v.push_back(rng.in_box(0.05));
    wd.w.push_back(rng.in_box(30.0));
    wd.r.push_back(rng.uniform(5e-4, 2e-3));
  }
  wd.F.assign(n, Vec3::Zero());
  wd.T.assign(n, Vec3::Zero());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double gap = (wd.x[i] - wd.x[j]).norm() - wd.r[i] - wd.r[j];
      if (gap > 5e-4) continue;  // listed: touching, and some within a skin
      wd.list.pairs.push_back({i, j, wd.r[i] + wd.r[j]});
      ContactCoefficients k;
      k.kn = rng.uniform(1.0, 2.0);
      k.kt0 = rng.uniform(1.0, 2.0);
      k.gamma0 = rng.uniform(1e-4, 1e-3);
      k.gamma_t0 = rng.uniform(1e-4, 1e-3);
      k.mu = rng.uniform(0.1, 0.5);
      wd.list.k.push_back(k);
      // Springs: most small (sticking), some large (sliding), tilted out of the plane.
      if (friction) wd.list.spring.push_back(rng.in_box(rng.uniform() < 0.8 ? 1e-6 : 1e-3));
    }
  return wd;
}

// The per-contact reference: the loop the engine ran before it was vectorised.
void reference(World& wd, const PairForceEffects& fx, double dt) {
  for (std::size_t k = 0; k < wd.list.pairs.size(); ++k) {
    const PairEntry& e = wd.list.pairs[k];
    const int i = e.i, j = e.j;
    const Vec3 d = wd.x[i] - wd.x[j];
    if (d.squaredNorm() >= e.r_sum * e.r_sum) {
      if (fx.friction) wd.list.spring[k].setZero();
      continue;
    }
    const double dist = d.norm();
    const Vec3 n = d / dist;
    const double h = e.r_sum - dist;
    const Vec3 vij = wd.v[i] - wd.v[j];
    Vec3 vc = vij;
    double ai = 0.0, aj = 0.0;
    if (fx.rotation) {
      ai = wd.r[i] - 0.5 * h;
      aj = wd.r[j] - 0.5 * h;
      vc -= (ai * wd.w[i] + aj * wd.w[j]).cross(n);
    }
    Vec3 none = Vec3::Zero();
    Vec3& spring = fx.friction ? wd.list.spring[k] : none;
    if (fx.friction) {
      if (fx.synchronized) {
        const Vec3 d_half = d - 0.5 * dt * vij;
        const Vec3 n_half = d_half / d_half.norm();
        Vec3 vc_half = vij;
        if (fx.rotation) {
          const double h_half = e.r_sum - d_half.norm();
          vc_half -= ((wd.r[i] - 0.5 * h_half) * wd.w[i] + (wd.r[j] - 0.5 * h_half) * wd.w[j]).cross(n_half);
        }
        advance_spring(spring, n_half, vc_half, n, dt);
      } else {
        advance_spring(spring, n, vc, n, dt);
      }
    }
    const ContactCoefficients& c = wd.list.k[k];
    const ContactForce cf = fx.friction ? (fx.damping ? contact_force<true, true>(n, h, vc, c, spring)
                                                      : contact_force<true, false>(n, h, vc, c, spring))
                                        : (fx.damping ? contact_force<false, true>(n, h, vc, c, spring)
                                                      : contact_force<false, false>(n, h, vc, c, spring));
    wd.F[i] += cf.F;
    wd.F[j] -= cf.F;
    if (fx.rotation) {
      wd.T[i] -= ai * n.cross(cf.Ft);
      wd.T[j] -= aj * n.cross(cf.Ft);
    }
  }
}

class PairForces : public ::testing::TestWithParam<int> {};  // bits: friction, damping, rotation, sync

TEST_P(PairForces, VectorisedLoopMatchesThePerContactRoutine) {
  const int bits = GetParam();
  const PairForceEffects fx = testing::effects_of(bits);
  World ref = random_world(fx.friction), vec = ref;
  const double dt = 1e-5;
  reference(ref, fx, dt);
  std::vector<int> scratch;
  accumulate_pair_forces(vec.list, PairForceArrays{vec.x.data(), vec.v.data(), fx.rotation ? vec.w.data() : nullptr,
                                                   vec.r.data(), vec.F.data(), fx.rotation ? vec.T.data() : nullptr},
                         fx, dt, scratch);
  double F_scale = 0.0, T_scale = 0.0, s_scale = 0.0;
  for (std::size_t i = 0; i < ref.F.size(); ++i) {
    F_scale = std::max(F_scale, ref.F[i].norm());
    T_scale = std::max(T_scale, ref.T[i].norm());
  }
  for (const auto& s : ref.list.spring) s_scale = std::max(s_scale, s.norm());
  ASSERT_GT(F_scale, 0.0);
  std::size_t touching = 0;
  for (const PairEntry& e : ref.list.pairs) touching += (ref.x[e.i] - ref.x[e.j]).norm() < e.r_sum;
  EXPECT_GT(touching, 100u);
  EXPECT_LT(touching, ref.list.pairs.size());  // some listed pairs are open
  for (std::size_t i = 0; i < ref.F.size(); ++i) {
    EXPECT_LT((vec.F[i] - ref.F[i]).norm(), kTolerance * F_scale) << "sphere " << i;
    if (fx.rotation) {
      EXPECT_LT((vec.T[i] - ref.T[i]).norm(), kTolerance * T_scale) << "sphere " << i;
    }
  }
  if (fx.friction) {
    for (std::size_t k = 0; k < ref.list.spring.size(); ++k) {
      EXPECT_LT((vec.list.spring[k] - ref.list.spring[k]).norm(), kTolerance * s_scale) << "pair " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Effects, PairForces, testing::effect_combinations(), testing::effects_name);


// The AVX-512 paths (touching-pair selection, batch gathers) and the portable ones must give
// the same bits, step after step: pairs open and close, springs slide, tilt and are cleared.
class PairPaths : public ::testing::TestWithParam<int> {};  // bits as above

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST_P(PairPaths, Avx512AndPortablePathsGiveTheSameBits) {
  if (!cpu::avx512_in_use()) GTEST_SKIP() << "this processor has no AVX-512: only the portable path runs here";
  const int bits = GetParam();
  const PairForceEffects fx = testing::effects_of(bits);
  World fast = random_world(fx.friction), portable = fast;
  testing::Random rng(5);
  std::vector<int> scratch_fast, scratch_portable;
  std::size_t opened = 0, closed_again = 0;
  for (int step = 0; step < 20; ++step) {
    for (World* wd : {&fast, &portable}) {
      cpu::allow_avx512(wd == &fast);
      accumulate_pair_forces(wd->list, PairForceArrays{wd->x.data(), wd->v.data(), fx.rotation ? wd->w.data() : nullptr,
                                                       wd->r.data(), wd->F.data(), fx.rotation ? wd->T.data() : nullptr},
                             fx, 1e-5, wd == &fast ? scratch_fast : scratch_portable);
    }
    cpu::allow_avx512(true);
    ASSERT_TRUE(same_bits(fast.F, portable.F)) << "step " << step;
    ASSERT_TRUE(same_bits(fast.T, portable.T)) << "step " << step;
    ASSERT_TRUE(same_bits(fast.list.spring, portable.list.spring)) << "step " << step;
    // Jiggle every sphere by up to 2% of the smallest radius, the same way in both worlds.
    std::vector<bool> touching_before;
    for (const PairEntry& e : fast.list.pairs) touching_before.push_back((fast.x[e.i] - fast.x[e.j]).norm() < e.r_sum);
    for (std::size_t i = 0; i < fast.x.size(); ++i) {
      const Vec3 dx = rng.in_box(1e-5);
      fast.x[i] += dx;
      portable.x[i] += dx;
    }
    for (std::size_t k = 0; k < fast.list.pairs.size(); ++k) {
      const PairEntry& e = fast.list.pairs[k];
      const bool now = (fast.x[e.i] - fast.x[e.j]).norm() < e.r_sum;
      opened += touching_before[k] && !now;
      closed_again += !touching_before[k] && now;
    }
  }
  EXPECT_GT(opened, 10u);  // the test saw contacts open and close
  EXPECT_GT(closed_again, 10u);
}

INSTANTIATE_TEST_SUITE_P(Effects, PairPaths, testing::effect_combinations(), testing::effects_name);

// The selection: exactly the pairs closer than Ri + Rj, in list order; the springs of the pairs
// that do not touch are cleared, loaded or not, whatever the flags said before a replace().
TEST(TouchingPairs, SelectsTheTouchingPairsAndClearsTheSpringsOfOpenOnes) {
  World wd = random_world(true);
  for (const bool avx512 : {false, true}) {
    if (avx512 && !cpu::avx512_in_use()) continue;
    World w = wd;
    w.list.spring_live.assign(w.list.pairs.size(), 0);  // stale flags, as a hand-made list might carry...
    w.list.replace(std::vector<PairEntry>(w.list.pairs), true);  // ...until replace() forgets them
    for (auto& s : w.list.spring) s = Vec3(1e-6, -2e-6, 3e-6);
    std::vector<int> closed(w.list.pairs.size());
    const std::size_t n = avx512 ? detail::select_touching_pairs_avx512(w.list, w.x.data(), true, closed.data())
                                 : detail::select_touching_pairs_portable(w.list, w.x.data(), true, closed.data());
    std::vector<int> expected;
    for (std::size_t k = 0; k < w.list.pairs.size(); ++k) {
      const PairEntry& e = w.list.pairs[k];
      const bool touching = (w.x[e.i] - w.x[e.j]).squaredNorm() < e.r_sum * e.r_sum;
      if (touching) expected.push_back(static_cast<int>(k));
      EXPECT_EQ(w.list.spring[k] == Vec3::Zero(), !touching) << "pair " << k;
      EXPECT_EQ(w.list.spring_live[k], touching ? 1 : 0) << "pair " << k;
    }
    ASSERT_EQ(n, expected.size()) << (avx512 ? "AVX-512" : "portable");
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), closed.begin())) << (avx512 ? "AVX-512" : "portable");
    EXPECT_GT(n, 100u);
    EXPECT_LT(n, w.list.pairs.size());
  }
}

}  // namespace
}  // namespace softpack
