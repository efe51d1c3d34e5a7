#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Helpers of test/e2e/newton_small_loads.sh (python3 standard library only).

  scale SOURCE.json S MODEL OUT.json
      SOURCE's problem with every prescribed value (Dirichlet values, null components kept; Neumann
      tractions; the body force) times S and material.model MODEL. A condition the scale cannot
      apply to (rotation, value_array, exact) is refused.
  ratio NAME LINEAR_S NONLINEAR_S LINEAR_HALF NONLINEAR_HALF
      d(s) = max |u_nl - u_lin| / max |u_lin| at the scales s and s/2 (u.mtx files): prints both and
      d(s) / d(s/2), which must lie in [1.7, 2.3] (the nonlinear solution differs from the linear
      one by O(s^2) in u, O(s) relative). Also checks the linear path is linear: u_lin(s/2) =
      u_lin(s) / 2 to 1e-9 of max |u_lin(s)|.
Each check exits 1 with a message when it fails.
"""
import json
import sys

RATIO_RANGE = (1.7, 2.3)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def scaled(values, s):
    return [None if v is None else v * s for v in values]


def scale(source, s, model, out):
    with open(source) as f:
        problem = json.load(f)
    s = float(s)
    for i, d in enumerate(problem.get("dirichlet", [])):
        for key in ("rotation", "value_array", "exact"):
            if key in d:
                fail("%s: dirichlet[%d] has '%s', which this test does not scale" % (source, i, key))
        if "value" in d:
            d["value"] = scaled(d["value"], s)
    for n in problem.get("neumann", []):
        n["traction"] = scaled(n["traction"], s)
    if "body_force" in problem:
        problem["body_force"] = scaled(problem["body_force"], s)
    problem["material"]["model"] = model
    with open(out, "w") as f:
        json.dump(problem, f, indent=1)


def read_array(path):
    """A Matrix Market `array` file: % comments, the size line, then one value per line."""
    values, size = [], None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("%"):
                continue
            if size is None:
                size = [int(t) for t in line.split()]
                continue
            values.append(float(line))
    if size is None or len(values) != size[0] * size[1]:
        fail("%s: expected %s values, read %d" % (path, size, len(values)))
    return values


def relative_difference(nonlinear, linear, what):
    if len(nonlinear) != len(linear):
        fail("%s: %d nonlinear and %d linear values" % (what, len(nonlinear), len(linear)))
    scale_ = max(abs(v) for v in linear)
    if scale_ == 0:
        fail("%s: the linear solution is zero" % what)
    return max(abs(a - b) for a, b in zip(nonlinear, linear)) / scale_


def ratio(name, lin_s, nl_s, lin_h, nl_h):
    lin_s, nl_s, lin_h, nl_h = (read_array(p) for p in (lin_s, nl_s, lin_h, nl_h))
    if len(lin_s) != len(lin_h):
        fail("%s: the linear solutions at s and s/2 differ in size" % name)
    big = max(abs(v) for v in lin_s)
    off = max(abs(a / 2 - b) for a, b in zip(lin_s, lin_h)) / big
    if off > 1e-9:
        fail("%s: the linear solution at s/2 is not half that at s (%.3g of max |u|)" % (name, off))
    d_s = relative_difference(nl_s, lin_s, name + " at s")
    d_h = relative_difference(nl_h, lin_h, name + " at s/2")
    if d_h == 0:
        fail("%s: the nonlinear solution at s/2 equals the linear one" % name)
    r = d_s / d_h
    print("%s: max |u_lin(s)| = %.4g m, d(s) = %.4g, d(s/2) = %.4g, d(s)/d(s/2) = %.3f" % (name, big, d_s, d_h, r))
    if not RATIO_RANGE[0] <= r <= RATIO_RANGE[1]:
        fail("%s: d(s)/d(s/2) = %.3f outside [%.1f, %.1f]" % (name, r, RATIO_RANGE[0], RATIO_RANGE[1]))


if __name__ == "__main__":
    commands = {"scale": (scale, 4), "ratio": (ratio, 5)}
    if len(sys.argv) < 2 or sys.argv[1] not in commands or len(sys.argv) != 2 + commands[sys.argv[1]][1]:
        fail("usage: newton_small_loads.py scale SOURCE S MODEL OUT | ratio NAME LIN_S NL_S LIN_HALF NL_HALF")
    commands[sys.argv[1]][0](*sys.argv[2:])
