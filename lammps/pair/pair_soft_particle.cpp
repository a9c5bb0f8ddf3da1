#include "pair/pair_soft_particle.hpp"

#include "pair/soft_history.hpp"
#include "pair/soft_contacts.hpp"
#include "pair/soft_wall.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>

#include "core/fnv1a.hpp"
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

// pair_style softpack/soft LAWFILE [keyword value] ...
void PairSoftParticle::settings(int narg, char** arg) {
  if (narg < 1 || narg % 2 != 1)
    fail("expected: pair_style softpack/soft LAWFILE [grain_contact wall|reduced-radius] [restitution E] [tangential_ratio X] "
         "[friction yes|no] [rotation yes|no] [history_update standard|synchronized] [history K]");
  const std::string path = arg[0];
  try {
    laws_ = soft_particle_laws(read_law_file(path), path);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  const auto number = [&](const std::string& key, const std::string& value, double lo, double hi) {
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end == value.c_str() || *end != '\0' || !(v > lo && v <= hi))
      fail(fmt::format("{} '{}' is not allowed; allowed: {} < {} <= {}", key, value, lo, key, hi));
    return v;
  };
  const auto choice = [&](const std::string& key, const std::string& value, const char* yes, const char* no) {
    if (value != yes && value != no) fail(fmt::format("{} '{}' is not allowed; allowed: {}, {}", key, value, yes, no));
    return value == yes;
  };
  setting_ = ContactSetting{};
  grain_rule_ = GrainContactRule::wall, history_capacity_ = 0;
  settings_text_ = fmt::format("{}", fmt::join(arg, arg + narg, " "));
  {  // the law file's bytes, for the signature: the same path rewritten is another law
    std::ifstream in(arg[0], std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    settings_text_ += "\n" + bytes;
  }
  fx_ = Effects{true, false, true, true};  // the engine's defaults: friction, rotation, synchronized history
  for (int k = 1; k < narg; k += 2) {
    const std::string key = arg[k], value = arg[k + 1];
    if (key == "grain_contact") grain_rule_ = choice(key, value, "wall", "reduced-radius") ? GrainContactRule::wall : GrainContactRule::reduced_radius;
    else if (key == "restitution") setting_.restitution = number(key, value, 0.0, 1.0), fx_.damping = true;
    else if (key == "tangential_ratio") setting_.tangential_ratio = number(key, value, -1e-300, 100.0);
    else if (key == "friction") fx_.friction = choice(key, value, "yes", "no");
    else if (key == "rotation") fx_.rotation = choice(key, value, "yes", "no");
    else if (key == "history_update") fx_.synchronized = choice(key, value, "synchronized", "standard");
    else if (key == "history") {
      history_capacity_ = static_cast<int>(number(key, value, 0.0, 100000.0));
      if (value != std::to_string(history_capacity_)) fail(fmt::format("history '{}' is not allowed; allowed: an integer from 1 to 100000", value));
    }
    else fail(fmt::format("'{}' is not a keyword; allowed: grain_contact, restitution, tangential_ratio, friction, rotation, history_update, history", key));
  }
  if (fx_.rotation && !fx_.friction) fail("rotation yes needs friction yes (without friction no contact turns a sphere)");
  if (fx_.friction && ((laws_.soft_solid && !laws_.soft_solid->tangential) || (laws_.soft_soft && !laws_.soft_soft->tangential)))
    fail(fmt::format("friction yes: {} has no tangential law (Eq. 8) for each of its scenes; allowed: friction no", laws_.source));
  setting_.soft_laws = &laws_;
  setting_.grain_rule = grain_rule_;
  params_ = SoftParticleModel::params(setting_);
  if (laws_.many_body) many_params_ = SoftManyBodyModel::params(setting_);
  comm_forward = laws_.many_body ? 7 : 0;  // a body's state, or its stress tensor
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
  if ((fx_.damping || fx_.friction) && !comm->ghost_velocity)
    fail("damping and friction read the ghosts' velocities: add comm_modify vel yes");
  if (fx_.rotation && !atom->omega_flag) fail("rotation yes needs per-atom angular velocities: atom_style sphere");
  if ((fx_.friction || laws_.many_body) && force->newton_pair)
    fail(fmt::format("{}: add newton off before the box is made (after read_restart: newton off off)",
                     fx_.friction ? "friction keeps each contact's spring on both of its ranks" : "the many-body law sums each body's contacts on its own rank"));
  neighbor->request(this, instance_me);
  walls_.clear();
  for (int k = 0; k < modify->nfix; ++k)
    if (auto* wall = dynamic_cast<FixSoftWall*>(modify->fix[k])) walls_.push_back(wall);
  // The roles against the laws as they are now (pair_style may have been given again).
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j) {
      if (!setflag[i][j]) continue;
      const int soft = (soft_[static_cast<std::size_t>(i)] == 1) + (soft_[static_cast<std::size_t>(j)] == 1);
      if (soft == 2 && !laws_.soft_soft) fail(fmt::format("types {} {}: soft soft, but {} has no soft-soft law", i, j, laws_.source));
      if (soft == 1 && !laws_.soft_solid) fail(fmt::format("types {} {}: soft grain, but {} has no soft-solid law", i, j, laws_.source));
    }
  {  // looked up at every init: the fix may have been removed or given again
    history_ = nullptr;
    const int at = modify->find_fix(FixSoftHistory::kId);
    if (at >= 0) {
      history_ = dynamic_cast<FixSoftHistory*>(modify->fix[at]);
      if (history_ && history_capacity_ > 0 && history_->capacity() != history_capacity_)
        fail(fmt::format("history {}: the fix {} keeps {} springs per atom; unfix {} first to change it", history_capacity_, FixSoftHistory::kId,
                         history_->capacity(), FixSoftHistory::kId));
    } else {
      std::string cmd = fmt::format("{} all {}", FixSoftHistory::kId, FixSoftHistory::kStyle);
      if (history_capacity_ > 0) cmd += fmt::format(" {}", history_capacity_);
      history_ = dynamic_cast<FixSoftHistory*>(modify->add_fix(cmd));
    }
    if (!history_) fail(fmt::format("fix {} is not a {}", FixSoftHistory::kId, FixSoftHistory::kStyle));
    history_->signature = [this] { return signature(); };
  }
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

// The engine's pair (forces/force_field.cpp pair_partners): body 1 is atom a.
ContactPartners PairSoftParticle::partners(int a, int b, bool rotation) const {
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const auto inv_I_r2 = [&](int c) { return radius[c] * radius[c] * (1.0 / (0.4 * rmass[c] * radius[c] * radius[c])); };
  ContactPartners p;
  p.kind = ContactPartners::Kind::pair;
  p.R1 = radius[a], p.R2 = radius[b];
  p.R12 = radius[a] * radius[b] / (radius[a] + radius[b]);
  p.m12 = rmass[a] * rmass[b] / (rmass[a] + rmass[b]);
  p.inv_mt = 1.0 / rmass[a] + 1.0 / rmass[b];
  if (rotation) p.inv_mt += inv_I_r2(a) + inv_I_r2(b);
  p.soft1 = soft_[static_cast<std::size_t>(atom->type[a])] == 1, p.soft2 = soft_[static_cast<std::size_t>(atom->type[b])] == 1;
  return p;
}

// What a run's kept forces depend on besides the atoms (pair/soft_history.hpp): the style's
// arguments and roles, the law file's content, the walls (ID, group, position, normal, velocity),
// the number of atoms and the step.
std::uint64_t PairSoftParticle::signature() const {
  Fnv1a h;
  h.add(settings_text_);
  h.add(soft_.data(), soft_.size() * sizeof(int));
  for (const FixSoftWall* w : walls_) {
    h.add(w->id);
    const int bit = w->group_bit();
    h.add(&bit, sizeof bit);
    for (const Vec3* v : {&w->point, &w->normal, &w->surface_velocity}) h.add(v->data(), 3 * sizeof(double));
  }
  h.add(&atom->natoms, sizeof atom->natoms);
  h.add(&update->dt, sizeof update->dt);
  return h.value;
}

// A wall's key among an atom's springs and caps: negative (tags are positive), from its fix ID,
// so that it names the same wall whatever the order of the fixes.
LAMMPS_NS::tagint PairSoftParticle::wall_key(std::size_t w) const {
  Fnv1a h;
  h.add(walls_[w]->id);
  return -1 - static_cast<LAMMPS_NS::tagint>(h.value % 1000000007ull);
}

// The engine's sphere on a wall (forces/force_field.cpp wall_partners): a plane's R12 is the sphere's radius.
ContactPartners PairSoftParticle::wall_partners(int i, bool rotation) const {
  const double r = atom->radius[i], m = atom->rmass[i];
  ContactPartners p;
  p.kind = ContactPartners::Kind::plane;
  p.R1 = r, p.R12 = r, p.m12 = m;
  p.inv_mt = 1.0 / m + (rotation ? r * r * (1.0 / (0.4 * m * r * r)) : 0.0);
  p.soft1 = true;
  return p;
}

template <class Model, Effects Fx>
void PairSoftParticle::compute_pairs(const typename Model::Params& params) {
  double** v = atom->v;
  double** f = atom->f;
  double** w = atom->omega;
  double** T = atom->torque;
  const double* radius = atom->radius;
  const LAMMPS_NS::tagint* tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dt = update->setupflag ? 0.0 : update->dt;  // the springs advance in steps, not in a run's setup (the engine's F(t0))
  const auto vec = [](const double* p) { return V3<double>{p[0], p[1], p[2]}; };
  // A force and a torque on atom c, also kept as its last step's (pair/soft_history.hpp).
  const auto apply = [&](int c, const V3<double>& Fc, const V3<double>& Tc) {
    double* L = history_->last(c);
    f[c][0] += Fc.x, f[c][1] += Fc.y, f[c][2] += Fc.z;
    L[0] += Fc.x, L[1] += Fc.y, L[2] += Fc.z;
    if constexpr (Fx.rotation) {
      T[c][0] += Tc.x, T[c][1] += Tc.y, T[c][2] += Tc.z;
      L[3] += Tc.x, L[4] += Tc.y, L[5] += Tc.z;
    }
  };
  if (!dry_run_) history_->clear_last(nlocal);
  // A contact's constants (radius scaling: two pow) are those of the last contact whose partners
  // were the same (the engine keeps them per contact; a medium of few radii and masses reuses them).
  ContactPartners last_partners{};
  typename Model::template Constants<double> last_k{};
  bool have_last = false;
  const auto constants = [&](const ContactPartners& p) {
    const bool same = have_last && p.kind == last_partners.kind && p.R1 == last_partners.R1 && p.R2 == last_partners.R2 && p.R12 == last_partners.R12 &&
                      p.m12 == last_partners.m12 && p.inv_mt == last_partners.inv_mt && p.materials == last_partners.materials &&
                      p.soft1 == last_partners.soft1 && p.soft2 == last_partners.soft2;
    if (!same) last_k = Model::constants(params, p), last_partners = p, have_last = true;
    return last_k;
  };
  each_contact([&](int i, int j, int a, int b, const V3<double>& d, double r_sum) {
    const typename Model::template Constants<double> k = constants(partners(a, b, Fx.rotation));
    ContactGeometry<double> g{};  // the engine's (forces/pair_contacts.hpp gather)
    const V3<double> vab = vec(v[a]) - vec(v[b]);
    const double dist = std::sqrt(dot(d, d));
    g.n = d * (1.0 / dist);
    g.h = r_sum - dist;
    g.vc = vab;
    if constexpr (BodyStateModel<Model>) {
      g.body1 = state_[static_cast<std::size_t>(a)], g.body2 = state_[static_cast<std::size_t>(b)];
      if (!stress_.empty()) g.stress1 = {&stress_[static_cast<std::size_t>(a)], radius[a]}, g.stress2 = {&stress_[static_cast<std::size_t>(b)], radius[b]};
    }
    double arm_a = 0.0, arm_b = 0.0;
    if constexpr (Fx.rotation) {
      arm_a = radius[a] - 0.5 * g.h, arm_b = radius[b] - 0.5 * g.h;
      g.vc = g.vc - cross(arm_a * vec(w[a]) + arm_b * vec(w[b]), g.n);
    }
    V3<double> xi{0.0, 0.0, 0.0};
    double* spring = nullptr;
    if constexpr (Fx.friction) {
      g.n_frame = g.n, g.vc_frame = g.vc;
      if constexpr (Fx.synchronized) {
        const V3<double> d_half = d - (0.5 * dt) * vab;
        const double dist_half = std::sqrt(dot(d_half, d_half));
        g.n_frame = d_half * (1.0 / dist_half);
        g.vc_frame = vab;
        if constexpr (Fx.rotation) {
          const double h_half = r_sum - dist_half;
          g.vc_frame = g.vc_frame - cross((radius[a] - 0.5 * h_half) * vec(w[a]) + (radius[b] - 0.5 * h_half) * vec(w[b]), g.n_frame);
        }
      }
      spring = dry_run_ ? history_->find(i, tag[j]) : history_->find_or_add(i, tag[j]);  // atom i is local
      if (spring) xi = vec(spring);
    }
    const ContactForce<double> F = Model::template force<Fx>(params, g, k, xi, dt);
    if (dry_run_) {  // a continuation's setup: the virial only (add_last gives the forces)
      if (evflag) ev_tally_xyz(a, b, nlocal, newton_pair, 0.0, 0.0, F.F.x, F.F.y, F.F.z, d.x, d.y, d.z);
      return;
    }
    if constexpr (Fx.friction) {
      spring[0] = xi.x, spring[1] = xi.y, spring[2] = xi.z;
      history_->touch(i, spring);
      if (j < nlocal) {  // both local: the pair is listed once, both atoms keep the spring
        double* other = history_->find_or_add(j, tag[i]);
        other[0] = xi.x, other[1] = xi.y, other[2] = xi.z;
        history_->touch(j, other);
      }
    }
    const V3<double> nxFt = Fx.rotation ? cross(g.n, F.Ft) : V3<double>{0.0, 0.0, 0.0};
    if (newton_pair || a < nlocal) apply(a, F.F, -arm_a * nxFt);
    if (newton_pair || b < nlocal) apply(b, -F.F, -arm_b * nxFt);
    if (evflag) ev_tally_xyz(a, b, nlocal, newton_pair, 0.0, 0.0, F.F.x, F.F.y, F.F.z, d.x, d.y, d.z);
  });
  if (!dry_run_)
    for (FixSoftWall* wall : walls_) wall->load = Vec3::Zero();
  each_wall_contact([&](int i, std::size_t wi, double h) {  // the engine's (forces/wall_contacts.hpp gather, add)
    FixSoftWall& wall = *walls_[wi];
    const typename Model::template Constants<double> k = constants(wall_partners(i, Fx.rotation));
    const V3<double> n{wall.normal.x(), wall.normal.y(), wall.normal.z()}, u{wall.surface_velocity.x(), wall.surface_velocity.y(), wall.surface_velocity.z()};
    ContactGeometry<double> g{};
    g.n = n, g.h = h;
    const V3<double> vu = vec(v[i]) - u;
    g.vc = vu;
    const double arm = radius[i] - 0.5 * h;
    if constexpr (Fx.rotation) g.vc = g.vc - cross(arm * vec(w[i]), g.n);
    if constexpr (BodyStateModel<Model>) {
      g.body1 = state_[static_cast<std::size_t>(i)], g.body2 = 0.0;
      if (!stress_.empty()) g.stress1 = {&stress_[static_cast<std::size_t>(i)], radius[i]};
    }
    V3<double> xi{0.0, 0.0, 0.0};
    double* spring = nullptr;
    if constexpr (Fx.friction) {
      g.n_frame = g.n, g.vc_frame = g.vc;
      if constexpr (Fx.synchronized) {
        const double h_half = h + 0.5 * dt * dot(vu, g.n);
        g.vc_frame = vu;
        if constexpr (Fx.rotation) g.vc_frame = g.vc_frame - cross((radius[i] - 0.5 * h_half) * vec(w[i]), g.n);
      }
      const LAMMPS_NS::tagint key = wall_key(wi);
      spring = dry_run_ ? history_->find(i, key) : history_->find_or_add(i, key);
      if (spring) xi = vec(spring);
    }
    const ContactForce<double> F = Model::template force<Fx>(params, g, k, xi, dt);
    if (dry_run_) return;
    if constexpr (Fx.friction) {
      spring[0] = xi.x, spring[1] = xi.y, spring[2] = xi.z;
      history_->touch(i, spring);
    }
    apply(i, F.F, -arm * (Fx.rotation ? cross(g.n, F.Ft) : V3<double>{0.0, 0.0, 0.0}));
    wall.load -= Vec3(F.F.x, F.F.y, F.F.z);
  });
  if (!dry_run_)
    for (FixSoftWall* wall : walls_) wall->sum_load();
  if (Fx.friction && !dry_run_) history_->prune(nlocal);
}

void PairSoftParticle::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  // A run's setup that continues the last step (pair/soft_history.hpp): its forces, and the virial.
  dry_run_ = update->setupflag && history_->continues();
  if (dry_run_) history_->add_last(atom->f, fx_.rotation ? atom->torque : nullptr);
  if (laws_.many_body) {
    body_passes();
    with_effects(fx_, [&]<Effects Fx>() { compute_pairs<SoftManyBodyModel, Fx>(many_params_); });
  } else {
    with_effects(fx_, [&]<Effects Fx>() { compute_pairs<SoftParticleModel, Fx>(params_); });
  }
}

}  // namespace softpack::lammps
