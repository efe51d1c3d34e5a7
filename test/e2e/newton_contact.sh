#!/usr/bin/env bash
# Issue 33 under large deformation: contact between a cut's faces in xfem-newton (docs/METHOD.md
# "Contact and pressure on the cut's faces at large deformation"; the follower pressure is test
# e2e.newton_follower). A cube [0,0.04]^3 (unstructured, size 0.005; neo-Hookean, E = 300 kPa,
# nu = 0.35):
#  (a) pressed closed: a square crack 0.025 x 0.025 at z = 0.02 inside the cube (7.5 mm from the
#      faces: the Dirichlet conditions hold the original DOFs only, so a cut reaching a held face
#      would leave its enriched DOFs free there), every outer face held at the homogeneous field
#      u = (F - I) X, F = diag(1.02, 1.02, 0.92) (8 % compression across the cut). The uncut body's
#      solution is that field (linear tets reproduce it), its first Piola stress P uniform and
#      diagonal, so the traction on the cut's reference plane is normal and compressive: with
#      frictionless contact measured in the reference configuration it is also the cut body's
#      solution. Checked: every contact node in contact, penetration <= tolerance (1e-8 max |u|), u
#      equal to the uncut body's xfem-newton u to 1e-7 max |u| (the Uzawa loop stops once the gaps
#      are below 1e-8 max |u|), every nodal pressure within 1e-3 of -P_zz, the contact force =
#      -P_zz A (A = 0.025^2, P_zz of the neo-Hookean law in closed form) to 1e-6; the same field
#      stretched (F = diag(0.98, 0.98, 1.08)) opens the crack: contact on and off give the same u to
#      1e-12 max |u| and no node in contact.
#  (b) a rigid motion: the cube cut through by the plane z = 0.02, every outer face turned by 60
#      degrees about the x axis through the cube's centre, in 3 load steps: the reference gap
#      g = G u of a rigid motion is 0, so no contact node may penetrate (penetration <= tolerance)
#      and u must be the uncut cube's (the rotation) to 1e-7 of max |u|.
# Newton's residual histories are printed. Then the bad inputs of contact.
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
faces() { printf '{"selector": {"boundary": true}, %s}' "$1"; }  # the boundary, held at the JSON value $1
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
# xfem-visualize takes xfem-newton's contact pressure as xfem-solve's: on the wound, -P_zz = 30,887 Pa.
"$B/xfem-visualize" enriched.vtu --cut crack.vtp --solution pressed.mtx --problem pressed.json \
  --contact-pressure pressed-p.mtx --faces wound.vtp -o deformed.vtu 2> visualize.log || { cat visualize.log; fail "visualize"; }
grep "contact pressure on the wound" visualize.log
grep -q "contact pressure on the wound: largest 3.09e+04 Pa" visualize.log && [ -s wound.vtp ] || fail "visualize: contact pressure"
newton opened enriched.vtu opened.json
newton opened-off enriched.vtu opened-off.json
newton turned through.vtu turned.json
sed 's/"contact": true/"contact": false/' turned.json > turned-uncut.json
newton turned-uncut uncut.vtu turned-uncut.json
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

# Bad input: one line on stderr, no output.
bad() {  # $1: what, $2: expected message (grep -E), the rest: xfem-newton's arguments
  local what=$1 message=$2; shift 2
  rm -f bad.mtx
  "$B/xfem-newton" -q "$@" -o bad.mtx 2> err && fail "$what accepted"
  [ "$(wc -l < err)" -eq 1 ] && grep -qE "^xfem-newton: error: $message" err || fail "$what: message: $(cat err)"
  [ ! -e bad.mtx ] || fail "$what: output left behind"
}
bad "--contact-pressure without contact" "opened-off.json: --contact-pressure: problem.json has no \"contact\"" \
  enriched.vtu --cut crack.vtp --problem opened-off.json --contact-pressure p.mtx
sed 's/"contact": true/"contact": {"friction": 0.3}/' pressed.json > friction.json
bad "friction" "friction.json: xfem-newton solves frictionless contact: contact.friction is solved by xfem-solve only" \
  enriched.vtu --cut crack.vtp --problem friction.json
bad "contact that cannot converge" "contact: no convergence in 1 multiplier updates at load factor 0.5" \
  enriched.vtu --cut crack.vtp --problem pressed.json --contact-updates 1 --contact-tol 1e-30
echo "PASS"
cd / && rm -rf "$XFEM_SCRATCH"
