#!/usr/bin/env bash
# Issue 33: a pressure on the faces of the penny-shaped crack of pipelines/verification (8^3 box,
# radius enrichment, the default conforming rule). Sneddon's field of the pressurised crack is
# imposed on the boundary (data/penny_pressure.json: the remote-tension field less its uniform
# part). Checks: the superposition identity on the same mesh, u(pressure p on the faces) =
# u(remote tension p) - u(uncracked, the uniform field), to round-off; hence the same absolute L2
# and H1 errors as the remote-tension penny; the crack's volume (xfem-solve's contact report; the
# crack opens, so contact never acts) at its measured value, below 16 (1 - nu^2) p a^3 / (3 E);
# one-line errors for a cut index out of range, a pressure that is not a number, contact with
# the PETSc backend, cut loads given to xfem-newton or xfem-sweep. K from xfem-front with the
# crack-face term: K(pressure) = K(remote) on the same mesh (to 2e-3 K), and for the inclined penny
# K(pressure and traction on the faces) = K(remote normal stress and shear).
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1
B="$XFEM_BIN"
D="$XFEM_SOURCE/pipelines/verification/data"
"$B/xfem-mesh" -q box --cells 8 8 8 --hi 1 1 1 -o mesh.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-disc --center 0.5 0.5 0.47 --normal 0 0 1 --radius 0.3 --rings 16 -o cut.vtp || fail "cut"
"$B/xfem-classify" -q mesh.vtu --cut cut.vtp --tip-radius 0.15 -o classified.vtu || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
for c in penny penny_pressure; do
  "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$D/$c.json" --format mtx -o $c/system || fail "assemble $c"
  "$B/xfem-solve" -q $c/system -o $c/u.mtx --report $c/solve.json || fail "solve $c"
  "$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp --solution $c/u.mtx --exact "$D/${c}_exact.json" --samples 26 \
    -o $c/error.json > /dev/null || fail "rmserror $c"
done
python3 - <<'PY' || fail "superposition"
import json
def vector(path):
    rows = [l for l in open(path) if not l.startswith('%')]
    return [float(x) for x in rows[1:]]
remote, pressure = vector('penny/u.mtx'), vector('penny_pressure/u.mtx')
xyz = vector('penny/system/coordinates.mtx')
E, nu, sigma, centre = 1.0, 0.3, 1.0, (0.5, 0.5, 0.47)
# The uncracked body under the remote tension: eps = sigma / E ((1 + nu) e_z e_z - nu I), u = eps (x - centre)
strain = (-nu * sigma / E, -nu * sigma / E, sigma / E)
np = len(xyz) // 3
worst = max(abs(remote[d] - (strain[d % 3] * (xyz[d] - centre[d % 3]) if d < 3 * np else 0.0) - pressure[d])
            for d in range(len(remote)))
scale = max(abs(v) for v in pressure)
print("superposition: max |u_remote - u_uniform - u_pressure| = %.3g m, max |u_pressure| = %.3g m" % (worst, scale))
assert worst <= 1e-10 * scale
a, b = (json.load(open(c + '/error.json')) for c in ('penny', 'penny_pressure'))
for k in ('l2', 'h1', 'max'):
    print("%s error: remote %.10g, pressure %.10g" % (k, a[k], b[k]))
    assert abs(a[k] - b[k]) <= 1e-9 * a[k]
c = json.load(open('penny_pressure/solve.json'))['contact']
exact = 16 * (1 - nu**2) * sigma * 0.3**3 / (3 * E)
print("crack volume %.5g m^3, Sneddon %.5g (%.1f %%); contact points %d, active %d" %
      (c['opened_volume'], exact, 100 * (c['opened_volume'] / exact - 1), c['points'], c['active_points']))
# 0.11416 with the rule of order 3 before issue 35 (-12.9 % of Sneddon's on this 8^3 mesh); 0.11558 since.
assert abs(c['opened_volume'] - 0.11558) < 0.005 * 0.11558 and c['opened_volume'] < exact
assert c['active_points'] == 0 and c['solves'] == 1
PY
# K with loaded faces (xfem-front's crack-face term): the superposition identity on the same mesh,
# K(pressure p on the faces) = K(remote tension p) (the uniform field has K = 0: its volume term and
# its faces' traction term cancel, to the face rule's error), hence the pressurised penny's K_I has
# the remote penny's error and convergence (docs/VERIFICATION.md); without the face term K_I is far off.
for c in penny penny_pressure; do
  "$B/xfem-front" enriched.vtu --cut cut.vtp --solution $c/u.mtx --problem "$D/$c.json" --radius 0.1 \
    --csv $c/front.csv 2> $c/front.err || fail "front $c: $(cat $c/front.err)"
done
grep -q "contact is on for cut 0: K leaves out the contact pressure" penny_pressure/front.err \
  || fail "no warning about the contact pressure: $(cat penny_pressure/front.err)"
printf '{"material": {"E": 1, "nu": 0.3}}\n' > unloaded.json
grep -v '^% xfem-fingerprint' penny_pressure/u.mtx > unsigned.mtx
"$B/xfem-front" -q enriched.vtu --cut cut.vtp --solution unsigned.mtx --problem unloaded.json --radius 0.1 \
  --csv unloaded.csv || fail "front without the face term"
python3 - <<'PY' || fail "K with loaded faces"
import csv, math
K = 2 * 1.0 * math.sqrt(0.3 / math.pi)
rows = {c: [r for r in csv.DictReader(open(c)) ] for c in ('penny/front.csv', 'penny_pressure/front.csv', 'unloaded.csv')}
remote, pressure, unloaded = rows['penny/front.csv'], rows['penny_pressure/front.csv'], rows['unloaded.csv']
assert len(remote) == len(pressure) == 19
identity = max(abs(float(p[k]) - float(r[k])) / K for p, r in zip(pressure, remote) for k in ('K_I', 'K_II', 'K_III'))
err = [float(p['K_I']) / K - 1 for p in pressure]
err_remote = [float(r['K_I']) / K - 1 for r in remote]
without = max(abs(float(u['K_I']) / K - 1) for u in unloaded)
print("K(pressure) - K(remote): max %.2e K; K_I error: pressure %+.2f .. %+.2f %%, remote %+.2f .. %+.2f %%; "
      "without the face term %.0f %%" % (identity, 100 * min(err), 100 * max(err), 100 * min(err_remote),
                                         100 * max(err_remote), 100 * without))
assert identity < 2e-3  # measured 7.8e-4 (the face rule's and the volume rule's error on the uniform field)
assert without > 0.5  # measured 109 %
PY
# A traction vector too: the inclined penny (normal stress 0.5 Pa, shear 0.5 Pa along x) loaded on
# its faces by pressure 0.5 and traction (0.5, 0, 0) against the same crack under the remote
# stress (data/penny_inclined.json): K_I, K_II and K_III the same on the same mesh.
python3 - "$D/penny_inclined.json" <<'PY' || fail "inclined problem"
import json, sys
j = json.load(open(sys.argv[1]))
for d in j['dirichlet']:
    d['exact']['penny']['loading'] = 'faces'
j['cut_loads'] = [{'cut': 0, 'pressure': 0.5, 'traction': [0.5, 0.0, 0.0]}]
json.dump(j, open('inclined_faces.json', 'w'))
PY
for c in inclined inclined_faces; do
  p="$D/penny_inclined.json"; [ $c = inclined ] || p=inclined_faces.json
  "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$p" -o $c/system || fail "assemble $c"
  "$B/xfem-solve" -q $c/system -o $c/u.mtx || fail "solve $c"
  "$B/xfem-front" -q enriched.vtu --cut cut.vtp --solution $c/u.mtx --problem "$p" --radius 0.1 --csv $c/front.csv \
    || fail "front $c"
done
python3 - <<'PY' || fail "K with a traction on the faces"
import csv
remote, faces = (list(csv.DictReader(open(c + '/front.csv'))) for c in ('inclined', 'inclined_faces'))
amplitude = {'K_I': 0.3090, 'K_II': 0.3635, 'K_III': 0.2545}
worst = {k: max(abs(float(f[k]) - float(r[k])) for f, r in zip(faces, remote)) / a for k, a in amplitude.items()}
print("inclined penny, K(faces loaded) - K(remote) over each factor's amplitude: " +
      ", ".join("%s %.2e" % kv for kv in worst.items()))
assert len(remote) == len(faces) == 19 and max(worst.values()) < 2e-3  # measured K_I 9.8e-4, K_II 3.9e-4, K_III 4.4e-4
PY
# Bad inputs: one line each, nothing written.
bad() {  # $1: problem.json text, $2: the expected message (grep -E)
  printf '%s\n' "$1" > bad.json
  "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem bad.json -o bad/system 2> err && fail "accepted: $1"
  [ "$(wc -l < err)" -eq 1 ] && grep -qE "^xfem-assemble: error: $2" err || fail "message: $(cat err)"
  [ ! -e bad ] || fail "output left behind"
}
bad '{"material": {"E": 1, "nu": 0.3}, "cut_loads": [{"cut": 1, "pressure": 1}]}' \
  "bad.json: cut_loads\[0\]\.cut is 1, but the mesh has 1 cut \(indices 0\.\.0\)"
bad '{"material": {"E": 1, "nu": 0.3}, "cut_loads": [{"pressure": "high"}]}' "bad.json: cut_loads\[0\]\.pressure must be a number"
bad '{"material": {"E": 1, "nu": 0.3}, "contact": {"cuts": [3]}}' "bad.json: contact\.cuts\[0\] is 3, but the mesh has 1 cut"
printf '{"material": {"E": 1, "nu": 0.3}, "cut_loads": [{"cut": 1, "pressure": 1}]}\n' > bad.json
"$B/xfem-front" -q enriched.vtu --cut cut.vtp --solution unsigned.mtx --problem bad.json --csv bad.csv 2> err \
  && fail "xfem-front accepted a load on a cut the mesh does not have"
[ "$(wc -l < err)" -eq 1 ] && grep -q "^xfem-front: error: bad.json: cut_loads\[0\]\.cut is 1, but the mesh has 1 cut" err \
  || fail "message: $(cat err)"
[ ! -e bad.csv ] || fail "output left behind"
# Contact on the PETSc backend (test e2e.contact_petsc): the pressed-open penny's faces stay apart
# there too, its first solve returned as it is.
if [ -x "$B/xfem-solve-petsc" ]; then
  "$B/xfem-solve" -q penny_pressure/system -o petsc.mtx --report petsc.json --backend petsc || fail "contact with PETSc"
  python3 -c "import json, sys; c = json.load(open('petsc.json'))['contact']; sys.exit(c['solves'] != 1 or c['active_points'] != 0)" \
    || fail "PETSc: the penny's faces touch"
fi
# The tool that would ignore them refuses cut loads and contact in one line (xfem-newton solves them:
# test e2e.newton_contact).
"$B/xfem-mesh" -q cut-sweep --path 0.2 0.1 1.2 0.2 0.9 1.2 --depth 0.5 --resolution 0.2 -o sweep.vtp || fail "cut-sweep"
"$B/xfem-sweep" -q mesh.vtu --cut sweep.vtp --problem "$D/penny_pressure.json" --steps 2 -o frames 2> err && fail "xfem-sweep accepted cut loads"
[ "$(wc -l < err)" -eq 1 ] && grep -q "^xfem-sweep: error: .*xfem-sweep's steps leave the cut's faces free" err || fail "message: $(cat err)"
[ ! -e bad.mtx ] && [ ! -e frames ] || fail "output left behind"
cd / && rm -rf "$XFEM_SCRATCH"
