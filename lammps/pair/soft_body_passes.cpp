// The many-body law's passes of the pair style softpack/soft (pair/pair_soft_particle.hpp): each body's state
// and stress tensor before the forces, and their forward communication to the ghosts.
#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "pair/soft_contacts.hpp"

namespace softpack::lammps {

// The many-body law's passes before the forces (the engine's, forces/compile_loops.hpp; LAMMPS's
// EAM pattern): each local body's state from its contacts (with newton off a rank sees every
// contact of its own atoms), sent to the ghosts; then, for a law with a stress term, each body's
// tensor from its contacts' base forces at those states, sent likewise.
void PairSoftParticle::body_passes() {
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  state_.assign(static_cast<std::size_t>(nall), 0.0);
  const bool caps = SoftManyBodyNormal::body_caps(many_params_.normal), stress = SoftManyBodyNormal::body_stress(many_params_.normal);
  if (caps) {
    caps_.resize(static_cast<std::size_t>(nlocal));
    for (int i = 0; i < nlocal; ++i) caps_[static_cast<std::size_t>(i)].clear();
  }
  each_contact([&](int i, int j, int a, int b, const V3<double>& d, double r_sum) {
    const auto k = SoftManyBodyModel::constants(many_params_, partners(a, b, false)).normal;
    const double h = r_sum - std::sqrt(dot(d, d));
    const double term = SoftManyBodyNormal::body_term(h, k);
    state_[static_cast<std::size_t>(i)] += term;
    if (j < nlocal) state_[static_cast<std::size_t>(j)] += term;
    if (!caps) return;
    const double depth = SoftManyBodyNormal::cap_depth_of(h, k);
    const Vec3 u = Vec3(d.x, d.y, d.z).normalized();  // from b towards a: b's cap, a's the other way
    const auto keep = [&](int atom_index, int body, const Vec3& direction, LAMMPS_NS::tagint partner) {
      if (atom_index >= nlocal || !(k.soft == SoftManyBodyNormal::kBoth || k.soft == body)) return;
      caps_[static_cast<std::size_t>(atom_index)].push_back({partner, direction, depth});
    };
    keep(a, 1, -u, atom->tag[b]), keep(b, 2, u, atom->tag[a]);
  });
  each_wall_contact([&](int i, std::size_t w, double h) {  // a wall's cap: from the centre against the wall's normal
    const auto k = SoftManyBodyModel::constants(many_params_, wall_partners(i, false)).normal;
    state_[static_cast<std::size_t>(i)] += SoftManyBodyNormal::body_term(h, k);
    if (caps) caps_[static_cast<std::size_t>(i)].push_back({wall_key(w), -walls_[w]->normal, SoftManyBodyNormal::cap_depth_of(h, k)});
  });
  if (caps)  // each body's caps in its partners' order: the same sums on any number of ranks
    for (int i = 0; i < nlocal; ++i) {
      auto& c = caps_[static_cast<std::size_t>(i)];
      if (c.size() < 2) continue;
      std::sort(c.begin(), c.end(), [](const Cap& x, const Cap& y) { return x.partner < y.partner; });
      cap_u_.clear(), cap_depth_.clear();
      for (const Cap& cap : c) cap_u_.push_back(cap.u), cap_depth_.push_back(cap.depth);
      state_[static_cast<std::size_t>(i)] = SoftManyBodyNormal::body_state(cap_u_, cap_depth_);
    }
  forwarding_ = Forward::state;
  comm->forward_comm_pair(this);
  stress_.clear();
  if (!stress) return;
  stress_.assign(static_cast<std::size_t>(nall), SymmetricTensor{});
  each_contact([&](int i, int j, int a, int b, const V3<double>& d, double r_sum) {
    const auto k = SoftManyBodyModel::constants(many_params_, partners(a, b, false)).normal;
    ContactGeometry<double> g{};
    const double dist = std::sqrt(dot(d, d));
    g.n = d * (1.0 / dist), g.h = r_sum - dist;
    g.body1 = state_[static_cast<std::size_t>(a)], g.body2 = state_[static_cast<std::size_t>(b)];
    const double Fn = SoftManyBodyNormal::evaluate(many_params_.normal, k, g).Fn;
    const auto add = [&](SymmetricTensor& S) {
      S[0] += Fn * g.n.x * g.n.x, S[1] += Fn * g.n.y * g.n.y, S[2] += Fn * g.n.z * g.n.z;
      S[3] += Fn * g.n.x * g.n.y, S[4] += Fn * g.n.x * g.n.z, S[5] += Fn * g.n.y * g.n.z;
    };
    add(stress_[static_cast<std::size_t>(i)]);
    if (j < nlocal) add(stress_[static_cast<std::size_t>(j)]);
  });
  each_wall_contact([&](int i, std::size_t w, double h) {
    const auto k = SoftManyBodyModel::constants(many_params_, wall_partners(i, false)).normal;
    ContactGeometry<double> g{};
    const Vec3& N = walls_[w]->normal;
    g.n = V3<double>{N.x(), N.y(), N.z()}, g.h = h, g.body1 = state_[static_cast<std::size_t>(i)], g.body2 = 0.0;
    const double Fn = SoftManyBodyNormal::evaluate(many_params_.normal, k, g).Fn;
    SymmetricTensor& S = stress_[static_cast<std::size_t>(i)];
    S[0] += Fn * g.n.x * g.n.x, S[1] += Fn * g.n.y * g.n.y, S[2] += Fn * g.n.z * g.n.z;
    S[3] += Fn * g.n.x * g.n.y, S[4] += Fn * g.n.x * g.n.z, S[5] += Fn * g.n.y * g.n.z;
  });
  forwarding_ = Forward::stress;
  comm->forward_comm_pair(this);
}

int PairSoftParticle::pack_forward_comm(int n, int* list_of, double* buf, int, int*) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const auto j = static_cast<std::size_t>(list_of[k]);
    if (forwarding_ == Forward::state) buf[m++] = state_[j];
    else
      for (double c : stress_[j]) buf[m++] = c;
  }
  return m;
}

void PairSoftParticle::unpack_forward_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i) {
    const auto j = static_cast<std::size_t>(i);
    if (forwarding_ == Forward::state) state_[j] = buf[m++];
    else
      for (double& c : stress_[j]) c = buf[m++];
  }
}

}  // namespace softpack::lammps
