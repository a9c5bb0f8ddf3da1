#include "core/cpu_features.hpp"

#include <atomic>

namespace softpack::cpu {
namespace {

std::atomic<bool> avx512_allowed{true};

bool avx512_present() {
  __builtin_cpu_init();  // may run before the library's own initialisation
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512dq");
}

}  // namespace

bool avx512_in_use() {
  static const bool present = avx512_present();
  return present && avx512_allowed.load(std::memory_order_relaxed);
}

void allow_avx512(bool allowed) { avx512_allowed.store(allowed, std::memory_order_relaxed); }

}  // namespace softpack::cpu
