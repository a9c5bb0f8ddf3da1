// What softpack-coarse's commands share when they read a medium (apps/softpack_coarse.cpp run,
// apps/coarse_estimate_cli.hpp estimate): the progress lines' ends on a terminal or in a log, and
// the medium read for its settings with its sites' contents made (nested soft-particles: minutes at
// two levels, so each site made is a line with the time left).
#pragma once
#include <fmt/format.h>
#include <unistd.h>

#include <string>

#include "coarse/medium_file.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"

namespace softpack::apps::coarse_app {

/// A progress line rewritten in place on a terminal, one line each in a log.
struct Lines {
  bool tty = ::isatty(STDERR_FILENO) != 0;
  const char* cr() const { return tty ? "\r\033[K" : ""; }
  const char* nl() const { return tty ? "" : "\n"; }
};

/// The medium of `mf` for settings `s` (read from `config`), its sites' contents made from their
/// seeds (medium_contents); InputError when the medium was made with other settings. `what` names
/// the command and seed in the progress lines.
inline Medium medium_with_contents(const CoarseGrainSettings& s, const std::string& config, const MediumFile& mf, const std::string& path,
                                   const std::string& what, bool quiet) {
  if (mf.settings != s.medium_text)
    throw InputError(fmt::format("{}: made with other settings than {} (rerun softpack-coarse medium)", path, config));
  Medium m = mf.medium;
  const Lines l;
  const Stopwatch clock;
  medium_contents(s, m, [&](std::size_t done, std::size_t sites) {
    if (quiet) return;
    const double t = clock.elapsed().wall;
    fmt::print(stderr, "{}{}: contents of site {} of {} made ({:.0f} s, ETA {:.0f} s){}", l.cr(), what, done, sites, t,
               t / static_cast<double>(done) * static_cast<double>(sites - done), l.nl());
  });
  if (!quiet && !m.contents.empty() && l.tty) fmt::print(stderr, "\n");  // ends the line the progress rewrote
  return m;
}

}  // namespace softpack::apps::coarse_app
