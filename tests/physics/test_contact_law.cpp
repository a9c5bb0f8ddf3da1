// The contact model (contact/contact_model.hpp, the paper's: contact/tsuji_model.hpp) is written once and runs on one double and on the
// eight lanes of a simd::Wide: every lane must get the bits the scalar evaluation gives, for every
// combination of effects and for each case of the spring (zero, along the normal, tilted beyond
// the series of rotate_into_tangent_plane, sticking, sliding). And what the law must satisfy
// whatever the number type: Eq. 3, the Coulomb cone, the spring's length kept by its rotation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "contact/contact_model.hpp"
#include "contact/hertz_normal.hpp"
#include "contact/tsuji_model.hpp"
#include "support/effect_combinations.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

using simd::Wide;

Vec3 unit(testing::Random& rng) { return rng.in_box(1.0).normalized(); }

using Hertz = TsujiModel<HertzNormal>;

struct LaneConstants {
  double kn, kt0, gamma0, gamma_t0, mu;
};

template <class T>
typename Hertz::Constants<T> hertz_constants(T kn, T kt0, T gamma0, T gamma_t0, T mu) {
  typename Hertz::Constants<T> c{};
  c.normal.kn = kn, c.tangential.kt0 = kt0, c.tangential.mu = mu, c.damping.gamma0 = gamma0, c.damping.gamma_t0 = gamma_t0;
  return c;
}
Hertz::Constants<double> hertz_constants(const LaneConstants& k) { return hertz_constants(k.kn, k.kt0, k.gamma0, k.gamma_t0, k.mu); }

template <Effects Fx, class T>
ContactForce<T> contact_force(const ContactGeometry<T>& g, const typename Hertz::Constants<T>& k, V3<T>& xi, double dt) {
  return Hertz::force<Fx>(Hertz::Params{}, g, k, xi, dt);
}

struct Lane {
  ContactGeometry<double> g;
  LaneConstants k;
  V3<double> xi;
};

// Lane m of a group: spring kinds cycle through the cases the law distinguishes.
Lane random_lane(testing::Random& rng, int m) {
  Lane l;
  const Vec3 n = unit(rng), n_frame = (n + 1e-3 * unit(rng)).normalized();
  l.g = {v3(n), rng.uniform(1e-7, 1e-4), v3(rng.in_box(0.05)), v3(n_frame), v3(rng.in_box(0.05)), 0.0, 0.0};
  l.k = {rng.uniform(1e5, 2e5), rng.uniform(1e5, 2e5), rng.uniform(1e-3, 1e-2), rng.uniform(1e-3, 1e-2), rng.uniform(0.1, 0.5)};
  Vec3 t = rng.in_box(1.0);
  t -= t.dot(n) * n;
  switch (m % 6) {
    case 0: l.xi = {0.0, 0.0, 0.0}; break;                                     // zero
    case 1: l.xi = v3(1e-6 * n); break;                                        // along n: cleared
    case 2: l.xi = v3(1e-7 * (t + 0.05 * n)); break;                           // tilted beyond the series
    case 3: l.xi = v3(1e-9 * (t + 1e-5 * n)); break;                           // sticking, slightly tilted
    case 4: l.xi = v3(1e-3 * t); break;                                        // sliding
    default: l.xi = v3(rng.in_box(1e-8)); break;
  }
  return l;
}

template <class Get>
Wide pack(const Lane* lanes, Get get) {
  Wide w;
  for (int m = 0; m < simd::kLanes; ++m) w.v[m] = get(lanes[m]);
  return w;
}

template <class Get>
V3<Wide> pack_v3(const Lane* lanes, Get get) {
  return {pack(lanes, [&](const Lane& l) { return get(l).x; }), pack(lanes, [&](const Lane& l) { return get(l).y; }),
          pack(lanes, [&](const Lane& l) { return get(l).z; })};
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

class ContactLaw : public ::testing::TestWithParam<std::size_t> {};

template <Effects Fx>
void check_lanes(const Lane* lanes, double dt) {
  ContactGeometry<Wide> g;
  V3<Wide> xi;
  g.n = pack_v3(lanes, [](const Lane& l) { return l.g.n; });
  g.vc = pack_v3(lanes, [](const Lane& l) { return l.g.vc; });
  g.n_frame = pack_v3(lanes, [](const Lane& l) { return l.g.n_frame; });
  g.vc_frame = pack_v3(lanes, [](const Lane& l) { return l.g.vc_frame; });
  xi = pack_v3(lanes, [](const Lane& l) { return l.xi; });
  g.h = pack(lanes, [](const Lane& l) { return l.g.h; });
  const auto k = hertz_constants(pack(lanes, [](const Lane& l) { return l.k.kn; }), pack(lanes, [](const Lane& l) { return l.k.kt0; }),
                                 pack(lanes, [](const Lane& l) { return l.k.gamma0; }), pack(lanes, [](const Lane& l) { return l.k.gamma_t0; }),
                                 pack(lanes, [](const Lane& l) { return l.k.mu; }));
  const ContactForce<Wide> wide = contact_force<Fx>(g, k, xi, dt);
  for (int m = 0; m < simd::kLanes; ++m) {
    Lane l = lanes[m];
    const ContactForce<double> one = contact_force<Fx>(l.g, hertz_constants(l.k), l.xi, dt);
    const auto expect_same = [&](double a, double b, const char* what) {
      EXPECT_TRUE(same(a, b)) << what << " of lane " << m << " (spring case " << m % 6 << "): " << a << " vs " << b;
    };
    expect_same(wide.Fn.v[m], one.Fn, "Fn");
    expect_same(wide.F.x.v[m], one.F.x, "Fx");
    expect_same(wide.F.y.v[m], one.F.y, "Fy");
    expect_same(wide.F.z.v[m], one.F.z, "Fz");
    expect_same(wide.Ft.x.v[m], one.Ft.x, "Ftx");
    expect_same(wide.Ft.z.v[m], one.Ft.z, "Ftz");
    expect_same(xi.x.v[m], l.xi.x, "spring x");
    expect_same(xi.y.v[m], l.xi.y, "spring y");
    expect_same(xi.z.v[m], l.xi.z, "spring z");
  }
}

TEST_P(ContactLaw, EveryLaneGetsTheBitsOfTheScalarLaw) {
  testing::Random rng(41);
  for (int group = 0; group < 200; ++group) {
    Lane lanes[simd::kLanes];
    for (int m = 0; m < simd::kLanes; ++m) lanes[m] = random_lane(rng, m + group);
    with_effects(testing::effects_of(GetParam()), [&]<Effects Fx>() { check_lanes<Fx>(lanes, 1e-5); });
    ASSERT_FALSE(HasFailure()) << "group " << group;
  }
}

INSTANTIATE_TEST_SUITE_P(Effects, ContactLaw, testing::effect_combinations(), testing::effects_name);

// Eq. 3, the Coulomb cone, and the spring's rotation that keeps its length.
TEST(ContactLaw, ForceFollowsEquation3AndStaysInTheCoulombCone) {
  testing::Random rng(43);
  int slid = 0;
  for (int c = 0; c < 1000; ++c) {
    Lane l = random_lane(rng, c);
    const double length = std::sqrt(dot(l.xi, l.xi)), tilt = std::abs(dot(l.xi, l.g.n)) / std::max(length, 1e-300);
    constexpr Effects fx{true, false, false, false};
    ContactGeometry<double> still = l.g;
    still.vc = still.vc_frame = {0.0, 0.0, 0.0};
    still.n_frame = still.n;
    V3<double> xi = l.xi;
    const ContactForce<double> f = contact_force<fx>(still, hertz_constants(l.k), xi, 1e-5);
    EXPECT_NEAR(f.Fn, l.k.kn * std::pow(l.g.h, 1.5), 1e-14 * f.Fn);  // Eq. 3
    const double Ft = std::sqrt(dot(f.Ft, f.Ft));
    EXPECT_LE(Ft, l.k.mu * f.Fn * (1.0 + 1e-14));  // |Ft| <= mu Fn (Eq. 5)
    EXPECT_NEAR(dot(f.Ft, l.g.n), 0.0, 1e-12 * std::max(Ft, 1e-300));  // tangential
    const double after = std::sqrt(dot(xi, xi));
    if (Ft < l.k.mu * f.Fn * (1.0 - 1e-12) && tilt < 1.0 - 1e-12) {
      EXPECT_NEAR(after, length, 1e-14 * length) << "a sticking spring keeps its length, case " << c % 6;
    }
    slid += Ft >= l.k.mu * f.Fn * (1.0 - 1e-12);
  }
  EXPECT_GT(slid, 100);
}

}  // namespace
}  // namespace softpack
