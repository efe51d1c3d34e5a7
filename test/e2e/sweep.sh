#!/usr/bin/env bash
# xfem-sweep: CLI contract and bad inputs, then a 5-step sweep through a small box whose every step
# equals a from-scratch run of xfem-classify, -enrich, -assemble, -solve and -visualize on the cut
# at that step (written out by --cuts) to 1e-9 relative.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; SWEEP=$B/xfem-sweep
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error <text> <args...>: exit 1, one "error:" line with <text>, no frames left
  local text=$1; shift
  rm -rf "$S/bad"
  "$SWEEP" "$@" -o "$S/bad" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $*: $(cat "$S/err.txt")"
  [ "$(grep -c "error:" "$S/err.txt")" -eq 1 ] || fail "expected one error: line for $*: $(cat "$S/err.txt")"
  grep -qF -- "$text" "$S/err.txt" || fail "expected '$text' for $*, got: $(cat "$S/err.txt")"
  [ ! -e "$S/bad/sweep.pvd" ] || fail "a collection left behind for $*"
}

"$SWEEP" --help >/dev/null || fail "--help"
"$SWEEP" --no-such-flag 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"

"$B/xfem-mesh" -q box --cells 4 4 8 --hi 1 1 2 -o "$S/box.vtu" || fail "mesh"
# A blade hanging 0.7 down from z = 2.2 moves along y from 0.05 to 0.75 at x = 0.43: the cut enters
# through the top face, its front inside the box (branch enrichment) all along the sweep.
"$B/xfem-mesh" -q cut-sweep --path 0.43 0.05 2.2 0.43 0.75 2.2 --depth 0.7 --resolution 0.1 -o "$S/sweep.vtp" \
  || fail "cut-sweep"
cat >"$S/problem.json" <<'JSON'
{
  "material": {"E": 1e3, "nu": 0.3},
  "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}],
  "neumann": [{"name": "left", "selector": {"box": {"lo": [-1, -1, -1], "hi": [0, 2, 3]}}, "traction": [-10, 0, 0]},
              {"name": "right", "selector": {"box": {"lo": [1, -1, -1], "hi": [2, 2, 3]}}, "traction": [10, 0, 3]}],
  "body_force": [0, 0, -5]
}
JSON
P=$S/problem.json

# Bad inputs.
"$B/xfem-mesh" -q cut-rect --corner 0.43 0 2.2 --edge1 0 0.5 0 --edge2 0 0 -0.7 -o "$S/plain.vtp" || fail "cut-rect"
expect_error "plain.vtp: no cell array 'time'" "$S/box.vtu" --cut "$S/plain.vtp" --problem "$P" --steps 2
expect_error "--steps 0: the number of steps must be at least 1" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 0
expect_error "--steps -3" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps -3
expect_error "--backend petsc: not available in xfem-sweep" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 2 \
  --backend petsc
expect_error "missing.vtu" "$S/missing.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 2
sed 's/"value": \[0, 0, 0\]/"exact": {"rigid": {"above": {"translation": [0, 0, 0]}}}/' "$P" >"$S/exact.json"
expect_error "prescribes an exact field" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$S/exact.json" --steps 2
sed 's/"nu": 0.3}/"nu": 0.3, "model": "corotational"}/' "$P" >"$S/corotational.json"
expect_error "corotational.json: xfem-sweep solves linear systems only: material.model \"corotational\" is not supported (use \"linear\"; xfem-newton solves \"corotational\")" \
  "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$S/corotational.json" --steps 2
[ ! -e "$S/bad" ] || fail "a refused material.model left the frame directory behind"
(unset DISPLAY; expect_error "rendering needs an X display" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 2 --png)
touch "$S/file"
"$SWEEP" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 2 -o "$S/file" 2>"$S/err.txt"
[ $? -eq 1 ] && grep -qF "exists and is not a directory" "$S/err.txt" || fail "output onto a file: $(cat "$S/err.txt")"

# The sweep, then every step from scratch.
"$SWEEP" "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 5 -o "$S/frames" --report "$S/report.json" \
  --solutions --cuts 2>"$S/progress.txt" || fail "sweep: $(cat "$S/progress.txt")"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 5 -o "$S/schur" --solutions --solver schur \
  || fail "--solver schur"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 5 -o "$S/refactor" --solutions --solver refactor \
  || fail "--solver refactor"
[ "$(grep -c "^xfem-sweep: step [1-5]/5" "$S/progress.txt")" -eq 5 ] || fail "progress per step: $(cat "$S/progress.txt")"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 5 -o "$S/quiet" --compression zlib 2>"$S/quiet.txt" \
  || fail "-q"
[ ! -s "$S/quiet.txt" ] || fail "-q must silence the progress: $(cat "$S/quiet.txt")"
# Frames: LZ4 by default, zlib on request.
grep -q 'compressor="vtkLZ4DataCompressor"' "$S/frames/step_003.vtu" || fail "frames: LZ4 by default"
grep -q 'compressor="vtkLZ4DataCompressor"' "$S/frames/step_003_wound.vtp" || fail "wound: LZ4 by default"
grep -q 'compressor="vtkZLibDataCompressor"' "$S/quiet/step_003.vtu" || fail "--compression zlib"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 1 -o "$S/bad" --compression gzip 2>/dev/null
[ $? -eq 2 ] || fail "--compression gzip must exit 2"
[ "$(grep -c "<DataSet timestep=" "$S/frames/sweep.pvd")" -eq 10 ] || fail "sweep.pvd: 5 steps x (body, wound)"
grep -q '"enriched_dofs"' "$S/report.json" || fail "report"
[ "$(grep -o '"step_seconds"' "$S/report.json" | wc -l)" -eq 5 ] || fail "report: step_seconds per step"
python3 - "$S/report.json" <<'PY2' || fail "report: step_cpu_seconds per step, positive, and their median"
import json, sys
r = json.load(open(sys.argv[1]))
cpu = [s["step_cpu_seconds"] for s in r["steps"]]
assert len(cpu) == 5 and all(c > 0 for c in cpu), cpu
assert r["median_step"]["cpu_seconds"] > 0
PY2
# A frame that cannot be written (it is written while the next step is solved): a clear error, exit 1.
mkdir -p "$S/blocked/step_003.vtu"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 5 -o "$S/blocked" 2>"$S/err.txt"
[ $? -eq 1 ] && grep -qF "step_003.vtu: cannot rename temporary file" "$S/err.txt" || fail "unwritable frame: $(cat "$S/err.txt")"
# Pictures: one per step, under xvfb-run as the other pictures.
if command -v xvfb-run >/dev/null; then
  # xvfb-run -a picks a display by its lock files; another program's X server starting at that
  # moment (a second build's tests on the same machine) can take it first ("bad X server
  # connection"): such a start is tried again, a failure of the sweep itself is not.
  for attempt in 1 2 3; do
    xvfb-run -a "$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$P" --steps 2 -o "$S/pictures" --png \
      --width 320 --height 240 2>"$S/png.err" && break
    grep -q "bad X server connection" "$S/png.err" && [ $attempt -lt 3 ] || { cat "$S/png.err"; fail "--png"; }
  done
  [ -s "$S/pictures/step_001.png" ] && [ -s "$S/pictures/step_002.png" ] || fail "--png: pictures missing"
fi
# mtx_values FILE: the values of a Matrix Market array vector, one per line.
mtx_values() { awk '!/^%/ { if (seen++) print $1 }' "$1"; }
for k in 001 002 003 004 005; do
  F=$S/frames; D=$S/scratch_$k; mkdir -p "$D"
  "$B/xfem-classify" -q "$S/box.vtu" --cut "$F/cut_$k.vtp" -o "$D/classified.vtu" || fail "classify $k"
  "$B/xfem-enrich" -q "$D/classified.vtu" -o "$D/enriched.vtu" || fail "enrich $k"
  "$B/xfem-assemble" -q "$D/enriched.vtu" --cut "$F/cut_$k.vtp" --problem "$P" -o "$D/system" || fail "assemble $k"
  "$B/xfem-solve" -q "$D/system" -o "$D/u.mtx" || fail "solve $k"
  "$B/xfem-visualize" -q "$D/enriched.vtu" --cut "$F/cut_$k.vtp" --solution "$D/u.mtx" --problem "$P" \
    -o "$D/deformed.vtu" --faces "$D/wound.vtp" || fail "visualize $k"
  paste <(mtx_values "$D/u.mtx") <(mtx_values "$F/u_$k.mtx") | awk -v k="$k" '
    { n++; d = $1 - $2; dd += d * d; uu += $1 * $1 }
    END { if (n == 0 || uu == 0) { print "step " k ": no values"; exit 1 }
          r = sqrt(dd / uu); if (r > 1e-9) { print "step " k ": relative difference " r; exit 1 } }' \
    || fail "step $k differs from the from-scratch run"
  paste <(mtx_values "$D/u.mtx") <(mtx_values "$S/refactor/u_$k.mtx") | awk -v k="$k" '
    { n++; d = $1 - $2; dd += d * d; uu += $1 * $1 }
    END { r = sqrt(dd / uu); if (!(r <= 1e-9)) { print "step " k ": relative difference " r; exit 1 } }' \
    || fail "step $k (--solver refactor) differs from the from-scratch run"
  paste <(mtx_values "$D/u.mtx") <(mtx_values "$S/schur/u_$k.mtx") | awk -v k="$k" '
    { n++; d = $1 - $2; dd += d * d; uu += $1 * $1 }
    END { r = sqrt(dd / uu); if (!(r <= 1e-9)) { print "step " k ": relative difference " r; exit 1 } }' \
    || fail "step $k (--solver schur) differs from the from-scratch run"
  [ "$(mtx_values "$D/u.mtx" | wc -l)" -eq "$(mtx_values "$F/u_$k.mtx" | wc -l)" ] || fail "step $k: N differs"
  # The frame is xfem-visualize's output on the same split: same points and cells.
  for pair in "deformed.vtu step_$k.vtu" "wound.vtp step_${k}_wound.vtp"; do
    set -- $pair
    a=$(grep -o 'NumberOf[A-Za-z]*="[0-9]*"' "$D/$1" | sort | tr '\n' ' ')
    b=$(grep -o 'NumberOf[A-Za-z]*="[0-9]*"' "$F/$2" | sort | tr '\n' ' ')
    [ "$a" = "$b" ] || fail "step $k: $2 ($b) and xfem-visualize's $1 ($a) differ in size"
  done
done
# The linear exact field is the same on both sides of the cut: accepted, and the bottom held by
# u = 0 + 0 x gives the frames of "value": [0, 0, 0] (the same values, another problem file).
sed 's/"value": \[0, 0, 0\]/"exact": {"linear": {"gradient": [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}}/' "$P" >"$S/linear.json"
grep -q '"linear"' "$S/linear.json" || fail "linear.json: no linear field"
"$SWEEP" -q "$S/box.vtu" --cut "$S/sweep.vtp" --problem "$S/linear.json" --steps 5 -o "$S/linear" --solutions \
  || fail "sweep with a linear exact field"
for k in 002 005; do
  cmp -s <(mtx_values "$S/linear/u_$k.mtx") <(mtx_values "$S/frames/u_$k.mtx") || fail "step $k: linear field != value"
done
# A frame's solution carries the fingerprints of its inputs: xfem-visualize takes it with the body
# enriched for its own step's cut and its problem, and refuses it with another problem.
grep -q "^% xfem-fingerprint cut fnv1a64:" "$S/frames/u_003.mtx" || fail "u_003.mtx: no cut fingerprint"
"$B/xfem-visualize" -q "$S/scratch_003/enriched.vtu" --cut "$S/frames/cut_003.vtp" --solution "$S/frames/u_003.mtx" \
  --problem "$P" -o "$S/check.vtu" || fail "xfem-visualize on the sweep's u_003.mtx"
sed 's/"E": 1e3/"E": 2e3/' "$P" >"$S/stiffer.json"
"$B/xfem-visualize" -q "$S/scratch_003/enriched.vtu" --cut "$S/frames/cut_003.vtp" --solution "$S/frames/u_003.mtx" \
  --problem "$S/stiffer.json" -o "$S/check.vtu" 2>"$S/err.txt"
[ $? -eq 1 ] && grep -qF "u_003.mtx: does not belong to" "$S/err.txt" || fail "u_003.mtx with another problem: $(cat "$S/err.txt")"
# The sweep grows: the last step has more enriched DOFs than the first, and the first step cuts.
first=$(grep -o '"enriched_dofs": *[0-9]*' "$S/report.json" | head -1 | grep -o '[0-9]*$')
last=$(grep -o '"enriched_dofs": *[0-9]*' "$S/report.json" | tail -1 | grep -o '[0-9]*$')
[ "$first" -gt 0 ] && [ "$last" -gt "$first" ] || fail "enriched DOFs first $first, last $last"
echo "ok"
