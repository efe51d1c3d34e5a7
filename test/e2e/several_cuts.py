#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Helpers of test/e2e/several_cuts.sh (python3 standard library only).

  problem MESH.vtu --plane PX PY PZ NX NY NZ [--plane ...] -o problem.json
      the discontinuous patch test for planar cuts through the whole body: the pieces are the
      regions of the sign vector (sign((x - p_k) . n_k))_k; region i (in the order of sorted
      sign vectors) moves by its own small rigid motion; every node on the mesh's bounding-box
      faces gets that motion's value (one Dirichlet condition per node, a box around it).
  check --deformed deformed.vtu --plane ... [--plane ...] [--regions R]
      every cell of deformed.vtu (xfem-visualize) lies in one region (its centroid's), every one
      of its points moves by that region's rigid motion (1e-10 of max|u|), its strain is zero
      (1e-10 of the motions' gradients); the cells' volume per region equals the region's true
      volume in the box (1e-12 relative; the box is the mesh's bounding box); R regions expected.
  linear --deformed deformed.vtu
      uniaxial tension along x (cut_catalogue.py problem --linear), exact for cuts normal to z
      ending inside the body: every point's displacement (1e-10) and every cell's strain (1e-9).
  wedge --deformed deformed.vtu --plane ... --plane ... --inside X Y Z
      the wedge (cells whose centroid lies in the region of the point X Y Z, given by the two
      planes) has zero displacement and zero strain (it is fixed and cut free), while the rest moves.
Prints one line per failed check and exits 1 if any.
"""
import argparse
import itertools
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_catalogue import read_vtk_xml, add, sub, mul, dot, cross, norm, tet_volume, LINEAR, linear  # noqa: E402


def region_of(planes, x):
    return tuple(1 if dot(sub(x, p), n) > 0 else -1 for p, n in planes)


def motion(i, centre):
    return {"translation": (0.01 * (i + 1), -0.007 * i + 0.003, 0.005 * (i % 2) - 0.002),
            "rotation": (1e-3 * (i + 1), -2e-3 * i + 5e-4, 7e-4 * (i % 3)), "centre": centre}


def rigid(m, x):
    return add(m["translation"], cross(m["rotation"], sub(x, m["centre"])))


def planes_of(args):
    return [(tuple(p[:3]), tuple(p[3:])) for p in args.plane]


def box_of(points):
    return tuple(min(p[i] for p in points) for i in range(3)), tuple(max(p[i] for p in points) for i in range(3))


def motions(planes, lo, hi):
    centre = mul(0.5, add(lo, hi))
    regions = sorted(itertools.product((-1, 1), repeat=len(planes)))
    return {r: motion(i, centre) for i, r in enumerate(regions)}


def cmd_problem(args):
    m = read_vtk_xml(args.mesh)
    pts = m["points"]
    lo, hi = box_of(pts)
    planes = planes_of(args)
    mo = motions(planes, lo, hi)
    eps = 1e-9 * norm(sub(hi, lo))
    conditions = []
    for k, x in enumerate(pts):
        if not any(abs(x[i] - lo[i]) <= eps or abs(x[i] - hi[i]) <= eps for i in range(3)):
            continue
        u = rigid(mo[region_of(planes, x)], x)
        conditions.append({"name": f"node {k}", "selector": {"box": {"lo": [c - eps for c in x], "hi": [c + eps for c in x]}},
                           "value": list(u)})
    json.dump({"description": "discontinuous patch test: each piece between the cuts moved by its own rigid motion",
               "material": {"E": 1.0, "nu": 0.3}, "dirichlet": conditions}, open(args.output, "w"), indent=1)


def strain_norm(s):
    return math.sqrt(sum(v * v for v in s[:3]) + 2 * sum(v * v for v in s[3:]))


def cmd_check(args):
    d = read_vtk_xml(args.deformed)
    pts, cells = d["points"], d["cells"]
    disp, strain = d["point"]["displacement"], d["cell"]["strain"]
    planes = planes_of(args)
    lo, hi = box_of(pts)
    mo = motions(planes, lo, hi)
    umax = max(norm(rigid(m, x)) for m in mo.values() for x in itertools.product(*zip(lo, hi)))
    # The motions' gradient scale, as cut_catalogue.py: rotations plus the jumps per body size.
    size = norm(sub(hi, lo)) / math.sqrt(3)
    grad = max(norm(m["rotation"]) for m in mo.values()) + \
        max(norm(sub(m["translation"], n["translation"])) for m in mo.values() for n in mo.values()) / size
    failures = []
    vol = {}
    worst_u, worst_e = (0, None), (0, None)
    for c, cell in enumerate(cells):
        p = [pts[i] for i in cell]
        centroid = mul(0.25, add(add(p[0], p[1]), add(p[2], p[3])))
        r = region_of(planes, centroid)
        vol[r] = vol.get(r, 0.0) + abs(tet_volume(p))
        for i in cell:
            e = norm(sub(disp[i], rigid(mo[r], pts[i])))
            if e > worst_u[0]:
                worst_u = (e, (c, i, r))
        e = strain_norm(strain[c])
        if e > worst_e[0]:
            worst_e = (e, (c, r))
    if worst_u[0] > 1e-10 * umax:
        c, i, r = worst_u[1]
        failures.append(f"displacement error {worst_u[0]:.3g} m at point {i} of cell {c} (region {r}) > 1e-10 x {umax:.3g}")
    if worst_e[0] > 1e-10 * grad:
        failures.append(f"strain {worst_e[0]:.3g} in cell {worst_e[1][0]} (region {worst_e[1][1]}) > 1e-10 x {grad:.3g}")
    # True volume of each region in the box: Monte-Carlo-free for axis-aligned boxes is hard in
    # general; for planes the region volumes follow by clipping the box (a convex polyhedron).
    for r, v in sorted(vol.items()):
        true = clipped_volume(lo, hi, planes, r)
        if abs(v - true) > 1e-12 * abs(true):
            failures.append(f"region {r}: deformed.vtu volume {v:.17g}, true {true:.17g}")
    if args.regions and len(vol) != args.regions:
        failures.append(f"{len(vol)} regions in deformed.vtu, expected {args.regions}")
    for f in failures:
        print(f)
    print(f"max displacement error {worst_u[0]:.3g} m (max|u| {umax:.3g}), max strain {worst_e[0]:.3g}; "
          f"{len(vol)} regions", file=sys.stderr)
    return 1 if failures else 0


def clipped_volume(lo, hi, planes, region):
    """Volume of the box cut by the half-spaces s_k (x - p_k) . n_k >= 0: the box split into 6
    tets (Kuhn), each clipped by every half-space (convex polyhedra as tet lists)."""
    corner = lambda i, j, k: (lo[0] if i == 0 else hi[0], lo[1] if j == 0 else hi[1], lo[2] if k == 0 else hi[2])
    tets = []
    for perm in itertools.permutations(range(3)):
        path = [(0, 0, 0)]
        v = [0, 0, 0]
        for a in perm:
            v[a] = 1
            path.append(tuple(v))
        tets.append([corner(*q) for q in path])
    for (p, n), s in zip(planes, region):
        nn = mul(s, n)
        out = []
        for t in tets:
            out += clip_tet(t, p, nn)
        tets = out
    return sum(abs(tet_volume(t)) for t in tets)


def clip_tet(t, p, n):
    """Parts of tet t with (x - p) . n >= 0, as tets."""
    d = [dot(sub(x, p), n) for x in t]
    inside = [i for i in range(4) if d[i] >= 0]
    if len(inside) == 4:
        return [t]
    if not inside:
        return []
    cut = lambda i, j: add(t[i], mul(d[i] / (d[i] - d[j]), sub(t[j], t[i])))
    outside = [i for i in range(4) if d[i] < 0]
    if len(inside) == 1:
        a = inside[0]
        return [[t[a]] + [cut(a, b) for b in outside]]
    if len(inside) == 3:
        o = outside[0]
        a, b, c = inside
        pa, pb, pc = cut(o, a), cut(o, b), cut(o, c)
        return [[t[a], t[b], t[c], pa], [t[b], t[c], pa, pb], [t[c], pa, pb, pc]]
    a, b = inside
    o1, o2 = outside
    p1, p2, p3, p4 = cut(a, o1), cut(a, o2), cut(b, o1), cut(b, o2)
    return [[t[a], t[b], p1, p2], [t[b], p1, p2, p3], [t[b], p2, p3, p4]]


def cmd_linear(args):
    """Uniaxial tension along x (cut_catalogue.py's LINEAR), exact for cuts normal to z that end
    inside the body: every point of deformed.vtu and the strain of every cell."""
    d = read_vtk_xml(args.deformed)
    pts, disp, strain = d["points"], d["point"]["displacement"], d["cell"]["strain"]
    G = LINEAR["gradient"]
    eps = [G[0][0], G[1][1], G[2][2], (G[0][1] + G[1][0]) / 2, (G[1][2] + G[2][1]) / 2, (G[0][2] + G[2][0]) / 2]
    umax = max(norm(linear(LINEAR, x)) for x in pts)
    grad = math.sqrt(sum(v * v for row in G for v in row))
    eu = max(norm(sub(u, linear(LINEAR, x))) for u, x in zip(disp, pts))
    es = max(strain_norm([a - b for a, b in zip(e, eps)]) for e in strain)
    failures = []
    if eu > 1e-10 * umax:
        failures.append(f"displacement error {eu:.3g} m > 1e-10 x {umax:.3g}")
    # Strain to 1e-9: two fronts' branch functions (gradients ~ r^-1/2 at the sampled cells) amplify
    # the solve's round-off; measured 0.8e-10 to 1.0e-10 of the gradient, depending on the last bits
    # of the crack-tip coordinates.
    if es > 1e-9 * grad:
        failures.append(f"strain error {es:.3g} > 1e-9 x {grad:.3g}")
    for f in failures:
        print(f)
    print(f"max displacement error {eu:.3g} m (max|u| {umax:.3g}), max strain error {es:.3g}", file=sys.stderr)
    return 1 if failures else 0


def cmd_wedge(args):
    d = read_vtk_xml(args.deformed)
    pts, cells = d["points"], d["cells"]
    disp, strain = d["point"]["displacement"], d["cell"]["strain"]
    planes = planes_of(args)
    wedge = region_of(planes, tuple(args.inside))
    umax = max(norm(u) for u in disp)
    emax = max(strain_norm(s) for s in strain)
    worst_u, worst_e, cells_in, vol_in = 0.0, 0.0, 0, 0.0
    for c, cell in enumerate(cells):
        p = [pts[i] for i in cell]
        centroid = mul(0.25, add(add(p[0], p[1]), add(p[2], p[3])))
        if region_of(planes, centroid) != wedge:
            continue
        cells_in += 1
        vol_in += abs(tet_volume(p))
        worst_u = max([worst_u] + [norm(disp[i]) for i in cell])
        worst_e = max(worst_e, strain_norm(strain[c]))
    failures = []
    if cells_in == 0:
        failures.append("no cell of deformed.vtu lies in the wedge")
    if not umax > 0:
        failures.append("nothing moves")
    if worst_u > 1e-10 * umax:
        failures.append(f"the fixed wedge moves by {worst_u:.3g} m (> 1e-10 x max|u| {umax:.3g})")
    if worst_e > 1e-10 * emax:
        failures.append(f"strain {worst_e:.3g} in the wedge (> 1e-10 x max strain {emax:.3g})")
    for f in failures:
        print(f)
    print(f"wedge: {cells_in} cells, volume {vol_in:.6g} m^3, max |u| {worst_u:.3g} m, max strain {worst_e:.3g}; "
          f"body max |u| {umax:.3g} m, max strain {emax:.3g}", file=sys.stderr)
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sp = ap.add_subparsers(dest="cmd", required=True)
    p = sp.add_parser("problem")
    p.add_argument("mesh")
    p.add_argument("--plane", type=float, nargs=6, action="append", required=True)
    p.add_argument("-o", "--output", required=True)
    p = sp.add_parser("check")
    p.add_argument("--deformed", required=True)
    p.add_argument("--plane", type=float, nargs=6, action="append", required=True)
    p.add_argument("--regions", type=int, default=0)
    p = sp.add_parser("linear")
    p.add_argument("--deformed", required=True)
    p = sp.add_parser("wedge")
    p.add_argument("--deformed", required=True)
    p.add_argument("--plane", type=float, nargs=6, action="append", required=True)
    p.add_argument("--inside", type=float, nargs=3, required=True)
    args = ap.parse_args()
    return {"problem": cmd_problem, "check": cmd_check, "linear": cmd_linear, "wedge": cmd_wedge}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
