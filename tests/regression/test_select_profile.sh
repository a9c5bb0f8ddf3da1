#!/usr/bin/env bash
# criteria.select_profile (issue 29): the select profile is the paper profile on the criteria's
# select seeds: every stage's sections are the paper profile's (the same canonical text), and its
# seeds are experiments/criteria.yaml's seeds.select; the paper profile's seeds are its seeds.report.
set -euo pipefail
bin=$1 root=$2
cd "$root"
for stage in packing normal tangential average; do
  diff <("$bin/softpack-config" experiments/paper.yaml text $stage | grep -v "^seeds:") \
       <("$bin/softpack-config" experiments/select.yaml text $stage | grep -v "^seeds:") ||
    { echo "FAIL: experiments/select.yaml's $stage sections differ from experiments/paper.yaml's" >&2; exit 1; }
done
seeds() { python3 -c "import re,sys; t=open('experiments/criteria.yaml').read(); print(' '.join(re.search(r'$1: \[([^\]]*)\]', t).group(1).replace(',', ' ').split()))"; }
[[ $("$bin/softpack-config" experiments/select.yaml seeds) == "$(seeds select)" ]] ||
  { echo "FAIL: experiments/select.yaml's seeds are not the criteria's select seeds ($(seeds select))" >&2; exit 1; }
[[ $("$bin/softpack-config" experiments/paper.yaml seeds) == "$(seeds report)" ]] ||
  { echo "FAIL: experiments/paper.yaml's seeds are not the criteria's report seeds ($(seeds report))" >&2; exit 1; }
echo "ok: the select profile is the paper profile on the criteria's select seeds"
