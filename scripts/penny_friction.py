#!/usr/bin/env python3
"""The inclined penny pressed shut with Coulomb friction (issue 33, docs/VERIFICATION.md "Friction").

  penny_friction.py problem CLOSED.json MU   prints data/penny_closed.json with friction MU: in
                                             "contact" and in the exact field on the boundary
  penny_friction.py table RUN...             one CSV row per run: RUN/opening.csv (xfem-probe at
                                             penny_opening.py's points) and RUN/solve.json (xfem-solve's
                                             report); RUN's
                                             name ends in frictionMU

tau / |sigma_n| = tan beta = 1 on the disc: for mu >= 1 the faces stick and u is the uniform field
(its error against it at the probe's points is reported, over the field's max |u| in the box); for mu < 1 they slide by Segedin's jump of
tau - mu |sigma_n| (its error against it, as penny_opening.py slip does for mu = 0).
"""
import csv
import json
import math
import re
import sys

CENTRE, A, E, NU = (0.5, 0.5, 0.47), 0.3, 1.0, 0.3
TAU, SIGMA = 0.5, -0.5  # the resolved shear (along -x) and the normal stress on the disc


def problem(path, mu):
    p = json.load(open(path))
    p["contact"] = {"friction": mu}
    for d in p["dirichlet"]:
        d["exact"]["penny"]["friction"] = mu
    print(json.dumps(p, indent=1))


def segedin(r, tau):
    return 16 * (1 - NU**2) * tau * math.sqrt(A * A - r * r) / (math.pi * (2 - NU) * E)


def vector(path):
    rows = [l for l in open(path) if not l.startswith('%')]
    return [float(x) for x in rows[1:]]


def uniform_error(run):
    """Largest |u - uniform field| over the probe's points on both faces (RUN/opening.csv), over the
    uniform field's largest |u| in the unit box (at its corners)."""
    sigma = [[0, 0, -TAU], [0, 0, 0], [-TAU, 0, SIGMA]]
    tr = SIGMA
    eps = [[((1 + NU) * sigma[i][j] - NU * tr * (i == j)) / E for j in range(3)] for i in range(3)]
    def uniform(x):
        return [sum(eps[i][j] * (x[j] - CENTRE[j]) for j in range(3)) for i in range(3)]
    corners = [(a, b, c) for a in (0, 1) for b in (0, 1) for c in (0, 1)]
    scale = max(max(abs(v) for v in uniform(x)) for x in corners)
    worst = 0.0
    for row in csv.DictReader(open(run + "/opening.csv")):
        x = [float(row[k]) for k in ("x", "y", "z")]
        exact = uniform(x)
        worst = max(worst, max(abs(float(row[k]) - exact[i]) for i, k in enumerate(("ux", "uy", "uz"))))
    return worst / scale


def table(runs):
    print("run,mu,points,stick,slip,solves,damped,updates,max_penetration,tolerance,normal_force_N,shear_force_N,"
          "max_slip_m,max_slip_error,rms_slip_error,uniform_error")
    for run in runs:
        mu = float(re.search(r"friction([0-9.]+)/*$", run).group(1))
        effective = max(0.0, TAU - mu * abs(SIGMA))
        r = json.load(open(run + "/solve.json"))
        c, f = r["contact"], r["friction"]
        worst, rms, uniform = "", "", ""
        if effective > 0:
            rows = list(csv.DictReader(open(run + "/opening.csv")))
            errors = []
            for i in range(0, len(rows), 2):
                up, down = rows[i], rows[i + 1]
                radius = math.hypot(float(up["x"]) - CENTRE[0], float(up["y"]) - CENTRE[1])
                errors.append(-(float(up["ux"]) - float(down["ux"])) / segedin(radius, effective) - 1)
            worst = "%.4f" % max(errors, key=abs)
            rms = "%.4f" % math.sqrt(sum(x * x for x in errors) / len(errors))
        else:
            uniform = "%.2e" % uniform_error(run)
        print("%s,%g,%d,%d,%d,%d,%d,%d,%.2g,%.2g,%.6g,%.6g,%.3g,%s,%s,%s" % (
            run, mu, c["points"], f["stick_points"], f["slip_points"], c["solves"], c["damped_steps"],
            c["multiplier_updates"], c["max_penetration"], c["tolerance"], c["force"], f["shear_force"],
            f["max_slip"], worst, rms, uniform))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "problem":
        problem(sys.argv[2], float(sys.argv[3]))
    elif len(sys.argv) >= 3 and sys.argv[1] == "table":
        table(sys.argv[2:])
    else:
        sys.exit(__doc__)
