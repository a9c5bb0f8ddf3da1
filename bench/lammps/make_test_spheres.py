#!/usr/bin/env python3
"""Synthetic input for confined.in.template: N non-overlapping spheres inside a
shell of radius Rs, radii log-uniform in [rmin, rmax], placed largest first by
random sequential addition.  Writes 'x y z r' lines (SI) after a '#' header.
usage: make_test_spheres.py OUT [N=200] [Rs=0.016] [rmin=0.0004] [rmax=0.004] [seed=1]"""
import sys
import numpy as np

if len(sys.argv) < 2:
    sys.exit(__doc__)
out = sys.argv[1]
arg = sys.argv[2:] + ["200", "0.016", "0.0004", "0.004", "1"][len(sys.argv) - 2:]
N, Rs, rmin, rmax, seed = int(arg[0]), *map(float, arg[1:4]), int(arg[4])
rng = np.random.default_rng(seed)
radii = np.sort(np.exp(rng.uniform(np.log(rmin), np.log(rmax), N)))[::-1]
pos = np.empty((0, 3)); rad = np.empty(0)
for r in radii:
    for _ in range(200000):
        p = rng.uniform(-(Rs - r), Rs - r, 3)
        if p @ p <= (Rs - r) ** 2 and np.all(np.sum((pos - p) ** 2, 1) >= (rad + r) ** 2):
            pos = np.vstack([pos, p]); rad = np.append(rad, r)
            break
    else:
        sys.exit("could not place sphere %d (r=%g): lower N or rmax" % (len(rad), r))
phi = np.sum(rad ** 3) / Rs ** 3
with open(out, "w") as fh:
    fh.write("# x y z r  (m)  N=%d Rs=%g phi=%.3f seed=%d\n" % (N, Rs, phi, seed))
    for p, r in zip(pos, rad):
        fh.write("%.17g %.17g %.17g %.17g\n" % (*p, r))
print("wrote %s: N=%d Rs=%g solid fraction %.3f" % (out, N, Rs, phi))
