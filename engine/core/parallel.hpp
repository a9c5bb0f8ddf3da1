// Threads: the engine's one use of OpenMP (Debian's libgomp). Work is cut into blocks whose
// number and bounds depend on the data only, never on the thread count, and every sum across
// blocks is made afterwards in a fixed order (forces/contact_loop.hpp): the result bits are the
// same for any number of threads (ResultBits.TheSameBitsForAnyThreadCount).
//
// The count: set_threads(), else the environment's SOFTPACK_THREADS, else 1. One is the default
// while the threaded sums cost more than the threads gain: on the 2-core machine of the issue, 2
// threads ran the 48 000-sphere coarse-grain medium 0.9 times as fast as one (issue 32: the sums
// read each sphere's contacts out of order until the spheres are sorted in space). A build
// without OpenMP runs every block on the calling thread.
#pragma once
#include <cstddef>

namespace softpack::parallel {

/// The threads the engine uses, >= 1: set_threads()'s, else SOFTPACK_THREADS (InputError when it
/// is not a whole number from 1 to 1024), else 1.
int threads();
/// Sets them (>= 1; InputError otherwise).
void set_threads(int n);
/// True when for_each_block(blocks, ...) runs the blocks on the calling thread, in order.
inline bool serial(std::size_t blocks) { return blocks <= 1 || threads() == 1; }

/// body(b) for b in [0, blocks), on threads() threads, each block on one thread; returns when
/// all are done. The body must not throw.
template <class Body>
void for_each_block(std::size_t blocks, Body&& body) {
  if (serial(blocks)) {
    for (std::size_t b = 0; b < blocks; ++b) body(b);
    return;
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads())
#endif
  for (std::size_t b = 0; b < blocks; ++b) body(b);
}

}  // namespace softpack::parallel
