#!/usr/bin/python3
"""Figure 3, the normal contact law Fn(Δn), redrawn with h5py, json and matplotlib.

    /usr/bin/python3 examples/figure3.py DATA_FOLDER [OUT.png|OUT.pdf]
    /usr/bin/python3 examples/figure3.py data/archive/0.5.0/paper figure3.png

DATA_FOLDER is a profile's results (data/paper after `make tables`, or an archive such as
data/archive/0.5.0/paper). For the soft-solid and the soft-soft scene it reads

    averages/<scene>.h5   normal/delta_n            Δn = hn / Rs, the normal grid
                          normal/Fn_mean, Fn_stderr  the normal force [N]: mean over the seeds
                                                     and its standard error
    fits/<scene>.json     "normal": a [N], b, c [N], delta, Eq. 7 fitted by softpack-fit:
                          Fn = a Δn^b + c for Δn >= delta, 0 below

(docs/reading-files.md lists every dataset and key) and draws, as figures/fig3_normal.gp does,
the mean forces with their error bars and the fitted law on a logarithmic force axis. Zero
forces (before the onset delta) have no place on a log axis: they are drawn as open triangles
on the bottom of the axis. Not drawn here: Hertz's law and the paper's Table 1, which the
gnuplot script takes from the profile and experiments/published.yaml.

In a notebook, leave out matplotlib.use("Agg") and call load_average, load_fit and eq7.
"""
import json
import sys
from pathlib import Path

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")  # draw to a file, no display needed
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

SCENES = {"soft-solid": ("#1f5fa8", "o"), "soft-soft": ("#c8400e", "s")}  # colour, marker


def load_average(folder, scene):
    """Δn, mean Fn [N], its standard error [N], and the average file's provenance."""
    with h5py.File(Path(folder) / "averages" / f"{scene}.h5", "r") as f:
        about = {key: f[f"provenance/{key}"].asstr()[()] for key in ("profile", "code_version")}
        about["seeds"] = int(f["normal/seeds"][()])
        return f["normal/delta_n"][:], f["normal/Fn_mean"][:], f["normal/Fn_stderr"][:], about


def load_fit(folder, scene):
    """Eq. 7's coefficients: the "normal" object of the fit file (a, b, c, delta, their errors...)."""
    return json.loads((Path(folder) / "fits" / f"{scene}.json").read_text())["normal"]


def eq7(dn, a, b, c, delta):
    """Eq. 7: Fn = a Δn^b + c for Δn >= delta, 0 below [N]."""
    dn = np.asarray(dn, dtype=float)
    return np.where(dn >= delta, a * dn**b + c, 0.0)


def measured(folder):
    """The scenes the folder holds an average and a fit of (a profile may measure one scene)."""
    return [s for s in SCENES if (Path(folder) / "averages" / f"{s}.h5").is_file() and (Path(folder) / "fits" / f"{s}.json").is_file()]


def main(folder, out="figure3.png"):
    fig, ax = plt.subplots(figsize=(5.0, 4.6))
    data = {scene: (*load_average(folder, scene), load_fit(folder, scene)) for scene in measured(folder)}
    # The axis floor: the decade below the smallest positive mean force (as fig3_normal.gp).
    smallest = min(F[F > 0].min(initial=1e-4) for _, F, _, _, _ in data.values())
    floor = 10.0 ** max(np.floor(np.log10(smallest)), -5)
    for scene, (dn, F, err, about, fit) in data.items():
        colour, marker = SCENES[scene]
        loaded = F >= floor
        ax.errorbar(dn[loaded], F[loaded], yerr=err[loaded], fmt=marker, ms=4, color=colour, capsize=2,
                    label=f"{scene}, mean ± s.e. over {about['seeds']} seeds")
        ax.plot(dn[~loaded], np.full((~loaded).sum(), floor), "v", mfc="none", color=colour, ms=5)
        a, b, c, delta = (fit[k] for k in ("a", "b", "c", "delta"))
        if delta is None:  # undefined when c >= 0: the law starts at 0
            delta = (-c / a) ** (1 / b) if c < 0 < a else 0.0
        x = delta + (dn.max() - delta) * np.linspace(0, 1, 400) ** 3  # dense near the onset, where Fn rises steeply
        y = eq7(x, a, b, c, delta)
        ax.plot(x[y > 0], y[y > 0], "-", color=colour, lw=1.5,
                label=f"{scene}, Eq. 7: a = {a:.3g} N, b = {b:.3g}, δ = {delta:.3f}")
    ax.set_yscale("log")
    ax.set_ylim(floor, None)
    ax.set_xlim(0, max(dn.max() for dn, *_ in data.values()) * 1.02)
    ax.set_xlabel(r"normal deformation $\Delta_n = h_n / R_s$")
    ax.set_ylabel(r"normal force $F_n$ [N]")
    ax.grid(color="#dddddd", lw=0.5)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title(f"Figure 3: {about['profile']} profile, softpack {about['code_version']}", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=200)  # PNG or PDF, after the name's suffix
    print(f"figure3.py: {out} from {folder} (zero forces drawn at {floor:g} N)")


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0)
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.split("\n\n")[1])
    if not measured(sys.argv[1]):  # a clear message, not a traceback, when the folder holds no scene
        sys.exit(f"figure3.py: {sys.argv[1]}: no scene with both averages/<scene>.h5 and fits/<scene>.json "
                 f"({', '.join(SCENES)}): give a profile's folder after make tables (data/<profile>) or an archive folder")
    main(*sys.argv[1:])
