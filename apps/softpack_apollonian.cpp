// softpack-apollonian: writes the 2D Apollonian gasket of Figure 1 as a plain-text data file
// (one circle per line: x y r generation) for figures/fig1_apollonian.gp.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"
#include "packing/apollonian.hpp"

namespace softpack::apps::apollonian_app {
namespace {
using Clock = std::chrono::steady_clock;

std::string header(const ApollonianOptions& o, const ApollonianPacking& p, double seconds) {
  const std::size_t n = p.circles.size() - 1;  // without the bounding circle
  std::string h = "# softpack-apollonian: 2D Apollonian gasket (Figure 1 of the paper)\n";
  h += fmt::format("# code_version: {}\n", code_version());
  h += fmt::format("# depth: {}\n", o.depth ? std::to_string(*o.depth) : "none");
  h += fmt::format("# min_radius: {}\n", o.min_radius ? fmt::format("{:g}", *o.min_radius) : "none");
  h += "# start: integral gasket (-1, 2, 2, 3): bounding circle r = 1 at (0, 0); r = 1/2 at (-1/2, 0) and (1/2, 0);"
       " r = 1/3 at (0, 2/3)\n";
  h += fmt::format("# circles: {} (without the bounding circle)\n", n);
  h += fmt::format("# per_generation: {}\n", fmt::join(p.per_generation, " "));
  h += fmt::format("# complete_above: {:.6g} (every circle of the full gasket larger than this is listed)\n",
                   p.complete_above);
  if (std::isnan(p.fit.d_f))
    h += fmt::format("# d_f: nan (complete only above r = {:.4g}, less than a decade below r = {:g}; depth-limited"
                     " packings leave the cusps unfilled: give --min-radius, e.g. 1e-3)\n",
                     p.complete_above, kFitLargestRadius);
  else
    h += fmt::format("# d_f: {:.4f} (least squares of log N(radius > r) vs log r, {} radii in [{:.4g}, {:.4g}];"
                     " known value {})\n",
                     p.fit.d_f, p.fit.points, p.fit.r_lo, p.fit.r_hi, kApollonianDimension);
  h += fmt::format("# seconds: {:.3f}\n", seconds);
  h += "# columns: x y r generation (generation -1: the bounding circle)\n";
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "softpack-apollonian: the 2D Apollonian gasket of Figure 1, built by the complex Descartes theorem from the\n"
      "integral gasket (-1, 2, 2, 3) inside a circle of radius 1, every gap filled down to --depth generations\n"
      "and/or circles of radius --min-radius. Writes 'x y r generation' per circle, largest first, with a '#'\n"
      "header (provenance, count per generation, fitted fractal dimension d_f of the size distribution)."};
  std::optional<int> depth;
  std::optional<double> min_radius;
  std::string out_path;
  app.add_option("--depth", depth,
                 fmt::format("last generation (0 = the three starting circles); 0..{} unless --min-radius is given",
                             kMaxDepthWithoutMinRadius));
  app.add_option("--min-radius", min_radius,
                 fmt::format("skip circles smaller than this (outer radius = 1); >= {:g}", kSmallestMinRadius));
  app.add_option("--out", out_path, "data file to write (atomically)")->required();
  if (const auto code = parse_command_line(app, argc, argv, "softpack-apollonian")) return *code;

  try {
    const auto start = Clock::now();
    const ApollonianOptions options{depth, min_radius};
    const ApollonianPacking packing = apollonian_gasket(options);
    std::string body;
    body.reserve(packing.circles.size() * 64);
    for (const auto& c : packing.circles) body += fmt::format("{} {} {} {}\n", c.x, c.y, c.r, c.generation);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    write_file_atomically(out_path, header(options, packing, seconds) + body);
    fmt::print(stderr, "softpack-apollonian: {} circles, d_f = {:.4f}, {}\n", packing.circles.size() - 1,
               packing.fit.d_f, out_path);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-apollonian");
  }
}

}  // namespace softpack::apps::apollonian_app
