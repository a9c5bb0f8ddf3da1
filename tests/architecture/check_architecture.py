#!/usr/bin/env python3
"""The architecture rules of docs/architecture.md, checked on the sources:

  1. wings: engine/ (the DEM engine), pipeline/ (files, packings, sweeps, analysis), studies/,
     lammps/ (softpack's styles in LAMMPS), apps/, in that order; a file includes only its own wing's files and those of wings before it;
  2. the other wings reach the engine through its public face only (ENGINE_FACE below, the table
     of docs/architecture.md): the rest of engine/ is the engine's own business;
  3. the engine needs the standard library, Eigen, yaml-cpp and fmt only (its other includes:
     the instruction sets' <immintrin.h>, POSIX <time.h> and OpenMP's <omp.h>, rule 9);
  4. no include cycle between files, and none between folders: within a wing, the folders form
     layers by themselves (any order the includes allow);
  5. a folder name is one wing's (includes are "folder/file.hpp" from the wings' roots);
  6. intrinsics (immintrin.h, _mm*, __m128/256/512, __mmask) only in engine/simd/;
  7. no #define in the wings (no macro that generates functions; headers use #pragma once);
  8. no C++ source file over 400 lines, the tests', benchmarks' and fuzz targets' included;
  9. OpenMP (#pragma omp, <omp.h>) only in engine/core/parallel.hpp: threads come from one place.

usage: check_architecture.py ROOT   (the project's folder; exit 1 with one line per violation)
"""
import re
import sys
from pathlib import Path

WINGS = ["engine", "pipeline", "studies", "lammps", "apps"]
# The engine's public face: what the pipeline, the studies and the commands may include from it.
ENGINE_FACE = {
    "core/error.hpp", "core/types.hpp", "core/version.hpp", "core/stopwatch.hpp", "core/random.hpp",
    "core/text_input.hpp", "core/suggest.hpp", "core/material.hpp",
    "config/yaml_node.hpp", "core/fnv1a.hpp", "core/parallel.hpp",
    "scene/scene_def.hpp", "scene/scene_yaml.hpp", "scene/validate.hpp",
    "scene/limits.hpp",
    "contact/soft_particle_law.hpp", "contact/viscous_damping.hpp", "walls/spherical_shell.hpp",
    "state/simulation_state.hpp",
    "forces/contact_models.hpp", "forces/contact_walk.hpp",
    "integrate/time_step.hpp",
    "sim/simulation.hpp", "relax/relaxation.hpp",
}
ENGINE_SYSTEM = re.compile(r"^(Eigen/|yaml-cpp/|fmt/|immintrin\.h$|time\.h$|omp\.h$|[a-z_]+$)")
MAX_LINES = 400
OPENMP = re.compile(r"^\s*#\s*pragma\s+omp\b|<omp\.h>", re.M)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SYSTEM_INCLUDE = re.compile(r'^\s*#\s*include\s+<([^>]+)>', re.M)
INTRINSIC = re.compile(r'\b(_mm\d*_\w+|__m(128|256|512)\w*|__mmask\d+)\b|<immintrin\.h>')
DEFINE = re.compile(r'^\s*#\s*define\b', re.M)
# One force loop (issue 32): a contact model's force (ContactForce, contact/contact_model.hpp) is
# evaluated only by the loop every model and every kind of contact go through.
FORCE_RESULT = re.compile(r'\bContactForce<|\btemplate\s+force<')
FORCE_LOOP_FILES = {"engine/forces/contact_loop.hpp", "engine/forces/pair_contacts.hpp", "engine/forces/wall_contacts.hpp"}
SOURCES = (".hpp", ".cpp")


def wing_files(root):
    """{path relative to its wing's root (apps: to the project): (wing, path)} of every source."""
    files = {}
    for wing in WINGS:
        base = root if wing == "apps" else root / wing
        for p in sorted((root / wing).rglob("*")):
            if p.suffix in SOURCES:
                files[p.relative_to(base).as_posix()] = (wing, p)
    return files


def cycles(graph):
    """Every back edge of a depth-first search, as the cycle it closes."""
    found, state = [], {}

    def visit(node, stack):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                found.append(" -> ".join(stack[stack.index(nxt):] + [nxt]))
            elif state.get(nxt) is None:
                visit(nxt, stack)
        stack.pop()
        state[node] = 2

    for node in sorted(graph):
        if state.get(node) is None:
            visit(node, [])
    return found


def main(root: Path) -> int:
    problems = []
    files = wing_files(root)
    rank = {w: k for k, w in enumerate(WINGS)}
    folder_wing, graph, folders = {}, {}, {}
    for rel, (wing, _) in files.items():
        folder = rel.split("/")[0]
        if folder_wing.setdefault(folder, wing) != wing:
            problems.append(f"{wing}/{rel}: folder '{folder}' is also a folder of {folder_wing[folder]}/")
    for face in sorted(ENGINE_FACE - {r for r, (w, _) in files.items() if w == "engine"}):
        problems.append(f"engine/{face}: on the engine's face (ENGINE_FACE) but no such file")
    for rel, (wing, path) in files.items():
        text = path.read_text()
        shown = path.relative_to(root).as_posix()
        folder = rel.split("/")[0]
        if text.count("\n") > MAX_LINES:
            problems.append(f"{shown}: {text.count(chr(10))} lines, more than {MAX_LINES}")
        if not shown.startswith("engine/simd/") and INTRINSIC.search(text):
            problems.append(f"{shown}: intrinsics outside engine/simd/ ({INTRINSIC.search(text).group(0)})")
        # LAMMPS's pair styles (lammps/pair/) are LAMMPS's loop over its own neighbour lists calling the same model.
        if FORCE_RESULT.search(text) and not shown.startswith(("engine/contact/", "lammps/pair/")) and shown not in FORCE_LOOP_FILES:
            problems.append(f"{shown}: evaluates a contact model's force (ContactForce) outside the one force loop "
                            f"(engine/forces/contact_loop.hpp and the kinds of contact it runs): a second force path")
        if DEFINE.search(text):
            problems.append(f"{shown}: #define (macros are not used in the wings)")
        if shown != "engine/core/parallel.hpp" and OPENMP.search(text):
            problems.append(f"{shown}: OpenMP outside engine/core/parallel.hpp (threads come from one place)")
        if wing == "engine":
            for inc in SYSTEM_INCLUDE.findall(text):
                if not ENGINE_SYSTEM.match(inc):
                    problems.append(f"{shown}: includes <{inc}>: the engine needs the standard library, Eigen, "
                                    f"yaml-cpp and fmt only")
        graph[rel] = set()
        for inc in INCLUDE.findall(text):
            if inc not in files:
                continue  # generated (softpack_version.hpp, softpack_build.hpp) or not ours
            to_wing = files[inc][0]
            to_folder = inc.split("/")[0]
            graph[rel].add(inc)
            if to_folder != folder:
                folders.setdefault(folder, set()).add(to_folder)
            if rank[to_wing] > rank[wing]:
                problems.append(f"{shown}: includes {inc}: {wing}/ may not depend on {to_wing}/, a wing above it")
            elif to_wing == "engine" and wing != "engine" and inc not in ENGINE_FACE:
                problems.append(f"{shown}: includes engine/{inc}, which is not on the engine's public face "
                                f"(ENGINE_FACE, docs/architecture.md)")
    problems += [f"include cycle: {c}" for c in cycles(graph)]
    problems += [f"folder cycle: {c}" for c in cycles(folders)]
    for extra in ("tests", "bench", "fuzz"):
        for p in sorted((root / extra).rglob("*")):
            if p.suffix in SOURCES and p.read_text().count("\n") > MAX_LINES:
                problems.append(f"{p.relative_to(root)}: {p.read_text().count(chr(10))} lines, more than {MAX_LINES}")
    for p in problems:
        print(p)
    print(f"{len(files)} files in {len(WINGS)} wings, {len(problems)} violations of the architecture rules")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
