#!/usr/bin/env bash
# Issue 33: contact between a cut's faces on the PETSc backend (docs/METHOD.md "Contact": the
# iteration is one code, contact_solve.h's, each penalised solve by the backend). Against CHOLMOD
# on the same system, PETSc's CG to --rtol 1e-12 (xfem-solve) or --cg-rtol 1e-12 (xfem-newton):
#  - xfem-solve, the plane crack inside the beam pressed closed by a hydrostatic field (the case of
#    e2e.contact_closed): u within 1e-8 of max |u| of CHOLMOD's (both iterations stop once the gaps
#    are below 1e-8 max |u|; measured 1.5e-9), the uncut field e x to 1e-7, the same contact nodes
#    in contact (the nodes with a positive pressure), the same report keys (PETSc adds
#    contact.cg_iterations), on 1 and 2 processes;
#  - xfem-solve, the beam cut through and pulled with "contact": the cut opens, one solve, no node in
#    contact, u within 1e-8 of CHOLMOD's;
#  - xfem-solve, friction (the inclined penny at mu = 0.5 tan beta of e2e.friction, every node slipping):
#    u within 1e-8, the same stick/slip counts;
#  - the penalty costs CG no more iterations than the solve without contact (at most twice): it acts
#    on enriched DOFs only, whose block the preconditioner factorizes (--enriched-block direct, the
#    default on cut systems). With one GAMG on the whole K (--enriched-block gamg) xfem-newton's
#    contact solves took ~800 iterations against ~330 without;
#  - xfem-newton --backend petsc, the crack pressed closed and pulled open (e2e.newton_contact's
#    cube, neo-Hookean): u within 1e-8 of CHOLMOD's, the same nodes in contact, on 1 and 2 processes.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
B="$XFEM_BIN"
S="$XFEM_SOURCE"
if [ ! -x "$B/xfem-solve-petsc" ] || [ ! -x "$B/xfem-newton-petsc" ]; then echo "SKIP: built without PETSc"; exit 0; fi
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
cd "$XFEM_SCRATCH" || exit 1

# compare <label> <cholmod dir> <petsc dir> [uncut e]: u, the nodes in contact, the report's keys.
compare() {
  python3 - "$@" <<'PY' || fail "$1: PETSc differs from CHOLMOD"
import json, sys
label, a, b = sys.argv[1:4]
def vector(path):
    return [float(l.split()[-1]) for l in open(path) if not l.startswith('%')][1:]
def in_contact(path):  # the (node, cut) pairs with a positive contact pressure
    rows = [l.split() for l in open(path) if not l.startswith('%')][1:]
    return {(r[0], r[1]) for r in rows if float(r[2]) > 0}
u, v = vector(a + '/u.mtx'), vector(b + '/u.mtx')
scale = max(abs(x) for x in u)
d = max(abs(x - y) for x, y in zip(u, v)) / scale
ra, rb = json.load(open(a + '/solve.json')), json.load(open(b + '/solve.json'))
ca, cb = ra['contact'], rb['contact']
iterations = cb.get('cg_iterations', [])
print("%s: max |u_petsc - u_cholmod| / max |u| = %.3g (limit 1e-8); %d of %d nodes in contact, %d and %d solves; "
      "CG iterations %s" % (label, d, cb['active_points'], cb['points'], ca['solves'], cb['solves'], iterations))
assert len(u) == len(v) and d <= 1e-8, "u"
assert ca['active_points'] == cb['active_points'], "active points"
assert in_contact(a + '/p.mtx') == in_contact(b + '/p.mtx'), "the nodes in contact"
assert set(cb) == set(ca) | {'cg_iterations'}, "report keys"
assert ('friction' in ra) == ('friction' in rb), "friction keys"
if 'friction' in ra:
    assert set(ra['friction']) == set(rb['friction'])
    assert (ra['friction']['stick_points'], ra['friction']['slip_points']) == \
           (rb['friction']['stick_points'], rb['friction']['slip_points']), "stick and slip"
assert rb['backend'] == 'petsc' and len(iterations) == cb['solves'], "PETSc's solves"
assert max(iterations) <= 2 * iterations[0], "the penalty made CG slower"
if len(sys.argv) > 4:  # the uncut field u = e x
    e = float(sys.argv[4])
    xyz = vector(a + '/system/coordinates.mtx')
    worst = max(abs(v[k] - e * xyz[k]) for k in range(len(xyz)))
    print("   max |u_petsc - e x| / max |u| = %.3g (limit 1e-7)" % (worst / scale))
    assert worst <= 1e-7 * scale
PY
}
solve() {  # solve <dir> <system> [options]: u.mtx, solve.json, p.mtx in <dir>
  local dir=$1 system=$2; shift 2
  mkdir -p "$dir" && ln -sfn "$PWD/$system" "$dir/system"
  "$B/xfem-solve" -q "$system" -o "$dir/u.mtx" --report "$dir/solve.json" --contact-pressure "$dir/p.mtx" "$@" \
    || fail "xfem-solve $dir $*"
}

# 1. The plane crack pressed closed (e2e.contact_closed's hydrostatic field u = e x on every face).
"$B/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size 0.005 -o beam.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --corner 0.0075 0.0125 0.1 --edge1 0.015 0 0 --edge2 0 0.035 0 -o plane.vtp || fail "cut"
cat > hydro.json <<'EOF'
{"material": {"E": 300e3, "nu": 0.35}, "contact": true, "dirichlet": [
  {"selector": {"boundary": true}, "exact": {"linear": {"gradient": [[-0.005,0,0],[0,-0.005,0],[0,0,-0.005]]}}}]}
EOF
"$B/xfem-classify" -q beam.vtu --cut plane.vtp -o classified.vtu 2>/dev/null || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-assemble" -q enriched.vtu --cut plane.vtp --problem hydro.json --format mtx -o closed || fail "assemble"
solve closed-cholmod closed
solve closed-petsc closed --backend petsc --rtol 1e-12
compare "plane crack pressed closed, PETSc on 1 process" closed-cholmod closed-petsc -0.005
solve closed-petsc2 closed --backend petsc --np 2 --rtol 1e-12
compare "plane crack pressed closed, PETSc on 2 processes" closed-cholmod closed-petsc2 -0.005
# From a binary system (xfem-assemble's default) too, every rank reading K whole for the iteration;
# --backend auto (the default) with --np 2 chooses PETSc.
"$B/xfem-assemble" -q enriched.vtu --cut plane.vtp --problem hydro.json -o closed-bin || fail "assemble binary"
solve closed-bin-petsc closed-bin --np 2 --rtol 1e-12
compare "plane crack pressed closed, binary system, auto backend on 2 processes" closed-cholmod closed-bin-petsc -0.005

# 2. The beam cut through and pulled (the golden X-FEM beam's inputs) with contact: the cut opens.
"$B/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size 0.02 -o open.vtu || fail "open mesh"
"$B/xfem-mesh" -q cut-rect --beam-cut -o open.vtp || fail "open cut"
"$B/xfem-classify" -q open.vtu --cut open.vtp -o open-classified.vtu 2>/dev/null || fail "open classify"
"$B/xfem-enrich" -q open-classified.vtu -o open-enriched.vtu || fail "open enrich"
python3 -c "
import json, sys
p = json.load(open(sys.argv[1])); p['contact'] = True; json.dump(p, open('open.json', 'w'))" "$S/pipelines/beam/problem.json"
"$B/xfem-assemble" -q open-enriched.vtu --cut open.vtp --problem open.json --format mtx -o opened 2>/dev/null || fail "open assemble"
solve opened-cholmod opened
solve opened-petsc opened --backend petsc --rtol 1e-12
compare "beam pulled open" opened-cholmod opened-petsc
python3 -c "import json, sys; c = json.load(open('opened-petsc/solve.json'))['contact']; sys.exit(c['solves'] != 1 or c['active_points'] != 0)" \
  || fail "the pulled beam's faces touch"

# 3. Friction: the inclined penny pressed shut, mu = 0.5 tan beta (every node slips).
D="$S/pipelines/verification/data"
"$B/xfem-mesh" -q box --cells 8 8 8 --hi 1 1 1 -o cube.vtu || fail "penny mesh"
"$B/xfem-mesh" -q cut-disc --center 0.5 0.5 0.47 --normal 0 0 1 --radius 0.3 --rings 16 -o disc.vtp || fail "disc"
"$B/xfem-classify" -q cube.vtu --cut disc.vtp --tip-radius 0.15 -o penny-classified.vtu || fail "penny classify"
"$B/xfem-enrich" -q penny-classified.vtu -o penny.vtu || fail "penny enrich"
python3 - "$D/penny_closed.json" > friction.json <<'PY' || fail "friction problem"
import json, sys
p = json.load(open(sys.argv[1]))
p["contact"] = {"friction": 0.5}
for d in p["dirichlet"]:
    d["exact"]["penny"]["friction"] = 0.5
print(json.dumps(p, indent=1))
PY
"$B/xfem-assemble" -q penny.vtu --cut disc.vtp --problem friction.json --format mtx -o friction || fail "friction assemble"
solve friction-cholmod friction
solve friction-petsc friction --backend petsc --rtol 1e-12
compare "inclined penny with friction" friction-cholmod friction-petsc

# 4. xfem-newton: the cube's square crack pressed closed and pulled open (e2e.newton_contact).
"$B/xfem-mesh" -q unstructured-box --hi 0.04 0.04 0.04 --size 0.005 -o box.vtu || fail "cube mesh"
"$B/xfem-mesh" -q cut-rect --corner 0.0075 0.0075 0.02 --edge1 0.025 0 0 --edge2 0 0.025 0 -o crack.vtp || fail "crack"
"$B/xfem-classify" -q box.vtu --cut crack.vtp -o box-classified.vtu 2>/dev/null || fail "cube classify"
"$B/xfem-enrich" -q box-classified.vtu -o box.enriched.vtu || fail "cube enrich"
cube_faces() { printf '{"selector": {"boundary": true}, %s}' "$1"; }  # the boundary, held at the JSON value $1
field() { echo "\"exact\": {\"linear\": {\"gradient\": [[$1,0,0],[0,$1,0],[0,0,$2]], \"translation\": [0,0,0]}}"; }
material='"material": {"E": 300e3, "nu": 0.35, "model": "neo-hookean"}'
printf '{%s, "load_steps": 2, "contact": true, "dirichlet": [%s]}\n' "$material" "$(cube_faces "$(field 0.02 -0.08)")" > pressed.json
printf '{%s, "load_steps": 2, "contact": true, "dirichlet": [%s]}\n' "$material" "$(cube_faces "$(field -0.02 0.08)")" > pulled.json
newton() {  # newton <dir> <problem> [options]
  local dir=$1 problem=$2; shift 2
  mkdir -p "$dir"
  "$B/xfem-newton" -q box.enriched.vtu --cut crack.vtp --problem "$problem" -o "$dir/u.mtx" --reactions "$dir/r.mtx" \
    --report "$dir/newton.json" --contact-pressure "$dir/p.mtx" "$@" || fail "xfem-newton $dir $*"
}
newton pressed-cholmod pressed.json
newton pressed-petsc pressed.json --backend petsc --np 1 --cg-rtol 1e-12
newton pressed-petsc2 pressed.json --backend petsc --np 2 --cg-rtol 1e-12
newton pulled-cholmod pulled.json
newton pulled-petsc pulled.json --backend petsc --np 1 --cg-rtol 1e-12
python3 - <<'PY' || fail "xfem-newton: PETSc differs from CHOLMOD"
import json
def vector(path):
    return [float(l.split()[-1]) for l in open(path) if not l.startswith('%')][1:]
def in_contact(path):
    rows = [l.split() for l in open(path) if not l.startswith('%')][1:]
    return {(r[0], r[1]) for r in rows if float(r[2]) > 0}
def per_solve(r):  # CG iterations per linear solve
    return sum(s['linear_iterations'] for s in r['steps']) / sum(s['factorizations'] for s in r['steps'])
cost = {}
for case, petsc in (('pressed', 'pressed-petsc'), ('pressed', 'pressed-petsc2'), ('pulled', 'pulled-petsc')):
    a, b = case + '-cholmod', petsc
    d = {}
    for what in ('u', 'r'):
        x, y = vector(a + '/' + what + '.mtx'), vector(b + '/' + what + '.mtx')
        d[what] = max(abs(p - q) for p, q in zip(x, y)) / max(abs(p) for p in x)
    ra, rb = json.load(open(a + '/newton.json')), json.load(open(b + '/newton.json'))
    ca, cb = ra['contact'], rb['contact']
    cost[petsc] = per_solve(rb)
    print("xfem-newton %s: u %.3g, reactions %.3g of their max (limit 1e-8); %d of %d nodes in contact; %.0f CG "
          "iterations per solve" % (petsc, d['u'], d['r'], cb['active_points'], cb['points'], cost[petsc]))
    assert d['u'] <= 1e-8 and d['r'] <= 1e-8
    assert rb['backend'] == 'petsc' and set(ca) == set(cb) and ca['active_points'] == cb['active_points']
    assert in_contact(a + '/p.mtx') == in_contact(b + '/p.mtx')
    assert (ca['active_points'] > 0) == (case == 'pressed')
# The contact's penalty (pressed) against none active (pulled): CG per solve at most twice.
assert cost['pressed-petsc'] <= 2 * cost['pulled-petsc'], "the penalty made CG slower"
PY

# Bad input, one line and nothing written: friction in xfem-newton (frictionless only, on either
# backend), an unknown --enriched-block.
sed 's/"contact": true/"contact": {"friction": 0.3}/' pressed.json > newton-friction.json
"$B/xfem-newton" -q box.enriched.vtu --cut crack.vtp --problem newton-friction.json -o bad.mtx --backend petsc --np 1 2> err \
  && fail "xfem-newton accepted friction"
[ "$(wc -l < err)" -eq 1 ] && grep -q "^xfem-newton: error: newton-friction.json: xfem-newton solves frictionless contact" err \
  || fail "message: $(cat err)"
[ ! -e bad.mtx ] || fail "output left behind"
"$B/xfem-newton" -q box.enriched.vtu --cut crack.vtp --problem pressed.json -o bad.mtx --backend petsc \
  --enriched-block bogus 2> err && fail "xfem-newton accepted --enriched-block bogus"
[ "$(wc -l < err)" -eq 1 ] && grep -q "^xfem-newton: usage error: --enriched-block: bogus not in {auto,direct,gamg}" err \
  || fail "message: $(cat err)"
[ ! -e bad.mtx ] || fail "output left behind"
echo "PASS"
cd / && rm -rf "$XFEM_SCRATCH"
