// make_normal_law<Law>(): a normal law type (contact/hertz_normal.hpp shows the members one
// needs) turned into the run-time record of forces/normal_law.hpp, with its force loops compiled
// for every combination of effects (contact/effects.hpp) and two instruction sets:
//
//   AVX-512 (x86-64-v4)   simd::Avx512 data movement, eight lanes in one register
//   baseline              portable data movement, the release flags' x86-64-v2
//
// chosen at run time (core/cpu_features.hpp), block by block; both give the same bits. A build
// without SOFTPACK_AVX512 (the sanitizer's, CMakeLists.txt) compiles the baseline only. One step
// of a world is: sphere pairs, then each plane, then each shell, each through
// forces/contact_loop.hpp.
#pragma once
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/cpu_features.hpp"
#include "forces/contact_loop.hpp"
#include "forces/normal_law.hpp"
#include "forces/pair_contacts.hpp"
#include "forces/wall_contacts.hpp"
#include "softpack_build.hpp"

namespace softpack {
namespace loops {

// One block of a kind of contact (forces/contact_loop.hpp contact_block), compiled for each
// instruction set: the threads of the loop call it, so that the target attribute (which a lambda
// does not inherit) is on a function of its own.
template <class Law, Effects Fx, class Contacts>
[[gnu::target("arch=x86-64-v4")]] void block_avx512(Contacts& c, double dt, std::int32_t* closed, std::size_t begin,
                                                   std::size_t end) {
  contact_block<Law, Fx>(simd::Avx512{}, c, dt, closed, begin, end);
}

template <class Law, Effects Fx, class Contacts>
void block_portable(Contacts& c, double dt, std::int32_t* closed, std::size_t begin, std::size_t end) {
  contact_block<Law, Fx>(simd::Portable{}, c, dt, closed, begin, end);
}

// The per-body pass's block (forces/contact_loop.hpp body_block), likewise.
template <class Law, class Contacts>
[[gnu::target("arch=x86-64-v4")]] void body_avx512(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) {
  body_block<Law>(simd::Avx512{}, c, closed, begin, end);
}

template <class Law, class Contacts>
void body_portable(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) {
  body_block<Law>(simd::Portable{}, c, closed, begin, end);
}

/// One block of any kind of contact, on the instruction set chosen at run time: of the force
/// pass, or with `body` of the per-body pass.
template <class Law, Effects Fx, bool body = false>
struct BlockOf {
  bool avx512 = build::kAvx512Loops && cpu::vector_isa() == cpu::VectorIsa::avx512;
  double dt = 0.0;

  template <class Contacts>
  void operator()(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) const {
    if constexpr (body) {
      if constexpr (build::kAvx512Loops)
        if (avx512) return body_avx512<Law>(c, closed, begin, end);
      body_portable<Law>(c, closed, begin, end);
    } else {
      if constexpr (build::kAvx512Loops)
        if (avx512) return block_avx512<Law, Fx>(c, dt, closed, begin, end);
      block_portable<Law, Fx>(c, dt, closed, begin, end);
    }
  }
};

/// Every contact of a world: sphere pairs, then each plane, then each shell. On threads (one
/// parallel region, core/parallel.hpp run_phases): each thread's ghost pairs, then its own pairs
/// and its spheres' wall contacts; afterwards the walls' loads, in list order. A law with a body
/// state (contact/contact_law.hpp BodyStateLaw) has the per-body pass run first, in the same
/// order: each sphere's state is summed as its force is.
template <class Law, Effects Fx>
void all_contacts(World& world, ContactLists& lists, double dt, std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  constexpr bool kBody = BodyStateLaw<Law>;
  if constexpr (kBody) lists.body_state.resize(p.size());
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), p.F.data(),
                       Fx.rotation ? p.T.data() : nullptr, kBody ? lists.body_state.data() : nullptr};
  BlockOf<Law, Fx> block;
  block.dt = dt;
  const BlockOf<Law, Fx, true> body_pass;
  PairContacts<Fx> pairs{lists.pairs, s, p.size()};
  // Kept from step to step (no allocation per step); the references, not the thread_local
  // names, are what the threads' phases see.
  thread_local std::vector<WallContacts<Fx, PlaneWall>> kept_planes;
  thread_local std::vector<WallContacts<Fx, SphericalShell>> kept_shells;
  auto& planes = kept_planes;
  auto& shells = kept_shells;
  planes.clear(), shells.clear();
  for (std::size_t k = 0; k < world.planes.size(); ++k) planes.push_back({lists.planes[k], world.planes[k], s, world.plane_loads[k], p.size()});
  for (std::size_t k = 0; k < world.shells.size(); ++k) shells.push_back({lists.shells[k], world.shells[k], s, world.shell_loads[k], p.size()});
  pairs.prepare();
  for (auto& w : planes) w.prepare();
  for (auto& w : shells) w.prepare();
  if (parallel::threads() == 1) {
    closed.resize(kScratch);
    const auto pass = [&](const auto& b) {
      run_blocks(pairs, closed.data(), b);
      for (auto& w : planes) run_blocks(w, closed.data(), b);
      for (auto& w : shells) run_blocks(w, closed.data(), b);
    };
    if constexpr (kBody) std::fill(lists.body_state.begin(), lists.body_state.end(), 0.0), pass(body_pass);
    pass(block);
    return;
  }
  const auto parts = static_cast<std::size_t>(parallel::threads());
  closed.resize(parts * kScratch);
  const auto scratch = [&](std::size_t t) { return closed.data() + t * kScratch; };
  // A masked list (an active set: never with a body state) runs on this thread.
  if (pairs.direct) run_blocks(pairs, closed.data(), block);
  const auto ghosts = [&](std::size_t t, const auto& b) {
    if (pairs.direct) return;
    PairContacts<Fx> c = pairs.part(0, t, parts);
    run_blocks(c, scratch(t), b);
  };
  const auto own = [&](std::size_t t, const auto& b) {
    if (!pairs.direct) {
      PairContacts<Fx> c = pairs.part(1, t, parts);
      run_blocks(c, scratch(t), b);
    }
    for (auto& w : planes) {
      auto c = w.part(0, t, parts);
      run_blocks(c, scratch(t), b);
    }
    for (auto& w : shells) {
      auto c = w.part(0, t, parts);
      run_blocks(c, scratch(t), b);
    }
  };
  if constexpr (kBody) {
    parallel::run_phases(
        parts,
        [&](std::size_t t) {
          std::fill(lists.body_state.begin() + static_cast<std::ptrdiff_t>(parallel::share_begin(p.size(), t, parts)),
                    lists.body_state.begin() + static_cast<std::ptrdiff_t>(parallel::share_begin(p.size(), t + 1, parts)), 0.0);
          ghosts(t, body_pass);
        },
        [&](std::size_t t) { own(t, body_pass); }, [&](std::size_t t) { ghosts(t, block); }, [&](std::size_t t) { own(t, block); });
  } else {
    parallel::run_phases(parts, [&](std::size_t t) { ghosts(t, block); }, [&](std::size_t t) { own(t, block); });
  }
  for (auto& w : planes) w.finish();
  for (auto& w : shells) w.finish();
}

template <class Law, Effects Fx>
void masked_pairs(World& world, PairList& list, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                  std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), F, Fx.rotation ? T : nullptr};
  if constexpr (BodyStateLaw<Law>) throw std::logic_error("an active set with a law that has a body state");  // refused on load
  MaskedPairContacts<Fx> pairs{{list, s, p.size()}, mask, sign};
  BlockOf<Law, Fx> block;
  contact_loop(pairs, closed, block);
}

template <class Law, Effects Fx>
class LoopsOf final : public ForceLoops {
 public:
  void run(World& world, ContactLists& lists, double dt, std::vector<std::int32_t>& closed) const override {
    all_contacts<Law, Fx>(world, lists, dt, closed);
  }
  void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                       std::vector<std::int32_t>& closed) const override {
    masked_pairs<Law, Fx>(world, pairs, mask, sign, F, T, closed);
  }
};

}  // namespace loops

template <class Law>
NormalLaw make_normal_law() {
  NormalLaw n;
  n.name = Law::name;
  n.stiffness = [](double R12, double D) { return Law::stiffness(R12, D); };
  n.force = [](double kn, double h, [[maybe_unused]] double s1, [[maybe_unused]] double s2) {
    if constexpr (BodyStateLaw<Law>) return Law::force(kn, h, std::sqrt(h), s1, s2);
    else return Law::force(kn, h, std::sqrt(h));
  };
  n.energy = [](double kn, double h, [[maybe_unused]] double s1, [[maybe_unused]] double s2) {
    if constexpr (BodyStateLaw<Law>) return Law::energy(kn, h, s1, s2);
    else return Law::energy(kn, h);
  };
  n.body_state = BodyStateLaw<Law>;
  n.damping_coefficient = [](double e) { return Law::damping_coefficient(e); };
  n.loops = [](Effects fx) {
    return with_effects(fx, []<Effects Fx>() -> std::unique_ptr<ForceLoops> { return std::make_unique<loops::LoopsOf<Law, Fx>>(); });
  };
  return n;
}

}  // namespace softpack
