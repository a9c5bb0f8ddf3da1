#!/usr/bin/python3
"""Bit flips in an HDF5 file the project wrote, read with h5py alone (a standard reader).

  h5_bitflips.py FILE [--flips N] [--seed S] [--all]

Flips one bit at N random offsets (every byte with --all), each in a fresh copy, and reads every
dataset and attribute of the copy with h5py. Each flip must either make the read fail (a checksum
error, or any error) or leave every value read identical to the original file's: never a silent
wrong value. Prints how many flips were caught, harmless, or wrong (exit 1 if any is wrong).
"""
import argparse, os, random, sys, tempfile
import h5py, numpy as np

def contents(path):
    out = {}
    def visit(name, obj):
        for k, v in obj.attrs.items():
            out[f"{name}@{k}"] = bytes(v) if isinstance(v, (bytes, np.bytes_)) else repr(v)
        if isinstance(obj, h5py.Dataset):
            v = obj[()]
            out[name] = (v.dtype.str, v.shape, v.tobytes()) if isinstance(v, np.ndarray) else repr(v)
    with h5py.File(path, "r") as f:
        for k, v in f.attrs.items():
            out[f"/@{k}"] = repr(v)
        f.visititems(visit)
    return out

def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--flips", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--all", action="store_true", help="flip one bit of every byte")
    a = ap.parse_args()
    data = bytearray(open(a.file, "rb").read())
    pristine = contents(a.file)
    rng = random.Random(a.seed)
    offsets = range(len(data)) if a.all else [rng.randrange(len(data)) for _ in range(a.flips)]
    caught = harmless = 0
    wrong = []
    fd, tmp = tempfile.mkstemp(suffix=".h5")
    os.close(fd)
    try:
        for off in offsets:
            bit = rng.randrange(8)
            flipped = bytearray(data)
            flipped[off] ^= 1 << bit
            with open(tmp, "wb") as out:
                out.write(flipped)
            try:
                got = contents(tmp)
            except Exception:
                caught += 1
                continue
            if got == pristine:
                harmless += 1
            else:
                diff = sorted(k for k in set(got) | set(pristine) if got.get(k) != pristine.get(k))
                wrong.append((off, bit, diff[:3]))
    finally:
        os.remove(tmp)
    print(f"{a.file}: {len(data)} bytes, {len(offsets)} flips (seed {a.seed}): {caught} caught by a read error, "
          f"{harmless} harmless (every value identical), {len(wrong)} wrong values read")
    for off, bit, diff in wrong[:10]:
        print(f"  WRONG: byte {off} bit {bit} changed {diff}")
    return 1 if wrong else 0

if __name__ == "__main__":
    sys.exit(main())
