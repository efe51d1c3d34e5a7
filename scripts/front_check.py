#!/usr/bin/env python3
"""Checks xfem-front's front.csv files against imposed stress intensity factors (issue 15).

  front_check.py --tolerance 0.01 --exact data/exact1.json out/s8-radius/mode1/front.csv ...

Each CSV is paired with the exact field given before it (--exact applies to the CSVs that follow).
At every interior front point (end = 0): |K_m - K_m,exact| <= tolerance * K_ref for the imposed
factor and the two others, K_ref = the largest imposed |K| (for an inclined penny, whose K_II and
K_III vary along the front: each factor's amplitude) (--others TOL: a separate tolerance for the
factors whose exact value is 0). Prints one line per file with the worst relative errors;
exits 1 when a check fails, 2 on bad input.
"""
import csv
import json
import math
import sys


def load_exact(path):
    """The exact factors as (function of a front.csv row -> [K_I, K_II, K_III], references [3]): a
    Williams field's constant K's (references: the largest |K|), or the penny-shaped crack's
    K_I = 2 sigma sqrt(a / pi) (0 with "loading": "closed") and, with a remote shear tau (an inclined disc),
    K_II = 4 / (2 - nu) sqrt(a / pi) tau.a, K_III = 4 (1 - nu) / (2 - nu) sqrt(a / pi) tau.c in the
    frame a = radial, b = the disc's normal, c = a x b (exact_fields.h; references: each factor's
    amplitude along the front)."""
    with open(path) as f:
        j = json.load(f)
    if "penny" in j:
        p = j["penny"]
        a, sigma = float(p["radius"]), float(p["sigma"])
        # "loading": "closed": the faces pressed shut carry the normal stress, no opening: K_I = 0.
        closed = p.get("loading") == "closed"
        k1 = 0.0 if closed else 2.0 * sigma * math.sqrt(a / math.pi)
        tau = [float(v) for v in p.get("shear", [0.0, 0.0, 0.0])]
        if not any(tau):
            return (lambda row: [k1, 0.0, 0.0]), [abs(k1)] * 3
        nu = float(p["nu"])
        centre = [float(v) for v in p.get("centre", [0.0, 0.0, 0.0])]
        n = [float(v) for v in p["normal"]]
        nn = math.sqrt(sum(v * v for v in n))
        n = [v / nn for v in n]
        g = math.sqrt(a / math.pi) / (2.0 - nu)
        t = math.sqrt(sum(v * v for v in tau))

        def exact(row):
            d = [float(row[k]) - centre[i] for i, k in enumerate("xyz")]
            dn = sum(d[i] * n[i] for i in range(3))
            r = [d[i] - dn * n[i] for i in range(3)]
            rn = math.sqrt(sum(v * v for v in r))
            ea = [v / rn for v in r]
            ec = [ea[1] * n[2] - ea[2] * n[1], ea[2] * n[0] - ea[0] * n[2], ea[0] * n[1] - ea[1] * n[0]]
            return [k1, 4.0 * g * sum(tau[i] * ea[i] for i in range(3)),
                    4.0 * (1.0 - nu) * g * sum(tau[i] * ec[i] for i in range(3))]

        # K_I's reference: its amplitude, or with shut faces (K_I = 0) K_II's.
        return exact, [4.0 * g * t if closed else abs(k1), 4.0 * g * t, 4.0 * (1.0 - nu) * g * t]
    w = j["williams"]
    k = [float(w.get("K1", 0.0)), float(w.get("K2", 0.0)), float(w.get("K3", 0.0))]
    kref = max(abs(v) for v in k)
    return (lambda row: k), [kref] * 3


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
        exact_of, kref = exact
        worst = [0.0, 0.0, 0.0]
        nonzero = [False, False, False]
        for r in rows:
            k = exact_of(r)
            for m, name in enumerate(("K_I", "K_II", "K_III")):
                worst[m] = max(worst[m], abs(float(r[name]) - k[m]) / kref[m])
                nonzero[m] |= k[m] != 0
        tol = [tolerance if nonzero[m] or others is None else others for m in range(3)]
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
