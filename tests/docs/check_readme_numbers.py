#!/usr/bin/env python3
"""Every number in README.md is measured or generated (issue 31: the README said a packing of
"about 5 700 grains in 1.5 s" and "100 CPU-minutes" long after either was true).

A number in the README's prose (code blocks and `code` spans are commands, paths and keys, not
claims) is one of:
  - a claim below, in CLAIMS: a phrase of the README with the value recomputed here from the
    committed results (the archive of this release, data/fast-check/) or from the file that
    sets it; a claim whose phrase is not in the README with the value of today fails;
  - a reference (Eq. 7, Table 2, Figures 1-6, §4, release 0.6.0, a citation's year);
  - an input (a value of an experiments/**/*.yaml file, so it cannot drift from it);
  - on tests/docs/readme-numbers.yaml with its source (a platform, an exit code, a format).
Exit 1 listing every claim that fails and every other number, with its line.

    tests/docs/check_readme_numbers.py BIN_DIR [README]
"""
import functools
import glob
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

root = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "tests" / "paper"))
from check_numbers import allowed_list  # noqa: E402  (one reader of the allow-lists)
bin_dir = Path(sys.argv[1])
readme_path = Path(sys.argv[2]) if len(sys.argv) > 2 else root / "README.md"
version = re.search(r"project\(softpack VERSION (\S+)", (root / "CMakeLists.txt").read_text()).group(1)
archive = root / "data" / "archive" / version / "paper"


def timing(**files):
    """softpack-timing's JSON for the files given (packings=[...], normal=[...], tangential=[...])."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "timing.json"
        args = [str(bin_dir / "softpack-timing"), "--json", str(out)]
        for kind, paths in files.items():
            args += [f"--{kind}"] + [str(p) for p in paths]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
        return json.loads(out.read_text())


@functools.cache
def archive_cpu_minutes():
    files = {k: sorted(glob.glob(str(archive / k / "*.h5"))) for k in ("packings", "normal", "tangential")}
    return sum(s["cost"]["cpu"] for s in timing(**files)["stages"]) / 60


@functools.cache
def longest_job():
    """The archive's sweep file of most CPU time: (its scene and stage, CPU-minutes)."""
    best = (0.0, "")
    for stage in ("normal", "tangential"):
        for f in sorted(glob.glob(str(archive / stage / "*.h5"))):
            cpu = sum(s["cost"]["cpu"] for s in timing(**{stage: [f]})["stages"])
            scene = Path(f).name.split("-seed-")[0]
            best = max(best, (cpu, f"{scene} {stage}"))
    return best[1], best[0] / 60


@functools.cache
def fast_check():
    return json.loads((root / "data" / "fast-check" / "check.json").read_text())


def fast_forces_agree():
    """The README's sentence: every force compared agrees, and no compared Eq. 7 coefficient does."""
    rows = [r for r in fast_check()["rows"] if r["established"]]
    forces = [r for r in rows if re.search(r"(Fn|kt)\(", r["quantity"])]
    eq7 = [r for r in rows if re.search(r"normal (a|b|c|delta)$", r["quantity"])]
    return forces and eq7 and all(r["agrees"] for r in forces) and not any(r["agrees"] for r in eq7)


def make_default(variable, makefile):
    return re.search(rf"^{variable} \?= (\S+)", (root / makefile).read_text(), re.M).group(1)


# (what, the README's phrase with {} for each value, the values now: a function)
CLAIMS = [
    ("the paper profile's CPU time from scratch, its archive's record",
     "its packings and sweeps take {} CPU-minutes (release {}", lambda: (f"{archive_cpu_minutes():.0f}", version)),
    ("the longest job of the paper profile, its archive's record",
     "the longest job of the paper profile, a {} sweep, took {} CPU-minutes in release {}",
     lambda: (longest_job()[0], f"{longest_job()[1]:.0f}", version)),
    ("the fast profile's CPU time against the full protocol's (data/fast-check/check.json)",
     "at {} times less CPU time than the full protocol on them ({} CPU-minutes",
     lambda: (f"{1 / fast_check()['cpu_ratio']:.1f}", f"{fast_check()['candidate_cpu'] / 60:.1f}")),
    ("the fast check's agreement (data/fast-check/check.json)",
     "of the {} quantities that run compared, {} agree", lambda: (fast_check()["compared"], fast_check()["agreeing"])),
    ("the fuzzers' default time (workflow/fuzz.mk)", "`FUZZ_SECONDS` ({}) per target",
     lambda: (make_default("FUZZ_SECONDS", "workflow/fuzz.mk"),)),
]
# Sentences whose truth is a property of the data, not a number.
STATEMENTS = [
    ("every force among them (Fn at Δn = 0.3, 0.4, 0.5 and kt at 0.4, 0.5, where the paper profile tells them from zero), "
     "but Eq. 7's a, b, c and δ do not", fast_forces_agree),
]

REFERENCES = [
    r"```.*?```",  # code blocks: commands
    r"`[^`\n]*`",  # code spans: commands, paths, keys
    r"\]\([^)]*\)",  # link targets
    r"(?:Eqs?|Figures?|Figs?|Tables?|§|paper §)\.?\s*\d+(?:\s*[–-]\s*\d+)?",
    r"(?:releases?|release up to|version)\s*(?:up to\s*)?\d+\.\d+\.\d+",
    r"\d+\.\d+\.\d+",  # any other version
    r"[A-Za-z][\w-]*\d[\w-]*",  # names holding digits: C++20, x86-64-v2, AVX-512, NFSv4, h5py, Fletcher-32, SHA-256
    r"\(\d{4}\)|\b(?:19|20)\d\d\b",  # a citation's year
]


def inputs():
    values = set()
    for f in glob.glob(str(root / "experiments" / "**" / "*.yaml"), recursive=True):
        text = "\n".join(l.split("#")[0] for l in Path(f).read_text().splitlines())
        for v in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?:e[+-]?\d+)?", text):
            values.add(v)
            try:
                values.add(f"{float(v):g}")
            except ValueError:
                pass
    return values


def blank(m):
    """A match replaced by spaces, its line breaks kept (the line numbers of what follows)."""
    return re.sub(r"[^\n]", " ", m.group(0))


def find(phrase):
    """The phrase in the text, whatever the line breaks and spaces between its words."""
    return re.compile(r"\s+".join(re.escape(w) for w in phrase.split()))


def main():
    text = readme_path.read_text()
    bad = []
    for what, phrase, values in CLAIMS:
        now = phrase.format(*values())
        if not find(now).search(text):
            bad.append(f"{readme_path}: the claim '{what}' is not stated with today's value; the README should say: {now!r}")
        text = find(now).sub(blank, text)
    for phrase, holds in STATEMENTS:
        if not find(phrase).search(text):
            bad.append(f"{readme_path}: the sentence {phrase[:60]!r}... is missing (tests/docs/check_readme_numbers.py)")
        elif not holds():
            bad.append(f"{readme_path}: the data no longer say {phrase!r}")
        text = find(phrase).sub(blank, text)
    for pattern in REFERENCES:
        text = re.sub(pattern, blank, text, flags=re.S)
    allowed, given = allowed_list(root / "tests" / "docs" / "readme-numbers.yaml"), inputs()
    for number, line in enumerate(text.split("\n"), 1):
        for m in re.finditer(r"(?<![\w.^-])\d+(?:\.\d+)?(?:[  ]\d{3})*", line):
            value = re.sub(r"[  ]", "", m.group(0))
            if value in allowed or value in given:
                continue
            original = readme_path.read_text().split("\n")[number - 1]
            bad.append(f"{readme_path}:{number}: {value!r} in: {original.strip()[:110]}")
    if bad:
        print("check_readme_numbers: claims that do not hold today, and numbers that are neither a claim recomputed here, "
              "a reference, an input of experiments/ nor on tests/docs/readme-numbers.yaml:", file=sys.stderr)
        print("\n".join(bad), file=sys.stderr)
        return 1
    print(f"check_readme_numbers: {readme_path}: {len(CLAIMS)} claims and {len(STATEMENTS)} statements hold; "
          "every other number is a reference, an input or allowed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
