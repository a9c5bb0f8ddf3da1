// Viscous contact damping of Tsuji, Tanaka & Ishida (1992):
//
//   Fd_n = -gamma_n vn,   gamma_n = zeta sqrt(m12 kn) h^(1/4)
//   Fd_t = -gamma_t vt,   gamma_t = ratio_t zeta sqrt(mt kt0) h^(1/4)
//
// with kn = sqrt(R12)/D the Hertz stiffness of Eq. 3, kt0 = Dt sqrt(R12) that of Eq. 5, and
// m12 = m1 m2/(m1 + m2) (m12 = m for a wall). The tangential law applies the same zeta to its
// own mode: stiffness kt0 and effective mass mt, 1/mt = sum over both bodies of
// (1/m + a^2/I), the inertia the contact point feels when it slides and the spheres roll
// (mt = m12/3.5 for rotating solid spheres, m12 without rotation). Tsuji et al. used
// gamma_t = gamma_n instead, which over-damps the sliding-rolling mode by sqrt(3.5/(Dt D))
// ~ 1.7: with the explicit integrator that makes small grains chatter at the Coulomb limit
// and a frictional packing never relaxes (measured in docs/physics.md). ratio_t (scene key
// effects.damping.tangential_ratio) scales it further. With this h^(1/4) factor the equation of motion of a binary collision,
// m12 h'' = -kn h^(3/2) - zeta sqrt(m12 kn) h^(1/4) h', becomes in the scaled variables
// X = h/L, tau = t/T (T = sqrt(m12/(kn L^(1/2))), L set by the impact speed)
//
//   X'' = -X^(3/2) - zeta X^(1/4) X',   X(0) = 0, X'(0) = 1,
//
// independent of speed, masses and stiffness: the coefficient of restitution e = -X'(end)
// depends on zeta alone. We prescribe e and obtain zeta(e) by integrating that equation
// (not by Tsuji's polynomial fit), so the restitution of a normal impact is e up to the time
// discretisation of the simulation. The normal force is not clipped at zero: the same
// unclipped equation defines zeta(e).
#pragma once

namespace softpack::damping {

/// Restitution coefficient of a normal Hertz impact with damping coefficient zeta >= 0
/// (0 when the spheres stick).
double restitution_from_zeta(double zeta);

/// The zeta giving restitution e, 0 < e <= 1 (zeta = 0 for e = 1). Accurate to ~1e-9 in e.
/// Remembered for the process (scenes are built many times with the same e).
double zeta_from_restitution(double e);
/// Forgets what zeta_from_restitution remembered, so that the next scene pays its bisection as
/// the first scene of a process does (timings that compare runs of one process,
/// studies/coarse/speed.hpp); the answers are the same bits.
void forget_zeta_cache();

/// zeta sqrt(m k): with k = kn and m = m12 the normal damping factor gamma0
/// (gamma_n = gamma0 h^(1/4) [kg/s]); with k = kt0 and m = mt the tangential one.
double gamma_factor(double zeta, double m, double k);

}  // namespace softpack::damping
