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

# The manifest of the archive being checked, read once (load_manifest ARCHIVE): listed[PATH] is
# its SHA-256 of PATH. Sums are taken in one sha256sum call for all the files a check needs
# (sums_of FILE...: sum[FILE]), which keeps `make tables` from an archive quick (a call per file
# and per lookup made it several seconds).
declare -A listed=() sum=()
load_manifest() {
  listed=()
  local line
  while IFS= read -r line || [[ -n $line ]]; do
    [[ ${#line} -gt 66 && -z ${listed[${line:66}]+x} ]] && listed[${line:66}]=${line:0:64}
  done < "$1/MANIFEST.sha256"
}
sums_of() {
  sum=()
  local existing=() f line
  for f in "$@"; do [[ -f $f ]] && existing+=("$f"); done
  [[ ${#existing[@]} -gt 0 ]] || return 0
  while IFS= read -r line; do sum[${line:66}]=${line:0:64}; done < <(sha256sum -- "${existing[@]}")
}

# check_manifest ARCHIVE: the manifest is the one dataset.bib (the citation) names (its sum in
# sum[], sums_of).
check_manifest() {
  local archive=$1 cited= bib= pattern='MANIFEST\.sha256 SHA-256 \{([0-9a-f]{64})\}'
  [[ -f $archive/dataset.bib ]] || { problem "$archive" "$archive/dataset.bib is missing (it cites the SHA-256 of MANIFEST.sha256)"; return; }
  IFS= read -r -d '' bib < "$archive/dataset.bib" || true
  [[ $bib =~ $pattern ]] && cited=${BASH_REMATCH[1]}
  [[ -n $cited ]] || { problem "$archive" "$archive/dataset.bib cites no SHA-256 of MANIFEST.sha256"; return; }
  local actual=${sum[$archive/MANIFEST.sha256]:-}
  [[ $cited == "$actual" ]] ||
    problem "$archive" "$archive/MANIFEST.sha256 does not match $archive/dataset.bib: the citation says $cited, the file's SHA-256 is $actual"
}

# check_file ARCHIVE PATH: ARCHIVE/PATH is listed and matches its sum (in sum[], sums_of).
check_file() {
  local archive=$1 path=$2 expected actual
  expected=${listed[$path]:-}
  [[ -n $expected ]] || { problem "$archive" "$archive/$path is not listed in $archive/MANIFEST.sha256"; return; }
  [[ -f $archive/$path ]] || { problem "$archive" "$archive/$path is missing (MANIFEST.sha256 lists it with SHA-256 $expected)"; return; }
  [[ ! -L $archive/$path ]] || { problem "$archive" "$archive/$path is a symlink, not a file: an archive holds none"; return; }
  actual=${sum[$archive/$path]:-}
  [[ $expected == "$actual" ]] ||
    problem "$archive" "$archive/$path does not match $archive/MANIFEST.sha256: the manifest says $expected, the file's SHA-256 is $actual"
}

case $1 in
  reuse)
    [[ $# -ge 4 ]] || usage
    archive=$2 stamp=$3
    shift 3
    [[ -f $archive/MANIFEST.sha256 ]] || exit 1  # no archive of this release and profile
    load_manifest "$archive"
    stamp_path=stamps/${stamp##*/}
    # FILE is DATA/PROFILE/<sub>/<name>: its archived path is <sub>/<name>.
    paths=()
    for f in "$@"; do
      sub=${f%/*}
      paths+=("${sub##*/}/${f##*/}")
    done
    sums_of "$archive/MANIFEST.sha256" "$archive/$stamp_path" "${paths[@]/#/$archive/}"
    check_manifest "$archive" || damaged "$archive"
    check_file "$archive" "$stamp_path" || damaged "$archive"
    cmp -s "$archive/$stamp_path" "$stamp" || exit 1  # archived under another configuration
    for path in "${paths[@]}"; do
      if [[ -z ${listed[$path]+x} ]]; then
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
        load_manifest "$archive"
        files=("$archive/MANIFEST.sha256")
        while IFS= read -r line; do files+=("$archive/${line:66}"); done < "$archive/MANIFEST.sha256"
        sums_of "${files[@]}"
        check_manifest "$archive" || bad=1
        while IFS= read -r line; do
          check_file "$archive" "${line:66}" || bad=$((bad + 1))
          n=$((n + 1))
        done < "$archive/MANIFEST.sha256"
        while IFS= read -r path; do
          [[ -n ${listed[$path]+x} ]] ||
            { problem "$archive" "$archive/$path is not listed in $archive/MANIFEST.sha256"; bad=$((bad + 1)); }
        done < <(cd "$archive" && find . -type f ! -name MANIFEST.sha256 ! -name dataset.bib -printf '%P\n' | LC_ALL=C sort)
        # An archive holds regular files and the folders of listed ones, nothing else: a symlink
        # (it could point anywhere, and its target is not what the manifest vouches for), a
        # device or a pipe, and a folder with no listed file in it are damage too.
        declare -A folders=()
        for path in "${!listed[@]}"; do while [[ $path == */* ]]; do path=${path%/*}; folders[$path]=1; done; done
        while IFS= read -r path; do
          problem "$archive" "$archive/$path is not a regular file ($(stat -c %F "$archive/$path")): an archive holds none" ||
            true
          bad=$((bad + 1))
        done < <(cd "$archive" && find . -mindepth 1 ! -type f ! -type d -printf '%P\n' | LC_ALL=C sort)
        while IFS= read -r path; do
          [[ -n ${folders[$path]+x} ]] ||
            { problem "$archive" "$archive/$path/ is a folder with no file of $archive/MANIFEST.sha256 in it"; bad=$((bad + 1)); }
        done < <(cd "$archive" && find . -mindepth 1 -type d -printf '%P\n' | LC_ALL=C sort)
        unset folders
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
