#!/usr/bin/env python3
"""Tables of a convergence study (docs/CONVERGENCE.md, formats in docs/FORMATS.md), CSV on stdout,
summaries on stderr. Three commands:

  convergence_table.py runs [--reference reference.csv] [--rms rms.json] RUN...
      One row per run directory <family>-<mesh> (xfem: X-FEM on an unstructured mesh, xgrid: X-FEM
      on a structured grid not aligned to the cut, cg: CG-FEM on a cut-aligned grid), each holding
      rms.json (xfem-rmserror), solve.json (xfem-solve) and classify.json (xfem-classify --summary).
      With --reference, column `resolved` says whether the RMS is at least 3 times the reference's
      own error estimate (the RMS between its two finest levels), and column `opening_error` the
      relative error of the run's crack opening at mid-width against the opening extrapolated from
      the reference's three levels (Richardson), a measure free of the reference's own error. --rms: the name of the RMS report
      in each run directory (default rms.json). Stderr: the fitted rate of each
      family (least squares of log RMS against log unknowns) and, for each X-FEM run, the CG-FEM
      RMS at the same number of unknowns (interpolated on log-log axes) and their ratio.
  convergence_table.py reference LEVEL...
      One row per reference level (directories ref-NXxNYxNZ, coarse to fine, each with solve.json,
      probe.csv, and rms.json against the finest for all but the finest), and the reference's
      error estimates on stderr.
  convergence_table.py check convergence.csv
      Exit 1 unless every resolved X-FEM run lies below CG-FEM at equal unknowns (CG-FEM's RMS
      interpolated on log-log axes; runs outside CG-FEM's range of unknowns are skipped), and
      unless every run says whether it is resolved: the claim of docs/CONVERGENCE.md, checked.
  convergence_table.py limits RUN...
      Richardson extrapolation of the probed quantities (probe.csv of xfem-probe at the points of
      probes.csv, by row) per family, from its three finest runs.
"""
import csv
import json
import math
import os
import sys

ORDER = {"xfem": 0, "xgrid": 1, "cg": 2, "ref": 3}
FAMILY = {"xfem": "X-FEM unstructured", "xgrid": "X-FEM structured", "cg": "CG-FEM cut-aligned",
          "ref": "CG-FEM reference"}


def fail(message):
    print("convergence_table: error: " + message, file=sys.stderr)
    sys.exit(1)


def load(run, name):
    path = os.path.join(run, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail("%s: %s" % (path, e))


def family_of(run):
    return os.path.basename(os.path.normpath(run)).split("-", 1)


def probe_values(run):
    """The probed quantities of one run: mouth opening at mid-width (uz above - uz below), crack-
    mouth corner uz (upper face), top corner uz. Rows of probes.csv, see the pipelines."""
    path = os.path.join(run, "probe.csv")
    try:
        with open(path) as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail("%s: %s" % (path, e))
    if len(rows) != 5:
        fail("%s: %d points, expected the 5 of probes.csv" % (path, len(rows)))
    uz = [float(r["uz"]) for r in rows]
    return {"opening_m": uz[0] - uz[1], "mouth_corner_uz_m": uz[2], "top_corner_uz_m": uz[4]}


def fitted_rate(points):
    """Slope of log y against log x, least squares."""
    pts = [(math.log(x), math.log(y)) for x, y in points]
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)


def loglog_interpolate(points, x):
    """y at x on the polyline through `points` (x increasing) in log-log axes; None outside."""
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x0 <= x <= x1:
            t = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
            return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0)))
    return None


def richardson(h, q):
    """Limit q0 and order p of q = q0 + C h^p through three (h, q), h decreasing (any ratios).
    Returns (None, None) when the three values are not monotone (no power law fits them)."""
    d1, d2 = q[0] - q[1], q[1] - q[2]
    if d1 == 0 or d2 == 0 or (d1 > 0) != (d2 > 0):
        return None, None
    target = d1 / d2

    def ratio(p):
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p)

    lo, hi = 0.01, 8.0  # ratio(p) increases with p
    if not ratio(lo) <= target <= ratio(hi):
        return None, None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
    p = 0.5 * (lo + hi)
    c = d2 / (h[1] ** p - h[2] ** p)
    return q[2] - c * h[2] ** p, p


def reference_estimate(path):
    """The finest reference's error estimates from reference.csv: the RMS between its two finest
    levels, and the Richardson estimate of its own error (order from the three levels)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if len(rows) < 2:
        fail("%s: needs at least two reference levels" % path)
    level_rms = float(rows[-2]["rms_vs_finest_m"])
    richardson_rms = float(rows[-1]["richardson_error_m"]) if rows[-1]["richardson_error_m"] else None
    # The crack opening's limit from the three finest levels (h = the cube edge along z).
    last = rows[-3:]
    opening_limit, _ = richardson([0.2 / int(r["level"].split("x")[2]) for r in last],
                                  [float(r["opening_m"]) for r in last]) if len(last) == 3 else (None, None)
    return level_rms, richardson_rms, opening_limit


def cmd_runs(args):
    reference, rms_name = None, "rms.json"
    while len(args) >= 2 and args[0] in ("--reference", "--rms"):
        if args[0] == "--reference":
            reference = reference_estimate(args[1])
        else:
            rms_name = args[1]
        args = args[2:]
    rows = []
    for run in args:
        rms, solve, classify = load(run, rms_name), load(run, "solve.json"), load(run, "classify.json")
        method, label = family_of(run)
        resolved, opening_error = "", ""
        if reference:
            resolved = "yes" if rms["rms"] >= 3 * reference[0] else "no"
            if reference[2] and os.path.exists(os.path.join(run, "probe.csv")):
                opening_error = "%.4e" % abs(probe_values(run)["opening_m"] / reference[2] - 1)
        rows.append((method, label, classify["tets"], rms["n_vectors"], rms["n_unknowns"],
                     classify["sign"] + classify["branch"], rms["rms"], rms["relative_rms"], rms["max"],
                     solve["setup_seconds"] + solve["solve_seconds"], resolved, opening_error))
    rows.sort(key=lambda r: (ORDER.get(r[0], 9), r[4]))
    print("method,mesh,tets,n_vectors,unknowns,enriched_nodes,rms_m,relative_rms,max_m,solve_s,resolved,"
          "opening_error")
    for r in rows:
        print(",".join([r[0], r[1], str(r[2]), str(r[3]), str(r[4]), str(r[5]),
                        "%.6e" % r[6], "%.6e" % r[7], "%.6e" % r[8], "%.3f" % r[9], r[10], r[11]]))
    if reference:
        print("convergence_table: reference error estimate: RMS between its two finest levels %.3e m "
              "(resolved: RMS >= %.3e m); Richardson estimate of the finest level's own error %s"
              % (reference[0], 3 * reference[0], "%.3e m" % reference[1] if reference[1] else "n/a"),
              file=sys.stderr)
        if reference[2]:
            print("convergence_table: crack opening at mid-width, extrapolated from the reference levels: %.6e m"
                  % reference[2], file=sys.stderr)
    for method in ("xfem", "xgrid", "cg"):
        pts = [(r[4], r[6]) for r in rows if r[0] == method]
        if len(pts) >= 2:
            print("convergence_table: %s: RMS ~ unknowns^%.3f (%d runs)" % (method, fitted_rate(pts), len(pts)),
                  file=sys.stderr)
        resolved = [(r[4], r[6]) for r in rows if r[0] == method and r[10] == "yes"]
        if reference and 2 <= len(resolved) < len(pts):
            print("convergence_table: %s: RMS ~ unknowns^%.3f over the %d resolved runs" %
                  (method, fitted_rate(resolved), len(resolved)), file=sys.stderr)
        openings = [(r[4], float(r[11])) for r in rows if r[0] == method and r[11]]
        if len(openings) >= 2:
            print("convergence_table: %s: crack-opening error ~ unknowns^%.3f" % (method, fitted_rate(openings)),
                  file=sys.stderr)
    cg = [(r[4], r[6]) for r in rows if r[0] == "cg"]
    for r in rows:
        if r[0] in ("xfem", "xgrid") and len(cg) >= 2:
            at = loglog_interpolate(cg, r[4])
            print("convergence_table: %s %s: %d unknowns, RMS %.3e, CG-FEM at equal unknowns %s" %
                  (r[0], r[1], r[4], r[6], "%.3e (ratio %.2f)" % (at, r[6] / at) if at else "outside its range"),
                  file=sys.stderr)


def cmd_reference(levels):
    rows = []
    for level in levels:
        solve = load(level, "solve.json")
        rms = load(level, "rms.json")["rms"] if level != levels[-1] else 0.0
        rows.append((os.path.basename(os.path.normpath(level)).split("-", 1)[1], solve, rms, probe_values(level)))
    # h of a level: its cube edge along z, 0.2 / NZ.
    h = [0.2 / int(r[0].split("x")[2]) for r in rows]
    err = None
    if len(rows) >= 3:
        # The coarser levels' RMS against the finest: d_i = C (h_i^p - h_f^p) -> order p, then the
        # finest level's own error C h_f^p = d_{f-1} h_f^p / (h_{f-1}^p - h_f^p).
        d = [r[2] for r in rows]
        hf = h[-1]
        target = d[-3] / d[-2] if d[-2] > 0 else None

        def ratio(p):
            return (h[-3] ** p - hf ** p) / (h[-2] ** p - hf ** p)

        if target and ratio(0.01) <= target <= ratio(8.0):
            lo, hi = 0.01, 8.0
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
            p = 0.5 * (lo + hi)
            err = d[-2] * hf ** p / (h[-2] ** p - hf ** p)
            print("convergence_table: reference: observed order %.2f in h; the finest level's own error %.3e m "
                  "(RMS between the two finest levels %.3e m)" % (p, err, d[-2]), file=sys.stderr)
    print("level,unknowns,rms_vs_finest_m,richardson_error_m,opening_m,mouth_corner_uz_m,top_corner_uz_m,"
          "solve_s,iterations")
    for k, (label, solve, rms, q) in enumerate(rows):
        print("%s,%d,%.6e,%s,%.9e,%.9e,%.9e,%.1f,%s" % (
            label, 3 * solve["n"], rms, ("%.6e" % err) if (err and k == len(rows) - 1) else "",
            q["opening_m"], q["mouth_corner_uz_m"], q["top_corner_uz_m"],
            solve["setup_seconds"] + solve["solve_seconds"], solve.get("iterations", "")))


def cmd_limits(runs):
    by_family = {}
    for run in runs:
        method, label = family_of(run)
        n = load(run, "solve.json")["n"]
        by_family.setdefault(method, []).append((3 * n, label, probe_values(run)))
    print("method,quantity,mesh_1,mesh_2,mesh_3,unknowns_1,unknowns_2,unknowns_3,value_1,value_2,value_3,"
          "order_in_h,limit")
    for method in sorted(by_family, key=lambda m: ORDER.get(m, 9)):
        finest = sorted(by_family[method])[-3:]
        if len(finest) < 3:
            continue
        h = [u ** (-1.0 / 3.0) for u, _, _ in finest]  # mesh size ~ (unknowns)^(-1/3)
        for quantity in ("opening_m", "mouth_corner_uz_m", "top_corner_uz_m"):
            q = [v[quantity] for _, _, v in finest]
            limit, p = richardson(h, q)
            print("%s,%s,%s,%s,%s,%d,%d,%d,%.9e,%.9e,%.9e,%s,%s" % (
                method, quantity, finest[0][1], finest[1][1], finest[2][1], finest[0][0], finest[1][0],
                finest[2][0], q[0], q[1], q[2], "%.3f" % p if p else "", "%.9e" % limit if limit else ""))
            print("convergence_table: %s %s: %s" % (FAMILY.get(method, method), quantity,
                  "limit %.6e (order %.2f)" % (limit, p) if limit else "not monotone over the three finest runs: "
                  "no extrapolation"), file=sys.stderr)


def cmd_check(args):
    if len(args) != 1:
        fail("usage: convergence_table.py check convergence.csv")
    with open(args[0]) as f:
        rows = list(csv.DictReader(f))
    cg = sorted((int(r["unknowns"]), float(r["rms_m"])) for r in rows if r["method"] == "cg")
    checked, bad = 0, []
    for r in rows:
        if r["resolved"] not in ("yes", "no"):
            bad.append("%s %s: no `resolved` verdict" % (r["method"], r["mesh"]))
        if r["method"] not in ("xfem", "xgrid") or r["resolved"] != "yes":
            continue
        at = loglog_interpolate(cg, int(r["unknowns"]))
        if at is None:
            continue
        checked += 1
        if not float(r["rms_m"]) < at:
            bad.append("%s %s: RMS %s at %s unknowns, CG-FEM %.3e" % (r["method"], r["mesh"], r["rms_m"],
                                                                     r["unknowns"], at))
    if bad or checked == 0:
        fail("%s: X-FEM is not below CG-FEM at every resolved size: %s" % (args[0], "; ".join(bad) or "no run checked"))
    print("convergence_table: %s: X-FEM below CG-FEM at all %d resolved sizes within CG-FEM's range" %
          (args[0], checked), file=sys.stderr)


if __name__ == "__main__":
    commands = {"runs": cmd_runs, "reference": cmd_reference, "limits": cmd_limits, "check": cmd_check}
    if len(sys.argv) < 2 or sys.argv[1] not in commands:
        fail("usage: convergence_table.py runs|reference|limits|check ... (see the docstring)")
    commands[sys.argv[1]](sys.argv[2:])
