#!/usr/bin/env bash
# xfem-newton: with "linear" it equals xfem-assemble + xfem-solve; with neo-Hookean and corotational
# every load step converges quadratically (the report's residual history); its u.mtx is taken by
# xfem-visualize and xfem-probe unchanged; each bad input is refused with one line and no output.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; NEWTON=$B/xfem-newton; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error <text> <args...>: exit 1, one "error:" line with <text>, no output file
  local text=$1; shift
  rm -f bad.mtx
  "$NEWTON" "$@" -o bad.mtx 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $*: $(cat err.txt)"
  [ "$(grep -c "error:" err.txt)" -eq 1 ] || fail "not one error line for $*: $(cat err.txt)"
  grep -qF -- "$text" err.txt || fail "expected '$text' for $*, got: $(cat err.txt)"
  [ ! -e bad.mtx ] || fail "output left behind for $*"
}
with_model() {  # with_model <model> <load_steps> <out.json> [extra python]: the beam's problem with another model
  python3 -c "import json,sys; p=json.load(open('$PROBLEM')); p['material']['model']='$1'; p['load_steps']=$2; $4; json.dump(p, open('$3','w'))"
}

"$NEWTON" --help >/dev/null || fail "--help"
"$NEWTON" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"

# The paper's beam and cut (a front inside: original, sign and branch DOFs), coarse.
"$B/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size 0.012 -o beam.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp || fail "cut"
"$B/xfem-classify" -q beam.vtu --cut cut.vtp -o classified.vtu || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$PROBLEM" -o system || fail "assemble"
"$B/xfem-solve" -q system -o u_linear.mtx --reactions r_linear.mtx || fail "solve"

# 1. "linear" through Newton = the linear path, to 1e-10 of the largest displacement; reactions too.
"$NEWTON" -q enriched.vtu --cut cut.vtp --problem "$PROBLEM" -o u.mtx --reactions r.mtx --report linear.json \
  || fail "xfem-newton linear"
python3 - <<'PY' || fail "xfem-newton linear differs from xfem-assemble + xfem-solve"
def read(p): return [float(l.split()[-1]) for l in open(p) if not l.startswith('%')][1:]
for a, b, what in (('u.mtx', 'u_linear.mtx', 'u'), ('r.mtx', 'r_linear.mtx', 'reactions')):
    x, y = read(a), read(b)
    d = max(abs(p - q) for p, q in zip(x, y)) / max(abs(q) for q in y)
    print(f"newton: linear model, {what}: max difference / max = {d:.2e} (limit 1e-10)")
    assert len(x) == len(y) and d <= 1e-10
PY
grep -q "xfem-fingerprint problem" u.mtx || fail "u.mtx carries no fingerprints"

# 2. Neo-Hookean and corotational, the beam's pull in 2 load steps: every step converges, and its
#    last iterations are quadratic (from below 1e-2, the next residual below 10 x its square).
for model in neo-hookean corotational; do
  with_model $model 2 $model.json "pass"
  "$NEWTON" -q enriched.vtu --cut cut.vtp --problem $model.json -o u_$model.mtx --report report_$model.json \
    || fail "xfem-newton $model"
  python3 - report_$model.json <<'PY' || fail "$model: Newton not quadratic"
import json, sys
r = json.load(open(sys.argv[1]))
assert r['material_model'] in ('neo-hookean', 'corotational') and r['load_steps'] == 2
assert [s['load'] for s in r['steps'] if s['converged']][-1] == 1.0
for s in r['steps']:
    h = s['relative_residuals']
    print(f"newton: {r['material_model']}, load {s['load']}: residuals " + ' '.join(f'{x:.1e}' for x in h))
    assert s['converged'] and h[-1] <= 1e-8
    assert any(h[k] < 1e-2 and h[k + 1] < 10 * h[k] ** 2 for k in range(1, len(h) - 1)), h
    # Forces and tangent once per accepted iterate: the first step evaluates its start too, the
    # second starts from the first's answer (no projections, no halving here).
    first = s is r['steps'][0]
    assert s['tangents'] == s['iterations'] + (1 if first else 0), (s['tangents'], s['iterations'])
    assert s['factorizations'] == s['iterations'] and s['projected_tangents'] == 0
    assert min(s['assemble_seconds'], s['factor_seconds'], s['solve_seconds']) >= 0
assert r['min_det_F'] > 0 and r['factorizations'] >= 2
PY
done
# The later stages take its solution: xfem-visualize (the model's stress) and xfem-probe.
"$B/xfem-visualize" -q enriched.vtu --cut cut.vtp --solution u_neo-hookean.mtx --problem neo-hookean.json \
  -o deformed.vtu 2>vis.err || fail "xfem-visualize refuses xfem-newton's u: $(cat vis.err)"
printf 'x,y,z\n0.02,0.03,0.15\n' > points.csv
"$B/xfem-probe" -q enriched.vtu --cut cut.vtp --solution u_neo-hookean.mtx --points points.csv -o probe.csv \
  || fail "xfem-probe refuses xfem-newton's u"
# ... and check it belongs to the problem: another problem file is refused.
"$B/xfem-visualize" -q enriched.vtu --cut cut.vtp --solution u_neo-hookean.mtx --problem "$PROBLEM" -o other.vtu \
  2>/dev/null && fail "xfem-visualize took a u.mtx solved for another problem.json"

# 3. Bad inputs.
expect_error "enriched displacements (NS + 4 NB > 0) need the cut surface: give --cut" enriched.vtu --problem "$PROBLEM"
with_model neo-hookean 1 oversampling.json "p['integration']={'rule': 'oversampling'}"
expect_error "xfem-newton integrates with the conforming rule only" enriched.vtu --cut cut.vtp --problem oversampling.json
# The beam cut clean through at z = 0.1 and held at its bottom only: the top half is free.
"$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.1 --edge1 0.05 0 0 --edge2 0 0.08 0 -o through.vtp || fail "cut through"
"$B/xfem-classify" -q beam.vtu --cut through.vtp -o through_c.vtu && "$B/xfem-enrich" -q through_c.vtu -o through_e.vtu \
  || fail "classify, enrich the cut through"
with_model neo-hookean 1 free.json "p['dirichlet']=p['dirichlet'][:1]; p['body_force']=[0,0,-10]"
expect_error "has no Dirichlet condition: it can move rigidly" through_e.vtu --cut through.vtp --problem free.json
# Held by one edge only: a rotation about it is free, and no tangent is definite.
with_model neo-hookean 1 hinge.json "p['dirichlet']=p['dirichlet'][1:]"
expect_error "the tangent stiffness is singular even projected (a rigid motion left free?)" enriched.vtu --cut cut.vtp --problem hinge.json
with_model neohookean 1 unknown.json "pass"
expect_error 'material.model must be "linear", "corotational" or "neo-hookean", got "neohookean"' enriched.vtu --cut cut.vtp --problem unknown.json
# The beam squashed to a tenth of its length in one step, one iteration allowed: Newton gives up.
with_model neo-hookean 1 squash.json "p['dirichlet'][1]['value']=[0,0,-0.18]"
expect_error "Newton's method failed at load factor" enriched.vtu --cut cut.vtp --problem squash.json --max-iterations 1
echo "newton: ok"
