#include "core/parallel.hpp"

#include <fmt/format.h>

#include <cstdlib>

#include "core/error.hpp"

namespace softpack::parallel {
namespace {

int threads_ = 0;  // 0: not yet decided

int default_threads() {
  const char* env = std::getenv("SOFTPACK_THREADS");
  if (env == nullptr || *env == '\0') return 1;
  char* end = nullptr;
  const long n = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || n < 1 || n > 1024)
    throw InputError(fmt::format("SOFTPACK_THREADS = '{}' is not allowed; allowed: a whole number of threads from 1 to 1024", env));
  return static_cast<int>(n);
}

}  // namespace

int threads() {
  if (threads_ == 0) threads_ = default_threads();
  return threads_;
}

void set_threads(int n) {
  if (n < 1 || n > 1024) throw InputError(fmt::format("--threads {} is not allowed; allowed: 1 to 1024", n));
  threads_ = n;
}

}  // namespace softpack::parallel
