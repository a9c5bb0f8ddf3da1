// make_contact_model<Model>(): a contact model type (contact/contact_model.hpp; the paper's is
// contact/tsuji_model.hpp TsujiModel<HertzNormal>) turned into the run-time record of
// forces/contact_models.hpp, with its force loops compiled for every combination of effects
// (contact/effects.hpp) and two instruction sets:
//
//   AVX-512 (x86-64-v4)   simd::Avx512 data movement, eight lanes in one register
//   baseline              portable data movement, the release flags' x86-64-v2
//
// chosen at run time (core/cpu_features.hpp), block by block; both give the same bits. A build
// without SOFTPACK_AVX512 (the sanitizer's, CMakeLists.txt) compiles the baseline only. One step
// of a family of contacts is: sphere pairs, then each plane, then each shell, each through
// forces/contact_loop.hpp; every model runs through these loops.
#pragma once
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <stdexcept>

#include "core/cpu_features.hpp"
#include "core/error.hpp"
#include "forces/contact_loop.hpp"
#include "forces/contact_models.hpp"
#include "forces/contact_walk.hpp"
#include "forces/pair_contacts.hpp"
#include "forces/wall_contacts.hpp"
#include "softpack_build.hpp"

namespace softpack {
namespace loops {

// One block of a kind of contact (forces/contact_loop.hpp contact_block), compiled for each
// instruction set: the threads of the loop call it, so that the target attribute (which a lambda
// does not inherit) is on a function of its own. Each is `flatten` (every call inside inlined):
// the loops' speed then does not hang on how much of the translation unit's inlining budget the
// other loops left (simd/isa.hpp; the 5 000-sphere bench scene on one thread ran 5 % faster with
// AVX-512, the same with the portable loops, the same bits).
template <class Model, Effects Fx, class Contacts>
[[gnu::target("arch=x86-64-v4"), gnu::flatten]] void block_avx512(Contacts& c, const typename Model::Params& params, double dt, std::int32_t* closed,
                                                   std::size_t begin, std::size_t end) {
  contact_block<Model, Fx>(simd::Avx512{}, c, params, dt, closed, begin, end);
}

template <class Model, Effects Fx, class Contacts>
[[gnu::flatten]] void block_portable(Contacts& c, const typename Model::Params& params, double dt, std::int32_t* closed, std::size_t begin,
                    std::size_t end) {
  contact_block<Model, Fx>(simd::Portable{}, c, params, dt, closed, begin, end);
}

// The per-body pass's block (forces/contact_loop.hpp body_block) and the stress pass's
// (stress_block), likewise.
template <class Model, class Contacts>
[[gnu::target("arch=x86-64-v4"), gnu::flatten]] void body_avx512(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) {
  body_block<Model>(simd::Avx512{}, c, closed, begin, end);
}

template <class Model, class Contacts>
[[gnu::flatten]] void body_portable(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) {
  body_block<Model>(simd::Portable{}, c, closed, begin, end);
}

template <class Model, class Contacts>
[[gnu::target("arch=x86-64-v4"), gnu::flatten]] void stress_avx512(Contacts& c, const typename Model::Params& params, std::int32_t* closed,
                                                    std::size_t begin, std::size_t end) {
  stress_block<Model>(simd::Avx512{}, c, params, closed, begin, end);
}

template <class Model, class Contacts>
[[gnu::flatten]] void stress_portable(Contacts& c, const typename Model::Params& params, std::int32_t* closed, std::size_t begin,
                                      std::size_t end) {
  stress_block<Model>(simd::Portable{}, c, params, closed, begin, end);
}

/// Which pass a block is of: the forces, the per-body states or the bodies' stress tensors.
enum class Pass { force, body, stress };

/// One block of any kind of contact, on the instruction set chosen at run time, of pass `pass`.
template <class Model, Effects Fx, Pass pass = Pass::force>
struct BlockOf {
  bool avx512 = build::kAvx512Loops && cpu::vector_isa() == cpu::VectorIsa::avx512;
  const typename Model::Params* params = nullptr;
  double dt = 0.0;

  template <class Contacts>
  void operator()(Contacts& c, std::int32_t* closed, std::size_t begin, std::size_t end) const {
    if constexpr (pass == Pass::body) {
      if constexpr (build::kAvx512Loops)
        if (avx512) return body_avx512<Model>(c, closed, begin, end);
      body_portable<Model>(c, closed, begin, end);
    } else if constexpr (pass == Pass::stress) {
      if constexpr (build::kAvx512Loops)
        if (avx512) return stress_avx512<Model>(c, *params, closed, begin, end);
      stress_portable<Model>(c, *params, closed, begin, end);
    } else {
      if constexpr (build::kAvx512Loops)
        if (avx512) return block_avx512<Model, Fx>(c, *params, dt, closed, begin, end);
      block_portable<Model, Fx>(c, *params, dt, closed, begin, end);
    }
  }
};

/// Every contact of one family: sphere pairs, then each plane, then each shell. On threads (one
/// parallel region, core/parallel.hpp run_phases): each thread's ghost pairs, then its own pairs
/// and its spheres' wall contacts, then the loads of its walls, each in list order. A model with a
/// body state (contact/contact_model.hpp BodyStateModel) has the per-body pass run first, in
/// the same order: each sphere's state is summed as its force is; then, when its law has a stress
/// term (BodyStressModel), the stress pass, at the final states, in the same order again.
template <class Model, Effects Fx>
void all_contacts(World& world, ContactFamily& lists, const typename Model::Params& params, double dt, std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  constexpr bool kBody = BodyStateModel<Model>;
  static_assert(!BodyStressModel<Model> || ScalarOnlyModel<Model>, "the stress tensors are set lane by lane (forces/contact_loop.hpp lanes_force)");
  if constexpr (kBody) lists.body_state.resize(p.size());
  bool caps = false;  // the states made from the bodies' caps (contact/contact_model.hpp BodyCapsModel)
  if constexpr (BodyCapsModel<Model>) caps = Model::Normal::body_caps(params.normal);
  if (caps) lists.body_caps.resize(p.size());
  else lists.body_caps.clear();
  bool stress = false;  // the bodies' stress tensors (BodyStressModel): only for a law with the term
  if constexpr (BodyStressModel<Model>) stress = Model::Normal::body_stress(params.normal);
  if (stress) lists.body_stress.resize(p.size());
  else lists.body_stress.clear();
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), p.F.data(),
                       Fx.rotation ? p.T.data() : nullptr, kBody ? lists.body_state.data() : nullptr, caps ? lists.body_caps.data() : nullptr,
                       stress ? lists.body_stress.data() : nullptr};
  // Spheres [b, e) before the pass (states 0, no caps), and after it (a state from two caps or more).
  const auto clear_states = [&](std::size_t b, std::size_t e) {
    std::fill(lists.body_state.begin() + static_cast<std::ptrdiff_t>(b), lists.body_state.begin() + static_cast<std::ptrdiff_t>(e), 0.0);
    if (caps)
      for (std::size_t i = b; i < e; ++i) lists.body_caps[i].u.clear(), lists.body_caps[i].depth.clear();
  };
  const auto make_states = [&](std::size_t b, std::size_t e) {
    if constexpr (BodyCapsModel<Model>)
      if (caps)
        for (std::size_t i = b; i < e; ++i)
          if (lists.body_caps[i].u.size() >= 2) lists.body_state[i] = Model::Normal::body_state(lists.body_caps[i].u, lists.body_caps[i].depth);
    if (stress) std::fill(lists.body_stress.begin() + static_cast<std::ptrdiff_t>(b), lists.body_stress.begin() + static_cast<std::ptrdiff_t>(e),
                          SymmetricTensor{});  // before the stress pass
  };
  BlockOf<Model, Fx> block;
  block.params = &params, block.dt = dt;
  const BlockOf<Model, Fx, Pass::body> body_pass;
  BlockOf<Model, Fx, Pass::stress> stress_pass;
  stress_pass.params = &params;
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
  if (parallel::threads_for(p.size()) == 1) {
    closed.resize(kScratch);
    const auto pass = [&](const auto& b) {
      run_blocks(pairs, closed.data(), b);
      for (auto& w : planes) run_blocks(w, closed.data(), b);
      for (auto& w : shells) run_blocks(w, closed.data(), b);
    };
    if constexpr (kBody) clear_states(0, p.size()), pass(body_pass), make_states(0, p.size());
    if (stress) pass(stress_pass);
    pass(block);
    return;
  }
  const auto parts = static_cast<std::size_t>(parallel::threads_for(p.size()));
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
  // Each wall's load summed in list order by one thread (wall k by thread k mod parts).
  const auto finish = [&](std::size_t t) {
    for (std::size_t k = t; k < planes.size(); k += parts) planes[k].finish();
    for (std::size_t k = t; k < shells.size(); k += parts) shells[k].finish();
  };
  if constexpr (kBody) {
    const auto body_phases = [&](auto&&... then) {
      parallel::run_phases(
          parts,
          [&](std::size_t t) {
            clear_states(parallel::share_begin(p.size(), t, parts), parallel::share_begin(p.size(), t + 1, parts));
            ghosts(t, body_pass);
          },
          [&](std::size_t t) { own(t, body_pass); },
          [&](std::size_t t) { make_states(parallel::share_begin(p.size(), t, parts), parallel::share_begin(p.size(), t + 1, parts)); }, then...);
    };
    if (stress)  // after the states: the ghosts read states other threads made; the forces, tensors others summed
      body_phases([&](std::size_t t) { ghosts(t, stress_pass); }, [&](std::size_t t) { own(t, stress_pass); },
                  [&](std::size_t t) { ghosts(t, block); }, [&](std::size_t t) { own(t, block); }, finish);
    else
      body_phases([&](std::size_t t) { ghosts(t, block); }, [&](std::size_t t) { own(t, block); }, finish);
  } else {
    parallel::run_phases(parts, [&](std::size_t t) { ghosts(t, block); }, [&](std::size_t t) { own(t, block); }, finish);
  }
}

template <class Model, Effects Fx>
void masked_pairs(World& world, PairList& list, const typename Model::Params& params, const std::uint8_t* mask, double sign, Vec3* F,
                  Vec3* T, std::vector<std::int32_t>& closed) {
  Particles& p = world.p;
  const SphereArrays s{p.x.data(), p.v.data(), Fx.rotation ? p.w.data() : nullptr, p.r.data(), F, Fx.rotation ? T : nullptr};
  if constexpr (BodyStateModel<Model>) throw std::logic_error("an active set with a model that has a body state");  // refused on load
  MaskedPairContacts<Fx> pairs{{list, s, p.size()}, mask, sign};
  BlockOf<Model, Fx> block;
  block.params = &params;
  contact_loop(pairs, closed, block);
}

/// A model with a measured range (its normal sub-law's measured()): the closed contacts of
/// `lists` beyond it counted into `stats`, in the walk's order, or with the scene's `stop` a
/// NumericalError.
template <class Model>
void count_beyond_range(const World& world, const ContactFamily& lists, const SceneModel& model, const typename Model::Params& params,
                        RangeStats& stats) {
  for_each_closed_in_family(world, lists, model, [&](const ClosedContact& c) {
    const double dn = c.h / c.overlap_scale(world.p);
    const int plane = c.kind == ClosedContact::Kind::plane ? c.wall : -1;
    if (dn > stats.max_dn) stats.max_dn = dn, stats.i = c.i, stats.j = c.j, stats.plane = plane;
    const auto& law = Model::Normal::measured(params.normal, constants_at<Model>(*c.constants, c.k).normal);
    if (!(dn > law.dn_max)) return;
    ++stats.beyond_range;
    if (params.normal.stop_beyond_range)
      throw NumericalError(fmt::format("{} contact of sphere {} with {} at dn = {:.4g}, beyond the range its law was measured on ({:.4g} to "
                                       "{:.4g}, {}); {}",
                                       Model::name, c.i,
                                       c.j >= 0 ? fmt::format("sphere {}", c.j)
                                                : fmt::format("{} {}", c.kind == ClosedContact::Kind::plane ? "plane" : "shell", c.wall),
                                       dn, law.dn_min, law.dn_max, Model::Normal::source(params.normal), Model::Normal::kStopKey));
  });
}

template <class Model>
concept MeasuredRangeModel = requires(const typename Model::Params& p, const typename Model::template Constants<double>& c) {
  Model::Normal::measured(p.normal, c.normal);
};

/// A model type as a scene runs it (forces/contact_models.hpp SceneModel).
template <class Model>
class ModelOf final : public SceneModel {
 public:
  ModelOf(const ContactSetting& setting, Effects fx) : params_(Model::params(setting)) {
    with_effects(fx, [&]<Effects Fx>() {
      run_ = &all_contacts<Model, Fx>;
      masked_ = &masked_pairs<Model, Fx>;
    });
  }
  const char* name() const override { return Model::name; }
  std::size_t constants() const override { return Model::constant_count(); }
  bool body_state() const override { return BodyStateModel<Model>; }
  void set(ConstantArrays& a, std::size_t k, const ContactPartners& b) const override {
    set_constants_at<Model>(a, k, Model::constants(params_, b));
  }
  void run(World& world, ContactFamily& lists, double dt, std::vector<std::int32_t>& closed) override {
    run_(world, lists, params_, dt, closed);
    if constexpr (MeasuredRangeModel<Model>) count_beyond_range<Model>(world, lists, *this, params_, range_);
  }
  void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                       std::vector<std::int32_t>& closed) const override {
    masked_(world, pairs, params_, mask, sign, F, T, closed);
  }
  double Fn(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const override {
    return Model::Fn(params_, constants_at<Model>(a, k), g);
  }
  double normal_energy(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const override {
    return Model::normal_energy(params_, constants_at<Model>(a, k), g);
  }
  double kt(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const override {
    return Model::kt(params_, constants_at<Model>(a, k), g);
  }
  double overlap_scale(const ConstantArrays& a, std::size_t k, double r_min) const override {
    if constexpr (MeasuredRangeModel<Model>) return Model::Normal::overlap_scale(constants_at<Model>(a, k).normal);
    else return r_min;
  }
  const RangeStats& range() const override { return range_; }

 private:
  typename Model::Params params_;
  void (*run_)(World&, ContactFamily&, const typename Model::Params&, double, std::vector<std::int32_t>&) = nullptr;
  void (*masked_)(World&, PairList&, const typename Model::Params&, const std::uint8_t*, double, Vec3*, Vec3*,
                  std::vector<std::int32_t>&) = nullptr;
  RangeStats range_;
};

}  // namespace loops

/// The registry's record of a model type (forces/contact_models.hpp); `of_scene`: a scene may
/// name it in effects.normal.
template <class Model>
ContactModelType make_contact_model(bool of_scene = true) {
  ContactModelType m;
  m.name = Model::name;
  m.of_scene = of_scene;
  m.make = [](const ContactSetting& setting, Effects fx) -> std::unique_ptr<SceneModel> {
    return std::make_unique<loops::ModelOf<Model>>(setting, fx);
  };
  return m;
}

}  // namespace softpack
