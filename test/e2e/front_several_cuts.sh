#!/usr/bin/env bash
# xfem-front on a mesh with several cuts whose fronts end on the body's surface (issue "Never a
# silent wrong answer, round two"): the surface term of the domain form evaluates the solution at
# points of the body's faces, with a side code of every cut (side_codes.h), not a +1 / -1 side.
#   - two cuts far apart in a box, each entering through a face, its front crossing the box
#     (ends on the faces y = 0 and y = 1). Problem A clamps every node with z >= 1 (cut 1 with
#     the whole support of its enrichment, one element and more around it) and pulls the bottom:
#     the DOFs of cut 1 carry no load and couple to no free DOF, so the two-cut solution is the
#     one-cut solution of cut 0 alone (up to the solver's round-off) and K along front 0 must be
#     the one-cut run's to 1e-8 of max |K| (measured: equal to the 10 digits written), K along
#     front 1 zero (the field vanishes in its domains). Problem B: the same mirrored, for front 1.
#   - the issue's case: the paper's beam with its cut and a second cut from the other side at
#     z = 0.05: both fronts give finite K.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; M="$B/xfem-mesh -q"
fail() { echo "FAIL: $*"; exit 1; }

$M box --cells 6 6 12 --hi 1 1 2 -o "$S/box.vtu" &&
  $M cut-rect --corner -0.5 -0.5 0.52 --edge1 0.95 0 0 --edge2 0 2 0 -o "$S/c0.vtp" &&
  $M cut-rect --corner 0.55 -0.5 1.48 --edge1 0.95 0 0 --edge2 0 2 0 -o "$S/c1.vtp" || fail "inputs"
cat >"$S/A.json" <<'EOF'
{"material": {"E": 1000, "nu": 0.3},
 "dirichlet": [{"name": "upper half clamped", "selector": {"box": {"lo": [-1, -1, 1], "hi": [2, 2, 3]}}, "value": [0, 0, 0]}],
 "neumann": [{"name": "bottom pulled", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "traction": [0, 0, -1]}]}
EOF
cat >"$S/B.json" <<'EOF'
{"material": {"E": 1000, "nu": 0.3},
 "dirichlet": [{"name": "lower half clamped", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 1]}}, "value": [0, 0, 0]}],
 "neumann": [{"name": "top pulled", "selector": {"box": {"lo": [-1, -1, 2], "hi": [2, 2, 3]}}, "traction": [0, 0, 1]}]}
EOF
# solve <dir> <mesh> <problem> <cuts...>: the chain up to u.mtx.
solve() {
  local d=$1 mesh=$2 p=$3; shift 3
  local C=(); for c in "$@"; do C+=(--cut "$c"); done
  mkdir -p "$d"
  "$B/xfem-classify" -q "$mesh" "${C[@]}" -o "$d/classified.vtu" && "$B/xfem-enrich" -q "$d/classified.vtu" -o "$d/enriched.vtu" &&
    "$B/xfem-assemble" -q "$d/enriched.vtu" "${C[@]}" --problem "$p" -o "$d/system" && "$B/xfem-solve" -q "$d/system" -o "$d/u.mtx"
}
# front <dir> <problem> <k> <csv> <radius> <cuts...>
front() {
  local d=$1 p=$2 k=$3 csv=$4 r=$5; shift 5
  local C=(); for c in "$@"; do C+=(--cut "$c"); done
  "$B/xfem-front" "$d/enriched.vtu" "${C[@]}" --solution "$d/u.mtx" --problem "$p" --radius "$r" --front-of "$k" \
    --csv "$csv" 2>"$csv.err" || { echo "xfem-front --front-of $k: $(cat "$csv.err")"; return 1; }
}
solve "$S/twoA" "$S/box.vtu" "$S/A.json" "$S/c0.vtp" "$S/c1.vtp" && solve "$S/twoB" "$S/box.vtu" "$S/B.json" "$S/c0.vtp" "$S/c1.vtp" &&
  solve "$S/oneA" "$S/box.vtu" "$S/A.json" "$S/c0.vtp" && solve "$S/oneB" "$S/box.vtu" "$S/B.json" "$S/c1.vtp" || fail "solutions"
front "$S/twoA" "$S/A.json" 0 "$S/twoA/f0.csv" 0.25 "$S/c0.vtp" "$S/c1.vtp" &&
  front "$S/twoA" "$S/A.json" 1 "$S/twoA/f1.csv" 0.25 "$S/c0.vtp" "$S/c1.vtp" &&
  front "$S/twoB" "$S/B.json" 1 "$S/twoB/f1.csv" 0.25 "$S/c0.vtp" "$S/c1.vtp" &&
  front "$S/twoB" "$S/B.json" 0 "$S/twoB/f0.csv" 0.25 "$S/c0.vtp" "$S/c1.vtp" &&
  front "$S/oneA" "$S/A.json" 0 "$S/oneA/f0.csv" 0.25 "$S/c0.vtp" &&
  front "$S/oneB" "$S/B.json" 0 "$S/oneB/f1.csv" 0.25 "$S/c1.vtp" || fail "fronts of two cuts far apart"
python3 - "$S" <<'PY' || fail "two cuts far apart: K along each front differs from the one-cut run"
import csv, math, sys
S = sys.argv[1]
rows = lambda f: list(csv.DictReader(open(f"{S}/{f}")))
K = ("K_I", "K_II", "K_III")
for two, one, loaded, idle in (("twoA/f0.csv", "oneA/f0.csv", "A", "twoA/f1.csv"), ("twoB/f1.csv", "oneB/f1.csv", "B", "twoB/f0.csv")):
    a, b = rows(two), rows(one)
    assert len(a) == len(b) >= 5, (two, len(a), len(b))
    assert sum(r["end"] == "1" for r in a) == 2, "the front must end on the body's surface at both ends"
    scale = max(abs(float(r[k])) for r in b for k in K)
    kmin = min(float(r["K_I"]) for r in b)
    assert kmin > 0.5 * scale, f"{one}: the cut must open (K_I {kmin} of max |K| {scale})"
    worst = max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b) for k in K + ("G",))
    assert worst <= 1e-8 * scale, f"{two} vs {one}: {worst} (max |K| {scale})"
    still = max(abs(float(r[k])) for r in rows(idle) for k in K)
    assert still <= 1e-8 * scale, f"{idle}: K {still} in the clamped half"
    print(f"problem {loaded}: K_I {kmin:.4g} .. {max(float(r['K_I']) for r in b):.4g}, two cuts vs one: {worst:.2g}; "
          f"the clamped front: max |K| {still:.2g}", file=sys.stderr)
PY

# The issue's case: the beam's cut and a second from the other side at z = 0.05, both fronts.
$M unstructured-box --hi 0.03 0.06 0.2 --size 0.008 -o "$S/beam.vtu" && $M cut-rect --beam-cut -o "$S/b0.vtp" &&
  $M cut-rect --corner 0.015 -0.01 0.05 --edge1 0.025 0 0 --edge2 0 0.08 0 -o "$S/b1.vtp" || fail "beam inputs"
P="$XFEM_SOURCE/pipelines/beam/problem.json"
solve "$S/beam" "$S/beam.vtu" "$P" "$S/b0.vtp" "$S/b1.vtp" &&
  front "$S/beam" "$P" 0 "$S/beam/f0.csv" 0.012 "$S/b0.vtp" "$S/b1.vtp" &&
  front "$S/beam" "$P" 1 "$S/beam/f1.csv" 0.012 "$S/b0.vtp" "$S/b1.vtp" || fail "beam with two cuts"
python3 - "$S/beam/f0.csv" "$S/beam/f1.csv" <<'PY' || fail "beam with two cuts: K"
import csv, math, sys
for f in sys.argv[1:]:
    rows = list(csv.DictReader(open(f)))
    assert len(rows) >= 3 and all(math.isfinite(float(r[k])) for r in rows for k in ("K_I", "K_II", "K_III", "G")), f
    assert all(float(r["K_I"]) != 0 for r in rows), f
PY
echo "front with several cuts: all cases pass"
rm -rf "$S"
