#include "pair/pair_soft_particle.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <exception>

#include "formats/law_file.hpp"
#include "scene/validate.hpp"

namespace softpack::lammps {

PairSoftParticle::PairSoftParticle(LAMMPS_NS::LAMMPS* lmp) : Pair(lmp) {
  single_enable = 0;
  restartinfo = 0;
  one_coeff = 0;
}

PairSoftParticle::~PairSoftParticle() {
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairSoftParticle::fail(const std::string& what) const {
  error->all(FLERR, std::string(kStyle) + ": " + what);
  std::terminate();  // error->all does not return (it throws or aborts)
}

void PairSoftParticle::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 1; i <= n; ++i)
    for (int j = i; j <= n; ++j) setflag[i][j] = 0;
  soft_.assign(static_cast<std::size_t>(n) + 1, -1);
  max_radius_.assign(static_cast<std::size_t>(n) + 1, 0.0);
}

// pair_style softpack/soft LAWFILE [grain_contact wall|reduced-radius] [restitution E]
void PairSoftParticle::settings(int narg, char** arg) {
  if (narg < 1 || narg % 2 != 1)
    fail("expected: pair_style softpack/soft LAWFILE [grain_contact wall|reduced-radius] [restitution E]");
  const std::string path = arg[0];
  try {
    laws_ = soft_particle_laws(read_law_file(path), path);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  for (int k = 1; k < narg; k += 2) {
    const std::string key = arg[k], value = arg[k + 1];
    if (key == "grain_contact") {
      if (value != "wall" && value != "reduced-radius") fail(fmt::format("grain_contact '{}' is not allowed; allowed: wall, reduced-radius", value));
      grain_rule_ = value == "wall" ? GrainContactRule::wall : GrainContactRule::reduced_radius;
    } else if (key == "restitution") {
      char* end = nullptr;
      restitution_ = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !(restitution_ > 0.0 && restitution_ <= 1.0))
        fail(fmt::format("restitution '{}' is not allowed; allowed: 0 < e <= 1", value));
    } else {
      fail(fmt::format("'{}' is not a keyword; allowed: grain_contact, restitution", key));
    }
  }
  ContactSetting s;
  s.soft_laws = &laws_;
  s.grain_rule = grain_rule_;
  if (restitution_ > 0.0) s.restitution = restitution_;
  params_ = SoftParticleModel::params(s);
}

// pair_coeff I J ROLE_I ROLE_J (ROLE: soft or grain; at least one soft)
void PairSoftParticle::coeff(int narg, char** arg) {
  if (narg != 4) fail("expected: pair_coeff I J ROLE_I ROLE_J, each ROLE soft or grain");
  if (!allocated) allocate();
  int ilo = 0, ihi = 0, jlo = 0, jhi = 0;
  LAMMPS_NS::utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  LAMMPS_NS::utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const auto role = [&](const char* text) {
    if (std::strcmp(text, "soft") == 0) return 1;
    if (std::strcmp(text, "grain") == 0) return 0;
    fail(fmt::format("role '{}' is not allowed; allowed: soft, grain", text));
  };
  const int ri = role(arg[2]), rj = role(arg[3]);
  if (ri == 0 && rj == 0)
    fail("grain grain: two solid grains are not soft-particles; give their pairs to pair granular (pair_style hybrid, docs/lammps.md)");
  if (ri == 1 && rj == 1 && !laws_.soft_soft) fail(fmt::format("soft soft: {} has no soft-soft law", laws_.source));
  if (ri + rj == 1 && !laws_.soft_solid) fail(fmt::format("soft grain: {} has no soft-solid law", laws_.source));
  const auto set_role = [&](int type, int r) {
    int& known = soft_[static_cast<std::size_t>(type)];
    if (known >= 0 && known != r) fail(fmt::format("atom type {} is given the roles soft and grain", type));
    known = r;
  };
  int count = 0;
  for (int i = ilo; i <= ihi; ++i)
    for (int j = std::max(jlo, i); j <= jhi; ++j) {
      set_role(i, ri), set_role(j, rj);
      setflag[i][j] = 1;
      ++count;
    }
  if (count == 0) fail("pair_coeff names no pair of types");
}

void PairSoftParticle::init_style() {
  if (!atom->radius_flag || !atom->rmass_flag) fail("needs per-atom radius and mass: atom_style sphere");
  if (restitution_ > 0.0 && !comm->ghost_velocity) fail("restitution damps with the ghosts' velocities: add comm_modify vel yes");
  neighbor->request(this, instance_me);
  // The largest radius of each type, over all ranks: the types' cutoffs (init_one).
  std::vector<double> local(max_radius_.size(), 0.0);
  for (int i = 0; i < atom->nlocal; ++i) {
    double& m = local[static_cast<std::size_t>(atom->type[i])];
    m = std::max(m, atom->radius[i]);
  }
  MPI_Allreduce(local.data(), max_radius_.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_MAX, world);
  // Every soft-particle's radius within what its laws were measured at (the engine's rule).
  for (int i = 0; i < atom->nlocal; ++i) {
    const int t = atom->type[i];
    if (soft_[static_cast<std::size_t>(t)] != 1) continue;
    for (int u = 1; u <= atom->ntypes; ++u) {
      const int a = std::min(t, u), b = std::max(t, u);
      if (!setflag[a][b]) continue;
      const bool soft_soft = soft_[static_cast<std::size_t>(u)] == 1;
      const std::string why = soft_radius_refusal(laws_, soft_soft ? *laws_.soft_soft : *laws_.soft_solid, soft_soft ? "soft-soft" : "soft-solid",
                                                  atom->radius[i], false);
      if (!why.empty()) error->one(FLERR, fmt::format("{}: atom {} of type {}: {}", kStyle, atom->tag[i], t, why));
    }
  }
}

double PairSoftParticle::init_one(int i, int j) {
  if (!setflag[i][j]) fail(fmt::format("no pair_coeff for the types {} {}", i, j));
  return max_radius_[static_cast<std::size_t>(i)] + max_radius_[static_cast<std::size_t>(j)];
}

template <bool Damped>
void PairSoftParticle::compute_pairs() {
  constexpr Effects Fx{false, Damped, false, false};
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dt = update->dt;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* neighbours = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = neighbours[jj] & NEIGHMASK;
      const bool soft_i = soft_[static_cast<std::size_t>(type[i])] == 1, soft_j = soft_[static_cast<std::size_t>(type[j])] == 1;
      if (!soft_i && !soft_j) continue;
      const V3<double> d{x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double r_sum = radius[i] + radius[j];
      if (!(dot(d, d) < r_sum * r_sum)) continue;
      // The engine's pair (forces/force_field.cpp pair_partners, forces/pair_contacts.hpp gather).
      ContactPartners b;
      b.kind = ContactPartners::Kind::pair;
      b.R1 = radius[i], b.R2 = radius[j];
      b.R12 = radius[i] * radius[j] / (radius[i] + radius[j]);
      b.m12 = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      b.inv_mt = 1.0 / rmass[i] + 1.0 / rmass[j];
      b.soft1 = soft_i, b.soft2 = soft_j;
      const SoftParticleModel::Constants<double> k = SoftParticleModel::constants(params_, b);
      ContactGeometry<double> g{};
      const double dist = std::sqrt(dot(d, d));
      g.n = d * (1.0 / dist);
      g.h = r_sum - dist;
      g.vc = V3<double>{v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
      g.n_frame = g.n, g.vc_frame = g.vc;
      V3<double> spring{0.0, 0.0, 0.0};
      const ContactForce<double> F = SoftParticleModel::force<Fx>(params_, g, k, spring, dt);
      f[i][0] += F.F.x, f[i][1] += F.F.y, f[i][2] += F.F.z;
      if (newton_pair || j < nlocal) f[j][0] -= F.F.x, f[j][1] -= F.F.y, f[j][2] -= F.F.z;
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, F.F.x, F.F.y, F.F.z, d.x, d.y, d.z);
    }
  }
}

void PairSoftParticle::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  if (restitution_ > 0.0) compute_pairs<true>();
  else compute_pairs<false>();
}

}  // namespace softpack::lammps
