#!/usr/bin/env bash
# Checks archived results against their MANIFEST.sha256 before anything uses them.
#
#   workflow/archive_check.sh reuse ARCHIVE STAMP FILE...
#     Copies the archived FILEs into place (FILE is DATA/PROFILE/<path>, its archived copy
#     ARCHIVE/<path>) when the stage's archived stamp equals STAMP and every one of them, the
#     stamp and the manifest itself are what the manifest and dataset.bib say they are.
#     Exit 0: reused. Exit 1: nothing to reuse (no archive, another configuration, or files the
#     archive does not hold); the caller computes. Exit 2: the archive is damaged; one message
#     names the file and both sums, and nothing is copied (never a silent fallback).
#   workflow/archive_check.sh verify ARCHIVE...
#     Checks whole archives: the manifest against dataset.bib, every file against the manifest,
#     no listed file missing, no unlisted file. Exit 0 when all are intact, 2 otherwise.
set -uo pipefail

usage() {
  echo "usage: $0 reuse ARCHIVE STAMP FILE...  |  $0 verify ARCHIVE..." >&2
  exit 2
}
[[ $# -ge 2 && $1 != -h && $1 != --help ]] || usage

# problem ARCHIVE MESSAGE: says what is wrong with ARCHIVE and fails (status 1).
problem() {
  echo "archive: $2" >&2
  return 1
}
# damaged ARCHIVE: the end of every message about a damaged archive, exit 2.
damaged() {
  echo "archive: $1 is damaged: restore it (git checkout -- $1) or recompute without it (FROM_SCRATCH=1)" >&2
  exit 2
}

sum_of() { sha256sum -- "$1" | cut -c1-64; }

# listed_sum ARCHIVE PATH: the manifest's sum of PATH ("" when it is not listed).
listed_sum() {
  awk -v p="$2" 'substr($0, 67) == p { print substr($0, 1, 64); exit }' "$1/MANIFEST.sha256"
}

# check_manifest ARCHIVE: the manifest is the one dataset.bib (the citation) names.
check_manifest() {
  local archive=$1 cited actual
  [[ -f $archive/dataset.bib ]] || { problem "$archive" "$archive/dataset.bib is missing (it cites the SHA-256 of MANIFEST.sha256)"; return; }
  cited=$(sed -n 's/.*MANIFEST.sha256 SHA-256 {\([0-9a-f]\{64\}\)}.*/\1/p' "$archive/dataset.bib")
  [[ -n $cited ]] || { problem "$archive" "$archive/dataset.bib cites no SHA-256 of MANIFEST.sha256"; return; }
  actual=$(sum_of "$archive/MANIFEST.sha256")
  [[ $cited == "$actual" ]] ||
    problem "$archive" "$archive/MANIFEST.sha256 does not match $archive/dataset.bib: the citation says $cited, the file's SHA-256 is $actual"
}

# check_file ARCHIVE PATH: ARCHIVE/PATH is listed and matches its sum.
check_file() {
  local archive=$1 path=$2 expected actual
  expected=$(listed_sum "$archive" "$path")
  [[ -n $expected ]] || { problem "$archive" "$archive/$path is not listed in $archive/MANIFEST.sha256"; return; }
  [[ -f $archive/$path ]] || { problem "$archive" "$archive/$path is missing (MANIFEST.sha256 lists it with SHA-256 $expected)"; return; }
  actual=$(sum_of "$archive/$path")
  [[ $expected == "$actual" ]] ||
    problem "$archive" "$archive/$path does not match $archive/MANIFEST.sha256: the manifest says $expected, the file's SHA-256 is $actual"
}

case $1 in
  reuse)
    [[ $# -ge 4 ]] || usage
    archive=$2 stamp=$3
    shift 3
    [[ -f $archive/MANIFEST.sha256 ]] || exit 1  # no archive of this release and profile
    check_manifest "$archive" || damaged "$archive"
    stamp_path=stamps/$(basename "$stamp")
    check_file "$archive" "$stamp_path" || damaged "$archive"
    cmp -s "$archive/$stamp_path" "$stamp" || exit 1  # archived under another configuration
    # FILE is DATA/PROFILE/<sub>/<name>: its archived path is <sub>/<name>.
    paths=()
    for f in "$@"; do
      path=$(basename "$(dirname "$f")")/$(basename "$f")
      paths+=("$path")
      if [[ -z $(listed_sum "$archive" "$path") ]]; then
        [[ ! -e $archive/$path ]] || { problem "$archive" "$archive/$path is not listed in $archive/MANIFEST.sha256"; damaged "$archive"; }
        exit 1  # not archived (a seed the archive does not hold): computed
      fi
    done
    for path in "${paths[@]}"; do check_file "$archive" "$path" || damaged "$archive"; done
    i=0
    for f in "$@"; do
      cp -- "$archive/${paths[i]}" "$f.tmp.archive" && mv -- "$f.tmp.archive" "$f" || {
        rm -f -- "$f.tmp.archive"
        echo "archive: cannot copy $archive/${paths[i]} to $f" >&2
        exit 2
      }
      i=$((i + 1))
    done
    echo "reused $* from $archive (same configuration, SHA-256 verified)"
    ;;
  verify)
    shift
    status=0
    for archive in "$@"; do
      bad=0 n=0
      if [[ ! -f $archive/MANIFEST.sha256 ]]; then
        problem "$archive" "$archive/MANIFEST.sha256 is missing" || bad=1
      else
        check_manifest "$archive" || bad=1
        while IFS= read -r line; do
          check_file "$archive" "${line:66}" || bad=$((bad + 1))
          n=$((n + 1))
        done < "$archive/MANIFEST.sha256"
        while IFS= read -r path; do
          [[ -n $(listed_sum "$archive" "$path") ]] ||
            { problem "$archive" "$archive/$path is not listed in $archive/MANIFEST.sha256"; bad=$((bad + 1)); }
        done < <(cd "$archive" && find . -type f ! -name MANIFEST.sha256 ! -name dataset.bib -printf '%P\n' | LC_ALL=C sort)
      fi
      if [[ $bad == 0 ]]; then
        echo "verify: $archive: $n files match MANIFEST.sha256, which matches dataset.bib"
      else
        (damaged "$archive") || true
        status=2
      fi
    done
    exit $status
    ;;
  *) usage ;;
esac
