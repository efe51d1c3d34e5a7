#!/usr/bin/env python3
"""The layering rule of lib/xfem (docs/ARCHITECTURE.md): the stages are ordered, and a file includes
only files of its own stage or of an earlier one. Reads every #include "xfem/..." of lib/xfem and
prints one line per break, naming the file and the include; exits 1 if there is any.

usage: check_layers.py [LIB_DIR]    (default: lib/xfem beside this script's folder)
"""
import pathlib
import re
import sys

# The pipeline's order: each stage may use the ones above it, never the ones below.
STAGES = [
    "core",         # mesh, errors, threads, atomic files, fingerprints, JSON, command lines
    "io",           # file formats: VTK, gmsh, Matrix Market, PETSc binary, pictures, ParaView
    "generate",     # input generators: box, unstructured and organ meshes, cut surfaces, sweeps
    "geometry",     # the cut's geometry: cut surface, crack front, exact pieces, splits, point location
    "enrich",       # classification, several cuts, DOF numbering, enriched mesh and basis
    "integrate",    # quadrature rules, consistent gradients, element matrices
    "fracture",     # crack-tip fields and stress intensity factors
    "system",       # problem.json, Dirichlet, loads, reactions, assembly, the system directory
    "solve",        # CHOLMOD, PETSc, Schur complements, the solve driver
    "progressive",  # progressive cutting
    "post",         # deformed mesh, errors, probes
]
INCLUDE = re.compile(r'^\s*#\s*include\s+"xfem/([^"]+)"', re.MULTILINE)


def breaks(lib):
    rank = {stage: i for i, stage in enumerate(STAGES)}
    found = []
    for path in sorted(lib.rglob("*")):
        if not path.is_file() or path.suffix not in (".h", ".cpp", ".in"):
            continue
        relative = path.relative_to(lib)
        stage = relative.parts[0] if len(relative.parts) > 1 else None
        if stage not in rank:
            found.append(f"{path}: not in a stage folder ({', '.join(STAGES)}); "
                         "add the stage to scripts/check_layers.py and docs/ARCHITECTURE.md")
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            target_stage = target.split("/")[0]
            line = text.count("\n", 0, match.start()) + 1
            if target_stage not in rank:
                found.append(f'{path}:{line}: #include "xfem/{target}" names no stage')
            elif rank[target_stage] > rank[stage]:
                found.append(f'{path}:{line}: #include "xfem/{target}": stage {stage} may not use '
                             f"the later stage {target_stage}")
    return found


def main():
    lib = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent / "lib" / "xfem"
    if not lib.is_dir():
        print(f"check_layers: {lib}: not a directory", file=sys.stderr)
        return 2
    found = breaks(lib)
    for line in found:
        print(f"check_layers: {line}", file=sys.stderr)
    if not found:
        print(f"check_layers: {lib}: every include keeps the stage order ({' < '.join(STAGES)})")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
