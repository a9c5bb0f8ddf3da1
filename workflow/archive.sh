#!/usr/bin/env bash
# Archive one profile's results (packings, sweep results, averages, fits) with their configuration
# stamps, a MANIFEST of SHA-256 sums, the provenance and a BibTeX entry for the dataset.
#
#   workflow/archive.sh DATA PROFILE VERSION ARCHIVE_ROOT [PROFILE_FILE]
#
# PROFILE_FILE: the profile the results were made with (default experiments/PROFILE.yaml), archived
# as profile.yaml.
# The archive is assembled in a temporary directory next to its destination and moved into place
# at the end, so an interrupted run leaves the previous archive (if any) untouched.
set -euo pipefail

if [[ $# -lt 4 || $# -gt 5 || $1 == -h || $1 == --help ]]; then
  echo "usage: $0 DATA PROFILE VERSION ARCHIVE_ROOT [PROFILE_FILE]  (e.g. data paper 0.1.0 data/archive)" >&2
  exit 2
fi
data=$1 profile=$2 version=$3 root=$4 profile_file=${5:-experiments/$2.yaml}
source_dir=$data/$profile
dest=$root/$version/$profile

for part in packings normal tangential averages fits stamps; do
  [[ -d $source_dir/$part ]] || { echo "archive: $source_dir/$part is missing; run 'make PROFILE=$profile tables' first" >&2; exit 1; }
done

mkdir -p "$root/$version"
staging=$(mktemp -d "$root/$version/.$profile.staging.XXXXXX")
trap 'rm -rf "$staging"' EXIT

copy() {  # copy SUBDIR PATTERN...: the matching files of SOURCE/SUBDIR into the staging area
  local sub=$1; shift
  mkdir -p "$staging/$sub"
  local pattern
  for pattern in "$@"; do
    compgen -G "$source_dir/$sub/$pattern" > /dev/null && cp -p "$source_dir/$sub"/$pattern "$staging/$sub/"
  done
  return 0
}
copy packings 'seed-*[0-9].h5' '*.vtp' '*.xyz'  # not the kept contents, *.h5.contents.h5 (formats/contents_file.hpp)
copy normal '*.h5'
copy tangential '*-seed-*[0-9].h5'
copy averages '*.h5' '*.dat'
copy fits '*.json' '*.gp'
copy stamps '*.hash'
copy tables 'verdict.json' 'verdict.md' 'kt_unit.md'
cp "$profile_file" "$staging/profile.yaml"
[[ -f experiments/criteria.yaml ]] && cp experiments/criteria.yaml "$staging/criteria.yaml"

# Nothing to do when the archive already holds exactly these files (a fresh checkout that reused
# it): keep its provenance and BibTeX (they name the run that made the data), refresh its date.
# The tables (the verdict) are derived from the fits and averages and carry the code version and time
# of the run that wrote them: they are archived, not compared (tests/regression recomputes them).
# The profile and the criteria are compared by what they say, not by their comments: a comment
# edited since (a path renamed) is no other configuration -- the stamps, compared with the data,
# cover every section a stage reads -- and re-archiving for it would give data made by one commit
# the provenance of another.
data_sums() { (cd "$1" && find . -type f ! -name MANIFEST.sha256 ! -name PROVENANCE.json ! -name dataset.bib ! -path './tables/*' \
  ! -name profile.yaml ! -name criteria.yaml -printf '%P\n' | LC_ALL=C sort | xargs sha256sum); }
uncommented() { [[ ! -f $1 ]] || sed -E 's/(^|[[:space:]])#.*$//; s/[[:space:]]+$//' "$1" | grep -v '^$'; }
same_words() { diff -q <(uncommented "$staging/$1") <(uncommented "$dest/$1") > /dev/null; }
if [[ -f $dest/MANIFEST.sha256 ]] && diff -q <(data_sums "$staging") <(data_sums "$dest") > /dev/null \
  && same_words profile.yaml && same_words criteria.yaml; then
  touch "$dest/MANIFEST.sha256"
  echo "archive: $dest already holds these results (unchanged)"
  exit 0
fi

# Only from a clean tree (issue 29): an archive names a commit, and the commit must be what made
# it. Every change to a tracked file and every file git does not ignore counts, outside the
# archive folder itself; the refusal names them.
if git rev-parse --git-dir > /dev/null 2>&1; then
  changes=$(git status --porcelain --untracked-files=all 2> /dev/null | awk -v root="${root#./}/" '{ p = substr($0, 4); if (index(p, root) != 1) print "  " $0 }')
  if [[ -n $changes ]]; then
    echo "archive: refused: the working tree is not clean, so no commit describes what made these results; commit or" \
      "remove these files and run make archive again (the results are kept; nothing is recomputed):" >&2
    echo "$changes" >&2
    exit 1
  fi
fi
commit=$(git rev-parse --short=12 HEAD 2> /dev/null || echo unknown)
dirty=false
created=$(date -u +%Y-%m-%dT%H:%M:%SZ)
{
  echo "{"
  echo "  \"dataset\": \"softpack $version, profile $profile\","
  echo "  \"softpack_version\": \"$version\","
  echo "  \"git_commit\": \"$commit\","
  echo "  \"git_dirty\": $dirty,"
  echo "  \"created_utc\": \"$created\","
  echo "  \"profile\": \"profile.yaml\","
  echo "  \"stamps\": {"
  first=1
  for stamp in "$staging"/stamps/*.hash; do
    [[ $first == 1 ]] || echo ","
    printf '    "%s": "%s"' "$(basename "$stamp" .hash)" "$(cat "$stamp")"
    first=0
  done
  echo
  echo "  },"
  echo "  \"note\": \"each result file carries its own provenance (configuration slice, seed, code version, time spent) in /provenance\""
  echo "}"
} > "$staging/PROVENANCE.json"

(cd "$staging" && find . -type f ! -name MANIFEST.sha256 -printf '%P\n' | LC_ALL=C sort | xargs sha256sum > MANIFEST.sha256)
manifest_sum=$(sha256sum "$staging/MANIFEST.sha256" | cut -c1-64)

cat > "$staging/dataset.bib" << EOF
@misc{softpack-data,
  author       = {{softpack developers}},
  title        = {softpack {$version}: soft-particle contact laws, profile {$profile} (packings, sweeps, averages, fits)},
  year         = {${created:0:4}},
  howpublished = {softpack repository, \\texttt{data/archive/$version/$profile}, commit \\texttt{$commit}},
  note         = {MANIFEST.sha256 SHA-256 {$manifest_sum}}
}
EOF

rm -rf "$dest.old"
[[ -d $dest ]] && mv "$dest" "$dest.old"
mv "$staging" "$dest"
rm -rf "$dest.old"
trap - EXIT
echo "archive: $dest ($(find "$dest" -type f | wc -l) files, $(du -sh "$dest" | cut -f1)); cite with $dest/dataset.bib"
