#!/usr/bin/env bash
# Issue 33, "a closed cut under compression behaves as no cut", on the organ through xfem-newton:
# test/e2e/contact_closed_organ.sh's organ (size 0.008) and interior sine crack, neo-Hookean
# (E = 3 kPa, nu = 0.45), every boundary node moved by u = -e X (e = 0.01, one load step). The
# uncut organ's solution is the homogeneous F = (1 - e) I (linear tets reproduce it), its first
# Piola stress -p I with p = -(mu (a - 1/a) + lambda ln(a^3) / a), a = 1 - e, so with frictionless
# contact measured in the reference configuration (small sliding) it is also the cracked organ's
# solution, the faces pressed together by p (nominal, per reference area). Checked: every contact
# node in contact, penetration <= tolerance (1e-8 max |u|), u equal to the uncut organ's
# xfem-newton u to 1e-7 of max |u| (the Uzawa loop stops once the gaps are below 1e-8 max |u|;
# measured 6.0e-9), every nodal pressure within 1e-4 of p (measured 4e-6: 304.3459 Pa), the
# normal force p A to 1e-6 (A the triangulated sine's area). (Without contact u is far from the
# uncut field, 2.04 of max |u| at e = 0.02: e2e.contact_closed_organ shows it on the linear path; not run here,
# one xfem-newton solve of the cracked organ is ~8 s of CPU.)
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1
B="$XFEM_BIN"
"$B/xfem-mesh" -q organ --size 0.008 -o organ.vtu || fail "organ mesh"
"$B/xfem-mesh" -q cut-sine --lo -0.04 -0.025 --hi 0.04 0.025 --z0 0.005 --amplitude 0.006 --wavelength 0.04 \
  --divisions 80 40 -o sine.vtp || fail "sine crack"
cat > on.json <<'EOF'
{"material": {"E": 3e3, "nu": 0.45, "model": "neo-hookean"}, "contact": true,
 "dirichlet": [{"name": "compressed surface", "selector": {"boundary": true},
                "exact": {"linear": {"gradient": [[-0.01, 0, 0], [0, -0.01, 0], [0, 0, -0.01]]}}}]}
EOF
sed 's/"contact": true/"contact": false/' on.json > off.json
"$B/xfem-classify" -q organ.vtu --cut sine.vtp -o classified.vtu || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-classify" -q organ.vtu -o plain.vtu || fail "classify uncut"
"$B/xfem-enrich" -q plain.vtu -o uncut.vtu || fail "enrich uncut"
newton() {  # $1: name, $2: mesh, $3: problem, the rest: options
  local name=$1 mesh=$2 problem=$3; shift 3
  local cut=(--cut sine.vtp)
  [ "$mesh" = uncut.vtu ] && cut=()
  "$B/xfem-newton" -v "$mesh" "${cut[@]}" --problem "$problem" -o $name.mtx --report $name-report.json "$@" 2> $name.log ||
    { cat $name.log; fail "xfem-newton $name"; }
  grep -E "iteration|contact:" $name.log | sed "s/^/  $name: /"
}
newton on enriched.vtu on.json --contact-pressure p.mtx
newton uncut uncut.vtu off.json
python3 - <<'PY' || fail "organ checks"
import json, math
def vector(path):
    rows = [l for l in open(path) if not l.startswith('%')]
    return [float(x) for x in rows[1:]]
E, nu, e = 3e3, 0.45, 0.01
mu, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
a = 1 - e
p = -(mu * (a - 1 / a) + lam * math.log(a ** 3) / a)
xs = [-0.04 + 0.08 * i / 80 for i in range(81)]
zs = [0.005 + 0.006 * math.sin(2 * math.pi * x / 0.04) for x in xs]
A = 0.05 * sum(math.hypot(xs[i + 1] - xs[i], zs[i + 1] - zs[i]) for i in range(80))
u0, u = vector('uncut.mtx'), vector('on.mtx')
n = len(u0)
big = max(abs(v) for v in u0)
d = max(abs(x - y) for x, y in zip(u[:n], u0)) / big
c = json.load(open('on-report.json'))['contact']
pressures = [float(r.split()[2]) for r in open('p.mtx') if not r.startswith('%')][1:]
print("organ, neo-Hookean, e = %g: %d of %d contact nodes in contact, area %.9g m^2 (sine %.9g), %d multiplier "
      "updates, penetration %.3g m (tolerance %.3g m); max |u - u_uncut| / max |u| = %.3g; "
      "force %.6g N (p A = %.6g N); nodal pressures %.7g..%.7g Pa (p = %.7g Pa)"
      % (e, c['active_points'], c['points'], c['active_area'], A, c['multiplier_updates'], c['max_penetration'],
         c['tolerance'], d, c['force'], p * A, min(pressures), max(pressures), p))
assert c['points'] > 0 and c['active_points'] == c['points'], "not all in contact"
assert abs(c['active_area'] - A) <= 1e-12 * A, "area"
assert c['max_penetration'] <= c['tolerance'], "penetration"
assert d <= 1e-7, "u differs from the uncut organ's"
assert abs(c['force'] / (p * A) - 1) < 1e-6, "force"
assert len(pressures) == c['points'] and all(abs(x / p - 1) < 1e-4 for x in pressures), "nodal pressures"
PY
cd / && rm -rf "$XFEM_SCRATCH"
