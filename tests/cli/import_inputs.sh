# Sourced by the tests of imported packings (tests/cli/test_softpack_import.sh,
# tests/workflow/test_import_dag.sh), after tests/cli/common.sh, with $bin, $root and $py set:
# import_inputs writes into $tmp the packings of seeds 1 and 2 of the sweep test profile
# (gen-S.h5, gen-S.xyz) and the same spheres as a LAMMPS data file (run-S.data: millimetres, the
# shell off the origin, image flags, a Velocities section) and as "x y z r" text (run-S.txt);
# profile and import_section write profiles that import them.
base=$root/tests/data/sweep-profile.yaml
import_inputs() {
  local s
  for s in 1 2; do "$bin/softpack-pack" --config "$base" --seed $s --out "$tmp/gen-$s.h5" --xyz "$tmp/gen-$s.xyz" --quiet; done
  $py - "$tmp" <<'PY'
import sys, h5py
d = sys.argv[1]
for s in (1, 2):
    f = h5py.File(f"{d}/gen-{s}.h5", "r")
    x, r, R = f["centres"][()] * 1e3, f["radii"][()] * 1e3, f["shell/radius"][()] * 1e3  # millimetres
    c = (2.5, -1.0, 7.0)  # the shell's centre, off the origin
    with open(f"{d}/run-{s}.data", "w") as o:
        o.write("LAMMPS data file via write_data, version 2Aug2023, timestep = 0, units = si (in mm here)\n\n")
        o.write(f"{len(r)} atoms\n1 atom types\n\n")
        for k, a in enumerate("xyz"):
            o.write(f"{c[k] - R!r} {c[k] + R!r} {a}lo {a}hi\n")
        o.write("\nMasses\n\n1 1.0\n\nAtoms # sphere\n\n")
        for i in range(len(r)):
            # the density column: the sweep test profile's material.density (packing.import.density: the file's is taken)
            o.write(f"{i + 1} 1 {2 * r[i]!r} 250000 {x[i, 0] + c[0]!r} {x[i, 1] + c[1]!r} {x[i, 2] + c[2]!r} 0 0 0\n")
        o.write("\nVelocities\n\n" + "".join(f"{i + 1} 0 0 0 0 0 0\n" for i in range(len(r))))
    with open(f"{d}/run-{s}.txt", "w") as o:
        o.write("# x y z r [m]\n" + "".join(f"{p[0] / 1e3!r} {p[1] / 1e3!r} {p[2] / 1e3!r} {q / 1e3!r}\n" for p, q in zip(x, r)))
PY
}
# profile FILE PACKING_YAML [DELTA_N]: the sweep test profile with another packing section, no
# tangential section, and the normal grid DELTA_N; named `imported`.
profile() {
  awk -v packing="$2" -v grid="${3:-[0.1, 0.2, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65]}" '
    /^profile:/ {print "profile: imported"; next}
    /^packing:/ {print packing; skip = 1; next}
    /^tangential:/ {skip = 1; next}
    skip && /^  / {next}
    {skip = 0}
    /^  delta_n:/ {print "  delta_n: " grid; next}
    {print}' "$base" > "$1"
}
import_section() { printf 'packing:\n  import:\n    files: {1: %s, 2: %s}\n%s' "$1" "$2" "$3"; }
