#include "core/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace softpack::parallel {
namespace {

int threads_ = 0;  // 0: not yet decided
bool asked_ = false;

// Under make -jN with N > 1 (MAKEFLAGS holds -jN, -j or the jobserver): the jobs share the cores.
bool under_parallel_make() {
  const char* flags = std::getenv("MAKEFLAGS");
  if (flags == nullptr) return false;
  std::istringstream words{std::string(flags)};
  for (std::string w; words >> w;) {
    if (w.rfind("--jobserver", 0) == 0) return true;
    if (w.rfind("-j", 0) == 0) return w != "-j1";
  }
  return false;
}

int cores() {
#ifdef _OPENMP
  // The processors this process may run on (its affinity), or fewer when OMP_NUM_THREADS says so.
  return std::min(omp_get_num_procs(), omp_get_max_threads());
#else
  return 1;
#endif
}

int default_threads() {
  const char* env = std::getenv("SOFTPACK_THREADS");
  if (env == nullptr || *env == '\0') return under_parallel_make() ? 1 : std::max(1, std::min(cores(), 1024));
  char* end = nullptr;
  const long n = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || n < 1 || n > 1024)
    throw InputError(fmt::format("SOFTPACK_THREADS = '{}' is not allowed; allowed: a whole number of threads from 1 to 1024", env));
  asked_ = true;
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
  asked_ = true;
}

int threads_for(std::size_t spheres) {
  const int n = threads();
  if (asked_ || n == 1) return n;
  const std::size_t most = std::max<std::size_t>(1, spheres / kSpheresPerThread);
  return most < static_cast<std::size_t>(n) ? static_cast<int>(most) : n;
}

}  // namespace softpack::parallel
