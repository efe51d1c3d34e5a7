#!/usr/bin/env bash
# Issue 33 under large deformation: the pressure on a cut's faces as a follower load in xfem-newton
# (docs/METHOD.md "Contact and pressure on the cut's faces at large deformation"). The cube
# [0,0.04]^3 (unstructured, size 0.005; neo-Hookean, E = 300 kPa, nu = 0.35) cut through by the
# plane z = 0.02, the faces z = 0 and z = 0.04 clamped, a pressure p on the cut's faces:
#  - small loads: for p = 100 and 50 Pa xfem-newton's u differs from the linear path's
#    (xfem-assemble + xfem-solve, the linear law) by O(p^2): d(p)/d(p/2) in [1.7, 2.3]
#    (newton_small_loads.py ratio);
#  - p = 30 kPa (0.1 E, 3 load steps: the faces move apart by ~2 mm): the reaction on the clamped top
#    face balances the pressure on the deformed upper face, p times its vector area, computed
#    independently from the deformed positions of the face's boundary (xfem-probe on the upper side
#    at 800 points of the cube's perimeter at z = 0.02, A = 1/2 sum x_i x x_i+1), to 1e-3 (the
#    boundary's sampling; measured 1.3e-8); the report's force on the faces above (the quadrature
#    of p cof(F+) n) equals it too; with PETSc (--np 2, when built) u is CHOLMOD's to 1e-6. Newton's
#    residual histories are printed.
# Then a bad input: a load on a cut the mesh does not have.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1
B="$XFEM_BIN"
S="$XFEM_SOURCE"
"$B/xfem-mesh" -q unstructured-box --hi 0.04 0.04 0.04 --size 0.005 -o cube.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.02 --edge1 0.06 0 0 --edge2 0 0.06 0 -o through.vtp || fail "cut"
"$B/xfem-classify" -q cube.vtu --cut through.vtp -o through-classified.vtu 2>/dev/null || fail "classify through"
"$B/xfem-enrich" -q through-classified.vtu -o through.vtu || fail "enrich through"

newton() {  # $1: name, $2: mesh, $3: problem, the rest: options
  local name=$1 mesh=$2 problem=$3; shift 3
  "$B/xfem-newton" -v "$mesh" --cut through.vtp --problem "$problem" -o $name.mtx --report $name-report.json "$@" 2> $name.log ||
    { cat $name.log; fail "xfem-newton $name"; }
  grep -E "iteration" $name.log | sed "s/^/  $name: /"
}

# The faces z = 0 and z = 0.04 clamped, a pressure on the cut's faces.
clamped='"dirichlet": [{"name": "base", "selector": {"box": {"lo": [-1,-1,-1], "hi": [1,1,1e-9]}}, "value": [0,0,0]},
  {"name": "top", "selector": {"box": {"lo": [-1,-1,0.039999999], "hi": [1,1,1]}}, "value": [0,0,0]}]'
pressure() {  # $1: out, $2: p, $3: model, $4: load steps
  printf '{"material": {"E": 300e3, "nu": 0.35, "model": "%s"}, "load_steps": %s, "cut_loads": [{"cut": 0, "pressure": %s}], %s}\n' \
    "$3" "$4" "$2" "$clamped" > $1
}
for p in 100 50; do
  pressure linear-$p.json $p linear 1
  "$B/xfem-assemble" -q through.vtu --cut through.vtp --problem linear-$p.json -o system-$p || fail "assemble $p"
  "$B/xfem-solve" -q system-$p -o linear-$p.mtx || fail "solve $p"
  pressure follower-$p.json $p neo-hookean 1
  newton follower-$p through.vtu follower-$p.json
done
python3 "$S/test/e2e/newton_small_loads.py" ratio "follower pressure" linear-100.mtx follower-100.mtx linear-50.mtx \
  follower-50.mtx || fail "small loads"
pressure follower-large.json 30e3 neo-hookean 3
newton follower-large through.vtu follower-large.json
# The upper face's boundary: the cube's perimeter at z = 0.02, counter-clockwise about +z, side +1.
python3 - <<'PY' > perimeter.csv
n = 200
print("x,y,z,side")
corners = [(0, 0), (0.04, 0), (0.04, 0.04), (0, 0.04)]
for k in range(4):
    (x0, y0), (x1, y1) = corners[k], corners[(k + 1) % 4]
    for i in range(n):
        t = i / n
        print("%.17g,%.17g,0.02,1" % (x0 + t * (x1 - x0), y0 + t * (y1 - y0)))
PY
"$B/xfem-probe" -q through.vtu --cut through.vtp --solution follower-large.mtx --points perimeter.csv -o perimeter-u.csv ||
  fail "probe"

python3 - <<'PY' || fail "follower checks"
import csv, json
p = 30e3
rows = list(csv.DictReader(open('perimeter-u.csv')))
x = [[float(r[a]) + float(r['u' + a]) for a in 'xyz'] for r in rows]
area = [0.0, 0.0, 0.0]
for i in range(len(x)):
    a, b = x[i], x[(i + 1) % len(x)]
    c = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    for k in range(3):
        area[k] += c[k] / 2
r = json.load(open('follower-large-report.json'))
top = [c for c in r['reactions']['conditions'] if c['name'] == 'top'][0]['force']
above = r['cut_pressure']['force_on_faces_above']
expected = [p * a for a in area]
err_r = max(abs(top[k] + expected[k]) for k in range(3)) / abs(expected[2])
err_q = max(abs(above[k] - expected[k]) for k in range(3)) / abs(expected[2])
print("follower p = 30 kPa: deformed upper face's vector area from its boundary %s m^2 (reference 0.0016); "
      "p A = %s N; reaction on the top %s N (off by %.3g of p A_z); the report's force on the faces above %s N "
      "(off by %.3g)" % (['%.6g' % a for a in area], ['%.6g' % e for e in expected], ['%.6g' % t for t in top], err_r,
                         ['%.6g' % a for a in above], err_q))
for s in r['steps']:
    print("  load %.3g: residuals %s" % (s['load'], ' '.join('%.2g' % v for v in s['relative_residuals'])))
assert abs(area[2] / 0.0016 - 1) > 1e-3, "the face did not deform"
assert err_r < 1e-3 and err_q < 1e-3, "force on the deformed face"
PY

# The PETSc backend (CG + GAMG on 2 processes) takes the same follower tangent (the body's pattern).
if [ -x "$B/xfem-newton-petsc" ]; then
  "$B/xfem-newton" -q through.vtu --cut through.vtp --problem follower-large.json -o petsc.mtx --backend petsc --np 2 ||
    fail "PETSc"
  python3 - <<'PY' || fail "PETSc differs from CHOLMOD"
def read(p): return [float(l.split()[-1]) for l in open(p) if not l.startswith('%')][1:]
a, b = read('petsc.mtx'), read('follower-large.mtx')
d = max(abs(x - y) for x, y in zip(a, b)) / max(abs(y) for y in b)
print("follower p = 30 kPa, PETSc on 2 processes against CHOLMOD: max difference %.3g of max |u|" % d)
assert len(a) == len(b) and d <= 1e-6
PY
else
  echo "PETSc: not built, skipped"
fi

# Bad input: one line on stderr, no output.
sed 's/"cut": 0/"cut": 1/' follower-large.json > bad-cut.json
rm -f bad.mtx
"$B/xfem-newton" -q through.vtu --cut through.vtp --problem bad-cut.json -o bad.mtx 2> err && fail "a load on a missing cut accepted"
[ "$(wc -l < err)" -eq 1 ] && grep -qE "^xfem-newton: error: bad-cut.json: cut_loads\[0\]\.cut is 1, but the mesh has 1 cut" err ||
  fail "message: $(cat err)"
[ ! -e bad.mtx ] || fail "output left behind"
echo "PASS"
cd / && rm -rf "$XFEM_SCRATCH"
