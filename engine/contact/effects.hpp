// Which parts of the contact law a scene runs, as one value the force loops are compiled for,
// and the one place where a run-time choice of effects becomes a compile-time one.
//
//   friction      Tsuji tangential spring with the Coulomb limit (Eq. 5-6)
//   damping       viscous normal and tangential damping (contact/viscous_damping.hpp)
//   rotation      angular velocities and torques
//   synchronized  the spring is carried in the half-step frame (scene/scene_def.hpp HistoryUpdate)
//
// A loop compiled for an effect that is off holds none of its arithmetic.
#pragma once
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace softpack {

struct Effects {
  bool friction = false, damping = false, rotation = false, synchronized = false;
  constexpr bool operator==(const Effects&) const = default;
};

/// The combinations the loops are compiled for: rotation and the history frame need friction
/// (validate() refuses rotation without it; without friction the frame does not matter).
inline constexpr std::array<Effects, 10> kEffectCombinations{{
    {false, false, false, false},
    {false, true, false, false},
    {true, false, false, false},
    {true, false, true, false},
    {true, true, false, false},
    {true, true, true, false},
    {true, false, false, true},
    {true, false, true, true},
    {true, true, false, true},
    {true, true, true, true},
}};

/// The combination the loops run for `fx` (the history frame dropped without friction).
constexpr Effects compiled_effects(Effects fx) {
  if (!fx.friction) fx.synchronized = false;
  return fx;
}

/// "friction, damping, rotation, synchronized" (the declared ones), for messages and test names.
std::string describe(const Effects& fx);

namespace detail {
template <class F, std::size_t... I>
decltype(auto) with_effects(const Effects& fx, F&& f, std::index_sequence<I...>) {
  using R = decltype(f.template operator()<kEffectCombinations[0]>());
  if constexpr (std::is_void_v<R>) {
    const bool found = ((fx == kEffectCombinations[I] ? (f.template operator()<kEffectCombinations[I]>(), true) : false) || ...);
    if (!found) throw std::logic_error("no force loop for effects: " + describe(fx));
  } else {
    R out{};
    const bool found =
        ((fx == kEffectCombinations[I] ? (static_cast<void>(out = f.template operator()<kEffectCombinations[I]>()), true) : false) ||
         ...);
    if (!found) throw std::logic_error("no force loop for effects: " + describe(fx));
    return out;
  }
}
}  // namespace detail

/// Calls f.template operator()<Fx>() with Fx the compiled combination equal to `fx`:
/// `with_effects(fx, [&]<Effects Fx>() { ... })`.
template <class F>
decltype(auto) with_effects(Effects fx, F&& f) {
  return detail::with_effects(compiled_effects(fx), f, std::make_index_sequence<kEffectCombinations.size()>{});
}

}  // namespace softpack
