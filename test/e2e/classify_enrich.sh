#!/usr/bin/env bash
# xfem-classify and xfem-enrich: CLI contract, the beam pipeline's first two stages (counts,
# determinism), and each bad input refused with one error line and no output file.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
C=$XFEM_BIN/xfem-classify; E=$XFEM_BIN/xfem-enrich; M=$XFEM_BIN/xfem-mesh
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error <text> <output> <command...>: exit 1, one "error:" line with <text>, no output
  local text=$1 out=$2; shift 2
  rm -f "$out"
  "$@" 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $*: $(cat err.txt)"
  [ "$(grep -c 'error:' err.txt)" -eq 1 ] || fail "expected one error: line for $*: $(cat err.txt)"
  grep -qF -- "$text" err.txt || fail "expected '$text' for $*, got: $(cat err.txt)"
  [ ! -e "$out" ] || fail "output left behind for $*"
}
json() { sed -n "s/.*\"$1\": *\([0-9.]*\).*/\1/p" "$2"; }

for t in "$C" "$E"; do
  "$t" --help >/dev/null || fail "$t --help"
  "$t" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "$t: bad flag must exit 2"
done
"$M" -q box --cells 3 6 19 --hi 0.03 0.06 0.2 -o beam.vtu || fail "xfem-mesh box"
"$M" -q cut-rect --beam-cut -o cut.vtp || fail "xfem-mesh cut-rect"
"$C" beam.vtu --cut cut.vtp -o x.vtu --tip-radius -1 2>/dev/null; [ $? -eq 2 ] || fail "negative --tip-radius must exit 2"

# The beam: completely cut tets, both enrichments, a front; N = NP + NS + 4 NB. (On this grid the
# front x = 0.015, z = 0.1 lies in Kuhn faces: it touches tets, whose nodes are branch enriched,
# without passing through any: no tet is partially cut, docs/CLASSIFICATION.md.)
"$C" -q beam.vtu --cut cut.vtp -o classified.vtu --summary counts.json || fail "classify"
[ "$(json points counts.json)" -eq 560 ] || fail "points: $(cat counts.json)"
[ "$(json branch counts.json)" -gt 0 ] && [ "$(json complete counts.json)" -gt 0 ] || fail "no cut tets"
[ "$(json sign counts.json)" -gt 0 ] && [ "$(json branch counts.json)" -gt 0 ] || fail "no enriched nodes"
[ "$(json front_segments counts.json)" -ge 1 ] || fail "no front"
"$C" beam.vtu --cut cut.vtp -o classified2.vtu -v 2>log.txt || fail "classify -v"
grep -q "partial [0-9]*, complete" log.txt || fail "-v shows no counts: $(cat log.txt)"
cmp -s classified.vtu classified2.vtu || fail "classify is not deterministic"
"$E" classified.vtu -o enriched.vtu 2>log.txt || fail "enrich"
np=$(json points counts.json); ns=$(json sign counts.json); nb=$(json branch counts.json)
grep -q "NP $np, NS $ns, NB $nb: N = $((np + ns + 4 * nb)) displacements" log.txt || fail "enrich counts: $(cat log.txt)"
"$E" -q classified.vtu -o enriched2.vtu && cmp -s enriched.vtu enriched2.vtu || fail "enrich is not deterministic"

# A cut that misses the body: nothing enriched, N = NP.
"$M" -q cut-rect --corner 0 0 0.5 --edge1 0.1 0 0 --edge2 0 0.1 0 -o far.vtp || fail "far cut"
"$C" -q beam.vtu --cut far.vtp -o far_c.vtu --summary far.json 2>/dev/null || fail "classify far"
[ "$(json cut_edges far.json)" -eq 0 ] || fail "far cut meets edges"
"$E" far_c.vtu -o far_e.vtu 2>log.txt && grep -q "N = 560 displacements" log.txt || fail "N != NP: $(cat log.txt)"

# No cut (a cut-aligned mesh with doubled nodes): everything uncut, N = NP.
"$C" -q beam.vtu -o plain_c.vtu --summary plain.json || fail "classify without a cut"
[ "$(json uncut plain.json)" -eq "$(json tets plain.json)" ] || fail "without a cut not all uncut"
"$E" plain_c.vtu -o plain_e.vtu 2>log.txt && grep -q "N = 560 displacements" log.txt || fail "no cut: $(cat log.txt)"

# Bad inputs.
cat >hex.vtk <<'VTK'
# vtk DataFile Version 3.0
hex
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 8 double
0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1
CELLS 1 9
8 0 1 2 3 4 5 6 7
CELL_TYPES 1
12
VTK
cat >quad.vtk <<'VTK'
# vtk DataFile Version 3.0
quad
ASCII
DATASET POLYDATA
POINTS 4 double
0 0 0.1 1 0 0.1 1 1 0.1 0 1 0.1
POLYGONS 1 5
4 0 1 2 3
VTK
expect_error "hex.vtk" out.vtu "$C" hex.vtk --cut cut.vtp -o out.vtu
expect_error "quad.vtk" out.vtu "$C" beam.vtu --cut quad.vtk -o out.vtu
expect_error "missing.vtu" out.vtu "$C" missing.vtu --cut cut.vtp -o out.vtu
expect_error "beam.vtu: point array 'enrichment' missing (is this xfem-classify output?)" out.vtu "$E" beam.vtu -o out.vtu
expect_error "cut.vtp" out.vtu "$E" cut.vtp -o out.vtu
exit 0
