#!/usr/bin/python3
"""Compare two data folders of one profile, file by file, and print what differs.

    same_results.py DIR_A DIR_B [SUBFOLDER...]      (default: averages fits tables normal tangential)

Every file of each subfolder must exist in both. What no two runs share is set aside and
nothing else: the provenance (seconds spent, code version string, host) and a sweep point's
timing. Precisely:
  - text (.dat .gp .md .tex): byte-identical once comment lines ('#', '<!--', and the LaTeX
    '%' lines) are removed;
  - JSON (.json): identical once the top-level "provenance" object is removed, numbers compared
    as the text the file holds (17 significant digits: bit for bit);
  - HDF5 (.h5): the same groups, datasets and attributes; every dataset's dtype, shape and raw
    bytes identical, except the groups /provenance and /timing and the dataset /seconds.
Exit 0 when everything matches, 1 with one line per difference otherwise, 2 on bad usage.
"""
import json
import os
import sys

SKIP_H5 = ("provenance", "timing", "seconds")


def text_lines(path):
    with open(path, "rb") as f:
        return [l for l in f.read().split(b"\n")
                if not l.startswith((b"#", b"<!--", b"%"))]


def json_body(path):
    with open(path) as f:
        text = f.read()
    doc = json.loads(text)
    doc.pop("provenance", None)
    return json.dumps(doc, sort_keys=True)


def h5_items(path):
    import h5py
    import numpy as np
    items = {}

    def attrs(name, obj):
        for k, v in obj.attrs.items():
            items[f"{name}@{k}"] = np.asarray(v).tobytes() + str(np.asarray(v).dtype).encode()

    with h5py.File(path, "r") as f:
        attrs("/", f)

        def visit(name, obj):
            if name.split("/")[0] in SKIP_H5:
                return
            attrs(name, obj)
            if isinstance(obj, h5py.Dataset):
                data = obj[()]
                items[name] = (str(obj.dtype), obj.shape, np.asarray(data).tobytes())

        f.visititems(visit)
    return items


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2
    a, b = argv[1], argv[2]
    subs = argv[3:] or ["averages", "fits", "tables", "normal", "tangential"]
    problems, compared = [], 0
    for sub in subs:
        da, db = os.path.join(a, sub), os.path.join(b, sub)
        names = lambda d: sorted(n for n in os.listdir(d) if not n.endswith(".log")) if os.path.isdir(d) else []
        na, nb = names(da), names(db)
        if not na:
            problems.append(f"{da}: no files")
        for n in sorted(set(na) ^ set(nb)):
            problems.append(f"{sub}/{n}: only in {'the first' if n in na else 'the second'} folder")
        for n in sorted(set(na) & set(nb)):
            pa, pb = os.path.join(da, n), os.path.join(db, n)
            ext = os.path.splitext(n)[1]
            if ext == ".h5":
                ia, ib = h5_items(pa), h5_items(pb)
                diff = sorted(k for k in set(ia) | set(ib) if ia.get(k) != ib.get(k))
                if diff:
                    problems.append(f"{sub}/{n}: differs in {', '.join(diff[:5])}")
            elif ext == ".json":
                if json_body(pa) != json_body(pb):
                    problems.append(f"{sub}/{n}: differs (provenance aside)")
            elif text_lines(pa) != text_lines(pb):
                problems.append(f"{sub}/{n}: differs (comment lines aside)")
            compared += 1
    for p in problems:
        print(p)
    if not problems:
        print(f"same_results: {compared} files identical (provenance and timing aside) in {', '.join(subs)}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
