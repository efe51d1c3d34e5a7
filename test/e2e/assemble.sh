#!/usr/bin/env bash
# xfem-assemble: CLI contract, bad problem files (one error line each), the beam benchmark on a small
# structured mesh not aligned to the cut (deterministic output, a solvable system).
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; ASSEMBLE=$B/xfem-assemble; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }

"$ASSEMBLE" --help >/dev/null || fail "--help"
"$ASSEMBLE" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"

# Inputs: 3 x 5 x 13 cubes, so that no node lies on the cut z = 0.1 or its front x = 0.015.
"$B/xfem-mesh" -q box --cells 3 5 13 --hi 0.03 0.06 0.2 -o "$S/beam.vtu" || fail "xfem-mesh box"
"$B/xfem-mesh" -q cut-rect --beam-cut -o "$S/cut.vtp" || fail "xfem-mesh cut-rect"
"$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/classified.vtu" || fail "xfem-classify"
"$B/xfem-enrich" -q "$S/classified.vtu" -o "$S/enriched.vtu" || fail "xfem-enrich"

expect_error() {  # expect_error <text> <problem.json>: exit 1, one "error:" line with <text>, no output
  rm -rf "$S/bad"
  "$ASSEMBLE" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$2" -o "$S/bad" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $2: $(cat "$S/err.txt")"
  [ "$(grep -c "error:" "$S/err.txt")" -eq 1 ] || fail "expected one error line for $2: $(cat "$S/err.txt")"
  grep -qF -- "$1" "$S/err.txt" || fail "expected '$1' for $2, got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad" ] || fail "output left behind for $2"
}
bad() {  # bad <name> <sed expression on the beam problem>
  sed "$2" "$PROBLEM" >"$S/$1.json"
}
bad missing_e 's/"E": 300e3, //';            expect_error "missing field 'material.E'" "$S/missing_e.json"
bad negative_e 's/"E": 300e3/"E": -1/';      expect_error "material.E must be positive, got -1" "$S/negative_e.json"
bad nu 's/"nu": 0.35/"nu": 0.5/';            expect_error "material.nu must lie in (-1, 0.5), got 0.5" "$S/nu.json"
bad unknown 's/"dirichlet"/"dirichlett"/'; expect_error "unknown key 'dirichlett'" "$S/unknown.json"
bad empty 's/"point": \[0, 0, 0.199\]/"point": [0, 0, 0.2]/'
expect_error "empty.json: dirichlet[1] ('pulled edge z > 0.199, x < 0.001') selects no node" "$S/empty.json"
expect_error "cannot open" "$S/no_such_problem.json"
# K u = f is the small-strain model's: another material.model is refused (xfem-newton solves it).
bad neo 's/"nu": 0.35}/"nu": 0.35, "model": "neo-hookean"}/'
expect_error "neo.json: xfem-assemble writes the linear system of the small-strain model: material.model \"neo-hookean\" is not supported (use \"linear\"; xfem-newton solves \"neo-hookean\")" "$S/neo.json"
rm -rf "$S/bad"
"$ASSEMBLE" "$S/no_such.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/bad" 2>"$S/err.txt"
[ $? -eq 1 ] && grep -q "error:" "$S/err.txt" && [ ! -e "$S/bad" ] || fail "missing mesh must exit 1"
"$ASSEMBLE" "$S/beam.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/bad" 2>"$S/err.txt"
[ $? -eq 1 ] && grep -q "error:" "$S/err.txt" && [ ! -e "$S/bad" ] || fail "an unenriched mesh must exit 1"

# The beam: every file present, counts consistent, same bytes twice, and xfem-solve solves it.
"$ASSEMBLE" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/system" 2>"$S/log.txt" \
  || fail "assemble: $(cat "$S/log.txt")"
for f in K.petsc f.petsc coordinates.petsc dirichlet.mtx system.json; do [ -s "$S/system/$f" ] || fail "system/$f missing"; done
grep -q "3N = " "$S/log.txt" || fail "no N / 3N report on stderr"
grep -q '"ns": [1-9]' "$S/system/system.json" || fail "expected sign-enriched nodes: $(cat "$S/system/system.json")"
grep -q '"nb": [1-9]' "$S/system/system.json" || fail "expected branch-enriched nodes"
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/again" || fail "second run"
for f in K.petsc f.petsc coordinates.petsc dirichlet.mtx system.json; do cmp -s "$S/system/$f" "$S/again/$f" || fail "$f differs between runs"; done
# Fixed face: 4 x 6 nodes x 3 components; pulled edge: 6 nodes x 3 components.
head -3 "$S/system/dirichlet.mtx" | grep -q " 1 90$" || fail "expected 90 fixed DOFs: $(head -3 "$S/system/dirichlet.mtx")"
"$B/xfem-solve" -q "$S/system" -o "$S/u.mtx" || fail "xfem-solve on the assembled beam"
# --points changes the rule (64 -> 125 points in the cut tets), so K changes.
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --points 100 -o "$S/p100" || fail "--points"
! cmp -s "$S/system/K.petsc" "$S/p100/K.petsc" || fail "--points 100 gave the same K"
# --format mtx: the same system as Matrix Market text (scipy), solved to the same bits by CHOLMOD.
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --format mtx -o "$S/mtx" || fail "--format mtx"
for f in K.mtx f.mtx coordinates.mtx dirichlet.mtx system.json; do [ -s "$S/mtx/$f" ] || fail "mtx/$f missing"; done
[ ! -e "$S/mtx/K.petsc" ] || fail "--format mtx wrote K.petsc"
grep -q '"format": "matrix-market"' "$S/mtx/system.json" || fail "format not recorded: $(cat "$S/mtx/system.json")"
"$B/xfem-solve" -q "$S/mtx" -o "$S/u_mtx.mtx" --backend cholmod || fail "xfem-solve on the mtx system"
cmp -s "$S/u.mtx" "$S/u_mtx.mtx" || fail "binary and Matrix Market systems give different solutions"
# Replacing a system: the old files go (no stale K.mtx next to K.petsc) ...
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/mtx" || fail "overwrite mtx by petsc"
[ -s "$S/mtx/K.petsc" ] && [ ! -e "$S/mtx/K.mtx" ] || fail "replaced system: $(ls "$S/mtx")"
# ... a failed run leaves the old system as it was ...
cp -r "$S/mtx" "$S/mtx_before"
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/nu.json" -o "$S/mtx" 2>/dev/null && fail "bad nu accepted"
diff -r "$S/mtx" "$S/mtx_before" >/dev/null || fail "a failed run changed the old system"
ls -a "$S" | grep -q '^\.mtx\.tmp' && fail "a temporary directory was left behind: $(ls -a "$S")"
# ... and a directory holding other files is not replaced.
mkdir -p "$S/mine"; echo notes >"$S/mine/notes.txt"
"$ASSEMBLE" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/mine" 2>"$S/err.txt" && fail "replaced a foreign directory"
grep -q "xfem-assemble: error: $S/mine: exists and holds notes.txt, which is not part of a system directory" "$S/err.txt" ||
  fail "foreign directory message: $(cat "$S/err.txt")"
[ -s "$S/mine/notes.txt" ] || fail "notes.txt lost"
echo "ok"
