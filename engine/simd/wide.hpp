// The wide-number vocabulary of the force loops (in the manner of Box2D v3's b2FloatW): eight
// doubles operated on lane by lane, with the operators and functions the contact law uses. The
// law (contact/contact_model.hpp) is a template over its number type and runs on `double` for one
// contact and on `Wide` for eight; the functions below have a `double` overload each, so the
// same source reads the same for both.
//
// Wide is a GCC/Clang vector of eight doubles: a loop compiled for AVX-512 holds it in one
// register, for SSE2 in four. Every operation is an IEEE operation of its own
// lane, so a lane gets the bits the same expression gives on one double (the project compiles
// with -ffp-contract=off: no fused multiply-adds). Data movement that depends on the
// instruction set (gathers, compressed stores) lives in simd/isa.hpp.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace softpack::simd {

inline constexpr int kLanes = 8;

/// Eight lanes of a comparison: all bits set where it holds, zero elsewhere.
struct Mask {
  using Raw = std::int64_t __attribute__((vector_size(64)));
  Raw m;
};

/// Eight doubles.
struct Wide {
  using Raw = double __attribute__((vector_size(64)));
  Raw v;
  Wide() = default;
  /// Every lane x (so that `0.5 * h` reads as it does for a double).
  [[gnu::always_inline]] Wide(double x) : v{x, x, x, x, x, x, x, x} {}
  [[gnu::always_inline]] explicit Wide(Raw r) : v(r) {}
};

/// Eight 32-bit indices (of spheres, contacts, array elements).
struct Index {
  using Raw = std::int32_t __attribute__((vector_size(32)));
  Raw v;
};

// --- Arithmetic ------------------------------------------------------------------------------

[[gnu::always_inline]] inline Wide operator+(Wide a, Wide b) { return Wide(a.v + b.v); }
[[gnu::always_inline]] inline Wide operator-(Wide a, Wide b) { return Wide(a.v - b.v); }
[[gnu::always_inline]] inline Wide operator*(Wide a, Wide b) { return Wide(a.v * b.v); }
[[gnu::always_inline]] inline Wide operator/(Wide a, Wide b) { return Wide(a.v / b.v); }
[[gnu::always_inline]] inline Wide operator-(Wide a) { return Wide(-a.v); }
[[gnu::always_inline]] inline Wide& operator+=(Wide& a, Wide b) { return a = a + b; }
[[gnu::always_inline]] inline Wide& operator-=(Wide& a, Wide b) { return a = a - b; }
[[gnu::always_inline]] inline Wide& operator*=(Wide& a, Wide b) { return a = a * b; }

[[gnu::always_inline]] inline Mask operator<(Wide a, Wide b) { return Mask{a.v < b.v}; }
[[gnu::always_inline]] inline Mask operator<=(Wide a, Wide b) { return Mask{a.v <= b.v}; }
[[gnu::always_inline]] inline Mask operator>(Wide a, Wide b) { return Mask{a.v > b.v}; }
[[gnu::always_inline]] inline Mask operator>=(Wide a, Wide b) { return Mask{a.v >= b.v}; }
[[gnu::always_inline]] inline Mask operator==(Wide a, Wide b) { return Mask{a.v == b.v}; }
[[gnu::always_inline]] inline Mask operator!=(Wide a, Wide b) { return Mask{a.v != b.v}; }
[[gnu::always_inline]] inline Mask operator&(Mask a, Mask b) { return Mask{a.m & b.m}; }
[[gnu::always_inline]] inline Mask operator|(Mask a, Mask b) { return Mask{a.m | b.m}; }
[[gnu::always_inline]] inline Mask operator!(Mask a) { return Mask{~a.m}; }

/// Correctly rounded square root, lane by lane (one instruction with -fno-math-errno).
[[gnu::always_inline]] inline double sqrt(double x) { return std::sqrt(x); }
[[gnu::always_inline]] inline Wide sqrt(Wide a) {
  Wide r;
  for (int k = 0; k < kLanes; ++k) r.v[k] = __builtin_sqrt(a.v[k]);
  return r;
}

/// m ? a : b, lane by lane.
[[gnu::always_inline]] inline double select(bool m, double a, double b) { return m ? a : b; }
[[gnu::always_inline]] inline Wide select(Mask m, Wide a, Wide b) { return Wide(m.m ? a.v : b.v); }

/// Whether the condition holds in some lane: the law skips work no lane needs.
[[gnu::always_inline]] inline bool any(bool m) { return m; }
[[gnu::always_inline]] inline bool any(Mask m) {
  Mask::Raw r = m.m;
  std::int64_t acc = 0;
  for (int k = 0; k < kLanes; ++k) acc |= r[k];
  return acc != 0;
}

/// Bit k set where lane k of the mask holds.
[[gnu::always_inline]] inline unsigned bits(Mask m) {
  unsigned out = 0;
  for (int k = 0; k < kLanes; ++k) out |= (m.m[k] != 0 ? 1u : 0u) << k;
  return out;
}

// --- Memory ------------------------------------------------------------------------------------

/// Eight consecutive doubles (no alignment needed).
[[gnu::always_inline]] inline Wide load(const double* p) {
  Wide w;
  std::memcpy(&w.v, p, sizeof w.v);
  return w;
}
[[gnu::always_inline]] inline void store(double* p, Wide w) { std::memcpy(p, &w.v, sizeof w.v); }

[[gnu::always_inline]] inline Index load(const std::int32_t* p) {
  Index w;
  std::memcpy(&w.v, p, sizeof w.v);
  return w;
}
/// base, base + 1, ..., base + 7.
[[gnu::always_inline]] inline Index iota(std::int32_t base) {
  return Index{Index::Raw{0, 1, 2, 3, 4, 5, 6, 7} + base};
}
[[gnu::always_inline]] inline Index operator*(std::int32_t s, Index a) { return Index{a.v * s}; }
[[gnu::always_inline]] inline Index operator+(Index a, std::int32_t s) { return Index{a.v + s}; }

}  // namespace softpack::simd
