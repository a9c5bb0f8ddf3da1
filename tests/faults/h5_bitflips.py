#!/usr/bin/python3
"""Bit flips in an HDF5 file the project wrote, read with h5py alone (a standard reader).

  h5_bitflips.py FILE [--flips N] [--seed S] [--all]

Flips one bit at N random offsets (every byte with --all), each in a fresh copy, and reads every
dataset and attribute of the copy with h5py. Each flip must either make the read fail (a checksum
error, or any error) or leave every value read identical to the original file's: never a silent
wrong value. Each read runs in a child process, as libhdf5 1.10 aborts on some damaged files (a crash
is counted, it reads no value). Prints how many flips were caught, crashed the reader, were harmless
or read wrong values (exit 1 if any read a wrong value).
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
    caught = harmless = crashed = 0
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
            # Read in a child: libhdf5 1.10 aborts or crashes on some damaged files (h5py too).
            pid = os.fork()
            if pid == 0:
                os.dup2(os.open(os.devnull, os.O_WRONLY), 2)
                try:
                    got = contents(tmp)
                except Exception:
                    os._exit(4)
                if got == pristine:
                    os._exit(0)
                diff = sorted(k for k in set(got) | set(pristine) if got.get(k) != pristine.get(k))
                print(f"  WRONG: byte {off} bit {bit} changed {diff[:3]}", flush=True)
                os._exit(3)
            _, status = os.waitpid(pid, 0)
            if os.WIFSIGNALED(status):
                crashed += 1
            elif os.WEXITSTATUS(status) == 4:
                caught += 1
            elif os.WEXITSTATUS(status) == 0:
                harmless += 1
            else:
                wrong.append((off, bit))
    finally:
        os.remove(tmp)
    print(f"{a.file}: {len(data)} bytes, {len(offsets)} flips (seed {a.seed}): {caught} caught by a read error, "
          f"{crashed} crashed the reader (libhdf5), {harmless} harmless (every value identical), "
          f"{len(wrong)} wrong values read")
    return 1 if wrong else 0

if __name__ == "__main__":
    sys.exit(main())
