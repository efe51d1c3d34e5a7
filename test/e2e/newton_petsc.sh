#!/usr/bin/env bash
# xfem-newton --backend petsc: the linear solves on xfem-solve's PETSc backend (xfem-newton-petsc,
# on --np MPI processes under mpirun). The same answer as CHOLMOD (Newton's convergence test is on
# the true residual: the CG tolerance 1e-10 only limits each update); progress per load step; the
# backend in the report; xfem-solve's messages when mpirun is missing, fails or its ranks fail
# (one line, exit 1, no output).
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; NEWTON=$B/xfem-newton
fail() { echo "FAIL: $*"; exit 1; }
if [ ! -x "$B/xfem-newton-petsc" ]; then echo "SKIP: built without PETSc"; exit 0; fi

# The beam and its cut (original, sign and branch DOFs), pulled 10 % of its length: neo-Hookean,
# 2 load steps.
"$B/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size 0.012 -o beam.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp || fail "cut"
"$B/xfem-classify" -q beam.vtu --cut cut.vtp -o classified.vtu && "$B/xfem-enrich" -q classified.vtu -o enriched.vtu \
  || fail "classify, enrich"
python3 -c "import json; p=json.load(open('$XFEM_SOURCE/pipelines/beam/problem.json')); p['material']['model']='neo-hookean'; p['load_steps']=2; json.dump(p, open('nh.json','w'))"
run() { "$NEWTON" enriched.vtu --cut cut.vtp --problem nh.json "$@"; }
run -q -o u_cholmod.mtx --reactions r_cholmod.mtx --report cholmod.json || fail "cholmod"
compare() {  # compare <label> <suffix> <processes>: u and reactions against CHOLMOD's, the report's backend
  python3 - "$@" <<'PY' || fail "$1 differs from CHOLMOD"
import json, sys
label, suffix, processes = sys.argv[1], sys.argv[2], int(sys.argv[3])
def read(p): return [float(l.split()[-1]) for l in open(p) if not l.startswith('%')][1:]
for what in ('u', 'r'):
    x, y = read(f'{what}_{suffix}.mtx'), read(f'{what}_cholmod.mtx')
    d = max(abs(p - q) for p, q in zip(x, y)) / max(abs(q) for q in y)
    print(f"newton_petsc: {label}, {what}: max difference / max = {d:.2e} (limit 1e-8)")
    assert len(x) == len(y) and d <= 1e-8
r, c = json.load(open(f'{suffix}.json')), json.load(open('cholmod.json'))
assert c['backend'] == 'cholmod' and r['backend'] == 'petsc' and r['processes'] == processes, (r['backend'], r['processes'])
assert all(s['converged'] and s['linear_iterations'] > 0 for s in r['steps'])
assert all(s['linear_iterations'] == 0 for s in c['steps'])
assert r['steps'][-1]['relative_residuals'][-1] <= 1e-8
PY
}
run -o u_p1.mtx --reactions r_p1.mtx --report p1.json --backend petsc --np 1 2>p1.err || fail "petsc 1: $(cat p1.err)"
compare "PETSc, 1 process" p1 1
# Progress: the backend, then a line per load step with its CG iterations.
grep -q "linear solves: PETSc CG on 1 process" p1.err && [ "$(grep -c "PETSc solves (.* CG iterations)" p1.err)" -eq 2 ] \
  || fail "no progress per load step: $(cat p1.err)"
run -q -o q.mtx --backend petsc --np 1 2>q.err && [ ! -s q.err ] || fail "-q is not quiet: $(cat q.err)"

expect_error() {  # expect_error <label> <text> <env...> -- <args...>: exit 1, one line "xfem-newton: error: ...<text>", no u
  local label=$1 text=$2; shift 2
  local envs=(); while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  rm -f bad.mtx
  env "${envs[@]}" "$NEWTON" enriched.vtu --cut cut.vtp --problem nh.json -o bad.mtx "$@" 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "$label: expected exit 1, got $rc: $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$label: expected one line: $(head -c 800 err.txt)"
  grep -q "^xfem-newton: error: " err.txt && grep -qF -- "$text" err.txt || fail "$label: expected '$text', got: $(cat err.txt)"
  [ ! -e bad.mtx ] || fail "$label: output left behind"
}
# A restart under mpirun that fails, or "succeeds" without writing u.mtx (fake launchers first on PATH).
mkdir -p fake
launcher() { printf '#!/bin/sh\n%s\n' "$1" >fake/mpirun; chmod +x fake/mpirun; }
launcher 'exit 0'
expect_error "fake mpirun exit 0" "mpirun -np 2 xfem-newton-petsc exited 0 without writing bad.mtx: it printed nothing" \
  PATH="$S/fake:$PATH" -- --backend petsc --np 2
launcher 'exit 1'
expect_error "fake mpirun exit 1" "mpirun -np 2 xfem-newton-petsc failed (exit status 1), no output written: it printed nothing" \
  PATH="$S/fake:$PATH" -- --backend petsc --np 2
launcher 'kill -9 $$'
expect_error "fake mpirun killed" "mpirun -np 2 xfem-newton-petsc failed (killed by signal 9 (Killed)), no output written" \
  PATH="$S/fake:$PATH" -- --backend petsc --np 2
# ... while the PETSc program's own error line passes through as it is.
launcher 'echo "xfem-newton: error: the tangent is wrong" >&2; echo "Open MPI noise" >&2; exit 1'
expect_error "own error line" "xfem-newton: error: the tangent is wrong" PATH="$S/fake:$PATH" -- --backend petsc --np 2
# The PETSc program missing next to xfem-newton.
mkdir -p alone && cp "$NEWTON" alone/
rm -f bad.mtx; alone/xfem-newton enriched.vtu --cut cut.vtp --problem nh.json -o bad.mtx --backend petsc 2>err.txt
[ $? -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -qF "xfem-newton-petsc, which is missing: use --backend cholmod" err.txt \
  && [ ! -e bad.mtx ] || fail "missing xfem-newton-petsc: $(cat err.txt)"
# mpirun missing (an empty PATH): a warning and one process, as xfem-solve.
rm -f bad.mtx; env PATH= "$NEWTON" -q enriched.vtu --cut cut.vtp --problem nh.json -o bad.mtx --backend petsc --np 2 2>err.txt
rc=$?
if [ $rc -ne 0 ]; then  # Open MPI that cannot start at all without PATH: one line
  [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^xfem-newton: error: .*xfem-newton-petsc failed (exit status" err.txt ||
    fail "no mpirun: expected one error line: $(head -c 800 err.txt)"
  [ ! -e bad.mtx ] || fail "no mpirun: output left behind"
else
  [ -s bad.mtx ] || fail "no mpirun: exit 0 without u.mtx"
fi

if command -v mpirun >/dev/null; then
  run -q -o u_p2.mtx --reactions r_p2.mtx --report p2.json --backend petsc --np 2 || fail "petsc 2"
  compare "PETSc, 2 processes" p2 2
  # Under the user's own mpirun: each rank becomes xfem-newton-petsc, the same answer.
  rm -f u_p3.mtx r_p3.mtx p3.json
  mpirun --allow-run-as-root --oversubscribe -np 2 "$NEWTON" -q enriched.vtu --cut cut.vtp --problem nh.json \
    -o u_p3.mtx --reactions r_p3.mtx --report p3.json --backend petsc || fail "petsc under mpirun"
  compare "PETSc under the user's mpirun, 2 processes" p3 2
  # Ranks that cannot reach each other (only the "self" transport): one line, exit 1.
  expect_error "btl=self" "mpirun -np 2 xfem-newton-petsc failed" OMPI_MCA_btl=self -- --backend petsc --np 2
  # A failure every rank meets alike (Newton gives up: one iteration per step, the beam squashed):
  # rank 0's one line.
  python3 -c "import json; p=json.load(open('nh.json')); p['dirichlet'][1]['value']=[0,0,-0.18]; p['load_steps']=1; json.dump(p, open('squash.json','w'))"
  rm -f bad.mtx
  "$NEWTON" -q enriched.vtu --cut cut.vtp --problem squash.json -o bad.mtx --max-iterations 1 --backend petsc --np 2 2>err.txt
  [ $? -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^xfem-newton: error: Newton's method failed at load factor" err.txt \
    && [ ! -e bad.mtx ] || fail "Newton failure on 2 ranks: $(head -c 800 err.txt)"
else
  echo "SKIP mpirun part: no mpirun"
fi
rm -rf "$S"
echo "newton_petsc: ok"
