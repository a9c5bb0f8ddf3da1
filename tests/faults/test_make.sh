#!/usr/bin/env bash
# The workflow never uses a damaged archive and never lets two runs share a data folder:
#   1. a damaged archive (a flipped bit, a truncated, deleted or edited file, an unlisted file, an
#      edited manifest; file and position at random) stops `make tables` with one message naming
#      the file (and both SHA-256 sums when it differs), writes no table, and `make verify` says
#      the same; the intact archive is reused (make verify: exit 0);
#   2. two `make tables` on the same DATA, the second started after a random delay: the second
#      waits for the first (LOCK_WAIT=0: refuses, exit 2); both succeed with the tables of a
#      single run; no NUL bytes in any log, no temporaries;
#   3. a DATA path with a space, a ':' or a character make or the shell reads as syntax (drawn:
#      ; * ? # $ quotes, a backtick, a backslash, brackets, < > | &) is refused in one line,
#      before anything runs;
#   4. everything a run writes lives under its DATA and its lock (issue 28): every goal that
#      writes there takes the lock (drawn among those outside the pipeline's first list: timing,
#      the studies' reports); make -n of a study writes nothing; make figures draws into
#      DATA/PROFILE/figures and nothing outside DATA;
#   5. make archive with PROFILE_FILE archives that profile (issue 28, defect 9; and §1: make
#      verify sees a symlink or a folder the manifest does not list).
# The paper profile's tables come from the archive of this release (seconds, no simulation).
#
#   test_make.sh BUILD_DIR SOURCE_DIR   (FAULT_SEED=N replays)
build=$(cd "$1" && pwd) root=$(cd "$2" && pwd)
bin=$build/bin
source "$(dirname "$0")/common.sh"
cd "$root"
version=$(awk '/^project/ { print $3; exit }' CMakeLists.txt)
intact=data/archive/$version/paper
[[ -f $intact/MANIFEST.sha256 ]] || fail "no archive of release $version ($intact): make archive first"
export MAKEFLAGS=
# TOOLS= : the tools are built (ctest runs after the build); nothing recompiles under the test.
mk() { make --no-print-directory BUILD="$build" TOOLS= PROFILE=paper ARCHIVE_ROOT="$tmp/archive" "$@"; }
fresh_archive() { rm -rf "$tmp/archive" && mkdir -p "$tmp/archive/$version" && cp -r "$intact" "$tmp/archive/$version/"; }
archive=$tmp/archive/$version/paper

# --- 1. a damaged archive --------------------------------------------------------------------------
fresh_archive
mk DATA="$tmp/d0" tables > "$tmp/intact.log" 2>&1 || { cat "$tmp/intact.log"; fail "make tables with the intact archive"; }
grep -qE '^(pack|normal|tangential|average|fit): ' "$tmp/intact.log" && fail "the intact archive was not reused"
mk verify ARCHIVES="$archive" > /dev/null || fail "make verify on the intact archive"
echo "ok: the intact archive is reused ($(grep -c '^reused ' "$tmp/intact.log") results) and verified"

# The files `make tables` takes from the archive.
mapfile -t used < <(cd "$archive" && find packings normal tangential averages fits stamps -type f | LC_ALL=C sort)
pick() { echo "${used[$(random_below ${#used[@]})]}"; }
damage() {  # damage KIND: damages the archive; sets $file (relative) and $hint (what the message must say)
  case $1 in
    flip)
      file=$(pick)
      local size offset
      size=$(stat -c %s "$archive/$file") offset=$(random_below "$size")
      "$py" -c "import sys; p, o, b = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]); d = bytearray(open(p, 'rb').read()); d[o] ^= 1 << b; open(p, 'wb').write(d)" \
        "$archive/$file" "$offset" $(random_below 8)
      hint="does not match" ;;
    truncate)
      file=$(pick)
      truncate -s "$(random_below "$(stat -c %s "$archive/$file")")" "$archive/$file"
      hint="does not match" ;;
    edit)  # the issue's case: a digit of a fitted coefficient
      file=fits/soft-solid.json
      sed -i '0,/"a": [0-9]/s/\("a": \)\([0-9]\)/\1'$(( $(random_below 9) + 1 ))'\2/' "$archive/$file"
      hint="does not match" ;;
    delete)
      file=$(pick)
      rm "$archive/$file"
      hint="is missing" ;;
    manifest)  # the manifest itself edited to vouch for another file
      file=MANIFEST.sha256
      sed -i "1s/^./$(printf '%x' $(random_below 16))/" "$archive/$file"
      cmp -s "$archive/$file" "$intact/$file" && sed -i '1s/^./f/;1s/^ff/0f/' "$archive/$file"
      hint="does not match $archive/dataset.bib" ;;
  esac
}
for kind in flip truncate edit delete manifest flip truncate; do
  fresh_archive
  damage "$kind"
  cmp -s "$archive/$file" "$intact/$file" 2> /dev/null && { echo "  ($kind of $file changed nothing; skipped)"; continue; }
  rm -rf "$tmp/d1"
  set +e
  mk DATA="$tmp/d1" tables > "$tmp/out" 2> "$tmp/err"
  code=$?
  set -e
  [[ $code == 2 ]] || fail "$kind of $file: make tables exit $code (expected 2): $(tail -3 "$tmp/err")"
  grep -qF "$archive/$file" "$tmp/err" || fail "$kind of $file: the message does not name the file: $(cat "$tmp/err")"
  grep -qF "$hint" "$tmp/err" || fail "$kind of $file: expected '$hint': $(cat "$tmp/err")"
  [[ $hint != "does not match" || $kind == manifest ]] ||
    grep -qE "the manifest says [0-9a-f]{64}, the file's SHA-256 is [0-9a-f]{64}" "$tmp/err" || fail "$kind of $file: both sums not named: $(cat "$tmp/err")"
  [[ ! -e $tmp/d1/paper/tables/table1.md ]] || fail "$kind of $file: a table was written from a damaged archive"
  [[ $(grep -c '^archive: ' "$tmp/err") == 2 ]] || fail "$kind of $file: expected one message (and the advice): $(cat "$tmp/err")"
  set +e
  mk verify ARCHIVES="$archive" > /dev/null 2> "$tmp/verr"
  code=$?
  set -e
  [[ $code == 2 ]] || fail "$kind of $file: make verify exit $code"
  grep -qF "$archive/$file" "$tmp/verr" || fail "$kind of $file: make verify does not name the file: $(cat "$tmp/verr")"
  echo "ok: $kind of $file: make tables stops (exit 2) naming it; make verify too"
done
# What the manifest does not list but a folder can hold (issue 28): a symlink (unlisted, or in the
# place of a listed file), a folder with no listed file; drawn where.
for kind in symlink folder listed-symlink; do
  fresh_archive
  dir=$(dirname "$(pick)")
  case $kind in
    symlink) file=$dir/extra-$(random_below 100000).h5; ln -s "$intact/$(pick)" "$archive/$file"; hint="is not a regular file" ;;
    folder) file=$dir/extra-$(random_below 100000); mkdir "$archive/$file"; hint="is a folder with no file" ;;
    listed-symlink) file=$(pick); mv "$archive/$file" "$tmp/moved"; ln -s "$tmp/moved" "$archive/$file"; hint="is a symlink" ;;
  esac
  set +e
  mk verify ARCHIVES="$archive" > /dev/null 2> "$tmp/verr"
  code=$?
  set -e
  [[ $code == 2 ]] && grep -qF "$archive/$file" "$tmp/verr" && grep -qF "$hint" "$tmp/verr" ||
    fail "$kind $file in the archive: make verify exit $code: $(cat "$tmp/verr")"
  echo "ok: $kind $file in the archive: make verify says so (exit 2)"
done
fresh_archive
echo "stray" > "$archive/fits/extra.json"
set +e; mk verify ARCHIVES="$archive" > /dev/null 2> "$tmp/verr"; code=$?; set -e
[[ $code == 2 ]] && grep -qF "$archive/fits/extra.json is not listed" "$tmp/verr" || fail "an unlisted file: make verify exit $code: $(cat "$tmp/verr")"
echo "ok: an unlisted file in the archive: make verify names it"

# --- 2. two runs on one data folder ----------------------------------------------------------------
fresh_archive
tables_of() { cat "$1"/paper/tables/table{1,2}.md | grep -v '^<!--'; }
tables_of "$tmp/d0" > "$tmp/serial.tables"
waited=0
for round in 1 2 3; do
  d=$tmp/c$round
  mk DATA="$d" tables > "$tmp/a.log" 2>&1 &
  first=$!
  sleep "0.$(random_below 10)$(random_below 10)"
  mk DATA="$d" tables > "$tmp/b.log" 2>&1 || { cat "$tmp/b.log"; fail "round $round: the second make failed"; }
  wait "$first" || { cat "$tmp/a.log"; fail "round $round: the first make failed"; }
  grep -q 'is in use by another run' "$tmp/b.log" && waited=$((waited + 1))
  for log in "$tmp/a.log" "$tmp/b.log" $(find "$d" -name '*.log'); do
    if tr -d '\000' < "$log" | cmp -s - "$log"; then :; else fail "round $round: NUL bytes in $log"; fi
  done
  diff <(tables_of "$d") "$tmp/serial.tables" > /dev/null || fail "round $round: the tables differ from a single run's"
  no_temporaries "$d" || fail "round $round: temporaries left: $(find "$d" -name '*.tmp.*')"
done
echo "ok: two makes on one DATA, 3 rounds at random delays ($waited waited for the other): the tables of a single run"

mk DATA="$tmp/c4" tables > /dev/null 2>&1 &
first=$!
for _ in $(seq 100); do [[ -s $tmp/c4/.softpack.lock ]] && break; sleep 0.05; done
set +e; LOCK_WAIT=0 mk DATA="$tmp/c4" tables > /dev/null 2> "$tmp/err"; code=$?; set -e
wait "$first" || fail "the first make (LOCK_WAIT=0 case) failed"
[[ $code == 2 ]] && grep -q "is in use by another run (pid [0-9]* on .*); not started (LOCK_WAIT=0)" "$tmp/err" ||
  fail "LOCK_WAIT=0 while another make runs: exit $code: $(cat "$tmp/err")"
echo "ok: LOCK_WAIT=0 refuses at once (exit 2), naming the run that holds the folder"

# --- 3. paths make cannot use -----------------------------------------------------------------------
for bad in "$tmp/with space" "$tmp/with:colon"; do
  set +e; mk DATA="$bad" tables > "$tmp/out" 2>&1; code=$?; set -e
  [[ $code == 2 && $(grep -c . "$tmp/out") == 1 ]] || fail "DATA='$bad': exit $code, $(grep -c . "$tmp/out") lines: $(head -3 "$tmp/out")"
  [[ ! -e $bad ]] || fail "DATA='$bad': the folder was created"
done
syntax=(';' '*' '?' '#' '$' "'" '"' '`' '\\' '[' ']' '{' '}' '(' ')' '<' '>' '|' '&' '!')
for round in 1 2 3; do
  c=${syntax[$(random_below ${#syntax[@]})]}
  bad="$tmp/x${c}true"
  set +e; mk DATA="$bad" tables > "$tmp/out" 2>&1; code=$?; set -e
  [[ $code == 2 && $(grep -c . "$tmp/out") == 1 ]] && grep -q "characters make or the shell would read as syntax" "$tmp/out" ||
    fail "DATA='$bad': exit $code: $(head -3 "$tmp/out")"
  [[ -z $(find "$tmp" -maxdepth 1 -name 'x*') ]] || fail "DATA='$bad': something was created: $(find "$tmp" -maxdepth 1 -name 'x*')"
done
echo "ok: a DATA path with a space, a ':' or a character of make's or the shell's syntax is refused in one line"

# --- 4. everything under DATA and its lock ----------------------------------------------------------
held=$tmp/held
mkdir -p "$held"
exec 218>> "$held/.softpack.lock"
flock -n 218 || fail "cannot take the lock of $held"
goals=(timing accuracy-report calibrate-report radius-report coarse-grain-report figures)
for round in 1 2; do
  goal=${goals[$(random_below ${#goals[@]})]}
  set +e; LOCK_WAIT=0 mk DATA="$held" "$goal" > /dev/null 2> "$tmp/err"; code=$?; set -e
  [[ $code == 2 ]] && grep -q "is in use by another run" "$tmp/err" || fail "make $goal on a folder in use: exit $code: $(cat "$tmp/err")"
done
exec 218>&-
echo "ok: make timing and the studies' reports take DATA's lock like the pipeline's goals"
touch "$tmp/marker"
for goal in accuracy calibrate radius; do
  mk -n DATA="$tmp/dry" "$goal" > "$tmp/dry.log" 2>&1 || { cat "$tmp/dry.log"; fail "make -n $goal"; }
done
[[ ! -e $tmp/dry ]] || fail "make -n of a study wrote: $(find "$tmp/dry" | head -5)"
[[ -z $(find "$root/data" "$root/figures" "$root/paper" -newer "$tmp/marker" -not -path "$root/data/archive/*" 2> /dev/null) ]] ||
  fail "make -n of a study wrote into the source tree: $(find "$root/data" -newer "$tmp/marker" | head -5)"
echo "ok: make -n accuracy, calibrate and radius write nothing (DATA=$tmp/dry)"
mk DATA="$tmp/d0" figures > "$tmp/figures.log" 2>&1 || { cat "$tmp/figures.log"; fail "make figures"; }
for f in fig{1_apollonian,2_softparticle,3_normal,4_tangential_soft_solid,5_tangential_soft_soft,6_kt}.{pdf,png}; do
  [[ -s $tmp/d0/paper/figures/$f ]] || fail "make figures DATA=$tmp/d0: no $tmp/d0/paper/figures/$f"
done
outside=$(find "$root/data" "$root/figures" "$root/paper" -newer "$tmp/marker" -type f -not -path "$root/data/archive/*" 2> /dev/null | head -5)
[[ -z $outside ]] || fail "make figures DATA=$tmp/d0 wrote outside it: $outside"
echo "ok: make figures draws into DATA/PROFILE/figures and writes nothing outside DATA"

# make archive with PROFILE_FILE archives that profile, not experiments/PROFILE.yaml (defect 9).
a=$tmp/arch
for part in packings normal tangential averages fits stamps; do mkdir -p "$a/data/mine/$part" && echo "$part" > "$a/data/mine/$part/x.h5"; done
echo "value" > "$a/data/mine/stamps/normal.hash"
printf 'profile: mine\n# the profile used, not experiments/mine.yaml (there is none)\n' > "$a/mine.yaml"
# (run in a clean repository of its own: archive.sh archives only from a clean tree, issue 29)
mkdir -p "$a/repo" && git -C "$a/repo" init -q && echo one > "$a/repo/tracked" && git -C "$a/repo" add tracked &&
  git -C "$a/repo" -c user.name=t -c user.email=t@t commit -qm one
(cd "$a/repo" && "$root/workflow/archive.sh" "$a/data" mine 0.0.0 "$a/archive" "$a/mine.yaml") > /dev/null ||
  fail "workflow/archive.sh with a PROFILE_FILE"
cmp -s "$a/archive/0.0.0/mine/profile.yaml" "$a/mine.yaml" || fail "make archive did not archive its PROFILE_FILE"
grep -q 'archive.sh $(DATA) $(PROFILE) $(VERSION) $(ARCHIVE_ROOT) $(PROFILE_FILE)' "$root/workflow/archive.mk" ||
  fail "workflow/archive.mk does not give archive.sh the PROFILE_FILE"
echo "ok: make archive archives the profile it was given (PROFILE_FILE)"

# Archives only from a clean tree (issue 29): a changed tracked file or a file git does not ignore
# is refused, named, and no archive is written.
echo changed > "$a/data/mine/averages/x.h5"  # new results (a file archive.sh copies), so the archive would change
for dirt in modified untracked; do
  case $dirt in
    modified) echo two > "$a/repo/tracked"; name=tracked ;;
    untracked) git -C "$a/repo" checkout -q tracked; echo new > "$a/repo/new-source.cpp"; name=new-source.cpp ;;
  esac
  set +e; (cd "$a/repo" && "$root/workflow/archive.sh" "$a/data" mine 0.0.0 "$a/archive" "$a/mine.yaml") > /dev/null 2> "$tmp/err"
  code=$?; set -e
  [[ $code == 1 ]] || fail "make archive from a tree with a $dirt file: exit $code, expected 1"
  grep -q "not clean" "$tmp/err" && grep -qF "$name" "$tmp/err" || fail "the refusal ($dirt) does not name $name: $(cat "$tmp/err")"
  grep -q "changed" "$a/archive/0.0.0/mine/averages/x.h5" && fail "an archive was written from a tree with a $dirt file"
done
echo "ok: make archive refuses a dirty tree and names its files"
