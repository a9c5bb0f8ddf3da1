// The first pass of the pair loop, every step: which listed pairs touch (|xi - xj| < Ri + Rj),
// and clearing the springs of those that opened.
//
// Two implementations with the same result bits: a portable loop and an AVX-512 one that tests
// eight pairs per instruction (gathers for the positions, a compressed store for the indices).
// The AVX-512 one is used when the processor has it; tests/physics/test_pair_forces.cpp checks
// that both agree. A spring is only cleared when PairList::spring_live says it may be non-zero,
// which spares the ~60% of listed pairs that stay apart a write each step.
#pragma once
#include <cstddef>

#include "core/types.hpp"
#include "neighbor/contact_list.hpp"

namespace softpack {

/// Writes the indices of the touching pairs of `list`, in list order, to `closed` (room for
/// list.pairs.size() entries) and returns how many there are. With `friction`, the springs of
/// pairs that do not touch are cleared and list.spring_live is brought up to date.
std::size_t select_touching_pairs(PairList& list, const Vec3* x, bool friction, int* closed);

namespace detail {
std::size_t select_touching_pairs_portable(PairList& list, const Vec3* x, bool friction, int* closed);
/// Requires cpu::avx512_in_use() (core/cpu_features.hpp).
std::size_t select_touching_pairs_avx512(PairList& list, const Vec3* x, bool friction, int* closed);
}  // namespace detail

}  // namespace softpack
