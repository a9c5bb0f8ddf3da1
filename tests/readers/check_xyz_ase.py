#!/usr/bin/python3
"""A packing's extended-XYZ export read by ASE, against the packing file.

    /usr/bin/python3 tests/readers/check_xyz_ase.py packings/seed-1.xyz packings/seed-1.h5

ase.io.read(format="extxyz") must find one frame with one atom (species X) per sphere of the
packing file (read with h5py), the positions equal to the centres and atoms.arrays["radius"]
to the radii (1e-12 relative), and the box softpack-pack writes: Lattice = the cube of side 2 Rs
(atoms.cell), Origin = (-Rs, -Rs, -Rs) (kept by ASE in atoms.info["Origin"]; ASE's own cell
starts at 0), pbc F F F, every sphere inside that box, and a provenance naming softpack-pack
and the packing's seed.

Exit 0: ok; 1: ASE cannot read the file or disagrees; 2: usage; 77: python3-ase (or h5py) is
not installed.
"""
from packing_reference import Failed, close, load_packing, main, need

need(["ase.io"], "python3-ase")
import ase  # noqa: E402
import ase.io  # noqa: E402
import numpy as np  # noqa: E402


def run(xyz, h5):
    centres, radii, Rs, seed = load_packing(h5)
    try:
        frames = ase.io.read(xyz, index=":", format="extxyz")
    except Exception as e:  # ASE raises what its parser meets: ValueError, IndexError, XYZError...
        raise Failed(f"ase.io.read cannot read {xyz}: {type(e).__name__}: {e}")
    if len(frames) != 1:
        raise Failed(f"ASE reads {len(frames)} frames in {xyz}, expected 1")
    atoms, n = frames[0], len(radii)
    if len(atoms) != n:
        raise Failed(f"ASE reads {len(atoms)} atoms in {xyz}, {h5} holds {n} spheres")
    if "radius" not in atoms.arrays:
        raise Failed(f"ASE finds no per-atom 'radius' in {xyz} (arrays: {sorted(atoms.arrays)})")
    if set(atoms.get_chemical_symbols()) != {"X"}:
        raise Failed(f"species {sorted(set(atoms.get_chemical_symbols()))}, expected X only")
    close(f"ASE: positions of {xyz}", atoms.positions, centres, Rs)
    close(f"ASE: radius of {xyz}", atoms.arrays["radius"], radii, np.max(radii))
    close(f"ASE: cell (Lattice) of {xyz}", atoms.cell[:], np.diag([2 * Rs] * 3), Rs)
    if "Origin" not in atoms.info:
        raise Failed(f"ASE finds no Origin in {xyz} (info: {sorted(atoms.info)})")
    origin = np.asarray(atoms.info["Origin"], dtype=float)
    close(f"ASE: Origin of {xyz}", origin, [-Rs] * 3, Rs)
    if atoms.pbc.any():
        raise Failed(f"ASE reads pbc {atoms.pbc} in {xyz}, expected F F F")
    lo, hi = origin, origin + np.diag(atoms.cell[:])
    inside = (atoms.positions - atoms.arrays["radius"][:, None] >= lo - 1e-9 * Rs) & \
             (atoms.positions + atoms.arrays["radius"][:, None] <= hi + 1e-9 * Rs)
    if not inside.all():
        raise Failed(f"sphere {int(np.argmin(inside.all(axis=1)))} of {xyz} reaches out of the box Origin + Lattice")
    provenance = str(atoms.info.get("provenance", ""))
    if "softpack-pack" not in provenance or f"seed {seed} " not in provenance + " ":
        raise Failed(f"provenance {provenance!r} of {xyz} does not name softpack-pack and seed {seed}")
    return f"ASE {ase.__version__} reads {xyz}: {n} atoms, radius, positions, cell 2Rs = {2 * Rs} m and Origin as in {h5}"


if __name__ == "__main__":
    main(run, "check_xyz_ase.py FILE.xyz PACKING.h5")
