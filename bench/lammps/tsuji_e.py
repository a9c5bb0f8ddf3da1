#!/usr/bin/env python3
"""LAMMPS `damping tsuji` <-> our damping constant alpha.

LAMMPS (pair granular / fix wall/gran, 29Sep2021) turns the restitution
value e' given in the input into
    alpha_L(e') = 1.2728 - 4.2783 e' + 11.087 e'^2 - 22.348 e'^3
                  + 27.467 e'^4 - 18.022 e'^5 + 4.8218 e'^6
and applies  F_damp = -alpha_L * sqrt(m_eff * kn_L * a) * v_n,  a = sqrt(R12 h),
which equals our  -alpha * sqrt(m_eff * kn) * h^(1/4) * v_n  (kn = sqrt(R12)/D)
exactly when alpha_L(e') = alpha.  alpha_L is strictly decreasing on
[-0.2, 1.05] (checked numerically), so e' is unique.

usage:  tsuji_e.py ALPHA        -> prints e' with alpha_L(e') = ALPHA
        tsuji_e.py --alpha E    -> prints alpha_L(E)
"""
import sys

C = (1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218)


def alpha_lammps(e):
    """Same power-sum form as LAMMPS evaluates it."""
    return sum(c * e**k for k, c in enumerate(C))


def e_for_alpha(alpha, lo=-0.2, hi=1.05):
    """Bisection on the decreasing polynomial; |alpha_L(e') - alpha| ~ 1e-16."""
    if not alpha_lammps(hi) <= alpha <= alpha_lammps(lo):
        raise ValueError("alpha=%g outside [%g, %g] reachable by LAMMPS tsuji"
                         % (alpha, alpha_lammps(hi), alpha_lammps(lo)))
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if alpha_lammps(mid) > alpha:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--alpha":
        print(repr(alpha_lammps(float(sys.argv[2]))))
    elif len(sys.argv) == 2:
        print(repr(e_for_alpha(float(sys.argv[1]))))
    else:
        sys.exit(__doc__)
