// Wall-clock and CPU time of a piece of work, for the provenance of every output (issue 13:
// "time where it goes"). CPU time is the process's (CLOCK_PROCESS_CPUTIME_ID): a stage is one
// single-threaded process, so it is the time the machine spent on it, whatever else runs.
#pragma once
#include <time.h>

#include <chrono>

namespace softpack {

/// A span of time: wall clock and CPU [s].
struct Elapsed {
  double wall = 0.0, cpu = 0.0;
  Elapsed& operator+=(const Elapsed& o) {
    wall += o.wall, cpu += o.cpu;
    return *this;
  }
  friend Elapsed operator+(Elapsed a, const Elapsed& b) { return a += b; }
  friend Elapsed operator-(const Elapsed& a, const Elapsed& b) { return {a.wall - b.wall, a.cpu - b.cpu}; }
};

/// The process's CPU time since it started [s].
inline double process_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Started when made: elapsed() since then, lap() since the previous lap (or the start).
class Stopwatch {
 public:
  Stopwatch() : start_(now()), lap_(start_) {}
  Elapsed elapsed() const { return now() - start_; }
  Elapsed lap() {
    const Elapsed t = now(), d = t - lap_;
    lap_ = t;
    return d;
  }

 private:
  static Elapsed now() {
    return {std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(), process_cpu_seconds()};
  }
  Elapsed start_, lap_;
};

}  // namespace softpack
