#!/usr/bin/env python3
"""Collects a convergence study's run directories into one CSV on stdout.

Each argument is a run directory holding rms.json (xfem-rmserror), solve.json (xfem-solve) and
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
    method = "xfem" if os.path.basename(run).startswith("xfem-") else "cg"
    label = os.path.basename(run).split("-", 1)[1]
    rows.append((method, label, classify["tets"], rms["n_vectors"], rms["n_unknowns"],
                 classify.get("enriched_nodes", 0), rms["rms"], rms["relative_rms"], rms["max"],
                 solve["setup_seconds"] + solve["solve_seconds"]))
rows.sort(key=lambda r: (r[0] != "xfem", r[4]))
print("method,mesh,tets,n_vectors,unknowns,enriched_nodes,rms_m,relative_rms,max_m,solve_s")
for r in rows:
    print(",".join([r[0], r[1], str(r[2]), str(r[3]), str(r[4]), str(r[5]),
                    "%.6e" % r[6], "%.6e" % r[7], "%.6e" % r[8], "%.3f" % r[9]]))
