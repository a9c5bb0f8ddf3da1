// The data movement of the force loops that depends on the instruction set: gathers of
// scattered values into the lanes of a Wide (simd/wide.hpp), compressed stores, byte flags.
// Two back ends with the same results:
//
//   Portable  lane-by-lane loops, for any processor;
//   Avx512    AVX-512 F/VL/BW/DQ gathers and compressed stores.
//
// The force loops are templates over the back end (a tag argument); forces/force_field.cpp
// picks one at run time (core/cpu_features.hpp). This is the one file of the engine that holds
// intrinsics; the Avx512 functions carry their target attribute and are inlined only into
// loops compiled for AVX-512.
#pragma once
#include <immintrin.h>

#include <bit>
#include <cstdint>

#include "simd/wide.hpp"

namespace softpack::simd {

struct Portable {};
struct Avx512 {};

// --- Portable ----------------------------------------------------------------------------------

/// base[idx[k]] in lane k.
[[gnu::always_inline]] inline Wide gather(Portable, const double* base, Index idx) {
  Wide out;
  for (int k = 0; k < kLanes; ++k) out.v[k] = base[idx.v[k]];
  return out;
}
[[gnu::always_inline]] inline Index gather(Portable, const std::int32_t* base, Index idx) {
  Index out;
  for (int k = 0; k < kLanes; ++k) out.v[k] = base[idx.v[k]];
  return out;
}

/// Writes the lanes of `values` where `m` holds to out[0], out[1], ... in lane order and returns
/// how many; out must have room for eight.
[[gnu::always_inline]] inline int compress(Portable, std::int32_t* out, Mask m, Index values) {
  int n = 0;
  for (int k = 0; k < kLanes; ++k) {
    out[n] = values.v[k];
    n += m.m[k] != 0 ? 1 : 0;
  }
  return n;
}

/// Bit k set where byte p[k] is not zero.
[[gnu::always_inline]] inline unsigned nonzero_bytes(Portable, const std::uint8_t* p) {
  unsigned out = 0;
  for (int k = 0; k < kLanes; ++k) out |= (p[k] != 0 ? 1u : 0u) << k;
  return out;
}
/// p[k] = bit k of `b` (0 or 1).
[[gnu::always_inline]] inline void store_bits_as_bytes(Portable, std::uint8_t* p, unsigned b) {
  for (int k = 0; k < kLanes; ++k) p[k] = static_cast<std::uint8_t>((b >> k) & 1u);
}

// --- AVX-512 -----------------------------------------------------------------------------------
// Each operation is a target-specific function that takes its vectors by reference (so that a
// call from code compiled without AVX-512 passes them the same way: no vector in a register
// crosses a target boundary), behind an always_inline wrapper of the Portable form's signature.
// They are not always_inline themselves: the generic templates that call them are compiled for
// the baseline too, where they cannot be inlined. The AVX-512 loop (forces/compile_loops.hpp) is
// `flatten`: what it calls is inlined into it, these too (without it GCC 12 left 328 calls to
// them in the loops, the translation unit's inlining budget spent; with it 16, all in the
// scalar-only soft-particle model's loops);
// unoptimised, they stay calls, with the same results. Masked forms with a zero source
// throughout: the unmasked ones start from an undefined vector, which GCC 12 reports as
// maybe-uninitialized (an error under CI's -Werror). Vectors are reinterpreted with
// __builtin_bit_cast and assigned to the members, never passed to a function compiled without
// the target (std::bit_cast, a constructor): clang refuses that (it would change the ABI).

namespace avx512 {

[[gnu::target("avx512f,avx512vl,avx512bw,avx512dq")]] inline void gather(const double* base, const Index& idx, Wide& out) {
  const __m512d v = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), __mmask8{0xff}, __builtin_bit_cast(__m256i, idx.v), base, 8);
  out.v = __builtin_bit_cast(Wide::Raw, v);
}
[[gnu::target("avx512f,avx512vl,avx512bw,avx512dq")]] inline void gather(const std::int32_t* base, const Index& idx, Index& out) {
  const __m256i v = _mm256_mmask_i32gather_epi32(_mm256_setzero_si256(), __mmask8{0xff}, __builtin_bit_cast(__m256i, idx.v), base, 4);
  out.v = __builtin_bit_cast(Index::Raw, v);
}
[[gnu::target("avx512f,avx512vl,avx512bw,avx512dq")]] inline int compress(std::int32_t* out, const Mask& m, const Index& values) {
  const __mmask8 k = _mm512_movepi64_mask(__builtin_bit_cast(__m512i, m.m));
  _mm256_mask_compressstoreu_epi32(out, k, __builtin_bit_cast(__m256i, values.v));
  return std::popcount(static_cast<unsigned>(k));
}
[[gnu::target("avx512f,avx512vl,avx512bw,avx512dq")]] inline unsigned nonzero_bytes(const std::uint8_t* p) {
  const __m128i flags = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
  return static_cast<unsigned>(_mm_test_epi8_mask(flags, flags)) & 0xffu;
}
[[gnu::target("avx512f,avx512vl,avx512bw,avx512dq")]] inline void store_bits_as_bytes(std::uint8_t* p, unsigned b) {
  _mm_storel_epi64(reinterpret_cast<__m128i*>(p), _mm_maskz_set1_epi8(static_cast<__mmask16>(b & 0xffu), 1));
}

}  // namespace avx512

[[gnu::always_inline]] inline Wide gather(Avx512, const double* base, Index idx) {
  Wide out;
  avx512::gather(base, idx, out);
  return out;
}
[[gnu::always_inline]] inline Index gather(Avx512, const std::int32_t* base, Index idx) {
  Index out;
  avx512::gather(base, idx, out);
  return out;
}
[[gnu::always_inline]] inline int compress(Avx512, std::int32_t* out, Mask m, Index values) {
  return avx512::compress(out, m, values);
}
[[gnu::always_inline]] inline unsigned nonzero_bytes(Avx512, const std::uint8_t* p) { return avx512::nonzero_bytes(p); }
[[gnu::always_inline]] inline void store_bits_as_bytes(Avx512, std::uint8_t* p, unsigned b) { avx512::store_bits_as_bytes(p, b); }

}  // namespace softpack::simd
