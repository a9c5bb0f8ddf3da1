// softpack-lammps against softpack's engine (issue 34, item 3a): a row of soft-particles pressing each
// other, grains pressing them and two walls (fix softpack/wall, the ceiling moving down) pressing
// the row, with random velocities and spins, friction and rotation on, run
// by the engine and by LAMMPS (pair style softpack/soft, fix nve/sphere) on the ranks this test is
// started on (mpirun -np 1, 2, 3): at the start every body's force and torque equal the engine's to
// 1e-10 of the largest, contacts across a rank boundary included; after steps in which bodies
// change rank (fix balance moves the cuts mid-run, the springs travel with them), positions,
// velocities, spins, forces, torques and the walls' loads stay the engine's to 1e-12. Both with the pairwise laws
// and with the many-body law (its per-body states and stress tensors summed across ranks).
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "formats/law_file.hpp"
#include "host/styles.hpp"
#include "pair/lammps_headers.hpp"
#include "sim/simulation.hpp"
#include "support/scenes.hpp"

namespace softpack {
namespace {

// After the steps: the two programs' roundings apart, their sums in other orders (measured with
// SOFTPACK_LAMMPS_DIFFERENCES=1: at most 3e-13 of the largest value, both laws, 1 to 3 ranks).
constexpr double kMotion = 1e-12;

constexpr double kWall = 0.012, kCeilingSpeed = 0.01;  // [m], [m/s]

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
  s.effects.friction = true;
  s.effects.rotation = true;
  s.effects.soft_particles = SoftParticlesDef{laws, GrainContactRule::wall, SoftParticlesDef::BeyondRange::report};
  testing::Random rng(3401);
  const double R = laws.R0;
  double x = 0.0;
  for (int k = 0; k < 6; ++k) {
    ParticleDef p;
    p.x = Vec3(x, 0.002 * rng.uniform(-1, 1), 0.002 * rng.uniform(-1, 1));
    p.r = R, p.soft = true, p.mass = 0.02 * rng.uniform(0.8, 1.2);
    p.v = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 1e-3;
    p.w = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 0.05;
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
    if (std::abs(g.x.z()) + g.r > kWall - 3e-3) continue;  // grains away from the walls (solid grains meet LAMMPS's own)
    bool free = true;
    for (std::size_t k = static_cast<std::size_t>(f.soft); k < s.particles.size(); ++k)
      free = free && (s.particles[k].x - g.x).norm() > s.particles[k].r + g.r + 2e-3;  // apart: no two grains meet in the steps (LAMMPS leaves them to pair granular)
    if (!free) continue;
    g.mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * g.r * g.r * g.r;
    g.v = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 1e-3;
    g.w = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 0.2;
    s.particles.push_back(g);
  }
  // A floor and a ceiling pressing the row (Δn 0.1-0.4), the ceiling moving down.
  s.planes = {PlaneDef{"floor", Vec3(0, 0, -kWall), Vec3::UnitZ(), 0}, PlaneDef{"ceiling", Vec3(0, 0, kWall), -Vec3::UnitZ(), 0}};
  if (kCeilingSpeed > 0.0) s.drivers = {MoveWallDef{"ceiling", Vec3(0, 0, -kCeilingSpeed), 0.01, std::nullopt}};
  return f;
}

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

struct State {
  std::vector<Vec3> x, v, w, F, T;
};

State engine_state(const Simulation& sim) {
  const auto& p = sim.particles();
  return {{p.x.begin(), p.x.end()}, {p.v.begin(), p.v.end()}, {p.w.begin(), p.w.end()}, {p.F.begin(), p.F.end()}, {p.T.begin(), p.T.end()}};
}

std::vector<Vec3> gathered(LAMMPS_NS::LAMMPS* lmp, const char* name, std::size_t n) {
  std::vector<double> raw(3 * n);
  lammps_gather_atoms(lmp, const_cast<char*>(name), 1, 3, raw.data());
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec3(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
  return out;
}

State lammps_state(LAMMPS_NS::LAMMPS* lmp, std::size_t n) {
  return {gathered(lmp, "x", n), gathered(lmp, "v", n), gathered(lmp, "omega", n), gathered(lmp, "f", n), gathered(lmp, "torque", n)};
}

// The force on each wall (floor, ceiling) [N].
std::vector<Vec3> engine_loads(const Simulation& s) { return {s.plane_loads()[0].force, s.plane_loads()[1].force}; }

double largest(const std::vector<Vec3>& a) {
  double m = 0.0;
  for (const Vec3& e : a) m = std::max(m, e.norm());
  return m;
}

// |a_i - b_i| <= tolerance * max |b| for every body; the largest ratio found, for the message.
void expect_close(const std::vector<Vec3>& lmp, const std::vector<Vec3>& engine, double tolerance, const std::string& what) {
  const double scale = largest(engine);
  ASSERT_GT(scale, 0.0) << what;
  double worst = 0.0;
  for (std::size_t i = 0; i < engine.size(); ++i) worst = std::max(worst, (lmp[i] - engine[i]).norm() / scale);
  EXPECT_LE(worst, tolerance) << what << ": the largest difference is " << worst << " of the largest value";
  if (std::getenv("SOFTPACK_LAMMPS_DIFFERENCES")) std::printf("%s: %.2e\n", what.c_str(), worst);

}

// The bodies' owners: this rank's tags.
std::vector<LAMMPS_NS::tagint> local_tags(LAMMPS_NS::LAMMPS* lmp) { return {lmp->atom->tag, lmp->atom->tag + lmp->atom->nlocal}; }

// A folder all ranks share (rank 0's pid), removed at the end.
struct Scratch {
  std::string dir;
  Scratch() {
    int id = static_cast<int>(::getpid());
    MPI_Bcast(&id, 1, MPI_INT, 0, MPI_COMM_WORLD);
    dir = (std::filesystem::temp_directory_path() / ("softpack-lammps-" + std::to_string(id))).string();
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::filesystem::create_directories(dir);
    MPI_Barrier(MPI_COMM_WORLD);
  }
  ~Scratch() {
    MPI_Barrier(MPI_COMM_WORLD);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::filesystem::remove_all(dir);
  }
};

// The bodies as a LAMMPS data file (type 1 soft, 2 grain), written by rank 0.
std::string write_data(const Frozen& f, const std::string& dir) {
  const std::string data = dir + "/frozen.data";
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    std::ofstream out(data);
    out << "softpack frozen configuration\n\n" << f.scene.particles.size()
        << " atoms\n2 atom types\n-0.05 0.20 xlo xhi\n-0.05 0.05 ylo yhi\n-0.05 0.05 zlo zhi\n\nAtoms # sphere\n\n";
    for (std::size_t i = 0; i < f.scene.particles.size(); ++i) {
      const ParticleDef& p = f.scene.particles[i];
      out << i + 1 << " " << (p.soft ? 1 : 2) << " " << number(2.0 * p.r) << " 1000 " << number(p.x.x()) << " " << number(p.x.y()) << " "
          << number(p.x.z()) << "\n";
    }
    out << "\nVelocities\n\n";
    for (std::size_t i = 0; i < f.scene.particles.size(); ++i) {
      const ParticleDef& p = f.scene.particles[i];
      out << i + 1 << " " << number(p.v.x()) << " " << number(p.v.y()) << " " << number(p.v.z()) << " " << number(p.w.x()) << " "
          << number(p.w.y()) << " " << number(p.w.z()) << "\n";
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return data;
}

LAMMPS_NS::LAMMPS* start_lammps(const std::vector<std::string>& commands) {
  const char* args[] = {"softpack-lammps", "-log", "none", "-screen", std::getenv("SOFTPACK_LAMMPS_SCREEN") ? "/dev/stdout" : "none", "-nocite"};
  auto* lmp = new LAMMPS_NS::LAMMPS(6, const_cast<char**>(args), MPI_COMM_WORLD);
  lammps::register_styles(lmp);
  for (const std::string& c : commands) lmp->input->one(c);
  return lmp;
}

// The box and bodies from the data file, with the engine's masses and step.
std::vector<std::string> data_commands(const std::string& data, const Frozen& f, double dt) {
  std::vector<std::string> c = {"units si", "atom_style sphere", "atom_modify map array", "boundary m m m", "newton off", "read_data " + data,
                                "timestep " + number(dt)};
  for (std::size_t i = 0; i < f.scene.particles.size(); ++i) c.push_back("set atom " + std::to_string(i + 1) + " mass " + number(*f.scene.particles[i].mass));
  return c;
}

// What a restart file does not carry: the styles, the integrator, the walls (which take their state
// from it), the neighbour and communication settings.
std::vector<std::string> model_commands(const std::string& law_path) {
  return {"comm_modify vel yes", "pair_style hybrid softpack/soft " + law_path + " restitution 0.5", "pair_coeff 1 1 softpack/soft soft soft",
          "pair_coeff 1 2 softpack/soft soft grain", "pair_coeff 2 2 none", "neighbor 0.001 bin", "neigh_modify every 1 delay 0 check yes",
          "fix move all nve/sphere", "fix floor all softpack/wall z lo " + number(-kWall),
          "fix ceiling all softpack/wall z hi " + number(kWall) + " velocity 0 0 " + number(-kCeilingSpeed)};
}

// The pairwise laws (data/radius/report/laws.json) and the many-body law's sixth version, with its
// union of caps and its soft-soft stress term (data/many-body/report/laws-v6.json).
class LammpsPair : public ::testing::TestWithParam<const char*> {};

TEST_P(LammpsPair, ForcesTorquesAndMotionAreTheEnginesOnAnyNumberOfRanks) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const std::string law_path = std::string(SOFTPACK_SOURCE_DIR) + "/" + GetParam();
  const SoftParticleLaws laws = soft_particle_laws(read_law_file(law_path), law_path);
  const Frozen f = frozen_configuration(laws);
  const std::size_t n = f.scene.particles.size();
  ASSERT_GT(n, 20u);
  // Steps before any grain meets another grain or a wall (the walls squeeze grains out: near step
  // 18 one reaches the floor in the engine, whose Hertz law LAMMPS leaves to its own styles).
  constexpr long kSteps = 15;

  // The engine: F(t0), then kSteps steps.
  Simulation sim(f.scene);
  const State engine0 = engine_state(sim);
  const std::vector<Vec3> engine_walls0 = engine_loads(sim);
  sim.run_steps(kSteps);
  const State engine1 = engine_state(sim);
  const std::vector<Vec3> engine_walls1 = engine_loads(sim);

  // LAMMPS: the same bodies, read from a data file rank 0 writes (type 1 soft, 2 grain).
  const Scratch scratch;
  const std::string data = write_data(f, scratch.dir);
  auto* lmp = start_lammps(data_commands(data, f, sim.dt()));
  for (const std::string& c : model_commands(law_path)) lmp->input->one(c);
  const auto wall_loads = [&] {
    std::vector<Vec3> out;
    for (const char* name : {"floor", "ceiling"}) {
      LAMMPS_NS::Fix* fix = lmp->modify->fix[lmp->modify->find_fix(name)];
      out.emplace_back(fix->compute_vector(0), fix->compute_vector(1), fix->compute_vector(2));
    }
    return out;
  };
  lmp->input->one("run 0");
  const State lammps0 = lammps_state(lmp, n);
  const std::vector<Vec3> lammps_walls0 = wall_loads();

  // Contacts whose two bodies are on two ranks, at the start.
  const auto owned = [&](const Vec3& x) {
    bool mine = true;
    for (int a = 0; a < 3; ++a) mine = mine && x[a] >= lmp->domain->sublo[a] && x[a] < lmp->domain->subhi[a];
    return mine;
  };
  int straddling = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const ParticleDef &a = f.scene.particles[i], &b = f.scene.particles[j];
      if ((a.x - b.x).norm() < a.r + b.r && (a.soft || b.soft) && owned(a.x) && !owned(b.x)) ++straddling;
    }
  // The steps, the cuts between ranks moved every 5 steps (fix balance): bodies change rank, with
  // their springs.
  const std::vector<LAMMPS_NS::tagint> before = local_tags(lmp);
  if (ranks > 1) {  // weights that grow with x and with the step: the cuts move left at every balance
    lmp->input->one("variable weight atom 1.0+step*(x+0.05)*20.0");
    lmp->input->one("fix even all balance 5 1.0 shift x 20 1.0 weight var weight");
  }
  lmp->input->one("run " + std::to_string(kSteps));
  const std::vector<LAMMPS_NS::tagint> after = local_tags(lmp);
  int left = 0;
  for (LAMMPS_NS::tagint t : before) left += std::find(after.begin(), after.end(), t) == after.end();
  const State lammps1 = lammps_state(lmp, n);
  const std::vector<Vec3> lammps_walls1 = wall_loads();
  int all_straddling = 0, all_left = 0;
  MPI_Allreduce(&straddling, &all_straddling, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&left, &all_left, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  delete lmp;
  if (ranks > 1) {
    EXPECT_GT(all_straddling, 0) << "no contact crosses a rank boundary";
    EXPECT_GT(all_left, 0) << "no body changed rank";
  }

  expect_close(lammps0.F, engine0.F, 1e-10, "F at the start");
  expect_close(lammps0.T, engine0.T, 1e-10, "T at the start");
  expect_close(lammps_walls0, engine_walls0, 1e-10, "the walls' loads at the start");
  EXPECT_GT(std::min(engine_walls0[0].norm(), engine_walls0[1].norm()), 0.0) << "both walls should be pressed";
  int loaded = 0;
  for (const Vec3& e : engine0.F) loaded += e.norm() > 1e-3 * largest(engine0.F);
  EXPECT_GT(loaded, static_cast<int>(n) / 2) << "most bodies should be pressed";
  // After the steps: the displacements, velocities, spins, forces and torques.
  std::vector<Vec3> moved_lmp(n), moved_engine(n);
  for (std::size_t i = 0; i < n; ++i) moved_lmp[i] = lammps1.x[i] - f.scene.particles[i].x, moved_engine[i] = engine1.x[i] - f.scene.particles[i].x;
  expect_close(moved_lmp, moved_engine, kMotion, "displacement after the steps");
  expect_close(lammps1.v, engine1.v, kMotion, "v after the steps");
  expect_close(lammps1.w, engine1.w, kMotion, "w after the steps");
  expect_close(lammps1.F, engine1.F, kMotion, "F after the steps");
  expect_close(lammps1.T, engine1.T, kMotion, "T after the steps");
  expect_close(lammps_walls1, engine_walls1, kMotion, "the walls' loads after the steps");
}

INSTANTIATE_TEST_SUITE_P(LawFiles, LammpsPair, ::testing::Values("data/radius/report/laws.json", "data/many-body/report/laws-v6.json"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return p.index == 0 ? "Pairwise" : "ManyBodyV6"; });

// A second run, and a run from a restart file, continue the first (pair/soft_history.hpp): the
// steps split 4 + 6 as one run, as two runs, and as a run, write_restart, and a new LAMMPS that
// reads it and runs on, end in the same state to 1e-12 (without the continuation a run's setup
// recomputes the forces with full-step velocities: a percent apart after a few steps).
TEST(LammpsPair, ASecondRunAndARestartContinueTheFirst) {
  const std::string law_path = std::string(SOFTPACK_SOURCE_DIR) + "/data/radius/report/laws.json";
  const Frozen f = frozen_configuration(soft_particle_laws(read_law_file(law_path), law_path));
  const std::size_t n = f.scene.particles.size();
  const double dt = Simulation(f.scene).dt();
  const Scratch scratch;
  const std::string data = write_data(f, scratch.dir), restart = scratch.dir + "/mid.restart";
  const auto finish = [&](LAMMPS_NS::LAMMPS* lmp) {  // the state, the walls' loads as T's last rows
    State s = lammps_state(lmp, n);
    for (const char* name : {"floor", "ceiling"}) {
      LAMMPS_NS::Fix* fix = lmp->modify->fix[lmp->modify->find_fix(name)];
      s.T.emplace_back(fix->compute_vector(0), fix->compute_vector(1), fix->compute_vector(2));
    }
    delete lmp;
    return s;
  };
  const auto session = [&](const std::vector<std::string>& runs) {
    auto* lmp = start_lammps(data_commands(data, f, dt));
    for (const std::string& c : model_commands(law_path)) lmp->input->one(c);
    for (const std::string& c : runs) lmp->input->one(c);
    return finish(lmp);
  };
  const State one = session({"run 10"}), two = session({"run 4", "run 6"});
  session({"run 4", "write_restart " + restart});
  auto* lmp = start_lammps({"units si", "atom_modify map array", "read_restart " + restart, "newton off off"});  // pair's newton is not in the file
  for (const std::string& c : model_commands(law_path)) lmp->input->one(c);
  lmp->input->one("run 6");
  const State restarted = finish(lmp);
  for (const auto& [name, s] : {std::pair<const char*, const State&>{"two runs", two}, {"a restart", restarted}}) {
    expect_close(s.x, one.x, 1e-12, std::string(name) + ": x");
    expect_close(s.v, one.v, 1e-12, std::string(name) + ": v");
    expect_close(s.w, one.w, 1e-12, std::string(name) + ": w");
    expect_close(s.F, one.F, 1e-12, std::string(name) + ": F");
    expect_close(s.T, one.T, 1e-12, std::string(name) + ": T and the walls' loads");
  }
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
