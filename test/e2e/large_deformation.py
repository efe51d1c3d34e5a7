#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Helpers of test/e2e/large_deformation.sh (python3 standard library only).

  problems
      writes the problem files of every case into the current folder (E = 1e3 Pa, nu = 0.3).
  rotation deformed.vtu MODEL
      a 90 degree rotation of the whole boundary: for corotational and neo-hookean every cell's von
      Mises stress below 1e-8 E; for linear every cell's sigma_xx, sigma_yy equal to the closed form
      2 (lambda + mu)(cos theta - 1) within 1e-6 relative.
  book deformed.vtu
      the open book: stress-free, and the jump u+ - u- at every cut point equal to the two rigid
      motions' difference (the faces move apart) within 1e-8 of the largest jump.
  uniaxial deformed.vtu report.txt SIDES
      the neo-Hookean bar stretched to 1.5: every point's displacement (0.5 x, (l - 1) y, (l - 1) z)
      with l from P22 = 0, and every cell's P11 = sigma_xx J / 1.5 and lateral stresses, to 1e-8;
      then `volume report.txt J-1 SIDES`.
  shear deformed.vtu
      simple shear u = (gamma y, 0, 0): every cell's sigma_xy = mu gamma, sigma_xx = mu gamma^2,
      the rest 0, and every point's displacement, to 1e-8.
  volume report.txt CHANGE [SIDES]
      xfem-visualize's volume line: the body's and every side's relative change CHANGE (to 1e-3
      relative, it is printed with 3 digits, or 1e-10 absolute for 0), SIDES the number of piece sides listed, 0
      inverted cells.
Each check prints its measured figures and exits 1 with a message when one fails.
"""
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_catalogue import read_vtk_xml  # noqa: E402

E, NU = 1e3, 0.3
LAMBDA, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
BOX = [0.1, 0.1, 0.2]          # the box of every case but the bar
CUT_Z = 0.09                   # the plane cut through the box, between grid planes 0.05 and 0.1
THETA = 90.0                   # the rigid rotation about the vertical line through AXIS_AT, degrees
# Not the box's centre: that line holds all 3 interior nodes of the uncut box, whose exact linear
# displacement is then 0, and xfem-solve's relative residual ||K u - f|| / ||f|| is 0/0 (f = 0 on the
# free DOFs): it refuses the exact answer as "numerically singular".
AXIS_AT = [0.03, 0.06, 0.1]
BOOK = 30.0                    # the open book: +BOOK above the cut, -BOOK below, about the x axis at y = 0, z = CUT_Z
BAR = [0.2, 0.1, 0.1]          # the bar stretched along x to STRETCH
STRETCH = 1.5
GAMMA = 0.5                    # simple shear


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def faces(lo, hi, zmin=None, zmax=None):
    """Box selectors of the box's six faces, optionally clipped to zmin <= z <= zmax (None: all)."""
    out = []
    for axis in range(3):
        for end in (lo, hi):
            a, b = list(lo), list(hi)
            a[axis] = b[axis] = end[axis]
            if zmin is not None:
                a[2], b[2] = max(a[2], zmin), min(b[2], zmax)
                if a[2] > b[2]:
                    continue
            out.append(("face %s=%g" % ("xyz"[axis], end[axis]), {"box": {"lo": a, "hi": b}}))
    return out


def rotation(axis, angle, centre):
    return {"axis": axis, "angle_deg": angle, "center": centre}


def write(name, model, dirichlet, steps=4, body_force=None):
    p = {"material": {"E": E, "nu": NU, "model": model}, "load_steps": steps, "dirichlet": dirichlet}
    if body_force:
        p["body_force"] = body_force
    json.dump(p, open(name, "w"), indent=1)


def cmd_problems():
    lo = [0, 0, 0]
    turn = rotation([0, 0, 1], THETA, AXIS_AT)
    whole = [{"name": n, "selector": s, "rotation": turn} for n, s in faces(lo, BOX)]
    for model in ("linear", "corotational", "neo-hookean"):
        write("rotation-%s.json" % model, model, whole, body_force=None)
    hinge = [0, 0, CUT_Z]
    book = [{"name": "above: " + n, "selector": s, "rotation": rotation([1, 0, 0], BOOK, hinge)}
            for n, s in faces(lo, BOX, 0.1, BOX[2])]
    book += [{"name": "below: " + n, "selector": s, "rotation": rotation([1, 0, 0], -BOOK, hinge)}
             for n, s in faces(lo, BOX, 0.0, 0.05)]
    write("book.json", "neo-hookean", book)
    L = BAR[0]
    bar = [{"name": "end x=0, x fixed", "selector": {"box": {"lo": [0, 0, 0], "hi": [0, BAR[1], BAR[2]]}},
            "value": [0, None, None]},
           {"name": "origin", "selector": {"box": {"lo": [0, 0, 0], "hi": [0, 0, 0]}}, "value": [0, 0, 0]},
           {"name": "no turn about x", "selector": {"box": {"lo": [0, BAR[1], 0], "hi": [0, BAR[1], 0]}},
            "value": [0, None, 0]},
           {"name": "end x=L pulled", "selector": {"box": {"lo": [L, 0, 0], "hi": [L, BAR[1], BAR[2]]}},
            "value": [(STRETCH - 1) * L, None, None]}]
    write("uniaxial.json", "neo-hookean", bar)
    # Simple shear on every boundary node: u_x = gamma y, by face and grid level y (0, 0.05, 0.1).
    shear = []
    for y in (0.0, 0.05, 0.1):
        for n, s in faces(lo, BOX):
            a, b = s["box"]["lo"], s["box"]["hi"]
            if a[1] == b[1]:
                continue  # the faces y = 0 and y = 0.1: below, whole
            shear.append({"name": "%s, y=%g" % (n, y), "selector": {"box": {"lo": [a[0], y, a[2]], "hi": [b[0], y, b[2]]}},
                          "value": [GAMMA * y, 0, 0]})
    for y in (0.0, BOX[1]):
        shear.append({"name": "face y=%g" % y, "selector": {"box": {"lo": [0, y, 0], "hi": [BOX[0], y, BOX[2]]}},
                      "value": [GAMMA * y, 0, 0]})
    write("shear.json", "neo-hookean", shear, steps=2)


def stress(s):  # VTK order xx, yy, zz, xy, yz, xz
    return [[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]]


def cmd_rotation(path, model):
    d = read_vtk_xml(path)
    vm = d["cell"]["von_mises"]
    if model != "linear":
        print("rotation by %g degrees, %s: max von Mises %.3g Pa = %.3g E over %d cells" % (THETA, model, max(vm), max(vm) / E, len(vm)))
        if not max(vm) < 1e-8 * E:
            fail("%s: a rigid rotation is not stress-free: max von Mises %.3g Pa >= 1e-8 E" % (model, max(vm)))
        return
    want = 2 * (LAMBDA + MU) * (math.cos(math.radians(THETA)) - 1)
    worst = max(abs(s[c] - want) for s in d["cell"]["stress"] for c in (0, 1))
    print("rotation by %g degrees, linear: sigma_xx = %.10g Pa, closed form 2 (lambda + mu)(cos theta - 1) = %.10g Pa,"
          " max difference over cells %.3g Pa" % (THETA, d["cell"]["stress"][0][0], want, worst))
    if not worst <= 1e-6 * abs(want):
        fail("linear: sigma_xx, sigma_yy differ from 2 (lambda + mu)(cos theta - 1) by %.3g Pa" % worst)


def rotate_x(angle, x, centre):
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    y, z = x[1] - centre[1], x[2] - centre[2]
    return [x[0], centre[1] + c * y - s * z, centre[2] + s * y + c * z]


def cmd_book(path):
    d = read_vtk_xml(path)
    vm = max(d["cell"]["von_mises"])
    copies = {}
    for k, (x, side) in enumerate(zip(d["points"], d["point"]["side"])):
        if side != 0:
            copies.setdefault(tuple(x), {})[side] = k
    u = d["point"]["displacement"]
    hinge = [0, 0, CUT_Z]
    worst, largest, pairs = 0.0, 0.0, 0
    for x, c in copies.items():
        if 1 not in c or -1 not in c:
            continue
        jump = [u[c[1]][i] - u[c[-1]][i] for i in range(3)]
        want = [a - b for a, b in zip(rotate_x(BOOK, x, hinge), rotate_x(-BOOK, x, hinge))]
        worst = max(worst, max(abs(a - b) for a, b in zip(jump, want)))
        largest = max(largest, max(abs(v) for v in want))
        pairs += 1
    print("open book (+-%g degrees): max von Mises %.3g Pa = %.3g E; %d cut points, jump u+ - u- against the closed form:"
          " max difference %.3g m, largest jump %.4g m (2 y sin %g at y = %g: %.4g m)"
          % (BOOK, vm, vm / E, pairs, worst, largest, BOOK, BOX[1], 2 * BOX[1] * math.sin(math.radians(BOOK))))
    if not vm < 1e-8 * E:
        fail("open book: not stress-free: max von Mises %.3g Pa" % vm)
    if pairs == 0 or not worst <= 1e-8 * largest or not largest > 0.09:
        fail("open book: the cut faces do not move apart as the two rotations say (max difference %.3g m)" % worst)


def cmd_uniaxial(path):
    d = read_vtk_xml(path)
    l = 1.0  # lateral stretch from P22 = mu (l - 1/l) + lambda ln(J) / l = 0, J = STRETCH l^2
    for _ in range(100):
        g = MU * (l * l - 1) + LAMBDA * math.log(STRETCH * l * l)
        l -= g / (2 * MU * l + 2 * LAMBDA / l)
    J = STRETCH * l * l
    P11 = MU * (STRETCH - 1 / STRETCH) + LAMBDA * math.log(J) / STRETCH
    u = d["point"]["displacement"]
    worst_u = max(abs(ui - wi) for x, ui3 in zip(d["points"], u)
                  for ui, wi in zip(ui3, [(STRETCH - 1) * x[0], (l - 1) * x[1], (l - 1) * x[2]]))
    measured = [1 + ui[1] / x[1] for x, ui in zip(d["points"], u) if x[1] > 0.09]
    p11 = [s[0] * J / STRETCH for s in d["cell"]["stress"]]
    worst_p = max(abs(p - P11) for p in p11)
    worst_lateral = max(max(abs(s[c]) for c in (1, 2, 3, 4, 5)) for s in d["cell"]["stress"])
    print("uniaxial stretch %g, neo-Hookean: lateral stretch %.12f (closed form %.12f, max difference over %d points %.3g),"
          " P11 %.10g Pa (closed form %.10g Pa, max difference over %d cells %.3g Pa), max |other stress| %.3g Pa,"
          " max |u - exact| %.3g m"
          % (STRETCH, measured[0], l, len(measured), max(abs(m - l) for m in measured), p11[0], P11, len(p11), worst_p,
             worst_lateral, worst_u))
    if not (max(abs(m - l) for m in measured) <= 1e-8 and worst_p <= 1e-8 * P11 and worst_lateral <= 1e-8 * P11
            and worst_u <= 1e-8 * (STRETCH - 1) * BAR[0]):
        fail("uniaxial: the homogeneous stretch differs from the closed form by more than 1e-8")
    return J


def cmd_shear(path):
    d = read_vtk_xml(path)
    s = d["cell"]["stress"]
    want = [MU * GAMMA * GAMMA, 0, 0, MU * GAMMA, 0, 0]
    worst = max(abs(a - b) for t in s for a, b in zip(t, want))
    worst_u = max(max(abs(ui[0] - GAMMA * x[1]), abs(ui[1]), abs(ui[2])) for x, ui in zip(d["points"], d["point"]["displacement"]))
    print("simple shear gamma = %g, neo-Hookean: sigma_xy = %.10g Pa (mu gamma = %.10g Pa), sigma_xx = %.10g Pa"
          " (mu gamma^2 = %.10g Pa); max difference over %d cells %.3g Pa, max |u - exact| %.3g m"
          % (GAMMA, s[0][3], MU * GAMMA, s[0][0], MU * GAMMA * GAMMA, len(s), worst, worst_u))
    if not (worst <= 1e-8 * MU * GAMMA and worst_u <= 1e-8 * GAMMA * BOX[1]):
        fail("simple shear: the stress differs from sigma_xy = mu gamma by more than 1e-8")


def cmd_volume(path, change, sides):
    line = [l for l in open(path) if "xfem-visualize: volume " in l]
    if len(line) != 1:
        fail("%s: no volume line" % path)
    m = re.findall(r"relative change ([-+0-9.e]+)\)", line[0])
    inverted = re.search(r"; (\d+) inverted cells", line[0])
    body = float(m[0])
    tolerance = max(1e-3 * abs(change), 1e-10)  # 3 printed digits; the rigid motions' Newton tolerance
    ok = abs(body - change) <= tolerance
    print("volume: relative change %s (expected %.4g), %d sides listed, %s inverted" % (m[0], change, len(m) - 1, inverted.group(1)))
    if not ok or len(m) - 1 != sides or inverted.group(1) != "0" or not all(abs(float(v) - change) <= tolerance for v in m):
        fail("volume line: " + line[0].strip())


def main():
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "problems":
        cmd_problems()
    elif cmd == "rotation":
        cmd_rotation(*args)
    elif cmd == "book":
        cmd_book(*args)
    elif cmd == "uniaxial":
        J = cmd_uniaxial(args[0])
        cmd_volume(args[1], J - 1, int(args[2]))
    elif cmd == "shear":
        cmd_shear(*args)
    elif cmd == "volume":
        cmd_volume(args[0], float(args[1]), int(args[2]))
    else:
        fail("unknown command " + cmd)


if __name__ == "__main__":
    main()
