#!/usr/bin/env python3
"""The engine's architecture rules (docs/architecture.md), checked on the sources:

  1. folders form layers: a file includes only files of its own folder or of folders below it in
     LAYERS, so every dependency points one way (down);
  2. no include cycle between files;
  3. intrinsics (immintrin.h, _mm*, __m128/256/512, __mmask) only in engine/simd/;
  4. no #define in engine/ (no macro that generates functions; headers use #pragma once);
  5. no source file over 400 lines.

usage: check_architecture.py ENGINE_DIR   (exit 1 with one line per violation)
"""
import re
import sys
from pathlib import Path

# Bottom to top. A folder may include only folders earlier in this list (and itself).
LAYERS = ["core", "simd", "contact", "walls", "config", "scene", "state", "neighbor", "forces", "drivers",
          "integrate", "sim", "relax", "io", "packing", "analysis", "formats", "measure", "coarse", "report", "apps"]
MAX_LINES = 400
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
INTRINSIC = re.compile(r'\b(_mm\d*_\w+|__m(128|256|512)\w*|__mmask\d+)\b|<immintrin\.h>')
DEFINE = re.compile(r'^\s*#\s*define\b', re.M)


def main(engine: Path) -> int:
    problems = []
    files = sorted(p for p in engine.rglob("*") if p.suffix in (".hpp", ".cpp"))
    rank = {name: k for k, name in enumerate(LAYERS)}
    graph = {}
    for f in files:
        rel = f.relative_to(engine).as_posix()
        folder = rel.split("/")[0]
        text = f.read_text()
        if folder not in rank:
            problems.append(f"{rel}: folder '{folder}' is not in the layers of {Path(__file__).name}")
            continue
        lines = text.count("\n")
        if lines > MAX_LINES:
            problems.append(f"{rel}: {lines} lines, more than {MAX_LINES}")
        if folder != "simd" and INTRINSIC.search(text):
            problems.append(f"{rel}: intrinsics outside engine/simd/ ({INTRINSIC.search(text).group(0)})")
        if DEFINE.search(text):
            problems.append(f"{rel}: #define (macros are not used in engine/)")
        graph[rel] = []
        for inc in INCLUDE.findall(text):
            target_folder = inc.split("/")[0]
            if not (engine / inc).exists():
                continue  # generated (softpack_version.hpp) or not ours
            graph[rel].append(inc)
            if target_folder != folder and rank.get(target_folder, -1) > rank[folder]:
                problems.append(f"{rel}: includes {inc}: {folder}/ may not depend on {target_folder}/, a higher layer")
    # Include cycles (depth-first search; a back edge closes a cycle).
    state = {}

    def visit(node, stack):
        state[node] = 1
        stack.append(node)
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                problems.append("include cycle: " + " -> ".join(stack[stack.index(nxt):] + [nxt]))
            elif state.get(nxt) is None:
                visit(nxt, stack)
        stack.pop()
        state[node] = 2

    for node in graph:
        if state.get(node) is None:
            visit(node, [])
    for p in problems:
        print(p)
    print(f"{len(files)} files, {len(problems)} violations of the architecture rules")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
