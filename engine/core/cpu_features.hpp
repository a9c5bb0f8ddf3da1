// Which instruction set the force loops run with (forces/compile_loops.hpp): AVX-512 (F, VL,
// BW, DQ: x86-64-v4) or the portable baseline. Both give the same bits (simd/wide.hpp); tests
// lower the limit to compare them on one machine. (An AVX2 build of the loops was measured no
// faster than the baseline's on the benchmark scene, 1.00 s against 0.90 s, and is not made.)
#pragma once

namespace softpack::cpu {

enum class VectorIsa { portable = 0, avx512 = 1 };

/// The best the processor and the build offer, within the limit set by limit_vector_isa().
VectorIsa vector_isa();
/// Runs the loops with at most `isa` (tests); VectorIsa::avx512 restores what the processor offers.
void limit_vector_isa(VectorIsa isa);
/// What the processor offers (portable in a build without AVX-512 loops, CMakeLists.txt).
VectorIsa best_vector_isa();
const char* name(VectorIsa isa);

}  // namespace softpack::cpu
