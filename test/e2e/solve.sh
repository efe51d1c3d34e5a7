#!/usr/bin/env bash
# xfem-solve: CLI contract, CHOLMOD residual, exact Dirichlet values, PETSc (1 and 2 MPI ranks)
# agreeing with CHOLMOD, and each singular case refused with its message.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
SOLVE=$XFEM_BIN/xfem-solve; DATA=$XFEM_SOURCE/test/data/solve
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error <text> <args...>: exit 1, "error:" and <text> on stderr, no output file
  local text=$1; shift
  rm -f "$S/bad.mtx"
  "$SOLVE" "$@" -o "$S/bad.mtx" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $*: $(cat "$S/err.txt")"
  grep -q "error:" "$S/err.txt" || fail "no error: line for $*"
  grep -qF -- "$text" "$S/err.txt" || fail "expected '$text' for $*, got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad.mtx" ] || fail "output left behind for $*"
}
maxdiff() { paste <(tail -n +3 "$1") <(tail -n +3 "$2") | awk '{d=$1-$2; if(d<0)d=-d; if(d>m)m=d} END{printf "%.3g\n", m+0}'; }
remanifest() { python3 "$XFEM_SOURCE/test/e2e/remanifest.py" "$1" || fail "remanifest $1"; }  # after a deliberate edit

"$SOLVE" --help >/dev/null || fail "--help"
"$SOLVE" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"
"$SOLVE" "$DATA/beam_1x2x4" -o "$S/u.mtx" --backend nonsense 2>/dev/null; [ $? -eq 2 ] || fail "bad backend must exit 2"

# Bad inputs.
expect_error "no such directory" "$S/missing"
mkdir -p "$S/empty"; expect_error "$S/empty: no system.json, the marker xfem-assemble writes last: the directory is incomplete" "$S/empty"
cp -r "$DATA/beam_1x2x4" "$S/short_f"; printf '%%%%MatrixMarket matrix array real general\n2 1\n0\n0\n' >"$S/short_f/f.mtx"
expect_error "f.mtx: 2 rows, expected 3N = 90" "$S/short_f"

# CHOLMOD: residual below 1e-10, Dirichlet values exact (the pulled edge at 0.02, the fixed face 0).
"$SOLVE" -q "$DATA/beam_1x2x4" -o "$S/u.mtx" --report "$S/solve.json" || fail "cholmod solve"
res=$(sed -n 's/.*"relative_residual": *\([^,]*\).*/\1/p' "$S/solve.json")
awk -v r="$res" 'BEGIN{exit !(r < 1e-10)}' || fail "CHOLMOD residual $res >= 1e-10"
tail -n +4 "$DATA/beam_1x2x4/dirichlet.mtx" >"$S/fixed.txt"
awk 'NR==FNR{want[$1]=$3; next} FNR>2 && ((FNR-2) in want) && $1+0 != want[FNR-2]+0 {print "DOF " FNR-2 ": " $1 " != " want[FNR-2]; bad=1} END{exit bad}' \
  "$S/fixed.txt" "$S/u.mtx" || fail "Dirichlet values not exact"
grep -c '^0.02$' "$S/u.mtx" | grep -qx 3 || fail "expected the 3 pulled-edge nodes (x = 0, z = 0.2) at exactly 0.02"

# Singular cases.
cp -r "$DATA/beam_1x2x4" "$S/free"; printf '%%%%MatrixMarket matrix coordinate real general\n90 1 0\n' >"$S/free/dirichlet.mtx"; remanifest "$S/free"
expect_error "no Dirichlet condition" "$S/free"
cp -r "$DATA/beam_1x2x4" "$S/loose"
sed -i '/"pieces"/,$d' "$S/loose/system.json"
printf '  "pieces": [{"tets": 48, "constrained": true}, {"tets": 1234, "constrained": false}]\n}\n' >>"$S/loose/system.json"; remanifest "$S/loose"
expect_error "the body falls apart into 2 pieces; piece 2 (1234 tets) has no Dirichlet condition" "$S/loose"
cp -r "$DATA/beam_1x2x4" "$S/onenode"; printf '%%%%MatrixMarket matrix coordinate real general\n90 1 3\n1 1 0\n2 1 0\n3 1 0\n' >"$S/onenode/dirichlet.mtx"; remanifest "$S/onenode"
expect_error "K is not positive definite at DOF" "$S/onenode"
"$SOLVE" "$DATA/beam_1x2x4_tiny" -o "$S/u_tiny.mtx" 2>"$S/err.txt" || fail "tiny support must still solve"
grep -q "warning: 3 enriched DOFs have a diagonal below" "$S/err.txt" || fail "no tiny-support warning: $(cat "$S/err.txt")"
"$SOLVE" "$DATA/beam_1x2x4_tiny" -o "$S/u_drop.mtx" --drop-tiny-enrichment 1e-6 2>"$S/err.txt" || fail "drop"
grep -q "dropped 3 enriched DOFs" "$S/err.txt" || fail "no drop message"
[ "$(tail -n 3 "$S/u_drop.mtx" | tr '\n' ' ')" = "0 0 0 " ] || fail "dropped DOFs must be 0"

# Exactly zero enriched rows (no support): eliminated without a flag, one warning, the rest of the
# solution unchanged (the zero DOF is absent from the energy, so u equals the beam_1x2x4 one).
cp -r "$DATA/beam_1x2x4_tiny" "$S/zero"
awk 'NR<=2 {print; next} $1>=91 || $2>=91 {print $1, $2, 0; next} {print}' "$DATA/beam_1x2x4_tiny/K.mtx" >"$S/zero/K.mtx"; remanifest "$S/zero"
"$SOLVE" "$S/zero" -o "$S/u_zero.mtx" --report "$S/zero.json" 2>"$S/err.txt" || fail "zero rows must solve: $(cat "$S/err.txt")"
[ "$(grep -c warning "$S/err.txt")" -eq 1 ] || fail "expected one warning line: $(cat "$S/err.txt")"
grep -qF "warning: 3 enriched DOFs (1 vector) have an exactly zero row in K (no support on one side of the cut): fixed to 0; first DOF 90 (vector 30, sign-enriched vector 0 of 1, component x)" \
  "$S/err.txt" || fail "zero-row warning: $(cat "$S/err.txt")"
grep -q '"unsupported_enriched_dofs": 3' "$S/zero.json" || fail "report must count the unsupported DOFs"
[ "$(tail -n 3 "$S/u_zero.mtx" | tr '\n' ' ')" = "0 0 0 " ] || fail "unsupported DOFs must be 0"
d=$(maxdiff <(head -n 92 "$S/u_zero.mtx") "$S/u.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-14)}' || fail "zero DOF changed the solution by $d"
# ... while a zero row on a free ORIGINAL DOF (1-based row 40) stays an error.
cp -r "$DATA/beam_1x2x4" "$S/zero_orig"
awk 'NR<=2 {print; next} $1==40 || $2==40 {print $1, $2, 0; next} {print}' "$DATA/beam_1x2x4/K.mtx" >"$S/zero_orig/K.mtx"; remanifest "$S/zero_orig"
expect_error "K has an exactly zero row at DOF 39 (vector 13, original, mesh point 13, component x)" "$S/zero_orig"

# Wrong-kind inputs: a mesh instead of the directory, a mesh renamed K.mtx.
printf '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid">\n</VTKFile>\n' >"$S/mesh.vtu"
expect_error "mesh.vtu: not a directory (expected the system directory written by xfem-assemble)" "$S/mesh.vtu"
cp -r "$DATA/beam_1x2x4" "$S/wrong_kind"; cp "$S/mesh.vtu" "$S/wrong_kind/K.mtx"
expect_error "K.mtx: not a Matrix Market file" "$S/wrong_kind"
grep -qF "(is this xfem-assemble output?)" "$S/err.txt" || fail "wrong-kind K.mtx: no hint: $(cat "$S/err.txt")"

# Files that no longer belong together (system.json's manifest, docs/FORMATS.md "system/"): the
# last prescribed value truncated (0.02 -> 0.0, still a valid file), K from another system of the
# same size, a directory written before manifests existed: each refused, naming the file.
cp -r "$DATA/beam_1x2x4" "$S/trunc_d"; sed -i '$ s/0\.02$/0.0/' "$S/trunc_d/dirichlet.mtx"
expect_error "trunc_d/dirichlet.mtx: 323 bytes, but system.json's manifest says 324" "$S/trunc_d"
cp -r "$DATA/beam_1x2x4" "$S/other_k"
awk 'NR > 2 && !done && $3 ~ /^[0-9]/ { $3 = "9" substr($3, 2); done = 1 } { print }' "$DATA/beam_1x2x4/K.mtx" >"$S/other_k/K.mtx"
cmp -s "$S/other_k/K.mtx" "$DATA/beam_1x2x4/K.mtx" && fail "other_k: K.mtx unchanged"
[ "$(stat -c %s "$S/other_k/K.mtx")" = "$(stat -c %s "$DATA/beam_1x2x4/K.mtx")" ] || fail "other_k: K.mtx changed size"
expect_error "other_k/K.mtx: content differs from system.json's manifest" "$S/other_k"
cp -r "$DATA/beam_1x2x4" "$S/old"; python3 -c 'import json, sys; p = sys.argv[1]; j = json.load(open(p)); del j["files"]; json.dump(j, open(p, "w"))' "$S/old/system.json"
expect_error "old/system.json: no manifest of the system's files" "$S/old"

# PETSc: agrees with CHOLMOD within its tolerance, on 1 and 2 MPI ranks.
if ! "$SOLVE" --version | grep -q petsc; then
  echo "SKIP PETSc part: xfem-solve was built without PETSc"; exit 0
fi
"$SOLVE" -q "$DATA/beam_1x2x4" -o "$S/u_petsc1.mtx" --backend petsc --rtol 1e-10 || fail "petsc 1 rank"
d=$(maxdiff "$S/u.mtx" "$S/u_petsc1.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-9 * 0.02 * 100)}' || fail "PETSc (1) differs by $d"
# A restart under mpirun that fails, or "succeeds" without writing u.mtx, is one error line with
# mpirun's exit status and the first meaningful line it printed (fake launchers first on PATH).
mkdir -p "$S/fake"
expect_launch() {  # expect_launch <text> <fake mpirun body>: --np 2 through that mpirun
  local text=$1; printf '#!/bin/sh\n%s\n' "$2" >"$S/fake/mpirun"; chmod +x "$S/fake/mpirun"
  rm -f "$S/bad.mtx"
  PATH="$S/fake:$PATH" "$SOLVE" "$DATA/beam_1x2x4" -o "$S/bad.mtx" --backend petsc --np 2 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "fake mpirun ($2): expected exit 1, got $rc: $(cat "$S/err.txt")"
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] || fail "fake mpirun ($2): expected one line: $(cat "$S/err.txt")"
  grep -q "^xfem-solve: error: " "$S/err.txt" && grep -qF -- "$text" "$S/err.txt" || fail "fake mpirun ($2): expected '$text', got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad.mtx" ] || fail "fake mpirun ($2): output left behind"
}
expect_launch "mpirun -np 2 xfem-solve-petsc exited 0 without writing $S/bad.mtx: it printed nothing" 'exit 0'
expect_launch "mpirun -np 2 xfem-solve-petsc failed (exit status 1), no output written: it printed nothing" 'exit 1'
expect_launch "mpirun -np 2 xfem-solve-petsc failed (killed by signal 9 (Killed)), no output written" 'kill -9 $$'
noise='printf -- "-----\\n\\nAt least one pair of MPI processes are unable to reach each other for\\nMPI communications.  This means\\n-----\\n" >&2; i=0; while [ $i -lt 35 ]; do echo "[vm:1] *** noise $i" >&2; i=$((i+1)); done; exit 1'
expect_launch 'xfem-solve-petsc failed (exit status 1), no output written: "At least one pair of MPI processes are unable to reach each other for MPI communications."' "$noise"
# ... while the PETSc program's own error line passes through as it is, with its exit status.
expect_launch "xfem-solve: error: K is wrong" 'echo "xfem-solve: error: K is wrong" >&2; echo "Open MPI noise" >&2; exit 1'
# Open MPI that cannot start (no PATH: no ssh, no orted) on one process: one line, or a solution.
rm -f "$S/bad.mtx"; env PATH= "$SOLVE" "$DATA/beam_1x2x4" -o "$S/bad.mtx" --backend petsc 2>"$S/err.txt"; rc=$?
if [ $rc -ne 0 ]; then
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] && grep -q "^xfem-solve: error: .*xfem-solve-petsc failed (exit status" "$S/err.txt" ||
    fail "PETSc without PATH: expected one error line, got $(wc -l <"$S/err.txt"): $(head -c 600 "$S/err.txt")"
  [ ! -e "$S/bad.mtx" ] || fail "PETSc without PATH: output left behind"
else
  [ -s "$S/bad.mtx" ] || fail "PETSc without PATH: exit 0 without u.mtx"
fi
if command -v mpirun >/dev/null; then
  # Ranks that cannot reach each other (only the "self" transport): one line, exit 1.
  rm -f "$S/bad.mtx"; OMPI_MCA_btl=self "$SOLVE" "$DATA/beam_1x2x4" -o "$S/bad.mtx" --backend petsc --np 2 2>"$S/err.txt"
  rc=$?; [ $rc -eq 1 ] || fail "btl=self: expected exit 1, got $rc"
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] && grep -q "^xfem-solve: error: mpirun -np 2 xfem-solve-petsc failed" "$S/err.txt" ||
    fail "btl=self: expected one error line: $(head -c 600 "$S/err.txt")"
  mpirun --allow-run-as-root --oversubscribe -np 2 "$SOLVE" -q "$DATA/beam_1x2x4" -o "$S/u_petsc2.mtx" --backend petsc \
    --rtol 1e-10 || fail "petsc 2 ranks"
  d=$(maxdiff "$S/u.mtx" "$S/u_petsc2.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-9 * 0.02 * 100)}' || fail "PETSc (2) differs by $d"
else
  echo "SKIP mpirun part: no mpirun"
fi
rm -rf "$S"
echo "solve e2e: ok"
