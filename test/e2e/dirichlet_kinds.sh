#!/usr/bin/env bash
# The node-dependent Dirichlet conditions of problem.json through the linear chain (xfem-classify
# without a cut, xfem-enrich, xfem-assemble, xfem-solve), each on the whole boundary of an uncut
# box without loads, whose solution is then exactly the prescribed field interpolated (an affine
# field is in the linear elements' space):
#   rotation:    a finite rotation of 0.001 rad about an oblique axis plus a translation, given by
#                one condition per face (edges and corners get the same values from two or three
#                faces), a rigid motion: u = R (X - c) + c + t - X at EVERY node to 1e-9 relative;
#   value_array: a 3-component point array holding a linear field A X + b on the boundary (0
#                inside) of a mesh written here as legacy VTK: the interior nodes get A X + b.
# And the bad value_array paths through xfem-assemble: missing array, wrong component count, each a
# one-line error naming the file, condition, array. (A non-finite value cannot get this far: the
# tools refuse to write one into enriched.vtu; dirichlet_data's own check is unit-tested.)
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN
fail() { echo "FAIL: $*"; exit 1; }
chain() {  # chain <mesh> <problem> <prefix>: the uncut chain to <prefix>u.mtx, system in Matrix Market text
  "$B/xfem-classify" -q "$1" -o "$3classified.vtu" || fail "classify $1"
  "$B/xfem-enrich" -q "$3classified.vtu" -o "$3enriched.vtu" || fail "enrich $1"
  "$B/xfem-assemble" -q "$3enriched.vtu" --problem "$2" --format mtx -o "$3system" || fail "assemble $2"
  "$B/xfem-solve" -q "$3system" -o "$3u.mtx" || fail "solve $2"
}

# compare(prefix, want, label): run PREFIX's u against want(X) at every node, to 1e-9 relative.
cat >compare.py <<'EOF'
def column(path):  # a Matrix Market array, 1 column
    rows = [l for l in open(path) if not l.startswith("%")]
    return [float(v) for v in rows[1:]]
def compare(prefix, want, label):
    u, X = column(prefix + "u.mtx"), column(prefix + "system/coordinates.mtx")
    n = len(X) // 3
    assert len(u) == 3 * n, (n, len(u))
    worst, largest = 0.0, 0.0
    for k in range(n):
        w = want(X[3 * k:3 * k + 3])
        largest = max(largest, max(abs(v) for v in w))
        worst = max(worst, max(abs(u[3 * k + i] - w[i]) for i in range(3)))
    print("%s: max |u - exact| = %.3g over %d nodes, max |exact| = %.3g" % (label, worst, n, largest))
    assert largest > 1e-4 and worst <= 1e-9 * largest
    return [X[3 * k:3 * k + 3] for k in range(n)]
EOF

# --- rotation --------------------------------------------------------------------------------
"$B/xfem-mesh" -q box --cells 3 4 5 --hi 0.02 0.03 0.04 -o box.vtu || fail "xfem-mesh box"
python3 - <<'EOF' || fail "writing rotation.json"
import json, math
lo, hi = [0, 0, 0], [0.02, 0.03, 0.04]
rotation = {"axis": [1, 2, 2], "angle_deg": 0.001 * 180 / math.pi, "center": [0.01, 0.015, 0.02],
            "translation": [1e-4, 0, -2e-4]}
faces = []
for axis in range(3):
    for end in (lo, hi):
        a, b = list(lo), list(hi)
        a[axis] = b[axis] = end[axis]
        faces.append({"name": "face %s=%g" % ("xyz"[axis], end[axis]), "selector": {"box": {"lo": a, "hi": b}},
                      "rotation": rotation})
json.dump({"material": {"E": 1e3, "nu": 0.3}, "dirichlet": faces}, open("rotation.json", "w"), indent=1)
EOF
chain box.vtu rotation.json rot-
python3 - <<'EOF' || fail "rotation: u is not the rigid motion at every node"
import math
from compare import compare
axis = [1 / 3, 2 / 3, 2 / 3]; angle = 0.001; c = [0.01, 0.015, 0.02]; t = [1e-4, 0, -2e-4]
def rotate(v):  # Rodrigues: v cos + (k x v) sin + k (k . v)(1 - cos)
    kxv = [axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2], axis[0] * v[1] - axis[1] * v[0]]
    kv = sum(a * b for a, b in zip(axis, v))
    return [v[i] * math.cos(angle) + kxv[i] * math.sin(angle) + axis[i] * kv * (1 - math.cos(angle)) for i in range(3)]
def rigid(x):  # R (X - c) + c + t - X
    arm = [x[i] - c[i] for i in range(3)]
    return [r - a + ti for r, a, ti in zip(rotate(arm), arm, t)]
assert len(compare("rot-", rigid, "rotation (R (X - c) + c + t - X)")) == 4 * 5 * 6
EOF

# --- value_array -----------------------------------------------------------------------------
# A 4 x 4 x 4 box of unit-size-0.01 cubes, 6 tets each (oriented positively here), as legacy VTK
# with point arrays 'boundary' (selector) and 'measured' (A X + b on the boundary, 0 inside).
python3 - <<'EOF' || fail "writing the value_array mesh"
import itertools, json
n, h = 4, 0.01
A = [[0.01, -0.02, 0.005], [0.003, 0.02, -0.01], [-0.004, 0.007, 0.015]]; b = [1e-4, -2e-4, 3e-4]
idx = lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)
pts = [(i * h, j * h, k * h) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
tets = []
for i, j, k in itertools.product(range(n), repeat=3):
    for perm in itertools.permutations(range(3)):  # Kuhn's split along the main diagonal
        c = [i, j, k]; v = [idx(*c)]
        for a in perm:
            c[a] += 1; v.append(idx(*c))
        p = [pts[q] for q in v]
        e = [[p[m][r] - p[0][r] for r in range(3)] for m in (1, 2, 3)]
        det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
               + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
        tets.append(v if det > 0 else [v[0], v[2], v[1], v[3]])
on_boundary = [any(abs(x) < 1e-12 or abs(x - n * h) < 1e-12 for x in p) for p in pts]
measured = [sum(A[r][m] * p[m] for m in range(3)) + b[r] if s else 0.0 for p, s in zip(pts, on_boundary) for r in range(3)]
lines = lambda values, fmt="%r": "".join(" ".join(fmt % v for v in values[r:r + 6]) + "\n" for r in range(0, len(values), 6))
with open("field.vtk", "w") as f:
    f.write("# vtk DataFile Version 3.0\nlinear field on the boundary\nASCII\nDATASET UNSTRUCTURED_GRID\n")
    f.write("POINTS %d double\n" % len(pts) + lines([x for p in pts for x in p]))
    f.write("CELLS %d %d\n" % (len(tets), 5 * len(tets)) + "".join("4 %d %d %d %d\n" % tuple(t) for t in tets))
    f.write("CELL_TYPES %d\n" % len(tets) + "10\n" * len(tets))
    f.write("POINT_DATA %d\nSCALARS boundary double 1\nLOOKUP_TABLE default\n" % len(pts) + lines(on_boundary, "%d"))
    f.write("VECTORS measured double\n" + lines(measured))
def problem(name, condition):
    condition = dict({"name": "registered surface", "selector": {"point_array": "boundary"}}, **condition)
    json.dump({"material": {"E": 1e3, "nu": 0.3}, "dirichlet": [condition]}, open(name, "w"))
problem("value_array.json", {"value_array": "measured"})
problem("missing.json", {"value_array": "measurd"})
problem("scalar.json", {"value_array": "boundary"})
EOF
chain field.vtk value_array.json va-
python3 - <<'EOF' || fail "value_array: the interior nodes are not at the linear field"
from compare import compare
A = [[0.01, -0.02, 0.005], [0.003, 0.02, -0.01], [-0.004, 0.007, 0.015]]; b = [1e-4, -2e-4, 3e-4]
X = compare("va-", lambda x: [sum(A[r][m] * x[m] for m in range(3)) + b[r] for r in range(3)], "value_array (A X + b)")
assert len(X) == 125 and sum(all(1e-12 < c < 0.04 - 1e-12 for c in x) for x in X) == 27  # 27 interior nodes, solved for
EOF

# Bad value_array conditions: one line naming the problem file, the condition and the array.
expect_error() {  # expect_error <problem> <text>
  "$B/xfem-assemble" -q va-enriched.vtu --problem "$1" -o bad 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "$1: expected exit 1, got $rc: $(cat err.txt)"
  grep -qF -- "$2" err.txt || fail "$1: expected '$2', got: $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$1: more than one line: $(cat err.txt)"
}
expect_error missing.json "missing.json: dirichlet[0] ('registered surface'): the mesh has no point array 'measurd' (value_array)"
expect_error scalar.json "scalar.json: dirichlet[0] ('registered surface'): point array 'boundary' (value_array) must have 3 components per point, it has 1"
echo "PASS"
