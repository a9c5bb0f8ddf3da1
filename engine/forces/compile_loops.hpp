// make_normal_law<Law>(): a normal law type (contact/hertz_normal.hpp shows the members one
// needs) turned into the run-time record of forces/normal_law.hpp, with its force loops compiled
// for every combination of effects (contact/effects.hpp) and two instruction sets:
//
//   AVX-512 (x86-64-v4)   simd::Avx512 data movement, eight lanes in one register
//   baseline              portable data movement, the release flags' x86-64-v2
//
// chosen at run time (core/cpu_features.hpp); both give the same bits. A build without
// SOFTPACK_AVX512 (the sanitizer's, CMakeLists.txt) compiles the baseline only. One step of a world is:
// sphere pairs, then each plane, then each shell, each through forces/contact_loop.hpp.
#pragma once
#include <cmath>
#include <memory>

#include "core/cpu_features.hpp"
#include "forces/contact_loop.hpp"
#include "forces/normal_law.hpp"
#include "forces/pair_contacts.hpp"
#include "forces/wall_contacts.hpp"
#include "softpack_build.hpp"

namespace softpack {
namespace loops {

template <class Law, Effects Fx, class Isa>
[[gnu::always_inline]] inline void all_contacts(Isa isa, World& world, ContactLists& lists, double dt,
                                                std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), p.F.data(),
                       Fx.rotation ? p.T.data() : nullptr};
  PairContacts<Fx> pairs{lists.pairs, s};
  contact_loop<Law, Fx>(isa, pairs, dt, closed);
  for (std::size_t k = 0; k < world.planes.size(); ++k) {
    WallContacts<Fx, PlaneWall> plane{lists.planes[k], world.planes[k], s, world.plane_loads[k]};
    contact_loop<Law, Fx>(isa, plane, dt, closed);
  }
  for (std::size_t k = 0; k < world.shells.size(); ++k) {
    WallContacts<Fx, SphericalShell> shell{lists.shells[k], world.shells[k], s, world.shell_loads[k]};
    contact_loop<Law, Fx>(isa, shell, dt, closed);
  }
}

template <class Law, Effects Fx, class Isa>
[[gnu::always_inline]] inline void masked_pairs(Isa isa, World& world, PairList& list, const std::uint8_t* mask, double sign, Vec3* F,
                                                Vec3* T, std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), F, Fx.rotation ? T : nullptr};
  MaskedPairContacts<Fx> pairs{{list, s}, mask, sign};
  contact_loop<Law, Fx>(isa, pairs, 0.0, closed);
}

template <class Law, Effects Fx>
[[gnu::target("arch=x86-64-v4")]] void masked_pairs_avx512(World& world, PairList& list, const std::uint8_t* mask, double sign, Vec3* F,
                                                          Vec3* T, std::vector<std::int32_t>& closed) {
  masked_pairs<Law, Fx>(simd::Avx512{}, world, list, mask, sign, F, T, closed);
}

template <class Law, Effects Fx>
[[gnu::target("arch=x86-64-v4")]] void all_contacts_avx512(World& world, ContactLists& lists, double dt,
                                                          std::vector<std::int32_t>& closed) {
  all_contacts<Law, Fx>(simd::Avx512{}, world, lists, dt, closed);
}

template <class Law, Effects Fx>
void all_contacts_portable(World& world, ContactLists& lists, double dt, std::vector<std::int32_t>& closed) {
  all_contacts<Law, Fx>(simd::Portable{}, world, lists, dt, closed);
}

template <class Law, Effects Fx>
class LoopsOf final : public ForceLoops {
 public:
  void run(World& world, ContactLists& lists, double dt, std::vector<std::int32_t>& closed) const override {
    if constexpr (build::kAvx512Loops)
      if (cpu::vector_isa() == cpu::VectorIsa::avx512) return all_contacts_avx512<Law, Fx>(world, lists, dt, closed);
    all_contacts_portable<Law, Fx>(world, lists, dt, closed);
  }
  void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                       std::vector<std::int32_t>& closed) const override {
    if constexpr (build::kAvx512Loops)
      if (cpu::vector_isa() == cpu::VectorIsa::avx512) return masked_pairs_avx512<Law, Fx>(world, pairs, mask, sign, F, T, closed);
    masked_pairs<Law, Fx>(simd::Portable{}, world, pairs, mask, sign, F, T, closed);
  }
};

}  // namespace loops

template <class Law>
NormalLaw make_normal_law() {
  NormalLaw n;
  n.name = Law::name;
  n.stiffness = [](double R12, double D) { return Law::stiffness(R12, D); };
  n.force = [](double kn, double h) { return Law::force(kn, h, std::sqrt(h)); };
  n.energy = [](double kn, double h) { return Law::energy(kn, h); };
  n.damping_coefficient = [](double e) { return Law::damping_coefficient(e); };
  n.loops = [](Effects fx) {
    return with_effects(fx, []<Effects Fx>() -> std::unique_ptr<ForceLoops> { return std::make_unique<loops::LoopsOf<Law, Fx>>(); });
  };
  return n;
}

}  // namespace softpack
