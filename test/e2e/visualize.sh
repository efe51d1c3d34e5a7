#!/usr/bin/env bash
# xfem-visualize: CLI contract, then the paper's beam (coarse, unstructured) through the whole
# pipeline: the cut opens (positive normal opening everywhere on it), outputs are deterministic,
# and a PNG is rendered under xvfb-run.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; VIS=$B/xfem-visualize; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error <text> <args...>: exit 1, "error:" and <text> on stderr, no output left
  local text=$1; shift
  rm -f "$S/bad.vtu" "$S/bad.vtp" "$S/bad.png"
  "$VIS" "$@" -o "$S/bad.vtu" --faces "$S/bad.vtp" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $*: $(cat "$S/err.txt")"
  grep -q "error:" "$S/err.txt" || fail "no error: line for $*"
  grep -qF -- "$text" "$S/err.txt" || fail "expected '$text' for $*, got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad.vtu" ] && [ ! -e "$S/bad.vtp" ] && [ ! -e "$S/bad.png" ] || fail "output left behind for $*"
}

"$VIS" --help >/dev/null || fail "--help"
"$VIS" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"
"$VIS" x.vtu --cut c.vtp --solution u.mtx --problem p.json -o "$S/d.vtu" --scale -1 2>/dev/null
[ $? -eq 2 ] || fail "negative --scale must exit 2"

# The beam of the paper, coarse: mesh, cut, classify, enrich, assemble, solve.
"$B/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size 0.01 -o "$S/beam.vtu" || fail "mesh"
"$B/xfem-mesh" -q cut-rect --beam-cut -o "$S/cut.vtp" || fail "cut"
"$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/classified.vtu" || fail "classify"
"$B/xfem-enrich" -q "$S/classified.vtu" -o "$S/enriched.vtu" || fail "enrich"
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/system" || fail "assemble"
"$B/xfem-solve" -q "$S/system" -o "$S/u.mtx" --reactions "$S/r.mtx" --drop-tiny-enrichment 1e-6 || fail "solve"

# Bad inputs: missing files, a mesh that is not xfem-enrich output, a solution of the wrong size,
# a picture without a display.
expect_error "missing.vtu" "$S/missing.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM"
expect_error "missing (is this" "$S/beam.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM"
printf '%%%%MatrixMarket matrix array real general\n3 1\n0\n0\n0\n' >"$S/short.mtx"
expect_error "3 values, expected 3N" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/short.mtx" --problem "$PROBLEM"
expect_error "problem" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$S/none.json"
expect_error "3 values, expected 3N" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" \
  --reactions "$S/short.mtx"
expect_error "need the cut surface" "$S/enriched.vtu" --solution "$S/u.mtx" --problem "$PROBLEM"
(unset DISPLAY; expect_error "xvfb-run" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" \
   --problem "$PROBLEM" --png "$S/bad.png") || exit 1

# The run: the cut opens, (u+ - u-) . n > 0 at every duplicated cut point; deterministic files.
run() {
  "$VIS" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" \
    -o "$S/$1.vtu" --faces "$S/$1.vtp" --reactions "$S/r.mtx" --paraview "$S/$1.py" 2>"$S/$1.log" ||
    fail "visualize: $(cat "$S/$1.log")"
}
run a; run b
cmp -s "$S/a.vtu" "$S/b.vtu" || fail "deformed.vtu differs between two runs"
cmp -s "$S/a.vtp" "$S/b.vtp" || fail "wound.vtp differs between two runs"
sed 's/b\.v/a.v/g; s/b\.py/a.py/g' "$S/b.py" | cmp -s "$S/a.py" - || fail "the ParaView script differs between two runs"
grep -q "WarpByVector" "$S/a.py" && grep -q "RescaleTransferFunction(0.0, top)" "$S/a.py" || fail "ParaView script: $(cat "$S/a.py")"
line=$(grep "cut opening" "$S/a.log") || fail "no cut opening reported: $(cat "$S/a.log")"
echo "$line"
min=$(echo "$line" | sed -n 's/.*min \([-0-9.e]*\) m.*/\1/p')
pairs=$(echo "$line" | sed -n 's/.* at \([0-9]*\) points.*/\1/p')
[ "${pairs:-0}" -gt 0 ] || fail "no duplicated cut points"
awk -v m="$min" 'BEGIN{exit !(m > 0)}' || fail "the cut does not open everywhere: min opening $min"
for a in displacement von_mises stress strain cut_class parent piece_side reaction; do
  grep -q "Name=\"$a\"" "$S/a.vtu" || fail "array $a missing in deformed.vtu"
done
# ParaView-friendly: one array per name (point and cell arrays apart), named tensor components.
[ "$(grep -a -o 'Name="[a-z_]*"' "$S/a.vtu" | sort | uniq -d)" = "" ] || fail "arrays sharing a name in deformed.vtu"
[ "$(grep -a -o 'ComponentName0="xx"' "$S/a.vtu" | wc -l)" -eq 2 ] || fail "strain and stress without component names"
grep -q 'Name="side"' "$S/a.vtp" || fail "array side missing in wound.vtp"
# --compression: zlib by default, LZ4 or none on request (the reader's bitwise round trip is in
# test/unit/vtk_io.cpp); an unknown compressor is a usage error.
grep -q 'compressor="vtkZLibDataCompressor"' "$S/a.vtu" || fail "deformed.vtu: zlib by default"
"$VIS" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" -o "$S/l.vtu" \
  --faces "$S/l.vtp" --compression lz4 || fail "--compression lz4"
grep -q 'compressor="vtkLZ4DataCompressor"' "$S/l.vtu" && grep -q 'compressor="vtkLZ4DataCompressor"' "$S/l.vtp" \
  || fail "--compression lz4: no LZ4 compressor in the files"
"$VIS" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" -o "$S/n.vtu" \
  --compression none || fail "--compression none"
! grep -q 'compressor=' "$S/n.vtu" || fail "--compression none: compressed"
"$VIS" "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" -o "$S/g.vtu" \
  --compression gzip 2>/dev/null; [ $? -eq 2 ] || fail "--compression gzip must exit 2"

# A picture under a virtual display.
if command -v xvfb-run >/dev/null; then
  xvfb-run -a "$VIS" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --solution "$S/u.mtx" --problem "$PROBLEM" \
    -o "$S/p.vtu" --reactions "$S/r.mtx" --png "$S/p.png" --width 320 --height 240 || fail "png"
  [ "$(head -c 8 "$S/p.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "not a PNG"
  cmp -s "$S/a.vtu" "$S/p.vtu" || fail "deformed.vtu depends on --png"
fi
# A plain mesh (no --cut): the uncut box as it is, and a picture of it.
"$B/xfem-mesh" -q box --cells 2 3 8 --hi 0.03 0.06 0.2 -o "$S/box.vtu" || fail "box"
"$B/xfem-classify" -q "$S/box.vtu" -o "$S/box_classified.vtu" || fail "classify box"
"$B/xfem-enrich" -q "$S/box_classified.vtu" -o "$S/box_enriched.vtu" || fail "enrich box"
"$B/xfem-assemble" -q "$S/box_enriched.vtu" --problem "$PROBLEM" -o "$S/box_system" || fail "assemble box"
"$B/xfem-solve" -q "$S/box_system" -o "$S/box_u.mtx" || fail "solve box"
"$VIS" -q "$S/box_enriched.vtu" --solution "$S/box_u.mtx" --problem "$PROBLEM" -o "$S/box_d.vtu" --faces "$S/box_w.vtp" ||
  fail "visualize without --cut"
grep -q 'NumberOfCells="288"' "$S/box_d.vtu" || fail "plain mesh: expected the 2*3*8*6 = 288 tets unchanged"
if command -v xvfb-run >/dev/null; then
  xvfb-run -a "$VIS" -q "$S/box_enriched.vtu" --solution "$S/box_u.mtx" --problem "$PROBLEM" -o "$S/box_p.vtu" \
    --png "$S/box.png" --width 320 --height 240 || fail "png of a plain mesh"
fi
rm -rf "$S"
echo "ok"
