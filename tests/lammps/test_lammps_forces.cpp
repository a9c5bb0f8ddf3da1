// softpack-lammps against softpack's engine on a frozen configuration (issue 34, item 3a): a row of
// soft-particles pressing each other and grains pressing them, with random velocities (the normal
// damping), the forces computed once by the engine (Simulation's F(t0)) and once by LAMMPS with the
// pair style softpack/soft, on the ranks this test is started on (mpirun -np 1, 2, 3): every body's
// force equal to 1e-10 of the largest, the pairs that straddle two ranks included.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/law_file.hpp"
#include "host/styles.hpp"
#include "pair/lammps_headers.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

constexpr double kRelative = 1e-10;

struct Frozen {
  SceneDef scene;
  int soft = 0;
};

// Soft-particles of the law file's reference radius in a row along x, each pressing the next at
// Δn 0.22-0.40 (above the soft-soft onset), grains of 4-6 mm pressing them at Δn 0.11-0.30 (the
// soft-solid law, `wall` rule) in random directions, no two grains touching; random velocities.
Frozen frozen_configuration(const SoftParticleLaws& laws) {
  Frozen f;
  SceneDef& s = f.scene;
  s = testing::basic_scene();
  s.effects.restitution = 0.5;
  s.effects.soft_particles = SoftParticlesDef{laws, GrainContactRule::wall, SoftParticlesDef::BeyondRange::report};
  testing::Random rng(3401);
  const double R = laws.R0;
  double x = 0.0;
  for (int k = 0; k < 6; ++k) {
    ParticleDef p;
    p.x = Vec3(x, 0.002 * rng.uniform(-1, 1), 0.002 * rng.uniform(-1, 1));
    p.r = R, p.soft = true, p.mass = 0.02 * rng.uniform(0.8, 1.2);
    p.v = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 1e-3;
    s.particles.push_back(p);
    x += R * (2.0 - rng.uniform(0.22, 0.40));
  }
  f.soft = static_cast<int>(s.particles.size());
  for (int tries = 0; tries < 4000 && s.particles.size() < 40; ++tries) {
    const ParticleDef& host = s.particles[std::min(static_cast<std::size_t>(rng.uniform() * f.soft), static_cast<std::size_t>(f.soft - 1))];
    Vec3 u(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (!(u.norm() > 0.1 && u.norm() < 1.0)) continue;
    u.normalize();
    ParticleDef g;
    g.r = rng.uniform(0.004, 0.006);
    g.x = host.x + u * (host.r + g.r - rng.uniform(0.11, 0.30) * R);
    bool free = true;
    for (std::size_t k = static_cast<std::size_t>(f.soft); k < s.particles.size(); ++k)
      free = free && (s.particles[k].x - g.x).norm() > s.particles[k].r + g.r + 1e-4;
    if (!free) continue;
    g.mass = 2500.0 * 4.0 / 3.0 * 3.14159 * g.r * g.r * g.r;
    g.v = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 1e-3;
    s.particles.push_back(g);
  }
  return f;
}

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

TEST(LammpsPair, EveryBodysForceIsTheEnginesOnAnyNumberOfRanks) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const std::string law_path = std::string(SOFTPACK_SOURCE_DIR) + "/data/radius/report/laws.json";
  const SoftParticleLaws laws = soft_particle_laws(read_law_file(law_path), law_path);
  const Frozen f = frozen_configuration(laws);
  const std::size_t n = f.scene.particles.size();
  ASSERT_GT(n, 20u);

  // The engine.
  Simulation sim(f.scene);
  std::vector<Vec3> engine(sim.particles().F.begin(), sim.particles().F.end());

  // LAMMPS: the same bodies, read from a data file rank 0 writes (type 1 soft, 2 grain).
  int id = static_cast<int>(::getpid());  // rank 0's, so that every rank names the same folder
  MPI_Bcast(&id, 1, MPI_INT, 0, MPI_COMM_WORLD);
  const std::string dir = (std::filesystem::temp_directory_path() / ("softpack-lammps-" + std::to_string(id))).string();
  const std::string data = dir + "/frozen-" + std::to_string(ranks) + ".data";
  if (rank == 0) {
    std::filesystem::create_directories(dir);
    std::ofstream out(data);
    out << "softpack frozen configuration\n\n" << n << " atoms\n2 atom types\n-0.05 0.20 xlo xhi\n-0.05 0.05 ylo yhi\n-0.05 0.05 zlo zhi\n\nAtoms # sphere\n\n";
    for (std::size_t i = 0; i < n; ++i) {
      const ParticleDef& p = f.scene.particles[i];
      out << i + 1 << " " << (p.soft ? 1 : 2) << " " << number(2.0 * p.r) << " 1000 " << number(p.x.x()) << " " << number(p.x.y()) << " "
          << number(p.x.z()) << "\n";
    }
    out << "\nVelocities\n\n";
    for (std::size_t i = 0; i < n; ++i) {
      const ParticleDef& p = f.scene.particles[i];
      out << i + 1 << " " << number(p.v.x()) << " " << number(p.v.y()) << " " << number(p.v.z()) << " 0 0 0\n";
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const char* args[] = {"softpack-lammps", "-log", "none", "-screen", "none", "-nocite"};
  auto* lmp = new LAMMPS_NS::LAMMPS(6, const_cast<char**>(args), MPI_COMM_WORLD);
  lammps::register_styles(lmp);
  const std::vector<std::string> commands = {
      "units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes", "read_data " + data,
      "pair_style hybrid softpack/soft " + law_path + " restitution 0.5", "pair_coeff 1 1 softpack/soft soft soft",
      "pair_coeff 1 2 softpack/soft soft grain", "pair_coeff 2 2 none", "neighbor 0.001 bin", "timestep 1e-6"};
  for (const std::string& c : commands) lmp->input->one(c);
  for (std::size_t i = 0; i < n; ++i) lmp->input->one("set atom " + std::to_string(i + 1) + " mass " + number(*f.scene.particles[i].mass));
  lmp->input->one("run 0");
  std::vector<double> F(3 * n);
  lammps_gather_atoms(lmp, const_cast<char*>("f"), 1, 3, F.data());

  // Pairs of bodies on two ranks (each body's owner by its sub-box along the split axes).
  const auto owner_of = [&](const Vec3& x) {
    int mine = 1;
    for (int a = 0; a < 3; ++a) mine = mine && x[a] >= lmp->domain->sublo[a] && x[a] < lmp->domain->subhi[a];
    return mine;
  };
  int straddling = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const ParticleDef &a = f.scene.particles[i], &b = f.scene.particles[j];
      if ((a.x - b.x).norm() >= a.r + b.r || !(a.soft || b.soft)) continue;
      straddling += owner_of(a.x) != owner_of(b.x);
    }
  int all_straddling = 0;
  MPI_Allreduce(&straddling, &all_straddling, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  delete lmp;
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) std::filesystem::remove_all(dir);
  if (ranks > 1) {
    EXPECT_GT(all_straddling, 0) << "no contact crosses a rank boundary";
  }

  double largest = 0.0;
  for (const Vec3& e : engine) largest = std::max(largest, e.norm());
  ASSERT_GT(largest, 0.0);
  int loaded = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 lmp_F(F[3 * i], F[3 * i + 1], F[3 * i + 2]);
    EXPECT_LE((lmp_F - engine[i]).norm(), kRelative * largest) << "body " << i << " (" << (f.scene.particles[i].soft ? "soft" : "grain")
                                                              << "): LAMMPS " << lmp_F.transpose() << ", engine " << engine[i].transpose();
    loaded += engine[i].norm() > 1e-3 * largest;
  }
  EXPECT_GT(loaded, static_cast<int>(n) / 2) << "most bodies should be pressed";
}

}  // namespace
}  // namespace softpack

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) delete ::testing::UnitTest::GetInstance()->listeners().Release(::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int failed = RUN_ALL_TESTS();
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any;
}
