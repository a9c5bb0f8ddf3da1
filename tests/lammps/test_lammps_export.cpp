// softpack-coarse export --lammps (issue 34, docs/lammps.md, coarse/lammps_export.hpp): a medium of
// the sixth version's study exported with a short protocol (loading to 0.02, unloading 0.005, a
// platen shear of 0.01), run by LAMMPS on this test's ranks and read back, against the engine's
// compression of the same medium with the same settings. Exact where the two share the protocol:
// the rows, each row's strain, shear and solid fraction (from the walls' positions) to 1e-12, and
// the steps. σzz at the loaded rows to 1 % (measured: 3e-3): in these first increments few bodies
// touch, before the grains' contacts, LAMMPS's pair granular and fix wall/gran, part from the
// engine's Hertz–Mindlin by bench/lammps/README.md's remaining differences (the Coulomb cap, the
// branch lengths, the spring's frame) and the medium's chaos makes them two runs of one medium
// (make lammps-check judges those by the seeds' spread).
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "coarse/lammps_export.hpp"
#include "formats/law_file.hpp"
#include "host/styles.hpp"
#include "pair/lammps_headers.hpp"

namespace softpack {
namespace {

TEST(LammpsExport, TheCompressionInLammpsFollowsTheEngines) {
  const std::filesystem::path source = SOFTPACK_SOURCE_DIR, home = std::filesystem::current_path();
  std::filesystem::current_path(source);  // the settings name their profile and law file from the repository
  const std::string config = "data/many-body-v6/profiles/reference.yaml";
  CoarseGrainSettings s = read_coarse_grain_settings(config);
  s.strain = 0.02, s.unload_strain = 0.005, s.shear = 0.01, s.record_shear = 0.005;
  const MediumFile mf = read_medium_file("data/many-body-v6/reference/media/seed-327.h5");
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  char dir[256] = {};  // "" when rank 0's export failed: every rank stops (none waits for the others)
  if (rank == 0) {
    const std::string d = (std::filesystem::temp_directory_path() / ("softpack-lammps-export-" + std::to_string(::getpid()))).string();
    try {
      write_lammps_export(s, config, mf, d);
      d.copy(dir, sizeof(dir) - 1);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "the export: " << e.what();
    }
  }
  MPI_Bcast(dir, sizeof(dir), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (dir[0] == '\0') {
    std::filesystem::current_path(home);
    GTEST_FAIL() << "no export";
  }
  {
    std::filesystem::current_path(dir);
    const char* args[] = {"softpack-lammps", "-log", "log.lammps", "-screen", "none", "-nocite"};
    auto* lmp = new LAMMPS_NS::LAMMPS(6, const_cast<char**>(args), MPI_COMM_WORLD);
    lammps::register_styles(lmp);
    lmp->input->file("in.compression");
    delete lmp;
    std::filesystem::current_path(source);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) {
    int ranks = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const LammpsRun lammps = read_lammps_run(dir, s, mf);
    EXPECT_EQ(lammps.ranks, ranks);
    const SoftParticleLaws laws = soft_particle_laws(read_law_file(s.laws), s.laws);
    const CompressionRun engine = run_compression(medium_scene(s, mf.medium, CoarseModel::soft, laws), mf.medium, CoarseModel::soft, s);
    EXPECT_EQ(lammps.run.steps, engine.steps);
    ASSERT_EQ(lammps.run.rows.size(), engine.rows.size());
    int loaded = 0;
    for (std::size_t k = 0; k < engine.rows.size(); ++k) {
      const CurveRow &a = lammps.run.rows[k], &b = engine.rows[k];
      EXPECT_EQ(a.phase, b.phase) << "row " << k;
      EXPECT_NEAR(a.strain, b.strain, 1e-12) << "row " << k;
      EXPECT_NEAR(a.shear, b.shear, 1e-12) << "row " << k;
      EXPECT_NEAR(a.fraction, b.fraction, 1e-12) << "row " << k;
      if (b.phase == 1 && b.sigma_top > 0.0) {
        ++loaded;
        EXPECT_NEAR(a.sigma_top, b.sigma_top, 1e-2 * b.sigma_top) << "row " << k << " (strain " << b.strain << ")";
      }
    }
    EXPECT_EQ(loaded, 4);  // the four loading increments press the top wall
    std::filesystem::remove_all(dir);
  }
  std::filesystem::current_path(home);
}

}  // namespace
}  // namespace softpack
