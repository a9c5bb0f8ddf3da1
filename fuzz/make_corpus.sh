#!/usr/bin/env bash
# Regenerates the seed corpora fuzz/corpus/<target>/ (small valid inputs; each file < 50 kB):
#   config   the profiles and scenes of experiments/, tests/data/ and fuzz/seed-profile.yaml
#   packing  a packing of fuzz/seed-profile.yaml (softpack-pack), and the same file rewritten
#            by h5py (chunked, gzip, HDF5 1.10 format, fixed-length strings, float32)
#   sweep    point files (checkpoints: normal and tangential, soft-solid and soft-soft) and
#            sweep results files
#   average  softpack-average's file of two seeds, and a fitting one written with h5py
# Usage: fuzz/make_corpus.sh [BUILD]   (BUILD: the main build, default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/${1:-build}/engine
py=/usr/bin/python3
"$py" -c 'import h5py, numpy' || { echo "make_corpus.sh: needs python3-h5py" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
corpus=$root/fuzz/corpus
rm -rf "$corpus"
mkdir -p "$corpus"/{config,packing,sweep,average}

for f in "$root"/experiments/*.yaml; do cp "$f" "$corpus/config/profile-$(basename "$f")"; done
for f in "$root"/experiments/scenes/*.yaml; do cp "$f" "$corpus/config/scene-$(basename "$f")"; done
for f in "$root"/tests/data/*.yaml "$root"/fuzz/seed-profile.yaml; do cp "$f" "$corpus/config/$(basename "$f")"; done

profile=$root/fuzz/seed-profile.yaml
cd "$tmp"
for s in 1 2; do "$bin/softpack-pack" --config "$profile" --seed $s --out p$s.h5 --quiet; done
for scene in soft-solid soft-soft; do
  for s in 1 2; do
    args=(--config "$profile" --scene $scene --seed $s --packing p$s.h5 --second-packing p$((3 - s)).h5 --quiet)
    "$bin/softpack-normal" "${args[@]}" --checkpoints n-$scene-$s --out normal-$scene-$s.h5
    "$bin/softpack-tangential" "${args[@]}" --checkpoints t-$scene-$s --normal-checkpoints n-$scene-$s \
      --out tangential-$scene-$s.h5
  done
  "$bin/softpack-average" --scene $scene --profile fuzz-seed --normal normal-$scene-{1,2}.h5 \
    --tangential tangential-$scene-{1,2}.h5 --out-dir avg
done

cp p1.h5 "$corpus/packing/packing.h5"
cp n-soft-solid-1/point-003.h5 "$corpus/sweep/point-normal-soft-solid.h5"
cp n-soft-soft-1/point-005.h5 "$corpus/sweep/point-normal-soft-soft.h5"
cp t-soft-soft-1/point-001-002.h5 "$corpus/sweep/point-tangential-soft-soft.h5"
cp normal-soft-solid-1.h5 "$corpus/sweep/results-normal-soft-solid.h5"
cp tangential-soft-soft-1.h5 "$corpus/sweep/results-tangential-soft-soft.h5"
cp avg/soft-solid.h5 "$corpus/average/average-soft-solid.h5"
cp avg/soft-soft.h5 "$corpus/average/average-soft-soft.h5"

# The same content in other HDF5 encodings: what h5py or another tool might write.
"$py" - p1.h5 "$corpus/packing/packing-h5py-gzip.h5" << 'PY'
import sys, h5py, numpy as np
src, dst = sys.argv[1:]
with h5py.File(src, "r") as i, h5py.File(dst, "w", libver="latest") as o:
    def copy(name, obj):
        if not isinstance(obj, h5py.Dataset):
            return
        data = obj[()]
        if obj.dtype.kind == "O":  # variable-length strings -> fixed-length, space padded
            o.create_dataset(name, data=np.bytes_(data), dtype=h5py.string_dtype("ascii", len(data) + 1))
        elif obj.shape and obj.size > 3:
            o.create_dataset(name, data=data, chunks=True, compression="gzip", shuffle=True, fletcher32=True)
        elif obj.dtype.kind == "f" and name.startswith("stats"):
            o.create_dataset(name, data=data.astype(">f4"))
        else:
            o.create_dataset(name, data=data)
        for k, v in obj.attrs.items():
            o[name].attrs[k] = v
    i.visititems(copy)
PY
"$py" - "$corpus/average/average-h5py-fit.h5" << 'PY'
import sys, h5py, numpy as np
# Eq. 7 and 8 with the coefficients of the paper's soft-solid contact: the fits succeed.
a, b, c, ka, kb = 73.669, 2.799, -0.035, 0.740, 2.100
delta = (-c / a) ** (1 / b)
dn = np.arange(11) * 0.05
F = np.where(dn >= delta, a * dn ** b + c, 0.0)
kdn = 0.2 + np.arange(5) * 0.075
kt = ka * (kdn ** kb - delta ** kb)
with h5py.File(sys.argv[1], "w") as f:
    f["normal/delta_n"] = dn
    f["normal/Fn_mean"] = F
    f["normal/Fn_stderr"] = 0.01 * F + 1e-4
    f["normal/seeds"] = np.int64(7)
    f["kt/delta_n"] = kdn
    f["kt/mean"] = kt
    f["kt/stderr"] = 0.03 * np.abs(kt) + 1e-6
    f["provenance/scene"] = "soft-solid"
    f["provenance/profile"] = "h5py"
    f["provenance/code_version"] = "test"
PY
find "$corpus" -type f -size +50k -exec echo "make_corpus.sh: larger than 50 kB:" {} \; | grep . && exit 1
ls -l "$corpus"/*
