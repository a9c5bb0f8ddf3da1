#include "core/cpu_features.hpp"

#include <algorithm>
#include <atomic>

#include "softpack_build.hpp"

namespace softpack::cpu {
namespace {

std::atomic<int> limit{static_cast<int>(VectorIsa::avx512)};

VectorIsa detect() {
  if constexpr (!build::kAvx512Loops) return VectorIsa::portable;  // the build has no AVX-512 loops
  __builtin_cpu_init();  // may run before the library's own initialisation
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq"))
    return VectorIsa::avx512;
  return VectorIsa::portable;
}

}  // namespace

VectorIsa best_vector_isa() {
  static const VectorIsa best = detect();
  return best;
}

VectorIsa vector_isa() {
  return static_cast<VectorIsa>(std::min(static_cast<int>(best_vector_isa()), limit.load(std::memory_order_relaxed)));
}

void limit_vector_isa(VectorIsa isa) { limit.store(static_cast<int>(isa), std::memory_order_relaxed); }

const char* name(VectorIsa isa) {
  switch (isa) {
    case VectorIsa::avx512: return "AVX-512";
    default: return "portable";
  }
}

}  // namespace softpack::cpu
