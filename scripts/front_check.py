#!/usr/bin/env python3
"""Checks xfem-front's front.csv files against imposed stress intensity factors (issue 15).

  front_check.py --tolerance 0.01 --exact data/exact1.json out/s8-radius/mode1/front.csv ...

Each CSV is paired with the exact field given before it (--exact applies to the CSVs that follow).
At every interior front point (end = 0): |K_m - K_m,exact| <= tolerance * K_ref for the imposed
factor and the two others, K_ref = the largest imposed |K| (--others TOL: a separate tolerance for
the factors whose exact value is 0). Prints one line per file with the worst relative errors;
exits 1 when a check fails, 2 on bad input.
"""
import csv
import json
import math
import sys


def load_exact(path):
    """The exact K_I, K_II, K_III: a Williams field's, or the penny-shaped crack's K_I = 2 sigma sqrt(a / pi)."""
    with open(path) as f:
        j = json.load(f)
    if "penny" in j:
        p = j["penny"]
        return [2.0 * float(p["sigma"]) * math.sqrt(float(p["radius"]) / math.pi), 0.0, 0.0]
    w = j["williams"]
    return [float(w.get("K1", 0.0)), float(w.get("K2", 0.0)), float(w.get("K3", 0.0))]


def main(argv):
    tolerance, others, exact, failed, checked = None, None, None, False, 0
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--tolerance", "--exact", "--others"):
            if i + 1 >= len(argv):
                print(f"front_check.py: error: {a} needs a value", file=sys.stderr)
                return 2
            if a == "--tolerance":
                tolerance = float(argv[i + 1])
            elif a == "--others":
                others = float(argv[i + 1])
            else:
                exact = load_exact(argv[i + 1])
            i += 2
            continue
        if tolerance is None or exact is None:
            print("front_check.py: error: give --tolerance and --exact before the CSV files", file=sys.stderr)
            return 2
        with open(a) as f:
            rows = [r for r in csv.DictReader(f) if r["end"] == "0"]
        if not rows:
            print(f"front_check.py: error: {a}: no interior front point", file=sys.stderr)
            return 2
        kref = max(abs(k) for k in exact)
        worst = [0.0, 0.0, 0.0]
        for r in rows:
            for m, name in enumerate(("K_I", "K_II", "K_III")):
                worst[m] = max(worst[m], abs(float(r[name]) - exact[m]) / kref)
        tol = [tolerance if exact[m] != 0 or others is None else others for m in range(3)]
        ok = all(worst[m] <= tol[m] for m in range(3))
        failed |= not ok
        checked += 1
        print(f"{a}: {len(rows)} interior points, max |K - K_exact| / K: K_I {worst[0]:.2e}, "
              f"K_II {worst[1]:.2e}, K_III {worst[2]:.2e} (tolerance {'/'.join('%g' % t for t in tol)}) "
              f"{'ok' if ok else 'FAIL'}")
        i += 1
    if checked == 0:
        print("front_check.py: error: no CSV files", file=sys.stderr)
        return 2
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
