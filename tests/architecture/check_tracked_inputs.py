#!/usr/bin/env python3
"""Every file under data/ that an experiment or a study file reads (a value, not a comment, of
experiments/**/*.yaml) is tracked by git: a fresh clone has it. A law file or a generated profile
that is present here only because a run made it passes every test on this machine and fails on a
clean clone (the nested-medium study read an ignored profile of the three-decade chain).

usage: check_tracked_inputs.py ROOT   (exit 1 with one line per untracked input; 77, skipped,
outside a git checkout)
"""
import re
import subprocess
import sys
from pathlib import Path

INPUT = re.compile(r"(?<![\w/.-])(data/[\w./-]+\.(?:yaml|json|h5|dat))")


def main(root: Path) -> int:
    try:
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], check=True, capture_output=True).stdout
    except (OSError, subprocess.CalledProcessError):
        print("not a git checkout: skipped")
        return 77
    tracked = set(listed.decode().split("\0"))
    missing, checked = [], 0
    for f in sorted((root / "experiments").rglob("*.yaml")):
        for n, line in enumerate(f.read_text().splitlines(), 1):
            for path in INPUT.findall(line.split("#", 1)[0]):
                checked += 1
                if path not in tracked:
                    missing.append(f"{f.relative_to(root)}:{n}: {path} is not tracked by git (a fresh clone lacks it)")
    for m in missing:
        print(m)
    print(f"{checked} inputs under data/ named, {len(missing)} untracked")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
