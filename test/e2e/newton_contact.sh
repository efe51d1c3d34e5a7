#!/usr/bin/env bash
# Issue 33 under large deformation: contact between a cut's faces and the follower pressure on
# them in xfem-newton (docs/METHOD.md "Contact and pressure on the cut's faces at large
# deformation"). A cube [0,0.04]^3 (neo-Hookean, E = 300 kPa, nu = 0.35) cut through by the plane
# z = 0.02:
#  (a) pressed closed: every outer face held at the homogeneous field u = (F - I) X, F = diag(1.02,
#      1.02, 0.92) (8 % compression across the cut). The uncut body's solution is that field (linear
#      tets reproduce it), its first Piola stress P uniform and diagonal, so the traction on the cut's
#      reference plane is normal and compressive: with frictionless contact measured in the
#      reference configuration it is also the cut body's solution. Checked: every contact node in
#      contact, penetration <= tolerance (1e-8 max |u|), u equal to the uncut body's xfem-newton u to
#      1e-7 max |u| (the Uzawa loop stops once the gaps are below 1e-8 max |u|), every nodal
#      pressure within 1e-3 of -P_zz, the contact force = -P_zz A (A = 0.04^2, P_zz of the neo-Hookean law in
#      closed form) to 1e-6; the same field stretched (F = diag(0.98, 0.98, 1.08)) opens the cut:
#      contact on and off give the same u to 1e-12 max |u| and no node in contact.
#  (b) a rigid motion: every outer face turned by 60 degrees about the x axis (through the cube's
#      centre) in 3 load steps: the reference gap g = G u of a rigid motion is 0, so no contact node
#      may press (penetration <= tolerance) and u must be the rotation to 1e-7 of max |u|.
#  (c) the follower pressure p on the cut's faces, the faces z = 0 and z = 0.04 clamped: for small
#      p (1 and 0.5 Pa) xfem-newton's u differs from the linear path's (xfem-assemble + xfem-solve) by
#      O(p^2), d(p)/d(p/2) in [1.7, 2.3]; at p = 30 kPa (0.1 E: the faces move apart by ~2 mm) the
#      reaction on the clamped top face balances the pressure on the deformed upper face: p times its
#      vector area, computed independently from the deformed positions of the face's boundary
#      (xfem-probe on the upper side along the cube's perimeter at z = 0.02, 1/2 closed sum x × dx),
#      to 1e-3 (the boundary's sampling); the report's force on the faces above equals it too.
# Newton's residual histories are printed.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1
B="$XFEM_BIN"
S="$XFEM_SOURCE"
"$B/xfem-mesh" -q unstructured-box --hi 0.04 0.04 0.04 --size 0.005 -o cube.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --corner 0.0075 0.0075 0.02 --edge1 0.025 0 0 --edge2 0 0.025 0 -o crack.vtp || fail "crack"
"$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.02 --edge1 0.06 0 0 --edge2 0 0.06 0 -o through.vtp || fail "cut"
"$B/xfem-classify" -q cube.vtu --cut crack.vtp -o classified.vtu 2>/dev/null || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-classify" -q cube.vtu --cut through.vtp -o through-classified.vtu 2>/dev/null || fail "classify through"
"$B/xfem-enrich" -q through-classified.vtu -o through.vtu || fail "enrich through"
"$B/xfem-classify" -q cube.vtu -o plain.vtu || fail "classify uncut"
"$B/xfem-enrich" -q plain.vtu -o uncut.vtu || fail "enrich uncut"

# problem <out> <contact> <steps> <dirichlet value of every face...>
faces() {  # the six faces, each with the JSON value $1
  local first=1 value=$1
  for box in "[-1,-1,-1] [1e-9,1,1]" "[0.039999999,-1,-1] [1,1,1]" "[-1,-1,-1] [1,1e-9,1]" \
             "[-1,0.039999999,-1] [1,1,1]" "[-1,-1,-1] [1,1,1e-9]" "[-1,-1,0.039999999] [1,1,1]"; do
    set -- $box "$value"
    [ $first = 1 ] || printf ','
    first=0
    printf '{"selector": {"box": {"lo": %s, "hi": %s}}, %s}' "$1" "$2" "$3"
  done
}
material='"material": {"E": 300e3, "nu": 0.35, "model": "neo-hookean"}'
field() { echo "\"exact\": {\"linear\": {\"gradient\": [[$1,0,0],[0,$1,0],[0,0,$2]], \"translation\": [0,0,0]}}"; }
printf '{%s, "load_steps": 2, "contact": true, "dirichlet": [%s]}\n' "$material" "$(faces "$(field 0.02 -0.08)")" > pressed.json
printf '{%s, "load_steps": 2, "contact": false, "dirichlet": [%s]}\n' "$material" "$(faces "$(field 0.02 -0.08)")" > pressed-uncut.json
printf '{%s, "load_steps": 2, "contact": true, "dirichlet": [%s]}\n' "$material" "$(faces "$(field -0.02 0.08)")" > opened.json
sed 's/"contact": true/"contact": false/' opened.json > opened-off.json
rotation='"rotation": {"axis": [1, 0, 0], "angle_deg": 60, "center": [0.02, 0.02, 0.02]}'
printf '{%s, "load_steps": 3, "contact": true, "dirichlet": [%s]}\n' "$material" "$(faces "$rotation")" > turned.json

newton() {  # $1: name, $2: mesh, $3: problem, the rest: options
  local name=$1 mesh=$2 problem=$3; shift 3
  local cut=(--cut crack.vtp)
  [ "$mesh" = uncut.vtu ] && cut=()
  [ "$mesh" = through.vtu ] && cut=(--cut through.vtp)
  "$B/xfem-newton" -v "$mesh" "${cut[@]}" --problem "$problem" -o $name.mtx --report $name-report.json "$@" 2> $name.log ||
    { cat $name.log; fail "xfem-newton $name"; }
  grep -E "iteration|contact:" $name.log | sed "s/^/  $name: /"
}
newton pressed enriched.vtu pressed.json --contact-pressure pressed-p.mtx
newton pressed-uncut uncut.vtu pressed-uncut.json
newton opened enriched.vtu opened.json
newton opened-off enriched.vtu opened-off.json
newton turned through.vtu turned.json
sed 's/"contact": true/"contact": false/' turned.json > turned-uncut.json
newton turned-uncut uncut.vtu turned-uncut.json

# (c) The follower pressure on the through cut, the faces z = 0 and z = 0.04 clamped.
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

python3 - <<'PY' || fail "contact checks"
import json, math
def vector(path):
    rows = [l for l in open(path) if not l.startswith('%')]
    return [float(x) for x in rows[1:]]
E, nu = 300e3, 0.35
mu, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
# (a) pressed closed.
a, lat = 0.92, 1.02
J = lat * lat * a
P_zz = mu * (a - 1 / a) + lam * math.log(J) / a
u, u0 = vector('pressed.mtx'), vector('pressed-uncut.mtx')
np_ = len(u0) // 3
c = json.load(open('pressed-report.json'))['contact']
big = max(abs(v) for v in u0)
d = max(abs(x - y) for x, y in zip(u[:3 * np_], u0)) / big
force = -P_zz * 0.025 * 0.025
print("pressed: %d of %d contact nodes in contact, area %.6g m^2, %d multiplier updates, penetration %.3g m "
      "(tolerance %.3g m); max |u - u_uncut| / max |u| = %.3g; force %.6g N, closed form -P_zz A = %.6g N (%.2g)"
      % (c['active_points'], c['points'], c['active_area'], c['multiplier_updates'], c['max_penetration'],
         c['tolerance'], d, c['force'], force, abs(c['force'] / force - 1)))
assert c['points'] > 0 and c['active_points'] == c['points'], "not all in contact"
assert c['max_penetration'] <= c['tolerance'], "penetration"
assert d <= 1e-7, "u differs from the uncut body's"
assert abs(c['active_area'] - 0.025 ** 2) < 1e-12, "area"
assert abs(c['force'] / force - 1) < 1e-6, "force"
steps = json.load(open('pressed-report.json'))['steps']
for s in steps:
    print("  load %.3g: residuals %s, contact %s" % (s['load'], ' '.join('%.2g' % r for r in s['relative_residuals']),
                                                    s.get('contact')))
p = [float(r.split()[2]) for r in open('pressed-p.mtx') if not r.startswith('%')][1:]
print("   nodal contact pressure %.6g..%.6g Pa, -P_zz = %.6g Pa" % (min(p), max(p), -P_zz))
assert len(p) == c['points'] and all(abs(x / -P_zz - 1) < 1e-3 for x in p), "nodal pressures"
# Opened: contact on and off.
a_, b_ = vector('opened.mtx'), vector('opened-off.mtx')
big = max(abs(v) for v in b_)
diff = max(abs(x - y) for x, y in zip(a_, b_)) / big
c = json.load(open('opened-report.json'))['contact']
print("opened: contact on vs off: max difference %.3g of max |u|, %d of %d contact nodes in contact"
      % (diff, c['active_points'], c['points']))
assert len(a_) == len(b_) and diff <= 1e-12 and c['active_points'] == 0, "opening load"
# (b) turned.
c = json.load(open('turned-report.json'))['contact']
print("turned 60 degrees: %d of %d contact nodes in contact, penetration %.3g m (tolerance %.3g m), force %.3g N"
      % (c['active_points'], c['points'], c['max_penetration'], c['tolerance'], c['force']))
u, u0 = vector('turned.mtx'), vector('turned-uncut.mtx')
d = max(abs(x - y) for x, y in zip(u[:len(u0)], u0)) / max(abs(v) for v in u0)
print("   max |u - u_uncut| / max |u| = %.3g" % d)
assert c['max_penetration'] <= c['tolerance'], "rigid motion penetrates"
assert d <= 1e-7, "the turned cut body differs from the uncut one"
PY
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

# Bad input: one line on stderr, no output.
bad() {  # $1: what, $2: expected message (grep -E), the rest: xfem-newton's arguments
  local what=$1 message=$2; shift 2
  rm -f bad.mtx
  "$B/xfem-newton" -q "$@" -o bad.mtx 2> err && fail "$what accepted"
  [ "$(wc -l < err)" -eq 1 ] && grep -qE "^xfem-newton: error: $message" err || fail "$what: message: $(cat err)"
  [ ! -e bad.mtx ] || fail "$what: output left behind"
}
bad "contact with PETSc" "pressed.json: contact between the cut's faces is solved by the cholmod backend only" \
  enriched.vtu --cut crack.vtp --problem pressed.json --backend petsc
bad "--contact-pressure without contact" "opened-off.json: --contact-pressure: problem.json has no \"contact\"" \
  enriched.vtu --cut crack.vtp --problem opened-off.json --contact-pressure p.mtx
bad "contact that cannot converge" "contact: no convergence in 1 multiplier updates at load factor 0.5" \
  enriched.vtu --cut crack.vtp --problem pressed.json --contact-updates 1 --contact-tol 1e-30
sed 's/"cut": 0/"cut": 1/' follower-large.json > bad-cut.json
bad "a load on a missing cut" "bad-cut.json: cut_loads\[0\]\.cut is 1, but the mesh has 1 cut" \
  through.vtu --cut through.vtp --problem bad-cut.json
echo "PASS"
cd / && rm -rf "$XFEM_SCRATCH"
