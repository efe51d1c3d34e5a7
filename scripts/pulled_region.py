#!/usr/bin/env python3
"""Which top-face nodes a system's Dirichlet conditions pull, per run (docs/CONVERGENCE.md, the
unstructured X-FEM oddity). Each argument is a run directory with system/coordinates.mtx and
system/dirichlet.mtx (xfem-assemble) and probe.csv (xfem-probe at probes.csv), optionally rms.json (xfem-rmserror). Prints CSV: run,
pulled top-face nodes, the largest x of a pulled node, the smallest x of a free top-face node,
the mid-point of the two (where the pulled region's edge effectively sits: the displacement ramps
from 0.02 to free over the elements in between), the crack opening at mid-width and the RMS error.
"""
import csv
import json
import os
import sys


def read_mtx(path):
    """(rows, values) of a Matrix Market vector, coordinate or array."""
    with open(path) as f:
        banner = f.readline()
        lines = [l for l in f if not l.startswith("%")]
    if "coordinate" in banner:  # row col value, 1-based
        return {int(l.split()[0]) - 1: float(l.split()[2]) for l in lines[1:]}
    return {k: float(l) for k, l in enumerate(lines[1:])}


print("run,pulled_top_nodes,max_x_pulled_m,min_x_free_m,effective_edge_m,opening_m,rms_m")
for run in sys.argv[1:]:
    xyz = read_mtx(os.path.join(run, "system", "coordinates.mtx"))
    fixed = read_mtx(os.path.join(run, "system", "dirichlet.mtx"))
    np_ = len(xyz) // 3
    top = [k for k in range(np_) if xyz[3 * k + 2] > 0.2 - 1e-9]
    pulled = [k for k in top if abs(fixed.get(3 * k + 2, 0.0) - 0.02) < 1e-12]
    free = [k for k in top if 3 * k + 2 not in fixed]
    max_in = max(xyz[3 * k] for k in pulled)
    min_out = min(xyz[3 * k] for k in free) if free else float("nan")
    with open(os.path.join(run, "probe.csv")) as f:
        rows = list(csv.DictReader(f))
    opening = float(rows[0]["uz"]) - float(rows[1]["uz"])
    rms = ""
    if os.path.exists(os.path.join(run, "rms.json")):
        with open(os.path.join(run, "rms.json")) as f:
            rms = "%.4e" % json.load(f)["rms"]
    print("%s,%d,%.5f,%.5f,%.5f,%.6e,%s" % (os.path.basename(run), len(pulled), max_in, min_out,
                                            0.5 * (max_in + min_out), opening, rms))
