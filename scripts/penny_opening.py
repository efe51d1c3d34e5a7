#!/usr/bin/env python3
"""The pressurised penny crack's opening against Sneddon's (issue 33, docs/VERIFICATION.md).

  penny_opening.py points > points.csv        points on both faces of the disc of pipelines/verification
                                              (centre (0.5, 0.5, 0.47), radius 0.3, normal +z) for xfem-probe
  penny_opening.py slip RUN...                the inclined penny pressed shut (data/penny_closed.json): the
                                              slip against Segedin's, the gap, xfem-solve's contact report
  penny_opening.py table RUN...               one CSV row per run directory RUN (RUN/opening.csv: xfem-probe's
                                              values at those points; RUN/solve.json: xfem-solve's report with
                                              the contact operator's crack volume; RUN/error.json: xfem-rmserror's
                                              absolute L2 and H1 errors against the exact field)

Exact (E = 1, nu = 0.3, p = 1): opening 8 (1 - nu^2) p sqrt(a^2 - r^2) / (pi E), volume 16 (1 - nu^2) p a^3 / (3 E).
"""
import csv
import json
import math
import sys

CENTRE, A, E, NU, P = (0.5, 0.5, 0.47), 0.3, 1.0, 0.3, 1.0
RADII = [A * k / 20 for k in range(19)]  # 0 .. 0.9 a
DIRECTIONS = [(math.cos(t), math.sin(t)) for t in (0.1, 1.3, 2.5, 3.9, 5.2)]


def opening(r):
    return 8 * (1 - NU**2) * P * math.sqrt(A * A - r * r) / (math.pi * E)


def points():
    print("x,y,z,side")
    for c, s in DIRECTIONS:
        for r in RADII:
            for side in (1, -1):
                print("%.17g,%.17g,%.17g,%d" % (CENTRE[0] + r * c, CENTRE[1] + r * s, CENTRE[2], side))


def table(runs):
    volume = 16 * (1 - NU**2) * P * A**3 / (3 * E)
    print("run,l2_error,h1_error,max_opening_error,rms_opening_error,volume_m3,volume_error")
    for run in runs:
        rows = list(csv.DictReader(open(run + "/opening.csv")))
        errors = []
        for i in range(0, len(rows), 2):
            up, down = rows[i], rows[i + 1]
            r = math.hypot(float(up["x"]) - CENTRE[0], float(up["y"]) - CENTRE[1])
            errors.append((float(up["uz"]) - float(down["uz"])) / opening(r) - 1)
        v = json.load(open(run + "/solve.json"))["contact"]["opened_volume"]
        e = json.load(open(run + "/error.json"))
        print("%s,%.6g,%.6g,%.4f,%.4f,%.6f,%.4f" % (run, e["l2"], e["h1"], max(errors, key=abs),
                                                    math.sqrt(sum(x * x for x in errors) / len(errors)), v, v / volume - 1))


def slip(r, tau=0.5):
    """Segedin's sliding of the penny under the shear tau (frictionless shut faces, exact_fields.h)."""
    return 16 * (1 - NU**2) * tau * math.sqrt(A * A - r * r) / (math.pi * (2 - NU) * E)


def slip_table(runs):
    """The inclined penny pressed shut (data/penny_closed.json): the faces' jump u(above) - u(below)
    at the points of `points`, its x part against slip(r) along the resolved shear (-x here: tau =
    -0.5 Pa), its y part against 0, its normal part (the gap) against 0; xfem-solve's contact report."""
    print("run,max_slip_error,rms_slip_error,max_cross_slip,max_abs_gap,max_gap_over_slip0,points,active_points,"
          "solves,multiplier_updates,max_penetration,tolerance,force_N,force_exact_N")
    for run in runs:
        rows = list(csv.DictReader(open(run + "/opening.csv")))
        errors, cross, gap = [], 0.0, 0.0
        for i in range(0, len(rows), 2):
            up, down = rows[i], rows[i + 1]
            r = math.hypot(float(up["x"]) - CENTRE[0], float(up["y"]) - CENTRE[1])
            jump = [float(up[k]) - float(down[k]) for k in ("ux", "uy", "uz")]
            errors.append(-jump[0] / slip(r) - 1)  # the resolved shear points along -x
            cross = max(cross, abs(jump[1]) / slip(0))
            gap = max(gap, abs(jump[2]))
        c = json.load(open(run + "/solve.json"))["contact"]
        print("%s,%.4f,%.4f,%.2e,%.3g,%.2e,%d,%d,%d,%d,%.3g,%.3g,%.6g,%.6g" % (
            run, max(errors, key=abs), math.sqrt(sum(x * x for x in errors) / len(errors)), cross, gap,
            gap / slip(0), c["points"], c["active_points"], c["solves"], c["multiplier_updates"],
            c["max_penetration"], c["tolerance"], c["force"], 0.5 * math.pi * A * A))


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "points":
        points()
    elif len(sys.argv) >= 3 and sys.argv[1] == "table":
        table(sys.argv[2:])
    elif len(sys.argv) >= 3 and sys.argv[1] == "slip":
        slip_table(sys.argv[2:])
    else:
        sys.exit(__doc__)
