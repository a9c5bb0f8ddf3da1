// Which instruction set the force loops run with (forces/compile_loops.hpp): AVX-512 (F, VL,
// BW, DQ: x86-64-v4) or the portable baseline. Both give the same bits (simd/wide.hpp); tests
// lower the limit to compare them on one machine. There is no AVX2 path: it does not pay. The
// AVX-512 loops' gain is their gathers and compressed stores, not the width of the arithmetic:
// an AVX2 back end (simd/isa.hpp's pattern, its loops flattened) ran the 5 000-sphere bench scene
// on one thread (issue 32, min of 7 alternated runs of 1 000 steps) in 0.697 s with AVX2's
// gathers against 0.566 s portable and 0.341 s AVX-512; with scalar loads for its gathers in
// 0.575 s against 0.574 s portable; the portable loops compiled for AVX2 arithmetic alone took
// the portable loops' time.
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
