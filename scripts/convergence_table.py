#!/usr/bin/env python3
"""Collects a convergence study's run directories into one CSV on stdout, and prints on stderr
the fitted rate of each method: the slope of log(RMS) against log(unknowns), least squares.

Each argument is a run directory, named <method>-<mesh> (xfem: X-FEM on an unstructured mesh,
xgrid: X-FEM on a structured grid not aligned to the cut, cg: CG-FEM on a cut-aligned grid), holding rms.json (xfem-rmserror), solve.json (xfem-solve) and
classify.json (xfem-classify --summary). Rows are sorted by method, then by unknowns.
"""
import json
import os
import sys


def load(run, name):
    with open(os.path.join(run, name)) as f:
        return json.load(f)


rows = []
for run in sys.argv[1:]:
    rms, solve, classify = load(run, "rms.json"), load(run, "solve.json"), load(run, "classify.json")
    method = os.path.basename(run).split("-", 1)[0]
    label = os.path.basename(run).split("-", 1)[1]
    rows.append((method, label, classify["tets"], rms["n_vectors"], rms["n_unknowns"],
                 classify["sign"] + classify["branch"], rms["rms"], rms["relative_rms"], rms["max"],
                 solve["setup_seconds"] + solve["solve_seconds"]))
order = {"xfem": 0, "xgrid": 1, "cg": 2}
rows.sort(key=lambda r: (order.get(r[0], 3), r[4]))
print("method,mesh,tets,n_vectors,unknowns,enriched_nodes,rms_m,relative_rms,max_m,solve_s")
for r in rows:
    print(",".join([r[0], r[1], str(r[2]), str(r[3]), str(r[4]), str(r[5]),
                    "%.6e" % r[6], "%.6e" % r[7], "%.6e" % r[8], "%.3f" % r[9]]))

import math
for method in ("xfem", "xgrid", "cg"):
    pts = [(math.log(r[4]), math.log(r[6])) for r in rows if r[0] == method]
    if len(pts) < 2:
        continue
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    slope = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
    print("convergence_table: %s: RMS ~ unknowns^%.3f (%d runs)" % (method, slope, len(pts)), file=sys.stderr)
