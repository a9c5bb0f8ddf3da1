#include "sim/touching_pairs.hpp"

#include <immintrin.h>

#include <bit>
#include <cstddef>
#include <cstdint>

#include "core/cpu_features.hpp"
#include "sim/avx512_helpers.hpp"

namespace softpack {
namespace detail {
namespace {

// The flags must be as long as the list; a list replaced or filled by hand has none yet, and
// then every spring may be loaded.
void ensure_live_flags(PairList& list) {
  if (list.spring_live.size() != list.pairs.size()) list.spring_live.assign(list.pairs.size(), 1);
}

// Clearing a spring is `spring *= 0.0`, not setZero(): that is what it always was, bit for bit.
inline void clear_spring(Vec3& spring) { spring *= 0.0; }

// One pair, the portable way: the same squared distance as Eigen's squaredNorm(),
// (dx dx + dy dy) + dz dz, evaluated without FMA (the project compiles with -ffp-contract=off).
inline bool touching(const PairEntry& e, const Vec3* x) { return (x[e.i] - x[e.j]).squaredNorm() < e.r_sum * e.r_sum; }

std::size_t select_range_portable(PairList& list, const Vec3* x, bool friction, int* closed, std::size_t begin,
                                  std::size_t end, std::size_t n) {
  for (std::size_t k = begin; k < end; ++k) {
    const bool t = touching(list.pairs[k], x);
    closed[n] = static_cast<int>(k);
    n += t ? 1 : 0;
    if (friction) {
      if (list.spring_live[k] && !t) clear_spring(list.spring[k]);
      list.spring_live[k] = t ? 1 : 0;
    }
  }
  return n;
}

}  // namespace

std::size_t select_touching_pairs_portable(PairList& list, const Vec3* x, bool friction, int* closed) {
  if (friction) ensure_live_flags(list);
  return select_range_portable(list, x, friction, closed, 0, list.pairs.size(), 0);
}

// Eight pairs at a time. PairEntry is {int i, int j, double r_sum}, 16 bytes: two 512-bit
// loads hold eight entries, which permutes split into i, j and r_sum.
SOFTPACK_TARGET_AVX512 std::size_t select_touching_pairs_avx512(
    PairList& list, const Vec3* x, bool friction, int* closed) {
  static_assert(sizeof(PairEntry) == 16 && offsetof(PairEntry, j) == 4 && offsetof(PairEntry, r_sum) == 8);
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (friction) ensure_live_flags(list);
  const std::size_t npairs = list.pairs.size();
  const double* const xd = x->data();  // sphere i's x, y, z at xd[3i], xd[3i + 1], xd[3i + 2]
  const __m512i ij_words = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14);
  const __m512i r_sum_words = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
  __m256i kvec = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i eight = _mm256_set1_epi32(8);
  std::size_t n = 0, k = 0;
  for (; k + 8 <= npairs; k += 8) {
    const double* const entries = reinterpret_cast<const double*>(list.pairs.data() + k);
    const __m512d lo = _mm512_loadu_pd(entries), hi = _mm512_loadu_pd(entries + 8);
    const __m512i ij = _mm512_permutex2var_epi64(_mm512_castpd_si512(lo), ij_words, _mm512_castpd_si512(hi));
    const __m512d r_sum = _mm512_permutex2var_pd(lo, r_sum_words, hi);
    const __m256i i = _mm512_maskz_cvtepi64_epi32(0xff, ij);  // low halves (maskz: see avx512::gather8)
    const __m256i j = _mm512_maskz_cvtepi64_epi32(0xff, _mm512_maskz_srli_epi64(0xff, ij, 32));  // high halves
    const __m256i i3 = _mm256_add_epi32(i, _mm256_add_epi32(i, i));
    const __m256i j3 = _mm256_add_epi32(j, _mm256_add_epi32(j, j));
    const __m512d dx = _mm512_sub_pd(avx512::gather8(xd, i3), avx512::gather8(xd, j3));
    const __m512d dy = _mm512_sub_pd(avx512::gather8(xd + 1, i3), avx512::gather8(xd + 1, j3));
    const __m512d dz = _mm512_sub_pd(avx512::gather8(xd + 2, i3), avx512::gather8(xd + 2, j3));
    const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
    const __mmask8 touch = _mm512_cmp_pd_mask(d2, _mm512_mul_pd(r_sum, r_sum), _CMP_LT_OQ);
    _mm256_mask_compressstoreu_epi32(closed + n, touch, kvec);
    n += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(touch)));
    kvec = _mm256_add_epi32(kvec, eight);
    if (friction) {
      std::uint8_t* const live = list.spring_live.data() + k;
      const __m128i flags = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(live));
      for (unsigned opened = _mm_test_epi8_mask(flags, flags) & static_cast<unsigned>(~touch) & 0xffu; opened != 0;
           opened &= opened - 1)
        clear_spring(list.spring[k + static_cast<std::size_t>(std::countr_zero(opened))]);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(live), _mm_maskz_set1_epi8(touch, 1));
    }
  }
  return select_range_portable(list, x, friction, closed, k, npairs, n);
}

}  // namespace detail

std::size_t select_touching_pairs(PairList& list, const Vec3* x, bool friction, int* closed) {
  return cpu::avx512_in_use() ? detail::select_touching_pairs_avx512(list, x, friction, closed)
                                    : detail::select_touching_pairs_portable(list, x, friction, closed);
}

}  // namespace softpack
