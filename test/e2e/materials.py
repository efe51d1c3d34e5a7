#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Helpers of test/e2e/materials.sh (python3 standard library only).

  regions IN.vtu OUT.vtu --split C --ids A B [--names NA NB] [--exact FIELD.json]
      OUT.vtu (ASCII VTK XML): IN's points and tets, the cell array `region` (A where a tet's
      centroid has x < C, else B; C should be a plane of nodes), the names in the field arrays
      region_ids / region_names, and with --exact the point array exact_u: the field's
      displacement at each node.
  msh IN.vtu OUT.msh --split C --ids A B --names NA NB
      the same regions as a gmsh MSH 2.2 file: each tet in the Physical Volume A or B (named).
  check-bar ENRICHED.vtu U.mtx --length L --split C --E E1 E2 --traction T
      a bar [0, L] along x, fixed at x = 0 (u = 0), pulled by T at x = L, nu = 0: every node's
      u_x is T x / E1 (x <= C), T (C / E1 + (x - C) / E2) beyond, u_y = u_z = 0; the end's u_x
      is the two springs in series T (C / E1 + (L - C) / E2). Relative 1e-10.
  check-patch DEFORMED.vtu ENRICHED.vtu --exact FIELD.json
      deformed.vtu of the two-material patch test: every point's displacement the field's, every
      cell's stress sigma e_x e_x (both regions), its strain its region's (by its parent tet's
      region in ENRICHED.vtu, whose tets are the input's). Relative 1e-10. deformed.vtu's cell
      array `region` is each cell's parent's.
  same-values A.mtx B.mtx
      the same numbers (the fingerprint comments aside, which name the problem file).
  close-values A.mtx B.mtx
      the same numbers to 1e-10 of B's largest.
  same-vtu A.vtu B.vtu
      the same points, cells and arrays bit for bit, inputs_fingerprint aside (it hashes problem.json).

FIELD.json: {"sigma": S, "split": C, "E": [E1, E2], "ratio": R, "translation": [tx, ty, tz]}: uniaxial
stress S along x (the interface's normal) with nu / E = R in both regions, so that the lateral
strain -R S is the same on both sides and the field is continuous: u_x = S x / E1 for x <= C,
S (C / E1 + (x - C) / E2) beyond; u_y = -R S y, u_z = -R S z; plus the translation.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_catalogue import read_vtk_xml  # noqa: E402


def field_u(f, x):
    s, c, (e1, e2), r = f["sigma"], f["split"], f["E"], f["ratio"]
    ux = s * x[0] / e1 if x[0] <= c else s * (c / e1 + (x[0] - c) / e2)
    t = f["translation"]
    return (ux + t[0], -r * s * x[1] + t[1], -r * s * x[2] + t[2])


def field_strain(f, region_index):  # xx yy zz xy yz xz
    s, r = f["sigma"], f["ratio"]
    return [s / f["E"][region_index], -r * s, -r * s, 0.0, 0.0, 0.0]


def vtk_string(s):
    """A string of a VTK XML ASCII String array: its bytes as numbers, then 0."""
    return " ".join(str(b) for b in s.encode()) + " 0"


def cmd_regions(a):
    m = read_vtk_xml(a.input)
    pts, cells = m["points"], m["cells"]
    region = []
    for c in cells:
        cx = sum(pts[i][0] for i in c) / 4
        region.append(a.ids[0] if cx < a.split else a.ids[1])
    exact = json.load(open(a.exact)) if a.exact else None
    with open(a.output, "w") as o:
        o.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
                '<UnstructuredGrid>\n')
        if a.names:
            o.write('<FieldData>\n<DataArray type="Int32" Name="region_ids" NumberOfTuples="2" format="ascii">'
                    f'{a.ids[0]} {a.ids[1]}</DataArray>\n'
                    '<Array type="String" Name="region_names" NumberOfTuples="2" format="ascii">'
                    f'{vtk_string(a.names[0])} {vtk_string(a.names[1])}</Array>\n</FieldData>\n')
        o.write(f'<Piece NumberOfPoints="{len(pts)}" NumberOfCells="{len(cells)}">\n')
        if exact:
            o.write('<PointData>\n<DataArray type="Float64" Name="exact_u" NumberOfComponents="3" format="ascii">\n')
            for p in pts:
                o.write(" ".join(repr(v) for v in field_u(exact, p)) + "\n")
            o.write('</DataArray>\n</PointData>\n')
        o.write('<CellData>\n<DataArray type="Int32" Name="region" format="ascii">\n')
        o.write(" ".join(str(r) for r in region) + "\n</DataArray>\n</CellData>\n")
        o.write('<Points>\n<DataArray type="Float64" NumberOfComponents="3" format="ascii">\n')
        for p in pts:
            o.write(" ".join(repr(v) for v in p) + "\n")
        o.write('</DataArray>\n</Points>\n<Cells>\n<DataArray type="Int64" Name="connectivity" format="ascii">\n')
        for c in cells:
            o.write(" ".join(str(i) for i in c) + "\n")
        o.write('</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">\n')
        o.write(" ".join(str(4 * (k + 1)) for k in range(len(cells))) + "\n</DataArray>\n")
        o.write('<DataArray type="UInt8" Name="types" format="ascii">\n' + " ".join("10" for _ in cells) +
                "\n</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")
    counts = {r: region.count(r) for r in a.ids}
    if min(counts.values()) == 0:
        raise SystemExit(f"materials.py regions: a region has no tet ({counts})")
    return 0


def cmd_msh(a):
    m = read_vtk_xml(a.input)
    pts, cells = m["points"], m["cells"]
    with open(a.output, "w") as o:
        o.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n")
        for i, n in zip(a.ids, a.names):
            o.write(f'3 {i} "{n}"\n')
        o.write(f"$EndPhysicalNames\n$Nodes\n{len(pts)}\n")
        for k, p in enumerate(pts):
            o.write(f"{k + 1} {p[0]!r} {p[1]!r} {p[2]!r}\n")
        o.write(f"$EndNodes\n$Elements\n{len(cells)}\n")
        for k, c in enumerate(cells):
            cx = sum(pts[i][0] for i in c) / 4
            r = a.ids[0] if cx < a.split else a.ids[1]
            o.write(f"{k + 1} 4 2 {r} {r} " + " ".join(str(i + 1) for i in c) + "\n")
        o.write("$EndElements\n")
    return 0


def read_mtx(path):
    values = []
    header = None
    for line in open(path):
        if line.startswith("%"):
            continue
        if header is None:
            header = line.split()
            continue
        values.append(float(line))
    return values


def cmd_check_bar(a):
    m = read_vtk_xml(a.enriched)
    u = read_mtx(a.solution)
    e1, e2 = a.E
    t, c, L = a.traction, a.split, a.length
    end = t * (c / e1 + (L - c) / e2)
    worst, where, ends = 0.0, None, 0
    np_ = len(m["points"])  # the original DOFs come first (3 per point)
    for k, x in enumerate(m["points"]):
        ux = t * x[0] / e1 if x[0] <= c else t * (c / e1 + (x[0] - c) / e2)
        err = max(abs(u[3 * k] - ux), abs(u[3 * k + 1]), abs(u[3 * k + 2]))
        if err > worst:
            worst, where = err, (k, x, u[3 * k:3 * k + 3], ux)
        if abs(x[0] - L) < 1e-12 * L:
            ends += 1
            if abs(u[3 * k] - end) > 1e-10 * end:
                print(f"end node {k}: u_x {u[3 * k]!r}, two springs in series {end!r}")
                return 1
    if ends == 0 or len(u) < 3 * np_:
        print(f"no node at x = {L} or too few values ({len(u)} for {np_} points)")
        return 1
    if worst > 1e-10 * end:
        print(f"node displacement error {worst:.3g} > 1e-10 x {end:.6g} at {where}")
        return 1
    print(f"bar: end displacement {end:.17g} m at {ends} nodes to 1e-10 relative (worst node error {worst:.2g} m)")
    return 0


def cmd_check_patch(a):
    f = json.load(open(a.exact))
    d = read_vtk_xml(a.deformed)
    r = read_vtk_xml(a.regions)
    region = [int(v) for v in r["cell"]["region"]]
    ids = sorted(set(region))
    s = f["sigma"]
    umax = max(math.sqrt(sum(v * v for v in field_u(f, x))) for x in d["points"])
    gmax = s / min(f["E"])
    failures = []
    disp = d["point"]["displacement"]
    worst = max(range(len(disp)), key=lambda k: max(abs(a_ - b) for a_, b in zip(disp[k], field_u(f, d["points"][k]))))
    err = max(abs(a_ - b) for a_, b in zip(disp[worst], field_u(f, d["points"][worst])))
    if not err <= 1e-10 * umax:
        failures.append(f"displacement error {err:.3g} at point {worst} {d['points'][worst]} > 1e-10 x {umax:.3g}")
    serr, eerr, seen = 0.0, 0.0, set()
    for k, (stress, strain, parent) in enumerate(zip(d["cell"]["stress"], d["cell"]["strain"], d["cell"]["parent"])):
        ri = ids.index(region[int(parent)])
        seen.add(ri)
        serr = max(serr, max(abs(v - w) for v, w in zip(stress, [s, 0, 0, 0, 0, 0])))
        eerr = max(eerr, max(abs(v - w) for v, w in zip(strain, field_strain(f, ri))))
    if not serr <= 1e-10 * s:
        failures.append(f"stress error {serr:.3g} > 1e-10 x {s}: every cell's stress is sigma e_x e_x")
    if not eerr <= 1e-10 * gmax:
        failures.append(f"strain error {eerr:.3g} > 1e-10 x {gmax:.3g}: each region has its own strain")
    if len(seen) != 2:
        failures.append(f"cells of {len(seen)} regions in deformed.vtu, expected 2")
    # deformed.vtu's own `region`: each cell its parent's.
    shown = d["cell"].get("region")
    if shown is None or any(int(r_) != region[int(p_)] for r_, p_ in zip(shown, d["cell"]["parent"])):
        failures.append("deformed.vtu's cell array 'region' is missing or not each cell's parent tet's region")
    for x in failures:
        print(x)
    return 1 if failures else 0


def cmd_same_values(a):
    x, y = read_mtx(a.a), read_mtx(a.b)
    if x != y:
        diff = [i for i, (p, q) in enumerate(zip(x, y)) if p != q]
        print(f"{a.a} and {a.b} differ: {len(x)} / {len(y)} values, first difference at {diff[:1]}")
        return 1
    return 0


def cmd_close_values(a):
    x, y = read_mtx(a.a), read_mtx(a.b)
    scale = max(abs(v) for v in y)
    err = max(abs(p - q) for p, q in zip(x, y)) if len(x) == len(y) else float("inf")
    print(f"max |{a.a} - {a.b}| = {err:.3g} (largest value {scale:.3g})")
    return 0 if err <= 1e-10 * scale else 1


def cmd_same_vtu(a):
    """The two files' points, cells and arrays equal bit for bit, the inputs_fingerprint aside (it
    hashes problem.json, which differs by design)."""
    x, y = read_vtk_xml(a.a), read_vtk_xml(a.b)
    for d in (x, y):
        d["field"].pop("inputs_fingerprint", None)
    for key in ("points", "cells", "point", "cell", "field"):
        if x[key] != y[key]:
            print(f"{a.a} and {a.b} differ in their {key}")
            return 1
    return 0


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("regions")
    r.add_argument("input")
    r.add_argument("output")
    r.add_argument("--split", type=float, required=True)
    r.add_argument("--ids", type=int, nargs=2, required=True)
    r.add_argument("--names", nargs=2)
    r.add_argument("--exact")
    g = sub.add_parser("msh")
    g.add_argument("input")
    g.add_argument("output")
    g.add_argument("--split", type=float, required=True)
    g.add_argument("--ids", type=int, nargs=2, required=True)
    g.add_argument("--names", nargs=2, required=True)
    b = sub.add_parser("check-bar")
    b.add_argument("enriched")
    b.add_argument("solution")
    b.add_argument("--length", type=float, required=True)
    b.add_argument("--split", type=float, required=True)
    b.add_argument("--E", type=float, nargs=2, required=True)
    b.add_argument("--traction", type=float, required=True)
    c = sub.add_parser("check-patch")
    c.add_argument("deformed")
    c.add_argument("regions")
    c.add_argument("--exact", required=True)
    s = sub.add_parser("same-values")
    s.add_argument("a")
    s.add_argument("b")
    v = sub.add_parser("close-values")
    v.add_argument("a")
    v.add_argument("b")
    w = sub.add_parser("same-vtu")
    w.add_argument("a")
    w.add_argument("b")
    a = p.parse_args()
    return {"regions": cmd_regions, "msh": cmd_msh, "check-bar": cmd_check_bar, "check-patch": cmd_check_patch,
            "same-values": cmd_same_values, "close-values": cmd_close_values,
            "same-vtu": cmd_same_vtu}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())
