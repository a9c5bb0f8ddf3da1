// Which instruction set the force loops are compiled for and run with (forces/normal_law.hpp):
// AVX-512 (F, VL, BW, DQ), AVX2 (with FMA, BMI1/2: x86-64-v3), or the portable baseline. Every
// one gives the same bits (simd/wide.hpp); tests lower the limit to compare them on one machine.
#pragma once

namespace softpack::cpu {

enum class VectorIsa { portable = 0, avx2 = 1, avx512 = 2 };

/// The best the processor offers, within the limit set by limit_vector_isa().
VectorIsa vector_isa();
/// Runs the loops with at most `isa` (tests); VectorIsa::avx512 restores what the processor offers.
void limit_vector_isa(VectorIsa isa);
/// What the processor offers.
VectorIsa best_vector_isa();
const char* name(VectorIsa isa);

}  // namespace softpack::cpu
