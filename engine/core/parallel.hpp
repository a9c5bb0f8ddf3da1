// Threads: the engine's one use of OpenMP (Debian's libgomp). Work is cut in blocks or in shares
// of the spheres, and every sum is made by one thread in a fixed order (forces/pair_contacts.hpp):
// the result bits are the same for any number of threads (ResultBits.TheSameBitsForAnyThreadCount).
// A share [n t / T, n (t + 1) / T) of the spheres goes to thread t at every stage (integration,
// forces), so that a thread finds its spheres in its own cache: on the 2-vCPU machine of the
// issue a cache line takes about 0.24 us from one core to the other and a parallel region costs
// about 5 us, a barrier inside one about 1.7 us.
//
// The count: set_threads() (a command's --threads), else the environment's SOFTPACK_THREADS, as
// asked; else the default, the cores the process may use, but one thread per kSpheresPerThread
// spheres at most (threads_for) and one under a parallel make (make -jN, N > 1: its jobs share
// the cores already). A build without OpenMP runs everything on the calling thread.
#pragma once
#include <cstddef>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace softpack::parallel {

/// The threads the engine may use, >= 1: set_threads()'s, else SOFTPACK_THREADS (InputError when
/// it is not a whole number from 1 to 1024), else the cores this process may use (1 under a
/// parallel make).
int threads();
/// A default thread has at least this many spheres: on the 2-core machine of issue 32 two threads
/// ran slower than one on make bench's 1 600- and 5 000-sphere scenes and faster on the 48 000-sphere
/// coarse-grain medium (the same bits for any count).
inline constexpr std::size_t kSpheresPerThread = 8000;
/// The threads a world of `spheres` spheres runs on: threads() when asked for, else no more than
/// one per kSpheresPerThread spheres. Every stage of a world uses this count.
int threads_for(std::size_t spheres);
/// Sets them (>= 1; InputError otherwise).
void set_threads(int n);
/// True when for_each_block(blocks, ...) runs the blocks on the calling thread, in order.
inline bool serial(std::size_t blocks) { return blocks <= 1 || threads() == 1; }
/// The threads for_each_block(blocks, ...) runs on.
inline int block_threads(std::size_t blocks) { return blocks < static_cast<std::size_t>(threads()) ? static_cast<int>(blocks) : threads(); }

/// body(b) for b in [0, blocks), on threads() threads, each block on one thread; returns when
/// all are done. The body must not throw.
template <class Body>
void for_each_block(std::size_t blocks, Body&& body) {
  if (serial(blocks)) {
    for (std::size_t b = 0; b < blocks; ++b) body(b);
    return;
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(block_threads(blocks))
#endif
  for (std::size_t b = 0; b < blocks; ++b) body(b);
}

/// phase(t) for t in [0, parts) of each phase in turn, on `parts` threads in one parallel region,
/// share t on thread t (as for_each_block with `parts` blocks): every thread ends a phase before
/// any starts the next. The phases must not throw.
template <class... Phase>
void run_phases(std::size_t parts, Phase&&... phase) {
  const auto one_by_one = [&] { (..., [&] { for (std::size_t t = 0; t < parts; ++t) phase(t); }()); };
  if (parts <= 1 || threads() == 1) return one_by_one();
#ifdef _OPENMP
#pragma omp parallel num_threads(static_cast<int>(parts))
  {
    if (static_cast<std::size_t>(omp_get_num_threads()) == parts) {
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
      bool first = true;
      (..., [&] {
        if (!first) {
#pragma omp barrier
        }
        first = false;
        phase(t);
      }());
    } else if (omp_get_thread_num() == 0) {
      one_by_one();  // fewer threads than asked for: the shares on one
    }
  }
#else
  one_by_one();
#endif
}

/// Where share t of [0, n) cut in `parts` begins (share t ends where t + 1 begins).
inline std::size_t share_begin(std::size_t n, std::size_t t, std::size_t parts) { return n * t / parts; }

/// body(begin, end) over [0, n) cut in threads_for(n) nearly equal shares, [n t / T, n (t + 1) / T) on
/// thread t: the static schedule gives share t to the same thread at every call, so that the
/// stages of a step (integration, forces, sums) find their spheres in that thread's cache.
/// Only for work whose result does not depend on the cut (each item on its own, or sums made in
/// a fixed order per item).
template <class Body>
void for_each_share(std::size_t n, Body&& body) {
  const auto parts = static_cast<std::size_t>(threads_for(n));
  for_each_block(parts, [&](std::size_t t) { body(share_begin(n, t, parts), share_begin(n, t + 1, parts)); });
}

}  // namespace softpack::parallel
