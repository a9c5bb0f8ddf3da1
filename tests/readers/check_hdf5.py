#!/usr/bin/python3
"""Every HDF5 file of a softpack data folder, read with h5py alone, against docs/reading-files.md.

    /usr/bin/python3 tests/readers/check_hdf5.py DATA_DIR [--profile PROFILE.yaml] [--guide GUIDE.md]

DATA_DIR is a profile's folder (data/quick, data/archive/0.5.0/paper). Every .h5 in it must be
a packing, a sweep results file, an average or a checkpoint, and every fits/*.json a fit. The
layout is the guide's: its tables (after the `<!-- kind: ... -->` markers) are read here, so a
dataset the guide does not list, a listed one that is missing, another shape, type or `unit`
attribute fails. Counts must agree across files: len(radii) = len(centres) = stats/inserted,
one sweep row per grid point (the profile's grid with --profile or DATA_DIR/profile.yaml, else
one grid for all seeds), a results file per scene and seed, Fn = force[:, 0], hn = Δn Rs, the
averages equal to the mean and standard error of the seeds' results (1e-12 relative), the fits
to their average's seeds and grid, a checkpoint's state holding the spheres of its scene's
packings and its result the row of the results file. Needs python3-yaml for the profile only.

Exit 0: every file agrees; 1: one that cannot be opened or differs (each problem on a FAIL line);
2: usage; 77: python3-h5py (or numpy) is not installed.
"""
import argparse
import json
import math
import re
import sys
from pathlib import Path

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"check_hdf5.py: {e}: python3-h5py is not installed: skipped")
    sys.exit(77)

GUIDE = Path(__file__).resolve().parents[2] / "docs" / "reading-files.md"
errors = []


def fail(where, message):
    errors.append(f"{where}: {message}")


def report(where, before, message):
    """ok: line for a file that added no problem since `before` problems ("quiet": none)."""
    if len(errors) == before and message != "quiet":
        print(f"ok: {where}: {message}")


# --- The guide's tables -------------------------------------------------------------------------

def read_guide(path):
    """{kind: [row cells]} of the tables that follow a <!-- kind: K --> marker."""
    tables, kind = {}, None
    for line in path.read_text(encoding="utf-8").splitlines():
        m = re.match(r"<!-- kind: (\w+) -->", line)
        if m:
            kind = m.group(1)
            tables[kind] = []
        elif kind and line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if cells[0] not in ("dataset", "key") and not set(cells[0]) <= set("-"):
                tables[kind].append(cells)
        elif kind and tables[kind]:
            kind = None
    return tables


def expand(name):
    """The names a table's name stands for: `a/{b, c}_{d, e}` is a/b_d, a/b_e, a/c_d, a/c_e."""
    m = re.search(r"\{([^}]*)\}", name)
    if not m:
        return [name]
    return [n for alt in m[1].split(",") for n in expand(name[:m.start()] + alt.strip() + name[m.end():])]


def dataset_specs(rows):
    """(name, shape, type, unit, unit_attribute, since) of each dataset of an HDF5 table."""
    specs = []
    for name, shape, type_, unit, meaning in (r[:5] for r in rows):
        # axes separated by ",", an axis "D·S" is one flattened axis of D times S entries
        dims = tuple(tuple(int(d) if d.isdigit() else d for d in re.findall(r"\w+", axis)) for axis in shape.split(","))
        dims = tuple(axis[0] if len(axis) == 1 else axis for axis in dims if axis)
        since = re.search(r"since (\d+)\.(\d+)\.(\d+)", meaning)
        specs += [(n, dims, type_, unit.strip("*"), unit.startswith("**"), tuple(map(int, since.groups())) if since else (0, 0, 0))
                  for names in re.findall(r"`([^`]+)`", name) for n in expand(names)]
    return specs


# --- One file against its table -------------------------------------------------------------------

def release(f):
    m = re.match(r"(\d+)\.(\d+)\.(\d+)", text(f, "provenance/code_version") if "provenance/code_version" in f else "")
    return tuple(map(int, m.groups())) if m else (999, 0, 0)


def text(f, name):
    return f[name].asstr()[()]


def check_layout(f, where, specs):
    """Datasets, shapes, types and unit attributes as the guide says; returns the bound counts."""
    present = set()
    f.visititems(lambda name, obj: present.add(name) if isinstance(obj, h5py.Dataset) else None)
    dims, documented, file_release = {}, set(), release(f)
    if "normal/seeds" in f:  # S, the seeds of an average file (its per-seed datasets are D·S, K·S)
        dims["S"] = int(f["normal/seeds"][()])
    for name, shape, type_, unit, unit_attribute, since in specs:
        pattern = re.compile(re.escape(name).replace(re.escape("<w>"), r"(\d+)") + "$")
        found = sorted(n for n in present if pattern.match(n))
        documented.update(found)
        if not found and "<w>" not in name and file_release >= since:
            fail(where, f"/{name} is missing (docs/reading-files.md lists it)")
        for n in found:
            ds, wall = f[n], pattern.match(n).groups()
            if type_ == "str":
                ok = h5py.check_string_dtype(ds.dtype) is not None
            else:
                ok = ds.dtype == np.dtype(type_)
            if not ok:
                fail(where, f"/{n}: type {ds.dtype}, the guide says {type_}")
            if len(ds.shape) != len(shape):
                fail(where, f"/{n}: shape {ds.shape}, the guide says {shape}")
                continue
            for axis, (size, want) in enumerate(zip(ds.shape, shape)):
                if isinstance(want, int):
                    bound = want
                elif isinstance(want, tuple):  # a product of counts bound elsewhere in the file
                    if any(w not in dims for w in want if not isinstance(w, int)):
                        fail(where, f"/{n}: axis {axis} is {'·'.join(map(str, want))}, a count not bound in the file")
                        continue
                    bound = math.prod(w if isinstance(w, int) else dims[w] for w in want)
                else:  # a count: the first dataset with it binds it (m: per wall group)
                    bound = dims.setdefault(f"m of {name.replace('<w>', wall[0])}" if wall and want == "m" else want, size)
                if size != bound:
                    fail(where, f"/{n}: axis {axis} has {size} entries, but {want} = {bound} elsewhere in the file "
                                f"(shape {ds.shape}, the guide says {shape})")
            got = ds.attrs.get("unit")
            got = got.decode() if isinstance(got, bytes) else got  # a fixed-length string: bytes in h5py
            if unit_attribute and got != unit:
                fail(where, f"/{n}: attribute unit = {got!r}, the guide says {unit!r}")
            if not unit_attribute and got is not None:
                fail(where, f"/{n}: attribute unit = {got!r}, the guide lists none")
    for n in sorted(present - documented):
        fail(where, f"/{n} is not in docs/reading-files.md")
    return dims


def same(where, what, got, want, rtol=0.0):
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    if got.shape != want.shape:
        fail(where, f"{what}: {got.shape[0] if got.ndim else 1} values, expected {want.shape[0] if want.ndim else 1}")
    elif rtol == 0.0 and not np.array_equal(got, want, equal_nan=True):
        fail(where, f"{what}: {got.ravel()[:6]}... differs from {want.ravel()[:6]}...")
    elif rtol and not np.allclose(got, want, rtol=rtol, atol=rtol * np.max(np.abs(want), initial=0.0)):
        k = int(np.argmax(np.abs(got - want)))
        fail(where, f"{what}: value {k} is {got.ravel()[k]!r}, expected {want.ravel()[k]!r} (relative {rtol})")


def mean_error(values):
    """analysis/average.cpp's mean and standard error, in its order of operations."""
    n, m = float(len(values)), 0.0
    for x in values:
        m += x / n
    ss = sum((x - m) * (x - m) for x in values) if len(values) > 1 else 0.0
    return m, (math.sqrt(ss / (n - 1.0) / n) if len(values) > 1 else 0.0)


def slope(x, y):
    n = float(len(x))
    mx, my = sum(v / n for v in x), sum(v / n for v in y)
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else 0.0


# --- The data folder ------------------------------------------------------------------------------

def profile_grid(args, data):
    """The profile's seeds, scenes and grids, or None (no profile, or no python3-yaml)."""
    path = Path(args.profile) if args.profile else data / "profile.yaml"
    if not path.exists():
        return None
    try:
        import yaml
    except ImportError:
        print(f"note: no python3-yaml: the grid is not compared with {path}")
        return None
    p = yaml.safe_load(path.read_text())
    return {"name": p["profile"], "seeds": list(p["seeds"]), "scenes": list(p["normal"]["scenes"]),
            "Rs": float(p["packing"]["Rs"]), "bins": int(p["packing"].get("profile_bins", 0)) or None,
            "normal": [float(x) for x in p["normal"]["delta_n"]],
            "tangential": [(float(d), float(a)) for d in p["tangential"]["delta_n"] for a in p["tangential"]["alpha_deg"]]}


def visit(paths, data, spec, body):
    """body(path, where, f, dims) for each file that h5py opens and whose layout is the guide's;
    its string is the file's ok: line. A file that cannot be read as the guide says is a FAIL."""
    for path in paths:
        where, before = path.relative_to(data), len(errors)
        try:
            f = h5py.File(path, "r")
        except OSError as e:
            fail(where, f"h5py cannot open it: {e}")
            continue
        try:
            with f:
                dims = check_layout(f, where, spec)
                if len(errors) == before:
                    report(where, before, body(path, where, f, dims))
        except (KeyError, ValueError, IndexError, TypeError, AttributeError, OSError) as e:
            fail(where, f"cannot be read as the guide says: {type(e).__name__}: {e}")


class Folder:
    """What the files of one data folder say, gathered kind by kind for the next kind's checks."""

    def __init__(self, data, grid, normal_only=False):
        self.data, self.grid, self.normal_only = data, grid, normal_only
        self.sizes, self.Rs = {}, {}  # packing file name: spheres, shell radius
        self.results = {}             # (stage, scene, seed): columns of the results file
        self.averages = {}            # scene: seeds, delta_n

    def packing(self, path, where, f, d):
        x, r, Rs, grid = f["centres"][:], f["radii"][:], f["shell/radius"][()], self.grid
        imported = text(f, "provenance/program") == "softpack-import"
        if f["stats/inserted"][()] != len(r) or \
                (not imported and f["stats/sampled"][()] != len(r) + f["stats/discarded"][()]):
            fail(where, "stats/inserted differs from the number of spheres, or sampled from inserted + discarded")
        if np.any(np.linalg.norm(x, axis=1) + r > Rs * (1 + 1e-9)) or np.any(r <= 0) or \
                (not imported and np.any(r < f["radii_inserted"][:])):
            fail(where, "a sphere reaches beyond the shell, has a radius <= 0, or shrank in the growth")
        if imported and len(text(f, "imported/source_sha256")) != 64:
            fail(where, "imported/source_sha256 is not 64 hex digits")
        if f["parameters/Rs"][()] != Rs or (grid and Rs != grid["Rs"]) or (grid and grid["bins"] and d["B"] != grid["bins"]):
            fail(where, "shell/radius, parameters/Rs and the profile's Rs (or profile_bins) differ")
        if f["provenance/seed"][()] != int(path.stem.split("-")[-1]):
            fail(where, "provenance/seed differs from the file name")
        self.sizes[path.name], self.Rs[path.name] = len(r), Rs
        return f"{len(r)} spheres in a shell of radius {Rs} m, {d['B']} radial bins"

    def sweep(self, path, where, f, d):
        stage, m = path.parent.name, re.match(r"(soft-solid|soft-soft)-seed-(\d+)$", path.stem)
        if not m or text(f, "provenance/stage") != stage or text(f, "provenance/scene") != m[1] \
                or f["provenance/seed"][()] != int(m[2]):
            fail(where, "the file name, its folder and provenance/{stage, scene, seed} disagree")
            return ""
        col = {k: f[k][:] for k in ("delta_n", "hn", "alpha_deg", "ht", "Fn", "Ft_parallel", "Ft_perpendicular", "force")}
        for k, axis in (("Fn", 0), ("Ft_parallel", 1), ("Ft_perpendicular", 2)):
            same(where, f"/{k} against /force[:, {axis}]", col[k], col["force"][:, axis])
        names = [Path(p).name for p in re.findall(r"(\S+) \(seed \d+[,)]", text(f, "provenance/packings"))]
        if len(names) != (1 if m[1] == "soft-solid" else 2) or names[0] != f"seed-{m[2]}.h5" \
                or any(n not in self.sizes for n in names):
            fail(where, f"provenance/packings {names}: not this seed's packing(s) of packings/")
            return ""
        Rs = self.Rs[names[0]]
        same(where, "/hn against delta_n Rs", col["hn"], col["delta_n"] * Rs, rtol=1e-12)
        same(where, "/ht against pi Rs alpha / 180", col["ht"], math.pi * Rs * col["alpha_deg"] / 180.0, rtol=1e-12)
        points = f["relaxation/checks/point"][:]
        if np.any(np.diff(points) < 0) or np.any(points < 0) or np.any(points >= d["P"]):
            fail(where, "/relaxation/checks/point: not rows 0 to P - 1 in order")
        else:
            last = {p: k for k, p in enumerate(points)}
            ratio = [f["relaxation/checks/force_ratio"][last[p]] if p in last else 0.0 for p in range(d["P"])]
            same(where, "/relaxation/final_force_ratio against its last check", f["relaxation/final_force_ratio"][:], ratio)
        rows = list(zip(col["delta_n"], col["alpha_deg"])) if stage == "tangential" else list(col["delta_n"])
        if self.grid and rows != self.grid[stage]:
            fail(where, f"the rows differ from the profile's {stage} grid ({len(self.grid[stage])} points)")
        if stage == "normal" and (np.any(col["alpha_deg"] != 0) or np.any(col["ht"] != 0)):
            fail(where, "a normal sweep with alpha or ht not 0")
        self.results[(stage, m[1], int(m[2]))] = dict(col, packings=names, rows=rows, config=text(f, "provenance/config"))
        return f"{d['P']} points, {d['C']} relaxation checks"

    def average(self, path, where, f, d):
        scene, grid = path.stem, self.grid
        if text(f, "provenance/scene") != scene or (grid and text(f, "provenance/profile") != grid["name"]):
            fail(where, "provenance/scene differs from the file name, or provenance/profile from the profile's name")
        inputs = [Path(p) for p in text(f, "provenance/inputs").split("\n") if p]
        keys = [(p.parent.name, *re.fullmatch(r"(.*)-seed-(\d+)", p.stem).groups()) for p in inputs]
        normal = [self.results.get((st, sc, int(seed))) for st, sc, seed in keys if st == "normal"]
        tangential = [self.results.get((st, sc, int(seed))) for st, sc, seed in keys if st == "tangential"]
        if not normal or None in normal + tangential or any(k[1] != scene for k in keys) or \
                len(normal) != (len(normal) if self.normal_only else len(tangential)):
            fail(where, f"provenance/inputs {[str(p) for p in inputs]}: not this scene's results in the folder")
            return ""
        seeds = f["normal/seeds"][()]
        if seeds != len(normal) or (grid and seeds != len(grid["seeds"])):
            fail(where, f"normal/seeds = {seeds}, but {len(normal)} normal results are averaged")
        same(where, "/normal/delta_n", f["normal/delta_n"][:], normal[0]["delta_n"])
        groups = [("normal", normal, ("Fn", "Ft_parallel", "Ft_perpendicular")),
                  ("tangential", tangential, ("Ft_parallel", "Ft_perpendicular", "Fn"))]
        if self.normal_only and ("tangential" in f or "kt" in f):
            fail(where, "a normal-only profile's average holds /tangential or /kt")
        for group, runs, columns in groups[:1] if self.normal_only else groups:
            for c in columns:
                me = [mean_error([run[c][k] for run in runs]) for k in range(len(runs[0][c]))]
                same(where, f"/{group}/{c}_mean", f[f"{group}/{c}_mean"][:], [m for m, _ in me], rtol=1e-12)
                same(where, f"/{group}/{c}_stderr", f[f"{group}/{c}_stderr"][:], [e for _, e in me], rtol=1e-12)
        if self.normal_only:  # no tangential stage: the normal group only
            self.averages[scene] = {"seeds": int(seeds), "delta_n": f["normal/delta_n"][:]}
            return f"{d['D']} normal rows: the mean of {seeds} seeds' results (normal only)"
        for c in ("delta_n", "alpha_deg", "ht"):
            same(where, f"/tangential/{c}", f[f"tangential/{c}"][:], tangential[0][c])
        dn = tangential[0]["delta_n"]
        same(where, "/kt/delta_n", f["kt/delta_n"][:], list(dict.fromkeys(dn)))
        blocks = [np.flatnonzero(dn == v) for v in dict.fromkeys(dn)]
        kt = [mean_error([slope(run["ht"][b], run["Ft_parallel"][b]) for run in tangential]) for b in blocks]
        same(where, "/kt/mean", f["kt/mean"][:], [m for m, _ in kt], rtol=1e-9)
        same(where, "/kt/stderr", f["kt/stderr"][:], [e for _, e in kt], rtol=1e-9)
        self.averages[scene] = {"seeds": int(seeds), "delta_n": f["normal/delta_n"][:]}
        return f"{d['D']} normal rows, {d['T']} tangential rows, {d['K']} kt rows: the mean of {seeds} seeds' results"

    def point(self, path, where, f, d):
        stage, scene, seed = path.parts[-4], path.parts[-3], int(path.parts[-2][5:])
        index = [int(i) for i in re.findall(r"\d+", path.stem)]
        if text(f, "provenance/stage") != stage or text(f, "provenance/scene") != scene \
                or len(index) != (1 if stage == "normal" else 2):
            fail(where, "its folder and name disagree with provenance/{stage, scene}")
            return ""
        run = self.results.get((stage, scene, seed))
        if run:
            S = sum(self.sizes[n] for n in run["packings"])
            if d["S"] != S:
                fail(where, f"state/x holds {d['S']} spheres, the packings of the results file {S}")
            k = index[0] * len(set(run["alpha_deg"])) + index[1] if stage == "tangential" else index[0]
            if text(f, "provenance/config") == run["config"]:  # else: a stale checkpoint, not reused
                same(where, f"/result/force against row {k} of {stage}/{scene}-seed-{seed}.h5", f["result/force"][:], run["force"][k])
        for w in ("w", "T"):
            if f[f"state/{w}"].shape[0] not in (0, d["S"]):
                fail(where, f"/state/{w} has neither S = {d['S']} nor 0 rows")
        ids = [f["state/pair_springs/i"][:], f["state/pair_springs/j"][:]]
        for group, walls in (("plane_springs", d["Q"]), ("shell_springs", d["W"])):
            groups = sorted(f[f"state/{group}"].keys(), key=int) if f"state/{group}" in f else []
            if groups != [str(w) for w in range(walls)]:
                fail(where, f"/state/{group}: groups {groups}, expected one per wall (0 to {walls - 1})")
            ids += [f[f"state/{group}/{g}/i"][:] for g in groups]
        if any(np.any(i < 0) or np.any(i >= d["S"]) for i in ids) or np.any(ids[0] >= ids[1]):
            fail(where, "a spring's sphere is not one of the state's, or a pair spring has i >= j")
        return "quiet"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("data", type=Path)
    ap.add_argument("--profile", help="the profile file (default: DATA_DIR/profile.yaml when there)")
    ap.add_argument("--guide", type=Path, default=GUIDE)
    ap.add_argument("--normal-only", action="store_true",
                    help="a normal-only profile's folder (no tangential results; averages of the normal law only)")
    args = ap.parse_args()
    data = args.data
    if not data.is_dir():
        print(f"check_hdf5.py: {data} is not a folder", file=sys.stderr)
        return 2
    tables = read_guide(args.guide)
    specs = {k: dataset_specs(tables.get(k, [])) for k in ("packing", "sweep", "average", "point")}
    for kind, s in specs.items():
        if not s:
            fail(args.guide, f"no table of kind {kind}")
    folder = Folder(data, profile_grid(args, data), args.normal_only)
    if args.normal_only:  # the averages without their tangential and kt groups
        specs["average"] = [spec for spec in specs["average"] if not spec[0].startswith(("tangential/", "kt/"))]
    grid, results = folder.grid, folder.results

    # A packing is generated (softpack-pack) or imported (softpack-import): the guide's table of its kind.
    generated, imported = [], []
    for p in sorted(data.glob("packings/*.h5")):
        try:
            with h5py.File(p, "r") as f:
                (imported if text(f, "provenance/program") == "softpack-import" else generated).append(p)
        except (OSError, KeyError):
            generated.append(p)  # visit() says what is wrong with it
    visit(generated, data, specs["packing"], folder.packing)
    visit(imported, data, dataset_specs(tables.get("imported_packing", [])), folder.packing)
    visit(sorted(data.glob("normal/*.h5")) + sorted(data.glob("tangential/*.h5")), data, specs["sweep"], folder.sweep)
    for stage in ("normal",) if args.normal_only else ("normal", "tangential"):
        if len({tuple(v["rows"]) for k, v in results.items() if k[0] == stage}) > 1:
            fail(data / stage, "the seeds' results have different grids")
        have = sorted((k[1], k[2]) for k in results if k[0] == stage)
        want = sorted((s, seed) for s in grid["scenes"] for seed in grid["seeds"]) if grid else have
        if have != want:
            fail(data / stage, f"results of (scene, seed) {have}, the profile has {want}")
    visit(sorted(data.glob("averages/*.h5")), data, specs["average"], folder.average)

    fit_keys = [re.findall(r"`([\w.]+)`", row[0]) + [row[-1]] for row in tables.get("fit", [])]
    fits = sorted(data.glob("fits/*.json"))
    for path in fits:
        where, before = path.relative_to(data), len(errors)
        try:
            j = json.loads(path.read_text())
            check_fit_keys(j, where, fit_keys)
            check_fit(j, where, path.stem, folder.averages.get(path.stem))
        except (ValueError, KeyError, TypeError, IndexError, AttributeError) as e:
            fail(where, f"not a fit file as the guide says: {type(e).__name__}: {e}")
            continue
        law = j["tangential"]
        report(where, before, f"Eq. 7 on {j['normal']['points']} points, Eq. 8 {'on ' + str(law['points']) if law else 'none'}")

    before, points = len(errors), sorted(data.glob("checkpoints/*/*/seed-*/point-*.h5"))
    visit(points, data, specs["point"], folder.point)
    if points:
        report("checkpoints", before, f"{len(points)} point files: layout as the guide says, the spheres of their "
                                      "packings, each the row of its results file")

    for path in sorted(data.rglob("*.h5")):
        parts = path.relative_to(data).parts
        if len(parts) != (5 if parts[0] == "checkpoints" else 2) or \
                parts[0] not in ("packings", "normal", "tangential", "averages", "checkpoints"):
            fail(path.relative_to(data), "an HDF5 file of no kind the guide describes")
    counts = {"packings": len(folder.sizes), "results": len(results), "averages": len(folder.averages),
              "fits": len(fits), "checkpoints": len(points)}
    if args.normal_only:
        if not (counts["packings"] and counts["results"] and counts["averages"] and counts["fits"]) or \
                any(k[0] == "tangential" for k in results):
            fail(data, f"a normal-only folder holds packings, normal results, averages and fits ({counts})")
    elif not (counts["packings"] and counts["results"] and counts["averages"] and counts["fits"]):
        fail(data, f"no packings, results, averages or fits found ({counts})")
    for e in errors:
        print(f"FAIL: {e}")
    if errors:
        print(f"check_hdf5.py: {len(errors)} problem(s) in {data}", file=sys.stderr)
        return 1
    print(f"ok: {data}: every HDF5 file opens with h5py and agrees with {args.guide.name} "
          f"({', '.join(f'{v} {k}' for k, v in counts.items())})")
    return 0


def check_fit_keys(j, where, rows):
    """The keys the guide's fit table lists are there (but those it says are written only
    sometimes), and the file has no top-level or normal.* key the table does not list."""
    listed = set()
    for *keys, meaning in rows:
        for key in keys:
            listed.update(key.rsplit(".", k)[0] for k in range(key.count(".") + 1))
            node = j
            for part in key.split("."):
                node = node.get(part, KeyError) if isinstance(node, dict) else KeyError
            if node is KeyError and not re.search(r"only (when|with|then)|written only", meaning):
                fail(where, f"{key} is missing (docs/reading-files.md lists it)")
    for key in list(j) + [f"normal.{k}" for k in j["normal"]]:
        if key not in listed:
            fail(where, f"{key} is not in docs/reading-files.md")


def check_fit(j, where, scene, average):
    n, t = j["normal"], j["tangential"]
    if j["scene"] != scene:
        fail(where, f"scene = {j['scene']!r}, the file name says {scene}")
    for law, keys, size in ((n, "a b c delta", 3), (t, "a b c", 2)):
        if law is None:
            continue
        for key in keys.split():
            if not (isinstance(law[key], (int, float)) or key == "delta") or not isinstance(law[key + "_error"], (int, float, type(None))):
                fail(where, f"{key}: not a number, or its error neither a number nor null")
        if not (isinstance(law["points"], int) and isinstance(law["weighted"], bool) and len(law["range"]) == 2
                and isinstance(law["notes"], list) and [len(r) for r in law["covariance"]] == [size] * size):
            fail(where, "points, weighted, range, notes or covariance not as the guide says")
    if n["c"] < 0 and not (n["delta"] is not None and math.isclose(n["delta"], (-n["c"] / n["a"]) ** (1 / n["b"]), rel_tol=1e-9)):
        fail(where, "normal.delta differs from (-c/a)^(1/b)")
    if t is None and not isinstance(j["tangential_reason"], str):
        fail(where, "tangential is null without tangential_reason")
    if t is not None and (t["delta_used"] != n["delta"] or not math.isclose(t["c"], -t["a"] * n["delta"] ** t["b"], rel_tol=1e-9)):
        fail(where, "tangential.delta_used differs from normal.delta, or c from -a delta^b")
    p = j["provenance"]
    source = p["inputs"][0]
    if p["program"] != "softpack-fit" or source["scene"] != scene or Path(source["path"]).name != f"{scene}.h5":
        fail(where, "provenance: not softpack-fit's fit of this scene's average")
    if average and (source["seeds"] != average["seeds"] or n["points"] > len(average["delta_n"])
                    or n["range"][0] < average["delta_n"][0] or n["range"][1] > average["delta_n"][-1]):
        fail(where, "seeds, points or range do not fit the average file")


if __name__ == "__main__":
    sys.exit(main())
