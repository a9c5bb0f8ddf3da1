#!/usr/bin/env python3
"""Every file and folder a guide names exists: each `path` in backquotes of the given Markdown
files that looks like a source path (a name with an extension we keep in git, or a folder ending
in /) is found from the project's folder, from a wing's root (engine/, pipeline/, studies/: the
way includes name files) or from the guide's own folder. Paths with a placeholder (a segment in
capitals: DATA, PROFILE), the outputs of a run or a build (under data/, tables/, generated/,
build/) and paths outside the project (../) are left out: a fresh clone has none.

usage: check_doc_paths.py ROOT GUIDE.md...   (exit 1 with one line per missing path)
"""
import re
import sys
from pathlib import Path

WING_ROOTS = ["", "engine/", "pipeline/", "studies/"]
PATH = re.compile(r"^[\w.-]+(/[\w.-]+)*(\.(hpp|cpp|py|sh|mk|yaml|md|txt|cmake|tex|bib|gp|cff)|/)$")
OUTPUT = re.compile(r"^(data|tables|generated|build|\.\.)/|(^|/)[A-Z_]+(/|$)")
CODE = re.compile(r"`([^`\n]+)`")


def main(root: Path, guides) -> int:
    missing, checked = [], 0
    for guide in guides:
        text = guide.read_text()
        for n, line in enumerate(text.splitlines(), 1):
            for token in CODE.findall(line):
                token = token.split(" ")[0].rstrip(".,;:")
                if not PATH.match(token) or "/" not in token.rstrip("/") or OUTPUT.match(token):
                    continue
                checked += 1
                bases = [root / w for w in WING_ROOTS] + [guide.parent]
                if not any((b / token).exists() for b in bases):
                    missing.append(f"{guide.relative_to(root)}:{n}: `{token}` does not exist")
    for m in missing:
        print(m)
    print(f"{checked} paths named, {len(missing)} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    root = Path(sys.argv[1])
    sys.exit(main(root, [root / g for g in sys.argv[2:]]))
