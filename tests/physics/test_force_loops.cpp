// The force loops (forces/compile_loops.hpp: sphere pairs, planes and shells through
// forces/contact_loop.hpp, eight contacts at a time) against a per-contact reference written
// here from the equations with Eigen (paper Eq. 3 and 5, the damping of
// contact/viscous_damping.hpp, the history rules of contact/tsuji_tangential.hpp), for every
// combination of effects, on a world with touching and open pairs, a moving plane and a moving,
// turning shell, sticking, sliding and tilted springs; and the AVX-512 loops against the portable
// ones, bit for bit, over steps in which contacts open and close.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "contact/hertz_normal.hpp"
#include "core/cpu_features.hpp"
#include "contact/tsuji_model.hpp"
#include "forces/contact_loop.hpp"
#include "forces/contact_models.hpp"
#include "forces/pair_contacts.hpp"
#include "support/effect_combinations.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kLoopTolerance = 1e-12;  // relative to the largest value; only rounding differs

struct Case {
  World world;
  ContactFamily lists;
};

// The constants of the paper's model (contact/tsuji_model.hpp), as the reference reads them.
using Hertz = TsujiModel<HertzNormal>;
struct LoopConstants {
  double kn, kt0, gamma0, gamma_t0, mu;
};
void set_k(ConstantArrays& a, std::size_t k, const LoopConstants& c) {
  Hertz::Constants<double> h{};
  h.normal.kn = c.kn, h.tangential.kt0 = c.kt0, h.tangential.mu = c.mu, h.damping.gamma0 = c.gamma0, h.damping.gamma_t0 = c.gamma_t0;
  set_constants_at<Hertz>(a, k, h);
}
LoopConstants k_at(const ConstantArrays& a, std::size_t k) {
  const Hertz::Constants<double> h = constants_at<Hertz>(a, k);
  return {h.normal.kn, h.tangential.kt0, h.damping.gamma0, h.damping.gamma_t0, h.tangential.mu};
}

LoopConstants random_constants(testing::Random& rng, double scale) {
  return {scale * rng.uniform(1.0, 2.0), scale * rng.uniform(1.0, 2.0), 1e-3 * scale * rng.uniform(0.1, 1.0),
          1e-3 * scale * rng.uniform(0.1, 1.0), rng.uniform(0.1, 0.5)};
}

// The engine's model `hertz` for effects fx (no material is read: the constants are set by hand).
std::unique_ptr<SceneModel> hertz_model(const Effects& fx) { return contact_model("hertz").make(ContactSetting{}, fx); }

Case random_case(bool friction, bool rotation) {
  testing::Random rng(17);
  Case c;
  Particles& p = c.world.p;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    p.x.push_back(rng.in_box(0.01));
    p.v.push_back(rng.in_box(0.05));
    p.r.push_back(rng.uniform(5e-4, 2e-3));
    if (rotation) p.w.push_back(rng.in_box(30.0));
  }
  p.F.assign(n, Vec3::Zero());
  if (rotation) p.T.assign(n, Vec3::Zero());
  // Springs: most small (sticking), some large (sliding), all tilted out of the plane; a few zero.
  const auto spring = [&](int k) { return k % 17 == 0 ? Vec3::Zero() : rng.in_box(rng.uniform() < 0.8 ? 1e-6 : 1e-3); };
  std::vector<PairEntry> pairs;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((p.x[i] - p.x[j]).norm() - p.r[i] - p.r[j] < 5e-4) pairs.push_back({i, j, p.r[i] + p.r[j]});  // touching, or within a skin
  c.lists.pairs.k.resize(Hertz::constant_count(), 0);
  c.lists.pairs.replace(pairs, friction);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    set_k(c.lists.pairs.k, k, random_constants(rng, 1.0));
    if (friction) c.lists.pairs.spring[k] = spring(static_cast<int>(k));
  }
  c.world.planes.push_back(PlaneWall{Vec3(0, 0, -0.009), Vec3(0, 0, 1), Vec3(0.01, -0.02, 0.005), 0});
  c.world.shells.push_back(SphericalShell{Vec3(1e-3, -2e-3, 5e-4), 0.0105, 0, Vec3(0.01, -0.02, 0.005), Vec3(0.5, -1.0, 2.0), 0,
                                          ShellContactRadius::concave});
  for (auto* walls : {&c.lists.planes, &c.lists.shells}) {
    walls->emplace_back();
    walls->back().k.resize(Hertz::constant_count(), 0);
    std::vector<std::int32_t> all(n);
    for (int i = 0; i < n; ++i) all[i] = i;
    walls->back().replace(all, friction);
    for (int i = 0; i < n; ++i) {
      set_k(walls->back().k, static_cast<std::size_t>(i), random_constants(rng, 1e6));
      if (friction) walls->back().spring[i] = spring(i);
    }
  }
  c.world.plane_loads.resize(1);
  c.world.shell_loads.resize(1);
  return c;
}

// --- The reference: one contact at a time, from the equations --------------------------------

void rotate_into_plane(Vec3& xi, const Vec3& n) {
  if (xi.squaredNorm() == 0.0) return;
  const Vec3 t = xi - xi.dot(n) * n;
  xi = t.squaredNorm() > 0.0 ? Vec3(t * (xi.norm() / t.norm())) : Vec3::Zero();
}

struct Contact {
  Vec3 n, vc, n_frame, vc_frame;
  double h = 0.0;
};

// Returns the force on body 1 and its tangential part; advances and caps the spring.
std::pair<Vec3, Vec3> reference_force(const Effects& fx, const Contact& c, const LoopConstants& k, Vec3& xi,
                                      double dt) {
  if (fx.friction) {
    rotate_into_plane(xi, c.n_frame);
    xi += (c.vc_frame - c.vc_frame.dot(c.n_frame) * c.n_frame) * dt;
    rotate_into_plane(xi, c.n);
  }
  const double Fn = k.kn * std::pow(c.h, 1.5);                                   // Eq. 3
  const double damping = fx.damping ? std::pow(c.h, 0.25) : 0.0;                 // gamma = gamma0 h^(1/4)
  Vec3 F = (Fn - k.gamma0 * damping * c.vc.dot(c.n)) * c.n;
  Vec3 Ft = Vec3::Zero();
  if (fx.friction) {
    const double kt = k.kt0 * std::sqrt(c.h);                                    // Eq. 5
    const Vec3 vt = c.vc - c.vc.dot(c.n) * c.n;
    Ft = -kt * xi - k.gamma_t0 * damping * vt;
    if (Ft.norm() > k.mu * Fn) {                                                 // Coulomb
      Ft *= k.mu * Fn / Ft.norm();
      xi = -Ft / kt;
    }
  }
  return {F + Ft, Ft};
}

void reference_step(Case& c, const Effects& fx, double dt) {
  World& w = c.world;
  Particles& p = w.p;
  const auto spin = [&](int i) { return fx.rotation ? p.w[i] : Vec3::Zero(); };
  Vec3 unused = Vec3::Zero();
  const PairList& pl = c.lists.pairs;
  for (std::size_t k = 0; k < pl.size(); ++k) {
    const int i = pl.i[k], j = pl.j[k];
    Vec3& xi = fx.friction ? c.lists.pairs.spring[k] : unused;
    const Vec3 d = p.x[i] - p.x[j], vij = p.v[i] - p.v[j];
    if (d.norm() >= pl.r_sum[k]) {
      xi.setZero();
      continue;
    }
    Contact ct;
    ct.h = pl.r_sum[k] - d.norm();
    ct.n = d / d.norm();
    const double ai = p.r[i] - 0.5 * ct.h, aj = p.r[j] - 0.5 * ct.h;
    ct.vc = vij - (ai * spin(i) + aj * spin(j)).cross(ct.n);
    ct.n_frame = ct.n, ct.vc_frame = ct.vc;
    if (fx.synchronized) {
      const Vec3 dh = d - 0.5 * dt * vij;
      const double hh = pl.r_sum[k] - dh.norm();
      ct.n_frame = dh / dh.norm();
      ct.vc_frame = vij - ((p.r[i] - 0.5 * hh) * spin(i) + (p.r[j] - 0.5 * hh) * spin(j)).cross(ct.n_frame);
    }
    const auto [F, Ft] = reference_force(fx, ct, k_at(pl.k, k), xi, dt);
    p.F[i] += F, p.F[j] -= F;
    if (fx.rotation) p.T[i] -= ai * ct.n.cross(Ft), p.T[j] -= aj * ct.n.cross(Ft);
  }
  // `u` the wall's translation velocity, `ref` the point its torque is taken about.
  const auto wall = [&](WallList& l, auto&& geometry, const Vec3& u, const Vec3& ref, WallLoad& load) {
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int i = l.i[k];
      Vec3& xi = fx.friction ? l.spring[k] : unused;
      Contact ct;
      Vec3 surface_velocity;
      geometry(p.x[i], p.r[i], ct.n, ct.h, surface_velocity);
      if (ct.h <= 0.0) {
        xi.setZero();
        continue;
      }
      const double ai = p.r[i] - 0.5 * ct.h;
      ct.vc = p.v[i] - surface_velocity - (ai * spin(i)).cross(ct.n);
      ct.n_frame = ct.n, ct.vc_frame = ct.vc;
      if (fx.synchronized) {  // the sphere half a step back, relative to the wall
        Vec3 sv;
        double h_half = 0.0;
        geometry(p.x[i] - 0.5 * dt * (p.v[i] - u), p.r[i], ct.n_frame, h_half, sv);
        ct.vc_frame = p.v[i] - sv - ((p.r[i] - 0.5 * h_half) * spin(i)).cross(ct.n_frame);
      }
      const auto [F, Ft] = reference_force(fx, ct, k_at(l.k, k), xi, dt);
      p.F[i] += F;
      if (fx.rotation) p.T[i] -= ai * ct.n.cross(Ft);
      load.force -= F;
      load.torque += (p.x[i] - ai * ct.n - ref).cross(-F);
    }
  };
  const PlaneWall& plane = w.planes[0];
  wall(c.lists.planes[0], [&](const Vec3& x, double r, Vec3& n, double& h, Vec3& u) {
    n = plane.normal, h = r - (x - plane.point).dot(n), u = plane.velocity;
  }, plane.velocity, plane.point, w.plane_loads[0]);
  const SphericalShell& shell = w.shells[0];
  wall(c.lists.shells[0], [&](const Vec3& x, double r, Vec3& n, double& h, Vec3& u) {
    const Vec3 d = x - shell.centre;
    h = d.norm() + r - shell.radius, n = -d / d.norm();
    u = shell.surface_velocity(x - (r - 0.5 * h) * n);
  }, shell.velocity, shell.centre, w.shell_loads[0]);
}

double largest(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& x : v) m = std::max(m, x.norm());
  return m;
}

// |a - b| <= kLoopTolerance max(|a|, floor) element by element.
void expect_close(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const std::string& what, double floor = 1e-300) {
  ASSERT_EQ(a.size(), b.size()) << what;
  const double scale = std::max(largest(a), floor);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LE((a[k] - b[k]).norm(), kLoopTolerance * scale) << what << " " << k;
}

class ForceLoops : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ForceLoops, LoopsComputeTheEquationsContactByContact) {
  const Effects fx = testing::effects_of(GetParam());
  Case ref = random_case(fx.friction, fx.rotation), loop = ref;
  const auto loops = hertz_model(fx);
  std::vector<std::int32_t> scratch;
  const double dt = 1e-6;
  for (int step = 0; step < 3; ++step) {  // springs advanced by the loop are advanced again
    reference_step(ref, fx, dt);
    loops->run(loop.world, loop.lists, dt, scratch);
    expect_close(loop.world.p.F, ref.world.p.F, "F of sphere");
    if (fx.rotation) expect_close(loop.world.p.T, ref.world.p.T, "T of sphere");
    if (fx.friction) {
      expect_close(loop.lists.pairs.spring, ref.lists.pairs.spring, "spring of pair");
      expect_close(loop.lists.planes[0].spring, ref.lists.planes[0].spring, "spring of plane entry");
      expect_close(loop.lists.shells[0].spring, ref.lists.shells[0].spring, "spring of shell entry");
    }
    for (auto loads : {&World::plane_loads, &World::shell_loads}) {
      expect_close({(loop.world.*loads)[0].force}, {(ref.world.*loads)[0].force}, "wall load");
      // Without friction the shell's torque about its centre is rounding noise: judged against
      // force times radius.
      const double lever = (loop.world.*loads)[0].force.norm() * 0.01;
      expect_close({(loop.world.*loads)[0].torque}, {(ref.world.*loads)[0].torque}, "wall torque", lever);
    }
    ASSERT_FALSE(HasFailure()) << "step " << step;
  }
  // The case has touching and open contacts of each kind.
  std::size_t touching = 0;
  for (std::size_t k = 0; k < ref.lists.pairs.size(); ++k)
    touching += (ref.world.p.x[ref.lists.pairs.i[k]] - ref.world.p.x[ref.lists.pairs.j[k]]).norm() < ref.lists.pairs.r_sum[k];
  EXPECT_GT(touching, 100u);
  EXPECT_LT(touching, ref.lists.pairs.size());
  EXPECT_GT(ref.world.plane_loads[0].force.norm(), 0.0);
  EXPECT_GT(ref.world.shell_loads[0].force.norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Effects, ForceLoops, testing::effect_combinations(), testing::effects_name);

// --- The instruction sets give the same bits ---------------------------------------------------

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

class IsaPaths : public ::testing::TestWithParam<std::size_t> {};

TEST_P(IsaPaths, EveryInstructionSetGivesTheSameBits) {
  const Effects fx = testing::effects_of(GetParam());
  if (cpu::best_vector_isa() == cpu::VectorIsa::portable) GTEST_SKIP() << "this processor (or this build, without SOFTPACK_AVX512) runs the portable loops only";
  const std::vector<cpu::VectorIsa> isas{cpu::VectorIsa::portable, cpu::VectorIsa::avx512};
  std::vector<Case> cases(isas.size(), random_case(fx.friction, fx.rotation));
  const auto loops = hertz_model(fx);
  std::vector<std::int32_t> scratch;
  testing::Random rng(5);
  std::size_t opened = 0, closed_again = 0;
  for (int step = 0; step < 20; ++step) {
    for (std::size_t k = 0; k < isas.size(); ++k) {
      cpu::limit_vector_isa(isas[k]);
      loops->run(cases[k].world, cases[k].lists, 1e-5, scratch);
    }
    cpu::limit_vector_isa(cpu::VectorIsa::avx512);
    for (std::size_t k = 1; k < isas.size(); ++k) {
      const std::string which = std::string(cpu::name(isas[k])) + " against portable, step " + std::to_string(step);
      ASSERT_TRUE(same_bits(cases[k].world.p.F, cases[0].world.p.F)) << which;
      ASSERT_TRUE(same_bits(cases[k].world.p.T, cases[0].world.p.T)) << which;
      ASSERT_TRUE(same_bits(cases[k].lists.pairs.spring, cases[0].lists.pairs.spring)) << which;
      ASSERT_TRUE(same_bits(cases[k].lists.shells[0].spring, cases[0].lists.shells[0].spring)) << which;
      ASSERT_EQ(std::memcmp(&cases[k].world.shell_loads[0], &cases[0].world.shell_loads[0], sizeof(WallLoad)), 0) << which;
    }
    // Jiggle every sphere by up to 2% of the smallest radius, the same way in every case.
    const PairList& pl = cases[0].lists.pairs;
    const auto touching = [&](std::size_t k) {
      return (cases[0].world.p.x[pl.i[k]] - cases[0].world.p.x[pl.j[k]]).norm() < pl.r_sum[k];
    };
    std::vector<bool> before;
    for (std::size_t k = 0; k < pl.size(); ++k) before.push_back(touching(k));
    for (std::size_t i = 0; i < cases[0].world.p.size(); ++i) {
      const Vec3 dx = rng.in_box(1e-5);
      for (Case& c : cases) c.world.p.x[i] += dx;
    }
    for (std::size_t k = 0; k < pl.size(); ++k) opened += before[k] && !touching(k), closed_again += !before[k] && touching(k);
  }
  EXPECT_GT(opened, 10u);  // the test saw contacts open and close
  EXPECT_GT(closed_again, 10u);
}

INSTANTIATE_TEST_SUITE_P(Effects, IsaPaths, testing::effect_combinations(), testing::effects_name);

// The selection pass: exactly the pairs closer than Ri + Rj, in list order; the springs of the
// pairs that do not touch are cleared, loaded or not, whatever the flags said before a replace().
// With `prefetch` (what a scene beyond the caches gets) select() also reads ahead in the list and
// prefetches for the model's gather: the same selection (and under the sanitizer, no read beyond
// an array).
template <class Isa>
void check_selection(Isa isa, const char* name, bool prefetch) {
  Case c = random_case(true, true);
  PairList& list = c.lists.pairs;
  list.spring_live.assign(list.size(), 0);  // stale flags, as a hand-made list might carry...
  std::vector<PairEntry> same;
  for (std::size_t k = 0; k < list.size(); ++k) same.push_back({list.i[k], list.j[k], list.r_sum[k]});
  list.replace(same, true);  // ...until replace() forgets them
  for (auto& s : list.spring) s = Vec3(1e-6, -2e-6, 3e-6);
  const Particles& p = c.world.p;
  std::vector<Vec3> F(p.size());
  PairContacts<Effects{true, false, false, false}> pairs{list, SphereArrays{p.x.data(), p.v.data(), nullptr, p.r.data(), F.data(), nullptr}};
  std::vector<std::int32_t> closed(list.size() + simd::kLanes);
  pairs.prepare();
  pairs.prefetch = prefetch;
  const std::size_t n = prefetch ? pairs.template select<Hertz>(isa, closed.data(), 0, list.size())
                                 : pairs.template select<SelectOnly>(isa, closed.data(), 0, list.size());
  std::vector<std::int32_t> expected;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const bool touching = (p.x[list.i[k]] - p.x[list.j[k]]).squaredNorm() < list.r_sum[k] * list.r_sum[k];
    if (touching) expected.push_back(static_cast<std::int32_t>(k));
    EXPECT_EQ(list.spring[k] == Vec3::Zero(), !touching) << name << ", pair " << k;
    EXPECT_EQ(list.spring_live[k], touching ? 1 : 0) << name << ", pair " << k;
  }
  ASSERT_EQ(n, expected.size()) << name;
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), closed.begin())) << name;
  EXPECT_GT(n, 100u);
  EXPECT_LT(n, list.size());
}

TEST(PairSelection, SelectsTheTouchingPairsAndClearsTheSpringsOfOpenOnes) {
  for (const bool prefetch : {false, true}) {
    check_selection(simd::Portable{}, "portable", prefetch);
    if (cpu::best_vector_isa() == cpu::VectorIsa::avx512) check_selection(simd::Avx512{}, "AVX-512", prefetch);
  }
}

}  // namespace
}  // namespace softpack
