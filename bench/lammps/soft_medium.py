#!/usr/bin/env python3
"""A soft-particle medium for the softpack-lammps benchmark (issue 34): n^3 (or nx ny nz)
soft-particles of the law file's reference radius on a jittered cubic lattice, each pressing its six neighbours at Δn 0.22
(above the soft-soft onset), in a box of six walls pressing the outer ones, random velocities;
friction, rotation and damping (e = 0.5) on. Writes the same bodies twice:

  OUT.yaml             a softpack scene (docs/scene-format.md), run: STEPS steps of the engine's dt
  OUT.data, OUT.in     a LAMMPS data file and input (docs/lammps.md), the same dt and steps

usage: soft_medium.py N LAWFILE STEPS DT OUT [SAFETY]
  N: n (an n x n x n lattice) or nx,ny,nz;
  DT: the engine's step, which `softpack-run` reports (0 writes the scene only, to ask for it);
  SAFETY: the scene's integration.safety, the step over the stable limit (default 0.2)
"""
import math
import random
import sys

if len(sys.argv) not in (6, 7):
    sys.exit(__doc__)
shape = [int(v) for v in sys.argv[1].split(",")]
shape = shape * 3 if len(shape) == 1 else shape
laws, steps, dt, out = sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
safety = float(sys.argv[6]) if len(sys.argv) == 7 else 0.2
if len(shape) != 3 or min(shape) < 1 or steps < 1 or dt < 0:
    sys.exit("soft_medium.py: N (n or nx,ny,nz) >= 1, STEPS >= 1 and DT >= 0 are required")
R, MASS, DN = 0.016, 0.02, 0.22
a = R * (2.0 - DN)  # lattice spacing: neighbours overlap by DN R
rng = random.Random(3401)
bodies = []
for i in range(shape[0]):
    for j in range(shape[1]):
        for k in range(shape[2]):
            x = [(c + 0.5) * a + rng.uniform(-1, 1) * 0.002 for c in (i, j, k)]
            v = [rng.uniform(-1, 1) * 1e-3 for _ in range(3)]
            bodies.append((x, v))
L = [m * a for m in shape]
inset = 0.5 * DN * R  # the walls press the outer bodies at about Δn 0.22
walls = [(axis, side, inset if side == "lo" else L["xyz".index(axis)] - inset) for axis in "xyz" for side in ("lo", "hi")]

with open(out + ".yaml", "w") as f:
    f.write("materials:\n  grain: {E: 5.0e5, nu: 0.3, mu: 0.3, density: 2500.0}\n")
    f.write("effects:\n  normal: hertz\n  friction: tsuji\n  rotation: true\n  damping: {restitution: 0.5, tangential_ratio: 1.0}\n")
    f.write(f"  soft_particles: {{laws: {laws}, grain_contact: wall, beyond_range: report}}\n")
    f.write("particles:\n")
    for x, v in bodies:
        f.write(f"  - {{x: [{x[0]!r}, {x[1]!r}, {x[2]!r}], r: {R!r}, material: grain, mass: {MASS!r}, soft: true, v: [{v[0]!r}, {v[1]!r}, {v[2]!r}]}}\n")
    f.write("planes:\n")
    for axis, side, at in walls:
        point = [0.0, 0.0, 0.0]
        point["xyz".index(axis)] = at
        normal = [0, 0, 0]
        normal["xyz".index(axis)] = 1 if side == "lo" else -1
        f.write(f"  - {{name: {axis}{side}, point: [{point[0]!r}, {point[1]!r}, {point[2]!r}], normal: {normal}, material: grain}}\n")
    f.write(f"integration: {{safety: {safety!r}, tangential_history: synchronized}}\nneighbor: {{skin: 0.2, level_ratio: 2.0}}\n")
    f.write(f"run: {{duration: {(steps * dt if dt > 0 else 1e-9)!r}}}\n")
if dt == 0:
    sys.exit(0)

with open(out + ".data", "w") as f:
    f.write(f"softpack soft medium, {len(bodies)} soft-particles\n\n{len(bodies)} atoms\n1 atom types\n")
    for axis, length in zip("xyz", L):
        f.write(f"{-0.05!r} {length + 0.05!r} {axis}lo {axis}hi\n")
    f.write("\nAtoms # sphere\n\n")
    density = MASS / (4.0 / 3.0 * math.pi * R ** 3)
    for i, (x, _) in enumerate(bodies):
        f.write(f"{i + 1} 1 {2 * R!r} {density!r} {x[0]!r} {x[1]!r} {x[2]!r}\n")
    f.write("\nVelocities\n\n")
    for i, (_, v) in enumerate(bodies):
        f.write(f"{i + 1} {v[0]!r} {v[1]!r} {v[2]!r} 0 0 0\n")
with open(out + ".in", "w") as f:
    f.write("units si\natom_style sphere\natom_modify map array\nboundary f f f\nnewton off\ncomm_modify vel yes\n")
    f.write(f"read_data {out}.data\nset type 1 mass {MASS!r}\n")
    f.write(f"pair_style softpack/soft {laws} restitution 0.5\npair_coeff 1 1 soft soft\n")
    f.write(f"neighbor {0.2 * R!r} bin\nneigh_modify every 1 delay 0 check yes\n")  # the engine's skin, 0.2 r_min
    f.write(f"timestep {dt!r}\nfix move all nve/sphere\n")
    for axis, side, at in walls:
        f.write(f"fix {axis}{side} all softpack/wall {axis} {side} {at!r}\n")
    f.write(f"thermo 0\nrun {steps}\n")
