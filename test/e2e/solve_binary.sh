#!/usr/bin/env bash
# The binary system format end to end: xfem-assemble writes K.petsc, CHOLMOD and PETSc read it;
# PETSc loads it in parallel (each rank its rows) and agrees on 1 and 2 ranks; xfem-solve starts
# itself under mpirun (--np); the automatic backend; each damaged file refused in one line.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; SOLVE=$B/xfem-solve; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }
json() { sed -n "s/.*\"$1\": *\"\{0,1\}\([^,\"]*\).*/\1/p" "$2"; }
maxdiff() { paste <(grep -v '^%' "$1" | tail -n +2) <(grep -v '^%' "$2" | tail -n +2) | awk '{d=$1-$2; if(d<0)d=-d; if(d>m)m=d} END{printf "%.3g\n", m+0}'; }
expect_error() {  # expect_error <text> <system dir> [args]: exit 1, one error line naming the problem, no output
  local text=$1 dir=$2; shift 2
  rm -f "$S/bad.mtx"
  "$SOLVE" "$dir" -o "$S/bad.mtx" "$@" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $dir $*: $(cat "$S/err.txt")"
  [ "$(grep -c "error:" "$S/err.txt")" -eq 1 ] || fail "expected one error line for $dir $*: $(cat "$S/err.txt")"
  grep -qF -- "$text" "$S/err.txt" || fail "expected '$text' for $dir $*, got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad.mtx" ] || fail "output left behind for $dir $*"
}

# A cut beam on a 3 x 5 x 13 grid (enriched DOFs: the field split on the PETSc side).
"$B/xfem-mesh" -q box --cells 3 5 13 --hi 0.03 0.06 0.2 -o "$S/beam.vtu" || fail "xfem-mesh box"
"$B/xfem-mesh" -q cut-rect --beam-cut -o "$S/cut.vtp" || fail "xfem-mesh cut-rect"
"$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/classified.vtu" || fail "xfem-classify"
"$B/xfem-enrich" -q "$S/classified.vtu" -o "$S/enriched.vtu" || fail "xfem-enrich"
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/sys" || fail "assemble"
grep -q '"format": "petsc"' "$S/sys/system.json" || fail "default format is not petsc: $(cat "$S/sys/system.json")"

# Automatic backend: a small system goes to CHOLMOD.
"$SOLVE" -q "$S/sys" -o "$S/u.mtx" --report "$S/auto.json" --reactions "$S/r.mtx" || fail "auto solve"
[ "$(json backend "$S/auto.json")" = cholmod ] || fail "small system: auto picked $(json backend "$S/auto.json")"

if "$SOLVE" --version | grep -q petsc; then
  # PETSc on 1 rank, then --np 2 (xfem-solve starts itself under mpirun; each rank loads its rows).
  "$SOLVE" -q "$S/sys" -o "$S/u1.mtx" --backend petsc --np 1 --rtol 1e-10 --report "$S/p1.json" \
    --reactions "$S/r1.mtx" || fail "petsc 1"
  # The reactions from the rows of the constrained DOFs alone (PETSc path) = CHOLMOD's from the whole K.
  d=$(maxdiff "$S/r.mtx" "$S/r1.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-6)}' || fail "reactions CHOLMOD vs PETSc: $d N"
  awk '!/^%/ && NF == 1 && $1 != 0 {n++} END {exit !(n > 0)}' "$S/r1.mtx" || fail "PETSc reactions are all zero"
  [ "$(json processes "$S/p1.json")" = 1 ] || fail "--np 1: $(json processes "$S/p1.json") processes"
  if command -v mpirun >/dev/null; then
    "$SOLVE" -q "$S/sys" -o "$S/u2.mtx" --np 2 --rtol 1e-10 --report "$S/p2.json" 2>"$S/err2.txt" ||
      fail "--np 2: $(cat "$S/err2.txt")"
    [ "$(json processes "$S/p2.json")" = 2 ] || fail "--np 2 ran on $(json processes "$S/p2.json") processes"
    [ "$(json backend "$S/p2.json")" = petsc ] || fail "--np 2 must mean PETSc"
    # 1 and 2 ranks and CHOLMOD agree to 1e-7 of the pulled displacement (0.02 m) at rtol 1e-10.
    d=$(maxdiff "$S/u1.mtx" "$S/u2.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-7 * 0.02)}' || fail "1 vs 2 ranks: $d"
    d=$(maxdiff "$S/u.mtx" "$S/u2.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-7 * 0.02)}' || fail "CHOLMOD vs 2 ranks: $d"
    # the same through an explicit mpirun (no second start)
    mpirun --allow-run-as-root --oversubscribe -np 2 "$SOLVE" -q "$S/sys" -o "$S/u3.mtx" --backend petsc --np 2 \
      --rtol 1e-10 --report "$S/p3.json" || fail "explicit mpirun"
    [ "$(json processes "$S/p3.json")" = 2 ] || fail "explicit mpirun: $(json processes "$S/p3.json") processes"
    # -v prints the options once, not once more per process started under mpirun.
    "$SOLVE" -v "$S/sys" -o "$S/u4.mtx" --np 2 --rtol 1e-10 2>"$S/err4.txt" || fail "--np 2 -v: $(cat "$S/err4.txt")"
    [ "$(grep -c 'options:' "$S/err4.txt")" = 1 ] || fail "--np 2 -v printed the options $(grep -c 'options:' "$S/err4.txt") times"
  else
    echo "SKIP --np 2: no mpirun"
  fi
  d=$(maxdiff "$S/u.mtx" "$S/u1.mtx"); awk -v d="$d" 'BEGIN{exit !(d < 1e-7 * 0.02)}' || fail "CHOLMOD vs PETSc: $d"
fi

# Damaged systems: each refused by both backends with the file and what is wrong.
damage() {  # damage <name> <command on $S/<name>/K.petsc>
  rm -rf "${S:?}/$1"; cp -r "$S/sys" "$S/$1"; eval "$2"
}
backends="cholmod"
"$SOLVE" --version | grep -q petsc && backends="cholmod petsc"
K=$S/sys/K.petsc; size=$(stat -c %s "$K")
damage trunc 'head -c $((size - 5)) "$K" >"$S/trunc/K.petsc"'
damage classid 'cp "$S/sys/f.petsc" "$S/classid/K.petsc"'
damage trailing 'cat "$K" <(printf x) >"$S/trailing/K.petsc"'
# +inf as the first value (after the 16-byte header, 4 bytes per row and per non-zero).
rows=$(od -An -tu1 -j4 -N4 "$K" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
nnz=$(od -An -tu1 -j12 -N4 "$K" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
damage inf 'cp "$K" "$S/inf/K.petsc"; printf "\x7f\xf0\0\0\0\0\0\0" | dd of="$S/inf/K.petsc" bs=1 seek=$((16 + 4*rows + 4*nnz)) conv=notrunc status=none; python3 "$XFEM_SOURCE/test/e2e/remanifest.py" "$S/inf"'
# (remanifested: the readers' own finiteness checks are what this case tests; the manifest's is solve.sh's)
for b in $backends; do
  expect_error "trunc/K.petsc: $((size - 5)) bytes, but its header" "$S/trunc" --backend $b --np 1
  expect_error "(truncated?)" "$S/trunc" --backend $b --np 1
  expect_error "classid/K.petsc: class id 1211214, expected 1211216" "$S/classid" --backend $b --np 1
  expect_error "(trailing bytes)" "$S/trailing" --backend $b --np 1
  expect_error "inf/K.petsc:" "$S/inf" --backend $b --np 1
  grep -Eq "not finite|non-finite value" "$S/err.txt" || fail "$b: +inf in K: $(cat "$S/err.txt")"
done
# Through the start under mpirun: still one error line (not one per rank, no mpirun banner).
if "$SOLVE" --version | grep -q petsc && command -v mpirun >/dev/null; then
  expect_error "trunc/K.petsc: $((size - 5)) bytes, but its header" "$S/trunc" --np 2
  expect_error "inf/K.petsc: K holds a non-finite value" "$S/inf" --np 2
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] || fail "--np 2: more than the error line: $(cat "$S/err.txt")"
fi

# An incomplete directory (no system.json: an interrupted xfem-assemble) is refused.
rm -rf "$S/partial"; cp -r "$S/sys" "$S/partial"; rm "$S/partial/system.json"
expect_error "xfem-solve: error: $S/partial: no system.json" "$S/partial"
# Start-up: the tools link neither PETSc/MPI nor gmsh (loaded only when used); the PETSc backend is
# xfem-solve-petsc next to xfem-solve, and without it --backend petsc is one error line.
if command -v readelf >/dev/null; then
  for t in xfem-solve xfem-classify xfem-enrich xfem-assemble xfem-visualize xfem-mesh; do
    libs=$(readelf -d "$B/$t" | grep NEEDED | grep -E 'petsc|libmpi|gmsh')
    [ -z "$libs" ] || fail "$t links what it should load only when used: $libs"
  done
fi
if "$SOLVE" --version | grep -q petsc; then
  mkdir -p "$S/lone" && cp "$SOLVE" "$S/lone/"
  SOLVE=$S/lone/xfem-solve expect_error "xfem-solve-petsc, which is missing" "$S/sys" --backend petsc
  SOLVE=$S/lone/xfem-solve expect_error "xfem-solve-petsc, which is missing" "$S/sys" --np 2
fi
rm -rf "$S"
echo "solve_binary e2e: ok"
