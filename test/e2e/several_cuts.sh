#!/usr/bin/env bash
# Issue 21: several cuts in one body. Every case runs classify, enrich, assemble (default rule),
# solve and visualize without -q; no stage may print a warning. Checks: test/e2e/several_cuts.py.
#   - two parallel cuts through a box (structured 4x4x5, unstructured): three pieces, each moved by
#     its own rigid motion on the boundary: every cell of deformed.vtu moves rigidly with its
#     region (1e-10 of max|u|), zero strain, the volume of each region exact (1e-12);
#   - two cuts crossing inside one layer of tets (4x4x1), in a 4x4x4 box and an unstructured box:
#     four pieces, the junction enrichment H_0 H_1 on the nodes around the crossing, same checks;
#   - a wedge resection of the organ (cut 0 reaching past the line where cut 1 ends on it: a
#     T-junction): without a Dirichlet condition on the wedge xfem-solve names the freed piece; with
#     the wedge fixed and the ends pulled the wedge does not move (1e-10) and has zero strain;
#   - two discs ending inside a box (both fronts branch enriched): uniaxial tension parallel to them
#     reproduced exactly (1e-10; strain 1e-9), xfem-front on each front (--front-of 0 / 1);
#   - one cut_id file is the same as two --cut files (same solution bytes);
#   - every configuration refused: its one-line error.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; PY="python3 $XFEM_SOURCE/test/e2e/several_cuts.py"; M="$B/xfem-mesh -q"
fail() { echo "FAIL: $*"; exit 1; }

$M box --cells 4 4 5 --hi 1 1 1 -o "$S/s5.vtu" && $M box --cells 4 4 4 --hi 1 1 1 -o "$S/s4.vtu" &&
  $M box --cells 4 4 1 --hi 1 1 0.25 -o "$S/layer.vtu" &&
  $M unstructured-box --hi 1 1 1 --size 0.25 -o "$S/u.vtu" || fail "meshes"
# Parallel: z = 0.3 (normal +z) and a tilted plane through (-0.5, -0.5, z1), normal (-0.1, 0, 2).
$M cut-rect --corner -0.5 -0.5 0.3 --edge1 2 0 0 --edge2 0 2 0 -o "$S/p0.vtp" &&
  $M cut-rect --corner -0.5 -0.5 0.62 --edge1 2 0 0.1 --edge2 0 2 0 -o "$S/p1.vtp" &&
  $M cut-rect --corner -0.5 -0.5 0.64 --edge1 2 0 0.1 --edge2 0 2 0 -o "$S/p1u.vtp" || fail "parallel cuts"
# Crossing: two slanted vertical planes crossing along a vertical line near (0.5, 0.5).
$M cut-rect --corner 0.43 -0.5 -0.5 --edge1 0.2 2 0 --edge2 0 0 2 -o "$S/x0.vtp" &&
  $M cut-rect --corner -0.5 0.55 -0.5 --edge1 0 0 2 --edge2 2 -0.3 0 -o "$S/x1.vtp" &&
  $M cut-rect --corner -0.5 0.53 -0.5 --edge1 0 0 2 --edge2 2 -0.3 0 -o "$S/x1u.vtp" || fail "crossing cuts"
PLANES_P="--plane -0.5 -0.5 0.3 0 0 1 --plane -0.5 -0.5 0.62 -0.1 0 2"
PLANES_PU="--plane -0.5 -0.5 0.3 0 0 1 --plane -0.5 -0.5 0.64 -0.1 0 2"
PLANES_X="--plane 0.43 -0.5 -0.5 4 -0.4 0 --plane -0.5 0.55 -0.5 0.6 4 0"
PLANES_XU="--plane 0.43 -0.5 -0.5 4 -0.4 0 --plane -0.5 0.53 -0.5 0.6 4 0"

# run_case <name> <mesh> <regions> <cut0> <cut1> <plane args...>
run_case() {
  local name=$1 mesh=$2 regions=$3 c0=$4 c1=$5; shift 5
  local d="$S/$name"; mkdir -p "$d"
  $PY problem "$mesh" "$@" -o "$d/problem.json" || { echo "$name: problem.json"; return 1; }
  "$B/xfem-classify" "$mesh" --cut "$c0" --cut "$c1" -o "$d/classified.vtu" --summary "$d/classify.json" 2>"$d/classify.err" &&
    "$B/xfem-enrich" "$d/classified.vtu" -o "$d/enriched.vtu" 2>"$d/enrich.err" &&
    "$B/xfem-assemble" "$d/enriched.vtu" --cut "$c0" --cut "$c1" --problem "$d/problem.json" -o "$d/system" 2>"$d/assemble.err" &&
    "$B/xfem-solve" "$d/system" -o "$d/u.mtx" 2>"$d/solve.err" &&
    "$B/xfem-visualize" "$d/enriched.vtu" --cut "$c0" --cut "$c1" --solution "$d/u.mtx" --problem "$d/problem.json" \
      -o "$d/deformed.vtu" --faces "$d/wound.vtp" 2>"$d/visualize.err" ||
    { echo "$name: a stage failed: $(cat "$d"/*.err | grep -m1 error)"; return 1; }
  grep -i "warning" "$d"/*.err && { echo "$name: a stage warned"; return 1; }
  # The test geometry has no sliver below --tiny-support (else the patch test holds only up to it).
  python3 - "$d/classify.json" "$regions" <<'PY' || { echo "$name: classification"; return 1; }
import json, sys
c = json.load(open(sys.argv[1]))
assert all(k["sign_tiny"] == 0 for k in c["cuts"]), "sign_tiny"
assert c["product_tiny"] == 0, "product_tiny"
assert (len(c["products"]) > 0) == (sys.argv[2] == "4"), "junction enrichment where the cuts cross, only there"
PY
  $PY check --deformed "$d/deformed.vtu" "$@" --regions "$regions" 2>"$d/check.err" || { echo "$name: check"; return 1; }
  echo "ok $name: $(cat "$d/check.err")"
}
run_case parallel-s "$S/s5.vtu" 3 "$S/p0.vtp" "$S/p1.vtp" $PLANES_P || fail parallel-s
run_case parallel-u "$S/u.vtu" 3 "$S/p0.vtp" "$S/p1u.vtp" $PLANES_PU || fail parallel-u
run_case crossing-layer "$S/layer.vtu" 4 "$S/x0.vtp" "$S/x1.vtp" $PLANES_X || fail crossing-layer
run_case crossing-s "$S/s4.vtu" 4 "$S/x0.vtp" "$S/x1.vtp" $PLANES_X || fail crossing-s
run_case crossing-u "$S/u.vtu" 4 "$S/x0.vtp" "$S/x1u.vtp" $PLANES_XU || fail crossing-u

# Two cuts ending inside the body (discs, normals +z and -z): both fronts branch enriched, uniaxial
# tension along x (the discs traction-free) reproduced exactly; xfem-front on each front.
d="$S/fronts"; mkdir -p "$d"
$M box --cells 6 6 6 --hi 1 1 1 -o "$d/s6.vtu" &&
  $M cut-disc --center 0.47 0.52 0.29 --normal 0 0 1 --radius 0.25 --rings 4 -o "$d/d0.vtp" &&
  $M cut-disc --center 0.52 0.47 0.71 --normal 0 0 -1 --radius 0.25 --rings 4 -o "$d/d1.vtp" &&
  python3 "$XFEM_SOURCE/test/e2e/cut_catalogue.py" problem 0 0 0 1 1 1 --linear -o "$d/problem.json" --exact "$d/exact.json" ||
  fail "fronts inputs"
DC="--cut $d/d0.vtp --cut $d/d1.vtp"
"$B/xfem-classify" "$d/s6.vtu" $DC -o "$d/classified.vtu" --summary "$d/classify.json" 2>"$d/classify.err" &&
  "$B/xfem-enrich" "$d/classified.vtu" -o "$d/enriched.vtu" 2>"$d/enrich.err" &&
  "$B/xfem-assemble" "$d/enriched.vtu" $DC --problem "$d/problem.json" -o "$d/system" 2>"$d/assemble.err" &&
  "$B/xfem-solve" "$d/system" -o "$d/u.mtx" 2>"$d/solve.err" &&
  "$B/xfem-visualize" "$d/enriched.vtu" $DC --solution "$d/u.mtx" --problem "$d/problem.json" -o "$d/deformed.vtu" 2>"$d/visualize.err" &&
  "$B/xfem-front" "$d/enriched.vtu" $DC --solution "$d/u.mtx" --problem "$d/problem.json" --radius 0.12 --csv "$d/f0.csv" 2>"$d/front0.err" &&
  "$B/xfem-front" "$d/enriched.vtu" $DC --solution "$d/u.mtx" --problem "$d/problem.json" --radius 0.12 --front-of 1 --csv "$d/f1.csv" 2>"$d/front1.err" ||
  fail "fronts: $(cat "$d"/*.err | grep -m1 error)"
grep -i warning "$d"/*.err && fail "fronts: a stage warned"
# The same body with disc 0 alone (one cut): K along its front equals front 0 of the two-cut run
# (both solutions are the exact linear field; the interaction integral sees the same field).
"$B/xfem-classify" -q "$d/s6.vtu" --cut "$d/d0.vtp" -o "$d/one_classified.vtu" &&
  "$B/xfem-enrich" -q "$d/one_classified.vtu" -o "$d/one_enriched.vtu" &&
  "$B/xfem-assemble" -q "$d/one_enriched.vtu" --cut "$d/d0.vtp" --problem "$d/problem.json" -o "$d/one_system" &&
  "$B/xfem-solve" -q "$d/one_system" -o "$d/one_u.mtx" &&
  "$B/xfem-front" -q "$d/one_enriched.vtu" --cut "$d/d0.vtp" --solution "$d/one_u.mtx" --problem "$d/problem.json" \
    --radius 0.12 --csv "$d/one_f0.csv" || fail "fronts: disc 0 alone"
python3 - "$d/classify.json" "$d/f0.csv" "$d/f1.csv" "$d/one_f0.csv" <<'PY' || fail "fronts: both cuts branch enriched, K along both fronts"
import csv, json, math, sys
c = json.load(open(sys.argv[1]))
assert all(k["branch"] > 0 and k["partial"] > 0 and k["front_segments"] > 0 for k in c["cuts"]), c["cuts"]
f0, f1, one = (list(csv.DictReader(open(f))) for f in sys.argv[2:])
assert len(f0) == len(one) >= 4 and len(f1) >= 4
assert all(math.isfinite(float(r[k])) for r in f0 + f1 for k in ("K_I", "K_II", "K_III"))
scale = 1e-3 * math.sqrt(math.pi * 0.25)  # sigma sqrt(pi a)
worst = max(abs(float(a[k]) - float(b[k])) for a, b in zip(f0, one) for k in ("K_I", "K_II", "K_III"))
print(f"K along front 0 of two cuts vs disc 0 alone: max difference {worst:.2g} (sigma sqrt(pi a) = {scale:.3g})", file=sys.stderr)
assert worst <= 1e-8 * scale, worst
PY
$PY linear --deformed "$d/deformed.vtu" 2>"$d/check.err" || fail "fronts: linear patch test"
echo "ok fronts: $(cat "$d/check.err")"

# One file with cut_id = the two files: same classification, same solution.
d="$S/cut-id"; mkdir -p "$d"
$M cut-merge --cut-id "$S/x0.vtp" "$S/x1.vtp" -o "$d/both.vtp" || fail "cut-merge --cut-id"
"$B/xfem-classify" -q "$S/s4.vtu" --cut "$d/both.vtp" -o "$d/classified.vtu" &&
  "$B/xfem-enrich" -q "$d/classified.vtu" -o "$d/enriched.vtu" &&
  "$B/xfem-assemble" -q "$d/enriched.vtu" --cut "$d/both.vtp" --problem "$S/crossing-s/problem.json" -o "$d/system" &&
  "$B/xfem-solve" -q "$d/system" -o "$d/u.mtx" || fail "cut_id file"
grep -v "^%" "$d/u.mtx" | cmp -s - <(grep -v "^%" "$S/crossing-s/u.mtx") || fail "a cut_id file gives another solution than two --cut"

# Wedge resection of the organ: cut 0 (normal (1,0,1)) reaches 0.018 past the line x = 0.02, z = 0
# where cut 1 (normal (1,0,-1)) ends on it; the wedge between them above the line is cut free.
W="$S/wedge"; mkdir -p "$W"
$M organ --size 0.012 -o "$W/organ.vtu" &&
  $M cut-rect --corner 0.038 -0.07 -0.018 --edge1 0 0.14 0 --edge2 -0.078 0 0.078 -o "$W/cut0.vtp" &&
  $M cut-rect --corner 0.02 -0.07 0 --edge1 0 0.14 0 --edge2 0.06 0 0.06 -o "$W/cut1.vtp" || fail "wedge inputs"
cat >"$W/free.json" <<'EOF'
{"material": {"E": 3000, "nu": 0.35},
 "dirichlet": [
  {"name": "left end", "selector": {"half_spaces": [{"point": [-0.06, 0, 0], "normal": [-1, 0, 0]}]}, "value": [0, 0, 0]},
  {"name": "right end", "selector": {"half_spaces": [{"point": [0.062, 0, 0], "normal": [1, 0, 0]}]}, "value": [0.01, 0, 0]}]}
EOF
python3 - "$W/free.json" "$W/fixed.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p["dirichlet"].append({"name": "wedge", "selector": {"half_spaces": [
    {"point": [0, 0, 0.02], "normal": [0, 0, 1]}, {"point": [0.01, 0, 0], "normal": [1, 0, 0]},
    {"point": [0.03, 0, 0], "normal": [-1, 0, 0]}]}, "value": [0, 0, 0]})
json.dump(p, open(sys.argv[2], "w"), indent=1)
PY
WC="--cut $W/cut0.vtp --cut $W/cut1.vtp"
"$B/xfem-classify" "$W/organ.vtu" $WC -o "$W/classified.vtu" 2>"$W/classify.err" || fail "wedge classify: $(cat "$W/classify.err")"
grep -q "cut 1 (.*cut1.vtp): .* 0 branch nodes; 0 front segments; ends on cut 0 (junction)" "$W/classify.err" ||
  fail "wedge: cut 1 must end on cut 0 without a front: $(cat "$W/classify.err")"
"$B/xfem-enrich" -q "$W/classified.vtu" -o "$W/enriched.vtu" &&
  "$B/xfem-assemble" -q "$W/enriched.vtu" $WC --problem "$W/free.json" -o "$W/free" || fail "wedge assemble (free)"
"$B/xfem-solve" -q "$W/free" -o "$W/free.mtx" 2>"$W/free.err" && fail "a freed wedge without a Dirichlet condition must fail"
grep -q "^xfem-solve: error: the body falls apart into 2 pieces; piece 2 ([0-9]* tets) has no Dirichlet condition" "$W/free.err" ||
  fail "freed wedge message: $(cat "$W/free.err")"
"$B/xfem-assemble" "$W/enriched.vtu" $WC --problem "$W/fixed.json" -o "$W/fixed" 2>"$W/assemble.err" &&
  "$B/xfem-solve" "$W/fixed" -o "$W/u.mtx" 2>"$W/solve.err" &&
  "$B/xfem-visualize" "$W/enriched.vtu" $WC --solution "$W/u.mtx" --problem "$W/fixed.json" -o "$W/deformed.vtu" \
    --faces "$W/wound.vtp" 2>"$W/visualize.err" || fail "wedge fixed: $(cat "$W"/*.err | grep -m1 error)"
grep -i warning "$W"/*.err && fail "wedge: a stage warned"
$PY wedge --deformed "$W/deformed.vtu" --plane 0.038 -0.07 -0.018 1 0 1 --plane 0.02 -0.07 0 1 0 -1 --inside 0.02 0 0.02 \
  2>"$W/check.err" || fail "wedge check"
echo "ok wedge: $(cat "$W/check.err")"

# Refused configurations: one line each, nothing written.
refuse() {  # refuse <name> <expected message regex> <command...>
  local name=$1 re=$2; shift 2
  "$@" >"$S/$name.out" 2>"$S/$name.err" && fail "$name: must fail"
  [ "$(wc -l <"$S/$name.err")" -eq 1 ] || fail "$name: not one line: $(cat "$S/$name.err")"
  grep -Eq "$re" "$S/$name.err" || fail "$name: message: $(cat "$S/$name.err")"
  echo "ok refused $name: $(cat "$S/$name.err")"
}
$M cut-rect --corner 0.02 -0.07 0 --edge1 0 0.14 0 --edge2 -0.06 0 0.06 -o "$S/v0.vtp" &&
  $M cut-rect --corner -0.5 -0.5 0.55 --edge1 2 0 0 --edge2 0 2 0 -o "$S/z50.vtp" &&
  $M cut-rect --corner -0.5 -0.5 0.56 --edge1 2 0 0 --edge2 0 2 0 -o "$S/z51.vtp" &&
  $M cut-rect --corner -0.5 -0.5 0.57 --edge1 2 0 0 --edge2 0 2 0 -o "$S/z52.vtp" &&
  $M cut-disc --center 0.5 0.5 0.47 --normal 0 0 1 --radius 0.3 --rings 4 -o "$S/disc47.vtp" &&
  $M cut-disc --center 0.5 0.5 0.55 --normal 0 0 1 --radius 0.3 --rings 4 -o "$S/disc55.vtp" &&
  $M cut-rect --corner 0.61 -0.5 -0.5 --edge1 0 2 0 --edge2 0 0 2 -o "$S/x61.vtp" || fail "refused inputs"
refuse v-junction "^xfem-classify: error: .*organ.vtu: cuts 0 and 1 end on each other \(a V-shaped junction\)" \
  "$B/xfem-classify" -q "$W/organ.vtu" --cut "$S/v0.vtp" --cut "$W/cut1.vtp" -o "$S/v.vtu"
refuse three-cuts "^xfem-classify: error: .*s4.vtu: tet [0-9]+ meets cuts 0, 1 and 2: three cuts in one tet are not handled" \
  "$B/xfem-classify" -q "$S/s4.vtu" --cut "$S/z50.vtp" --cut "$S/z51.vtp" --cut "$S/z52.vtp" -o "$S/three.vtu"
refuse front-meets-cut "^xfem-classify: error: .*s4.vtu: tet [0-9]+: the front of cut 0 runs through it and cut 1 meets it" \
  "$B/xfem-classify" -q "$S/s4.vtu" --cut "$S/disc47.vtp" --cut "$S/x61.vtp" -o "$S/front.vtu"
refuse two-fronts "^xfem-classify: error: .*s4.vtu: tet [0-9]+ has branch-enriched nodes of cuts 0 and 1" \
  "$B/xfem-classify" -q "$S/s4.vtu" --cut "$S/disc47.vtp" --cut "$S/disc55.vtp" -o "$S/fronts.vtu"
[ ! -e "$S/v.vtu" ] && [ ! -e "$S/three.vtu" ] && [ ! -e "$S/front.vtu" ] && [ ! -e "$S/fronts.vtu" ] || fail "output left behind"
C="$S/crossing-s"
refuse too-few-cuts "^xfem-assemble: error: .*enriched.vtu: classified with 2 cuts, but 1 are given" \
  "$B/xfem-assemble" -q "$C/enriched.vtu" --cut "$S/x0.vtp" --problem "$C/problem.json" -o "$S/sys1"
refuse swapped-cuts "^xfem-assemble: error: .*x1.vtp: not cut 0 of .*enriched.vtu" \
  "$B/xfem-assemble" -q "$C/enriched.vtu" --cut "$S/x1.vtp" --cut "$S/x0.vtp" --problem "$C/problem.json" -o "$S/sys2"
refuse oversampling "^xfem-assemble: error: .*several cuts are integrated by the conforming rule only" \
  "$B/xfem-assemble" -q "$C/enriched.vtu" --cut "$S/x0.vtp" --cut "$S/x1.vtp" --problem "$C/problem.json" --rule oversampling -o "$S/sys3"
refuse visualize-one-cut "^xfem-visualize: error: .*classified with 2 cuts, but 1 are given" \
  "$B/xfem-visualize" -q "$C/enriched.vtu" --cut "$S/x0.vtp" --solution "$C/u.mtx" --problem "$C/problem.json" -o "$S/d.vtu"
refuse front-of-missing "^xfem-front: error: .*enriched.vtu: --front-of 2 but the mesh has 2 cuts \(0..1\)" \
  "$B/xfem-front" -q "$S/fronts/enriched.vtu" --cut "$S/fronts/d0.vtp" --cut "$S/fronts/d1.vtp" --solution "$S/fronts/u.mtx" \
  --problem "$S/fronts/problem.json" --front-of 2 --csv "$S/f2.csv"
refuse rmserror-several "^xfem-rmserror: error: .*enriched.vtu: classified with 2 cuts, but 1 is given \(this tool takes one cut\)" \
  "$B/xfem-rmserror" -q "$C/enriched.vtu" --cut "$S/x0.vtp" --solution "$C/u.mtx" --exact "$S/fronts/exact.json" -o "$S/e.json"
printf '# vtk DataFile Version 3.0\nbad cut_id\nASCII\nDATASET POLYDATA\nPOINTS 3 double\n0 0 0.5 2 0 0.5 0 2 0.5\nPOLYGONS 1 4\n3 0 1 2\nCELL_DATA 1\nSCALARS cut_id double 1\nLOOKUP_TABLE default\n0.5\n' >"$S/bad_id.vtk"
refuse bad-cut-id "^xfem-classify: error: .*bad_id.vtk: cell array 'cut_id' of triangle 0 is not a whole number" \
  "$B/xfem-classify" -q "$S/s4.vtu" --cut "$S/bad_id.vtk" -o "$S/bad.vtu"
[ ! -e "$S/f2.csv" ] && [ ! -e "$S/e.json" ] && [ ! -e "$S/sys1" ] && [ ! -e "$S/sys2" ] && [ ! -e "$S/sys3" ] && [ ! -e "$S/d.vtu" ] && [ ! -e "$S/bad.vtu" ] || fail "output left behind"
echo "several cuts: all cases pass"
rm -rf "$S"
