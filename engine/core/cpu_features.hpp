// Which instruction-set paths the engine takes. The hot loops with hand-written AVX-512 paths
// (sim/touching_pairs, sim/pair_forces) take them when the processor
// has AVX-512 F, VL, BW and DQ; their portable twins give the same bits, and tests switch the
// AVX-512 paths off to compare the two on one machine.
#pragma once

namespace softpack::cpu {

/// The processor has AVX-512 (F, VL, BW, DQ) and no test switched those paths off.
bool avx512_in_use();
/// false makes avx512_in_use() false (tests); true restores what the processor offers.
void allow_avx512(bool allowed);

}  // namespace softpack::cpu
