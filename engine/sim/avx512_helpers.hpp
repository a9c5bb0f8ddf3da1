// AVX-512 helpers shared by the hand-vectorised passes of the force loop (sim/touching_pairs.cpp,
// sim/pair_forces.cpp). Callers are compiled for AVX-512 and run only where
// cpu::avx512_in_use() (core/cpu_features.hpp).
#pragma once
#include <immintrin.h>

/// The instruction sets cpu::avx512_in_use() checks for: the target of every AVX-512 function.
#define SOFTPACK_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq")))

namespace softpack::avx512 {

/// Eight doubles base[idx], lanes outside `live` zero. The masked intrinsic with a zero source:
/// the unmasked one starts from an undefined vector, which GCC 12 reports as maybe-uninitialized
/// (an error under CI's -Werror); the same holds for the other intrinsics these passes use.
[[gnu::always_inline]] __attribute__((target("avx512f"))) inline __m512d gather8(const double* base, __m256i idx,
                                                                                 __mmask8 live = 0xff) {
  return _mm512_mask_i32gather_pd(_mm512_setzero_pd(), live, idx, base, 8);
}

}  // namespace softpack::avx512
