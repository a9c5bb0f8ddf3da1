// Sphere-wall contacts for the force loop (forces/contact_loop.hpp): body 1 is the sphere, body 2
// the wall, which has infinite mass. The two walls differ only in their geometry:
//
//   plane  (walls/plane_wall.hpp)       h = r - (x - p).N,  n = N (towards the spheres),
//                                        wall velocity u at every point;
//   shell  (walls/spherical_shell.hpp)  h = |x - c| + r - Rs,  n = -(x - c) / |x - c| (inwards),
//                                        surface velocity u + spin x (contact point - c).
//
// vc = v - (surface velocity) - (ai w) x n, ai = r - h/2. With the synchronized history update
// the spring's frame is the half-step one (the sphere at x - dt/2 (v - u)). The wall receives
// -F, with its torque about the wall's reference point (the plane's point, the shell's centre).
#pragma once
#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "core/parallel.hpp"
#include "forces/contact_loop.hpp"
#include "forces/pair_contacts.hpp"
#include "neighbor/contact_list.hpp"
#include "state/world.hpp"

namespace softpack {

template <Effects Fx, class Wall>
struct WallContacts {
  WallList& list;
  const Wall& wall;
  SphereArrays s;
  WallLoad& load;
  std::size_t spheres = 0;  ///< the length of the sphere arrays

  /// One thread: add() sums as it goes, into the spheres and the wall's load. On T threads
  /// (part()) thread t evaluates the entries of its share of the spheres (a sphere is listed
  /// once per wall: its sums are its own) and keeps the wall's terms, which finish() sums in list
  /// order.
  bool direct = true;
  std::size_t begin = 0, end = 0;  ///< the entries evaluated

  void prepare() {
    begin = 0, end = list.size();
    direct = parallel::threads_for(spheres) == 1;
    if (!direct) list.results.resize(list.size());
  }
  WallContacts part(std::size_t, std::size_t t, std::size_t parts) const {
    WallContacts c = *this;
    const auto at = [&](std::size_t share) {
      const auto first = static_cast<std::int32_t>(parallel::share_begin(spheres, share, parts));
      return static_cast<std::size_t>(std::lower_bound(list.i.begin(), list.i.end(), first) - list.i.begin());
    };
    c.begin = at(t), c.end = at(t + 1);
    return c;
  }

  /// The indices of the entries among [begin, end) whose sphere touches the wall (h > 0), in list
  /// order, each entry's `touched` set on threads; with friction the springs of the others are cleared.
  template <class Gather, class Isa>
  std::size_t select(Isa, std::int32_t* closed, std::size_t begin, std::size_t end) {
    std::size_t n = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const int i = list.i[k];
      const bool touching = wall.overlap(s.x[i], s.r[i]) > 0.0;
      if (!direct) list.results.touched[k] = touching ? 1 : 0;
      if (!touching) {
        if constexpr (Fx.friction) list.spring[k].setZero();
        continue;
      }
      closed[n++] = static_cast<std::int32_t>(k);
    }
    return n;
  }

  template <class Model, class Isa>
  [[gnu::always_inline]] auto gather(Isa isa, simd::Index k, double dt) const {
    using simd::Wide;
    ContactLanes<typename Model::template Constants<Wide>> c;
    c.i = simd::gather(isa, list.i.data(), k);
    const V3<Wide> x = gather_vec3(isa, s.x, c.i), v = gather_vec3(isa, s.v, c.i);
    const Wide r = simd::gather(isa, s.r, c.i);
    V3<Wide> w{};
    if constexpr (Fx.rotation) w = gather_vec3(isa, s.w, c.i);
    c.constants = gather_constants<Model, Fx>(isa, list.k, k);
    ContactGeometry<Wide>& g = c.geometry;
    V3<Wide> surface_velocity;
    geometry(x, r, g.n, g.h, c.ai, surface_velocity);
    g.vc = v - surface_velocity;
    if constexpr (Fx.rotation) g.vc = g.vc - cross(c.ai * w, g.n);
    if constexpr (Fx.friction) {
      c.spring = gather_vec3(isa, list.spring.data(), k);
      g.n_frame = g.n, g.vc_frame = g.vc;
      if constexpr (Fx.synchronized) half_step_frame(x, v, w, r, g.h, Wide(0.5 * dt), g);
    }
    return c;
  }

  /// The per-body pass: Model::Normal::body_term(h, normal constants) of entries k added to their spheres' states.
  template <class Model, class Isa>
  [[gnu::always_inline]] void add_body_terms(Isa isa, simd::Index k, int live) {
    const simd::Index i = simd::gather(isa, list.i.data(), k);
    V3<W> n, u;
    W h, ai;
    geometry(gather_vec3(isa, s.x, i), simd::gather(isa, s.r, i), n, h, ai, u);
    const auto constants = gather_normal_constants<Model>(isa, list.k, k);
    const W term = Model::Normal::body_term(h, constants);
    for (int m = 0; m < live; ++m) s.body[i.v[m]] += lane(term, m);
    if constexpr (BodyCapsModel<Model>)
      if (s.caps) {
        const W depth = Model::Normal::cap_depth_of(h, constants);
        for (int m = 0; m < live; ++m)
          if (Model::Normal::keeps_cap(constants, m, 1)) s.caps[i.v[m]].u.push_back(-lane(n, m)), s.caps[i.v[m]].depth.push_back(lane(depth, m));  // n: from the wall
      }
  }

  /// The stress pass: each of entries k's base force times n ⊗ n added to its sphere's tensor.
  template <class Model, class Isa>
  [[gnu::always_inline]] void add_stress_terms(Isa isa, const typename Model::Params& params, simd::Index k, int live) {
    const simd::Index i = simd::gather(isa, list.i.data(), k);
    ContactGeometry<W> g{};  // as gather() makes it
    V3<W> u;
    W ai;
    geometry(gather_vec3(isa, s.x, i), simd::gather(isa, s.r, i), g.n, g.h, ai, u);
    g.body1 = simd::gather(isa, s.body, i), g.body2 = W(0.0);
    const auto constants = gather_normal_constants<Model>(isa, list.k, k);
    for (int m = 0; m < live; ++m) add_stress(s.stress[i.v[m]], base_normal_force<Model>(params, constants, g, m), lane(g.n, m));
  }
  /// Lane m's tensor and radius of the sphere, for a law with a stress term (the wall has none).
  template <class Lanes>
  [[gnu::always_inline]] void lane_stress(const Lanes& c, int m, ContactGeometry<double>& g) const {
    if (s.stress) g.stress1 = {&s.stress[c.i.v[m]], s.r[c.i.v[m]]};
  }

  /// The sphere's state of the lanes' entries (the wall has none: 0), for a law that reads them.
  template <class Isa, class Lanes>
  [[gnu::always_inline]] void gather_body(Isa isa, Lanes& c) const {
    c.geometry.body1 = simd::gather(isa, s.body, c.i);
    c.geometry.body2 = W(0.0);
  }

  /// Each contact's force, the sphere's torque term ai n x Ft and the wall's torque kept; the springs back.
  template <class Lanes>
  [[gnu::always_inline]] void add(const Lanes& c, const ContactForce<simd::Wide>& f, const std::int32_t* k, int live) {
    const Vec3 ref = reference_point();
    WallResults& r = list.results;
    for (int m = 0; m < live; ++m) {
      const auto kk = static_cast<std::size_t>(k[m]);
      const int i = c.i.v[m];
      const Vec3 F = lane(f.F, m), n = lane(c.geometry.n, m);
      const double ai = lane(c.ai, m);
      if (direct) {
        s.F[i] += F;
        if constexpr (Fx.rotation) s.T[i] -= ai * n.cross(lane(f.Ft, m));
        load.force -= F;
        load.torque += (s.x[i] - ai * n - ref).cross(-F);
        if constexpr (Fx.friction) list.spring[kk] = lane(c.spring, m);
        continue;
      }
      // A sphere is listed once per wall: its sums are its own; the wall's wait for finish().
      s.F[i] += F;
      if constexpr (Fx.rotation) s.T[i] -= ai * n.cross(lane(f.Ft, m));
      r.F[kk] = F;
      r.torque[kk] = (s.x[i] - ai * n - ref).cross(-F);
      if constexpr (Fx.friction) list.spring[kk] = lane(c.spring, m);
    }
  }

  /// The wall's load -= F with its torque, in list order.
  void finish() {
    if (direct) return;
    const WallResults& r = list.results;
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (!r.touched[k]) continue;
      load.force -= r.F[k];
      load.torque += r.torque[k];
    }
  }

 private:
  using W = simd::Wide;

  Vec3 reference_point() const {
    if constexpr (std::is_same_v<Wall, PlaneWall>) return wall.point;
    else return wall.centre;
  }

  /// Normal, overlap, branch length and the wall's surface velocity at the contact point.
  [[gnu::always_inline]] void geometry(const V3<W>& x, const W& r, V3<W>& n, W& h, W& ai, V3<W>& u) const {
    if constexpr (std::is_same_v<Wall, PlaneWall>) {
      n = broadcast<W>(wall.normal);
      h = r - dot(x - broadcast<W>(wall.point), n);
      ai = r - W(0.5) * h;
      u = broadcast<W>(wall.velocity);
    } else {
      const V3<W> c = broadcast<W>(wall.centre);
      const V3<W> d = x - c;
      const W dist = simd::sqrt(dot(d, d));
      h = dist + r - W(wall.radius);
      n = d * (W(-1.0) / dist);  // inwards
      ai = r - W(0.5) * h;
      u = broadcast<W>(wall.velocity) + cross(broadcast<W>(wall.spin), (x - ai * n) - c);
    }
  }

  /// The synchronized history update's frame: the contact at t + dt/2.
  [[gnu::always_inline]] void half_step_frame(const V3<W>& x, const V3<W>& v, const V3<W>& w, const W& r, const W& h,
                                              const W& half_dt, ContactGeometry<W>& g) const {
    if constexpr (std::is_same_v<Wall, PlaneWall>) {
      const V3<W> u = broadcast<W>(wall.velocity);
      const W h_half = h + half_dt * dot(v - u, g.n);
      g.vc_frame = v - u;
      if constexpr (Fx.rotation) g.vc_frame = g.vc_frame - cross((r - W(0.5) * h_half) * w, g.n);
    } else {
      const V3<W> c = broadcast<W>(wall.centre), u = broadcast<W>(wall.velocity);
      const V3<W> d_half = (x - c) - half_dt * (v - u);
      const W dist_half = simd::sqrt(dot(d_half, d_half));
      g.n_frame = d_half * (W(-1.0) / dist_half);
      const W a_half = r - W(0.5) * (dist_half + r - W(wall.radius));
      g.vc_frame = v - (u + cross(broadcast<W>(wall.spin), ((c + d_half) - a_half * g.n_frame) - c));
      if constexpr (Fx.rotation) g.vc_frame = g.vc_frame - cross(a_half * w, g.n_frame);
    }
  }
};

}  // namespace softpack
