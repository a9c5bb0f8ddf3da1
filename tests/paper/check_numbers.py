#!/usr/bin/env python3
"""No hand-typed result in the report (issue 29): every number in the body of paper/paper.tex must
be a macro of paper/variables.py (generated from the result files), a reference (Eq. 7, Fig. 3,
Table 2, release 0.4.0), an input of the profile (a value of experiments/paper.yaml, so it cannot
drift from it), or on the allow-list tests/paper/allowed-numbers.yaml, which holds the seed
paper's published values and physical constants, each with its source. Exit 1 listing every other
number with its line.

    tests/paper/check_numbers.py [paper/paper.tex]
"""
import re
import sys
from pathlib import Path

root = Path(__file__).resolve().parents[2]
tex_path = Path(sys.argv[1]) if len(sys.argv) > 1 else root / "paper" / "paper.tex"


def allowed_list(path=root / "tests" / "paper" / "allowed-numbers.yaml"):
    """The numbers of an allow-list file ("number": its source), each with its source."""
    out = {}
    for line in Path(path).read_text().splitlines():
        m = re.match(r'\s*"?([0-9.eE+-]+)"?\s*:\s*(.+)', line)
        if m and not line.lstrip().startswith("#"):
            if not m.group(2).strip():
                sys.exit(f"check_numbers: {m.group(1)} on the allow-list {path} has no source")
            out[m.group(1)] = m.group(2).strip()
    return out


def profile_inputs():
    text = (root / "experiments" / "paper.yaml").read_text()
    text = "\n".join(l.split("#")[0] for l in text.splitlines())  # values, not comments
    return set(re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?:e[+-]?\d+)?", text))


def body(tex):
    start, end = tex.index(r"\begin{document}"), tex.index(r"\end{document}")
    lines = tex[start:end].split("\n")
    first = tex[:start].count("\n") + 1
    return [(first + k, re.sub(r"(?<!\\)%.*", "", l)) for k, l in enumerate(lines)]


STRIP = [
    r"\\(?:file|cite|citep|citet|label|ref|eqref|input|texttt|includegraphics|bibliography|bibliographystyle)"
    r"(?:\[[^\]]*\])?\{[^}]*\}",
    r"\\begin\{(?:tabular|longtable)\}\{[^\n]*",  # column specifications
    r"\\v[A-Za-z]+",  # the generated macros
    r"\\\\\[[^\]]*\]", r"width=[0-9.]*\\?\w*", r"\\multicolumn\{\d+\}", r"p\{[0-9.]+cm\}",
    r"\\(?:hspace|vspace)\*?\{[^}]*\}",
    r"_\{\d+\}", r"_\d", r"\{[0-9.]+\\textwidth\}", r"C\+\+\d+", r"SHA-\d+",  # subscripts, layout, names
    # references: Eq. 7, Eqs. 7 and 8, Fig. 3, Figs. 4--5, Table 2, Tables 1 and 2, §4
    r"(?:Eqs?|Figs?|Tables?|Section|Sections)\.?(?:~|\s)*\d+(?:(?:--|,|~and~|\s+and~|\s+and\s+|~and\s)\s*~?\d+)*",
    r"(?:[Rr]eleases?|version)(?:~|\s)*(?:\$\\le\$\s*)?\d+\.\d+\.\d+",
    r"\d+\.\d+\.\d+",  # any other version number
]


def main():
    allowed = allowed_list()
    inputs = profile_inputs()
    bad = []
    for number, line in body(tex_path.read_text()):
        text = line
        for pattern in STRIP:
            text = re.sub(pattern, " ", text)
        for m in re.finditer(r"(?<![A-Za-z\\])\d+(?:\.\d+)?(?:\\,\d+)*", text):
            value = m.group(0).replace("\\,", "")
            if value in allowed or value in inputs:
                continue
            bad.append(f"{tex_path}:{number}: {value!r} in: {line.strip()[:110]}")
    if bad:
        print("check_numbers: result-like numbers outside a generated macro (paper/variables.py), an input of "
              "experiments/paper.yaml or the allow-list tests/paper/allowed-numbers.yaml:", file=sys.stderr)
        print("\n".join(bad), file=sys.stderr)
        return 1
    print(f"check_numbers: {tex_path}: every number is a macro, a reference, an input or allowed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
