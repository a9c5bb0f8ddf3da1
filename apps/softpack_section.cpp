// softpack-section: the central cross-section of a packing, for the paper's Figure 2. Writes,
// for every sphere the plane z = offset cuts, the circle of the cut (x, y, radius), true to
// scale, plus the shell's circle in the header; gnuplot draws it (figures/fig2_softparticle.gp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>

#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/packing_file.hpp"
#include "io/atomic_file.hpp"

namespace softpack::apps::section_app {

int main(int argc, char** argv) {
  CLI::App app{"softpack-section: circles cut from a packing by the plane z = offset (Figure 2)"};
  std::string packing_path, out_path;
  double offset = 0.0;
  app.add_option("--packing", packing_path, "packing file (HDF5) written by softpack-pack")->required();
  app.add_option("--out", out_path, "data file: columns x y r [m] of the cut circles")->required();
  app.add_option("--offset", offset, "height of the cutting plane above the shell centre [m]");
  if (const auto code = parse_command_line(app, argc, argv, "softpack-section")) return *code;
  try {
    const PackingFile pk = read_packing_file(packing_path);
    if (!(std::abs(offset) < pk.Rs))
      throw InputError(fmt::format("--offset: {} m is not allowed; allowed: |offset| < Rs = {} m", offset, pk.Rs));
    std::string text = fmt::format(
        "# softpack-section {}: plane z = {} m through the packing {} (seed {}, {} spheres)\n"
        "# shell: centre (0, 0), radius of the cut {:.17g} m\n"
        "# columns: x [m]  y [m]  r [m] of each circle cut from a sphere\n",
        code_version(), offset, packing_path, pk.provenance.seed, pk.radii.size(),
        std::sqrt(pk.Rs * pk.Rs - offset * offset));
    std::size_t cut = 0;
    for (std::size_t i = 0; i < pk.radii.size(); ++i) {
      const double dz = pk.centres[i].z() - offset, r = pk.radii[i];
      if (std::abs(dz) >= r) continue;
      text += fmt::format("{:.17g} {:.17g} {:.17g}\n", pk.centres[i].x(), pk.centres[i].y(), std::sqrt(r * r - dz * dz));
      ++cut;
    }
    write_file_atomically(out_path, text);
    fmt::print(stderr, "softpack-section: {} of {} spheres cut by z = {} m -> {}\n", cut, pk.radii.size(), offset, out_path);
    return 0;
  } catch (...) {
    return exit_on_error("softpack-section");
  }
}

}  // namespace softpack::apps::section_app
