#!/usr/bin/env bash
# Issue 33, "a closed cut under compression behaves as no cut", on the organ (xfem-mesh organ, a
# curved outer surface) with a sine crack: the hydrostatic check of test/e2e/contact_closed.sh
# (which does it for a plane, a zig-zag and a node-layer crack in the beam). Every node of the
# organ's boundary (selector "boundary": true) is moved by u = -e X (Dirichlet "exact": {"linear":
# ...} with gradient -e I, e = 1e-3): the uncut organ's solution is that field (linear tets
# reproduce it exactly), its stress -P I with P = (3 lambda + 2 mu) e = E e / (1 - 2 nu) = 30 Pa
# on every plane, so it is also the frictionless contact solution with a crack of any shape, the
# faces pressed together by P. The crack lies strictly inside (Dirichlet data hold the original
# DOFs only: a crack reaching the surface would leave its enriched DOFs free there): the sine z = 0.005 + 0.006 sin(2 pi x /
# 0.04) over [-0.04, 0.04] x [-0.025, 0.025] m, two wavelengths whose normal turns by up to
# +-43 degrees, about 2.5 tets (size 0.008) per half wavelength, 80 x 40 quads. Checked: no
# contact node (no node whose support meets the crack) is a boundary node; with contact every
# contact node is in contact, over the crack's whole area (the triangulated sine's, exact), the
# penetration below the tolerance, every nodal pressure within kappa tol of P, the normal force
# P times the area, and u equal to the uncut organ's (= -e X) to 1e-7 of max |u| with the default
# tolerance (1e-8 max |u|: measured 5.8e-9) and to 1e-8 with --contact-tol 1e-13 m (measured
# 1.7e-10: the difference is the augmented Lagrangian's, it shrinks with the tolerance). Without
# contact the crack's faces are free and u is far from the uncut field (measured 2.0 max |u|), so
# the check can fail. Bad input: "boundary": false and a gradient of 2 rows are refused in one line.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1
B="$XFEM_BIN"
"$B/xfem-mesh" -q organ --size 0.008 -o organ.vtu || fail "organ mesh"
"$B/xfem-mesh" -q cut-sine --lo -0.04 -0.025 --hi 0.04 0.025 --z0 0.005 --amplitude 0.006 --wavelength 0.04 \
  --divisions 80 40 -o sine.vtp || fail "sine crack"
cat > on.json <<'EOF'
{"material": {"E": 3e3, "nu": 0.45}, "contact": true,
 "dirichlet": [{"name": "compressed surface", "selector": {"boundary": true},
                "exact": {"linear": {"gradient": [[-1e-3, 0, 0], [0, -1e-3, 0], [0, 0, -1e-3]]}}}]}
EOF
sed 's/"contact": true/"contact": false/' on.json > off.json
"$B/xfem-classify" -q organ.vtu --cut sine.vtp -o classified.vtu || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-classify" -q organ.vtu -o plain.vtu || fail "classify uncut"
"$B/xfem-enrich" -q plain.vtu -o uncut.vtu || fail "enrich uncut"
for k in on off; do
  "$B/xfem-assemble" -q enriched.vtu --cut sine.vtp --problem $k.json --format mtx -o $k || fail "assemble $k"
done
"$B/xfem-solve" -q on -o on.mtx --report on.json --contact-pressure p.mtx || fail "solve on"
"$B/xfem-solve" -q on -o tight.mtx --report tight.json --contact-tol 1e-13 || fail "solve on, tight tolerance"
"$B/xfem-solve" -q off -o off.mtx || fail "solve off"
"$B/xfem-assemble" -q uncut.vtu --problem off.json --format mtx -o uncut || fail "assemble uncut"
"$B/xfem-solve" -q uncut -o uncut.mtx || fail "solve uncut"
python3 - <<'PY' || fail "organ hydrostatic checks"
import json, math
def vector(path):
    rows = [l for l in open(path) if not l.startswith('%')]
    return [float(x) for x in rows[1:]]
def table(path):
    return [l.split() for l in open(path) if not l.startswith('%')][1:]
E, nu, e = 3e3, 0.45, 1e-3
P = E * e / (1 - 2 * nu)  # (3 lambda + 2 mu) e: the pressure on every plane, 30 Pa
xyz, uncut = vector('on/coordinates.mtx'), vector('uncut.mtx')
n = len(uncut)
scale = max(abs(v) for v in uncut)
# The uncut organ gives -e X exactly (round-off): the reference is right.
assert len(xyz) == n and max(abs(uncut[d] + e * xyz[d]) for d in range(n)) <= 1e-12 * scale
# No contact node on the boundary (the Dirichlet condition's nodes, the only one): the crack is inside.
boundary = {(int(r[0]) - 1) // 3 for r in table('on/dirichlet.mtx')}
points = table('on/contact_points.mtx')
contact_nodes = {int(float(r[2])) for r in points if r[1] == '6'}
assert contact_nodes and not contact_nodes & boundary, "a contact node on the boundary"
# The crack's area: the triangulated sine's strips, each flat across y.
xs = [-0.04 + 0.08 * i / 80 for i in range(81)]
zs = [0.005 + 0.006 * math.sin(2 * math.pi * x / 0.04) for x in xs]
A = 0.05 * sum(math.hypot(xs[i + 1] - xs[i], zs[i + 1] - zs[i]) for i in range(80))
kappa = max(float(r[2]) for r in points if r[1] == '2')
for name in ('on', 'tight', 'off'):
    u = vector(name + '.mtx')
    d = max(abs(a - b) for a, b in zip(u[:n], uncut)) / scale
    if name == 'off':
        print("organ, contact off: max |u - u_uncut| = %.3g of max |u| (%d boundary nodes)" % (d, len(boundary)))
        assert d > 0.1, "without contact the faces are free: far from the uncut field"
        continue
    c = json.load(open(name + '.json'))['contact']
    print("organ, contact on (%s tolerance %.3g m): max |u - u_uncut| = %.3g of max |u|; %d of %d contact nodes in "
          "contact, area %.9g of %.9g m^2 (sine %.9g), %d solves, %d multiplier updates, penetration %.3g m, force %.6g N "
          "(P A = %.6g N)" % ('default' if name == 'on' else 'tight', c['tolerance'], d, c['active_points'], c['points'],
                              c['active_area'], c['area'], A, c['solves'], c['multiplier_updates'], c['max_penetration'],
                              c['force'], P * A))
    assert c['active_points'] == c['points'] == len(contact_nodes) > 0, name
    assert abs(c['area'] - A) <= 1e-12 * A and abs(c['active_area'] - A) <= 1e-12 * A, name
    assert c['max_penetration'] <= c['tolerance'], name
    assert d <= (1e-7 if name == 'on' else 1e-8), name
    # p = lambda - kappa g carries the gaps' error times the penalty: |p - P| <= kappa tol.
    bound = kappa * c['tolerance']
    assert abs(c['force'] - P * A) <= bound * A, name
    if name == 'on':
        pressures = [float(r[2]) for r in table('p.mtx')]
        worst = max(abs(p - P) for p in pressures)
        print("   nodal pressures %.6g..%.6g Pa, largest |p - P| %.3g Pa (P = %.6g Pa), bound kappa tol %.3g Pa"
              % (min(pressures), max(pressures), worst, P, bound))
        assert len(pressures) == c['points'] and worst <= bound
PY

# Bad input: one line naming the file and the item, exit 1, nothing written.
bad() {  # $1: what, $2: the problem's dirichlet list, $3: the expected message
  printf '{"material": {"E": 3e3, "nu": 0.45}, "dirichlet": %s}\n' "$2" > bad.json
  "$B/xfem-assemble" -q enriched.vtu --cut sine.vtp --problem bad.json -o bad 2> err.txt && fail "$1 accepted"
  [ "$(wc -l < err.txt)" = 1 ] && grep -qF "$3" err.txt || fail "$1: $(cat err.txt)"
  [ ! -e bad ] || fail "$1: output written"
}
bad "boundary false" '[{"selector": {"boundary": false}, "value": [0, 0, 0]}]' \
  "bad.json: dirichlet[0].selector.boundary must be true (the nodes of the mesh's boundary faces), got false"
bad "gradient of 2 rows" '[{"selector": {"boundary": true}, "exact": {"linear": {"gradient": [[1, 0, 0], [0, 1, 0]]}}}]' \
  "bad.json: dirichlet[0].exact.linear.gradient must be a list of 3 rows of 3 numbers"
cd / && rm -rf "$XFEM_SCRATCH"
