#!/usr/bin/env bash
# Paths: no fixed-size buffer anywhere. An input path of 1200+ characters is read; a path the
# operating system refuses (a name over 255 bytes, a path over 4096), a folder that cannot be
# created (a file stands in the way) and a missing input are one message, exit 2, nothing left.
#
#   test_paths.sh BIN_DIR SOURCE_DIR
bin=$1 root=$2
source "$(dirname "$0")/common.sh"
copy_samples "$tmp/s"
s=$tmp/s

long=$tmp
for c in d e f g h i; do long=$long/$(printf "$c%.0s" {1..200}); done
mkdir -p "$long" && cp "$s/p1.h5" "$long/p1.h5"
[[ ${#long} -gt 1200 ]] || fail "the long path is only ${#long} characters"
normal 1 "$long/p1.h5" "$long/ck" "$long/n.h5" 2> "$tmp/err" || fail "a ${#long}-character path: $(cat "$tmp/err")"
h5dump -d /Fn "$long/n.h5" > /dev/null || fail "the result at a long path does not read"
echo "ok: inputs, checkpoints and results at a path of ${#long} characters"

name=$(printf 'n%.0s' {1..300})
expect_error "File name too long" "$tmp/$name.h5" pack 1 "$tmp/$name.h5"
expect_error "File name too long" "$tmp/$name/x.h5" pack 1 "$tmp/$name/x.h5"
deep=$long
while [[ ${#deep} -le 4200 ]]; do deep=$deep/$(printf 'z%.0s' {1..200}); done
expect_error "File name too long" "$deep/n.h5" normal 1 "$s/p1.h5" "$tmp/ck" "$deep/n.h5"
expect_error "File name too long" "$deep/fit.json" fit "$s/avg/soft-solid.h5" "$deep/fit.json" "$deep/fit.gp"
echo "ok: a name over 255 bytes, a path over 4096: one message, exit 2"
# defect 16 (issue 28): legal names of 246-255 bytes were refused for their temporary's suffix.
for n in 246 250 255; do
  name=$(printf 'l%.0s' $(seq $((n - 3))))
  pack 1 "$tmp/$name.h5" 2> "$tmp/err" || fail "a name of $n bytes: $(cat "$tmp/err")"
  h5dump -d /radii "$tmp/$name.h5" > /dev/null || fail "the packing named with $n bytes does not read"
  no_temporaries "$tmp" || fail "a name of $n bytes: a temporary was left"
  rm "$tmp/$name.h5"
done
echo "ok: names of 246, 250 and 255 bytes are written (defect 16)"

touch "$tmp/a-file"
expect_error "Not a directory" "$tmp/a-file/sub/p.h5" pack 1 "$tmp/a-file/sub/p.h5"
expect_error "Not a directory" "$tmp/a-file/avg/soft-solid.h5" average "$s/n1.h5" "$s/n2.h5" "$s/t1.h5" "$s/t2.h5" "$tmp/a-file/avg"
expect_error "no such file" "$tmp/n.h5" normal 1 "$tmp/missing/p1.h5" "$tmp/ck" "$tmp/n.h5"
echo "ok: a folder that cannot be made, a missing input: one message, exit 2, nothing left"
