#!/usr/bin/env bash
# Several materials (problem.json `materials`, one per region of the mesh) through the tools:
#   - a bar of two regions in series (nu = 0; a .vtu with regions, and a gmsh .msh whose physical
#     volumes are the regions), fixed at one end and pulled at the other: every
#     node's displacement, and the end's, the closed form of two springs in series to 1e-10;
#   - the same bar with every region given the default material: K, f, u bit for bit those of the
#     run without `materials` (cmp);
#   - cuts through the interface x = 0.5, the cut catalogue's patch tests with two materials:
#     cuts whose front lies inside (a disc across the interface, fronts on the interface's faces
#     and beyond it) under uniaxial stress along the interface's normal, nu / E equal in both
#     regions so that the exact field is continuous and piecewise linear: every point of
#     deformed.vtu exact, every cell's stress sigma e_x e_x and its strain its region's, to 1e-10
#     (and the same check fails for the body solved as one material); cuts through the body (a
#     plane, grid faces, a zigzag, two pieces), each side moved rigidly: cut_catalogue.py's checks
#     (displacement and zero strain to 1e-10, volumes, wound areas); xfem-front refuses a domain
#     spanning the interface;
#   - xfem-newton with several materials of the linear model equals the linear path (1e-10);
#   - xfem-sweep across the interface: each step the tools' solution with the same materials;
#   - bad `materials`: an unknown region (by id and by name, listing the mesh's), E <= 0, a region
#     listed twice, a bad type: one error line each, no output.
# Helpers: test/e2e/materials.py.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; PY="python3 $XFEM_SOURCE/test/e2e/materials.py"
fail() { echo "FAIL: $*"; exit 1; }
chain() {  # chain <mesh> <cut or ""> <problem> <dir>: classify .. solve into <dir>
  local cut=(); [ -n "$2" ] && cut=(--cut "$2")
  mkdir -p "$4"
  "$B/xfem-classify" -q "$1" "${cut[@]}" -o "$4/classified.vtu" || fail "classify $4"
  "$B/xfem-enrich" -q "$4/classified.vtu" -o "$4/enriched.vtu" || fail "enrich $4"
  "$B/xfem-assemble" -q "$4/enriched.vtu" "${cut[@]}" --problem "$3" -o "$4/system" 2>"$4/assemble.err" ||
    fail "assemble $4: $(cat "$4/assemble.err")"
  "$B/xfem-solve" -q "$4/system" -o "$4/u.mtx" || fail "solve $4"
}

# --- The bar: [0, 2] x [0, 0.5]^2, 8 x 2 x 2 cubes, regions 3 'soft' (x < 0.75) and 5 'hard'.
"$B/xfem-mesh" -q box --cells 8 2 2 --hi 2 0.5 0.5 -o box.vtu || fail "xfem-mesh box"
$PY regions box.vtu bar.vtu --split 0.75 --ids 3 5 --names soft hard || fail "regions"
bar_problem() {  # bar_problem <materials json or ""> <out>
  local materials=""; [ -n "$1" ] && materials="\"materials\": $1,"
  cat >"$2" <<JSON
{"material": {"E": 7000, "nu": 0}, $materials
 "dirichlet": [{"name": "fixed end", "selector": {"box": {"lo": [-1, -1, -1], "hi": [1e-9, 1, 1]}}, "value": [0, 0, 0]}],
 "neumann": [{"name": "pulled end", "selector": {"box": {"lo": [1.999999, -1, -1], "hi": [3, 1, 1]}}, "traction": [10, 0, 0]}]}
JSON
}
# 'soft' by name, 'hard' (id 5) keeps the default material.
bar_problem '[{"region": "soft", "E": 2000, "nu": 0}]' bar.json
chain bar.vtu "" bar.json bar
grep -q '"nb": 0' bar/system/system.json || fail "the bar has enriched DOFs"
$PY check-bar bar/enriched.vtu bar/u.mtx --length 2 --split 0.75 --E 2000 7000 --traction 10 || fail "bar"
# The same bar from gmsh: physical volumes 3 'soft' and 5 'hard' are the regions.
$PY msh box.vtu bar.msh --split 0.75 --ids 3 5 --names soft hard || fail "bar.msh"
chain bar.msh "" bar.json bar_msh
$PY check-bar bar_msh/enriched.vtu bar_msh/u.mtx --length 2 --split 0.75 --E 2000 7000 --traction 10 || fail "bar from gmsh"
# The same bar by ids, 'hard' given explicitly: the same system.
bar_problem '[{"region": 5, "E": 7000, "nu": 0}, {"region": 3, "E": 2000, "nu": 0}]' bar_ids.json
chain bar.vtu "" bar_ids.json bar_ids
cmp -s bar/system/K.petsc bar_ids/system/K.petsc || fail "materials by name and by id give different K"
# One material: the stiffer bar's end moves T L / E.
bar_problem "" one.json
chain bar.vtu "" one.json one
$PY check-bar one/enriched.vtu one/u.mtx --length 2 --split 0.75 --E 7000 7000 --traction 10 || fail "one material"
! cmp -s bar/system/K.petsc one/system/K.petsc || fail "two materials gave the single-material K"
# Every region given the default's material: bit for bit the run without `materials`.
bar_problem '[{"region": "soft", "E": 7000, "nu": 0}, {"region": "hard", "E": 7000, "nu": 0}]' same.json
chain bar.vtu "" same.json same
for f in K.petsc f.petsc dirichlet.mtx; do cmp -s one/system/$f same/system/$f || fail "$f differs with every region given the default's material"; done
$PY same-values one/u.mtx same/u.mtx || fail "u differs with every region given the default's material"
# Reactions (K u - f): the end moved by d = 1e-3 instead of pulled needs the force of the two
# springs in series, A d / (C / E1 + (L - C) / E2), A = 0.25 m^2 (the fixed end holds its opposite).
cat >moved.json <<'JSON'
{"material": {"E": 7000, "nu": 0}, "materials": [{"region": "soft", "E": 2000, "nu": 0}],
 "dirichlet": [{"name": "fixed end", "selector": {"box": {"lo": [-1, -1, -1], "hi": [1e-9, 1, 1]}}, "value": [0, 0, 0]},
               {"name": "moved end", "selector": {"box": {"lo": [1.999999, -1, -1], "hi": [3, 1, 1]}}, "value": [1e-3, 0, 0]}]}
JSON
chain bar.vtu "" moved.json moved
"$B/xfem-solve" -q moved/system -o moved/u2.mtx --report moved/solve.json || fail "solve --report"
python3 - moved/solve.json <<'PY' || fail "reactions of the moved bar"
import json, sys
r = {c["name"]: c["force"] for c in json.load(open(sys.argv[1]))["reactions"]["conditions"]}
expect = 0.25 * 1e-3 / (0.75 / 2000 + 1.25 / 7000)
ok = abs(r["moved end"][0] - expect) <= 1e-10 * expect and abs(r["fixed end"][0] + expect) <= 1e-10 * expect
print(f"reactions: moved end {r['moved end'][0]!r} N, fixed end {r['fixed end'][0]!r} N, closed form {expect!r} N")
sys.exit(0 if ok else 1)
PY

# --- Bad `materials`: one error line each, no output.
expect_error() {  # expect_error <text> <materials json>
  bar_problem "$2" bad.json
  rm -rf bad
  "$B/xfem-assemble" bar/enriched.vtu --problem bad.json -o bad 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc for $2: $(cat err.txt)"
  [ "$(grep -c "error:" err.txt)" -eq 1 ] || fail "expected one error line for $2: $(cat err.txt)"
  grep -qF -- "$1" err.txt || fail "expected '$1' for $2, got: $(cat err.txt)"
  [ ! -e bad ] || fail "output left behind for $2"
}
expect_error "bad.json: materials[0].region 'tumour' is not a region of bar/enriched.vtu (its regions: 3 'soft', 5 'hard')" \
  '[{"region": "tumour", "E": 1, "nu": 0}]'
expect_error "bad.json: materials[0].region 4 is not a region of bar/enriched.vtu (its regions: 3 'soft', 5 'hard')" \
  '[{"region": 4, "E": 1, "nu": 0}]'
expect_error "bad.json: materials[0].E must be positive, got 0" '[{"region": 3, "E": 0, "nu": 0}]'
expect_error "bad.json: materials[1].region lists region 3 again (materials[0] gives its material)" \
  '[{"region": 3, "E": 1, "nu": 0}, {"region": 3, "E": 2, "nu": 0}]'
expect_error "bad.json: materials[1].region names region 3 again (materials lists each region once)" \
  '[{"region": 3, "E": 1, "nu": 0}, {"region": "soft", "E": 2, "nu": 0}]'
expect_error "bad.json: materials[0].nu must be a number" '[{"region": 3, "E": 1, "nu": "zero"}]'
expect_error "bad.json: materials must be a list" '{"region": 3, "E": 1, "nu": 0}'

# --- Cuts through the interface x = 0.5 of the unit box (4 x 4 x 4 cubes): uniaxial stress
# 1e-3 along x, E = 1.5 (x < 0.5) and 0.5, nu = 0.45 and 0.15 (nu / E = 0.3 in both).
cat >field.json <<'JSON'
{"sigma": 1e-3, "split": 0.5, "E": [1.5, 0.5], "ratio": 0.3, "translation": [0.01, -0.02, 0.005]}
JSON
"$B/xfem-mesh" -q box --cells 4 4 4 --hi 1 1 1 -o cube.vtu || fail "xfem-mesh box (cube)"
$PY regions cube.vtu patch.vtu --split 0.5 --ids 1 2 --names stiff soft --exact field.json || fail "regions (patch)"
faces=""
for f in '[-1, -1, -1], [1e-9, 2, 2]' '[0.999999, -1, -1], [2, 2, 2]' '[-1, -1, -1], [2, 1e-9, 2]' \
         '[-1, 0.999999, -1], [2, 2, 2]' '[-1, -1, -1], [2, 2, 1e-9]' '[-1, -1, 0.999999], [2, 2, 2]'; do
  lo=${f%%]*}]; hi=[${f##*[}
  faces="$faces${faces:+,} {\"selector\": {\"box\": {\"lo\": $lo, \"hi\": $hi}}, \"value_array\": \"exact_u\"}"
done
cat >patch.json <<JSON
{"material": {"E": 1.5, "nu": 0.45}, "materials": [{"region": "soft", "E": 0.5, "nu": 0.15}], "dirichlet": [$faces]}
JSON
M="$B/xfem-mesh -q"
$M cut-rect --corner -0.5 -0.5 0.47 --edge1 2 0 0 --edge2 0 2 0 -o plane.vtp || fail "plane cut"
$M cut-rect --corner -0.5 -0.5 0.5 --edge1 2 0 0 --edge2 0 2 0 -o faces.vtp || fail "faces cut"
$M cut-disc --center 0.47 0.52 0.49 --normal 0 0 1 --radius 0.2 --rings 4 -o disc.vtp || fail "disc cut"
# A front on the interface's faces (x = 0.5), and one beyond it (x = 0.71).
$M cut-rect --corner 0.29 0.29 0.47 --edge1 0.21 0 0 --edge2 0 0.42 0 -o face-end.vtp || fail "face-end cut"
$M cut-rect --corner 0.29 0.29 0.47 --edge1 0.42 0 0 --edge2 0 0.42 0 -o across.vtp || fail "across cut"
$M cut-rect --corner -0.5 -0.5 0.3 --edge1 2 0 0 --edge2 0 2 0 -o a.vtp && $M cut-rect --corner -0.5 -0.5 0.7 \
  --edge1 0 2 0 --edge2 2 0 0 -o b.vtp && $M cut-merge a.vtp b.vtp -o two-pieces.vtp || fail "two-pieces cut"
# Fronts inside the body (enriched nodes off the faces x = 0, 1, which carry the load; the cut
# catalogue's rule): uniaxial stress across the interface, exact.
for c in disc face-end across; do
  chain patch.vtu $c.vtp patch.json $c
  "$B/xfem-visualize" -q $c/enriched.vtu --cut $c.vtp --solution $c/u.mtx --problem patch.json --wound-offset 0 \
    -o $c/deformed.vtu || fail "visualize $c"
  $PY check-patch $c/deformed.vtu $c/enriched.vtu --exact field.json || fail "patch test with two materials, cut $c"
  echo "ok: two-material patch test (uniaxial stress across the interface), cut $c"
done
# The check can fail: the same body solved as one material (no `materials`).
sed 's/"materials": \[[^]]*\], //' patch.json >one_patch.json
grep -q materials one_patch.json && fail "one_patch.json still has materials"
chain patch.vtu disc.vtp one_patch.json one_disc
"$B/xfem-visualize" -q one_disc/enriched.vtu --cut disc.vtp --solution one_disc/u.mtx --problem one_patch.json \
  -o one_disc/deformed.vtu || fail "visualize one_disc"
$PY check-patch one_disc/deformed.vtu one_disc/enriched.vtu --exact field.json >one_disc/check.txt &&
  fail "check-patch passes a one-material solution of the two-material field"
# Every region given the default's material, with a cut (enriched tets): the same bits as one_disc.
sed 's/"materials": \[[^]]*\]/"materials": [{"region": "soft", "E": 1.5, "nu": 0.45}, {"region": "stiff", "E": 1.5, "nu": 0.45}]/' \
  patch.json >same_patch.json
chain patch.vtu disc.vtp same_patch.json same_disc
for f in K.petsc f.petsc dirichlet.mtx; do cmp -s one_disc/system/$f same_disc/system/$f || fail "$f of the cut body differs with every region given the default's material"; done
$PY same-values one_disc/u.mtx same_disc/u.mtx || fail "u of the cut body differs with every region given the default's material"
"$B/xfem-visualize" -q same_disc/enriched.vtu --cut disc.vtp --solution same_disc/u.mtx --problem same_patch.json \
  -o same_disc/deformed.vtu || fail "visualize same_disc"
$PY same-vtu one_disc/deformed.vtu same_disc/deformed.vtu || fail "deformed.vtu differs with every region given the default's material"
# Cuts through the body (and the interface): the catalogue's discontinuous patch test, each side
# moved rigidly by its own motion (cut_catalogue.py), with the two materials: exact, zero strain.
CAT="python3 $XFEM_SOURCE/test/e2e/cut_catalogue.py"
$CAT problem 0 0 0 1 1 1 -o rigid0.json --exact rigid_exact.json || fail "cut_catalogue.py problem"
python3 - rigid0.json rigid.json <<'PY' || fail "rigid.json"
import json, sys
p = json.load(open(sys.argv[1]))
p["materials"] = [{"region": "soft", "E": 0.5, "nu": 0.15}, {"region": 1, "E": 1.5, "nu": 0.45}]
json.dump(p, open(sys.argv[2], "w"))
PY
$M cut-zigzag --lo -0.13 -0.1 --hi 1.07 1.1 --z0 0.47 --amplitude 0.13 --folds 3 -o zigzag.vtp || fail "zigzag cut"
for c in plane faces zigzag two-pieces; do
  chain patch.vtu $c.vtp rigid.json r-$c
  "$B/xfem-visualize" -q r-$c/enriched.vtu --cut $c.vtp --solution r-$c/u.mtx --problem rigid.json --wound-offset 0 \
    -o r-$c/deformed.vtu --faces r-$c/wound.vtp || fail "visualize r-$c"
  "$B/xfem-rmserror" -q r-$c/enriched.vtu --cut $c.vtp --solution r-$c/u.mtx --exact rigid_exact.json -o r-$c/error.json >/dev/null ||
    fail "rmserror r-$c"
  $CAT check --cut $c.vtp --deformed r-$c/deformed.vtu --wound r-$c/wound.vtp --box 0 0 0 1 1 1 --mode through \
    --rms r-$c/error.json --exact rigid_exact.json 2>/dev/null || fail "the catalogue's patch test with two materials, cut $c"
  echo "ok: two-material discontinuous patch test (rigid sides), cut $c"
done
grep -q '"nb": [1-9]' disc/system/system.json || fail "the disc has no branch DOFs"
# xfem-front: the disc's domains span the interface: refused with the reason.
"$B/xfem-front" disc/enriched.vtu --cut disc.vtp --solution disc/u.mtx --problem patch.json -o disc/front.vtp 2>err.txt
[ $? -eq 1 ] && [ "$(grep -c "error:" err.txt)" -eq 1 ] && grep -q "holds tets of two materials (regions" err.txt &&
  [ ! -e disc/front.vtp ] || fail "xfem-front with a domain across the interface: $(cat err.txt)"
# xfem-newton: each tet's law; with the linear model its answer is the linear path's.
"$B/xfem-newton" -q disc/enriched.vtu --cut disc.vtp --problem patch.json -o disc/newton.mtx ||
  fail "xfem-newton with two materials"
$PY close-values disc/newton.mtx disc/u.mtx || fail "xfem-newton with two materials differs from the linear path"
$PY close-values disc/newton.mtx one_disc/u.mtx >/dev/null && fail "xfem-newton's two materials give the one-material answer"
"$B/xfem-newton" -q same_disc/enriched.vtu --cut disc.vtp --problem same_patch.json -o same_disc/newton.mtx ||
  fail "xfem-newton with every region given one material"
# xfem-sweep: a blade moving along x across the interface; each step's solution equals the tools'
# (classify .. solve) on that step's cut with the same materials, and not the one-material one.
$M cut-sweep --path 0.05 0.43 1.2 0.95 0.43 1.2 --depth 0.6 --resolution 0.1 -o sweep.vtp || fail "cut-sweep"
cat >sweep.json <<'JSON'
{"material": {"E": 1e3, "nu": 0.3}, "materials": [{"region": "soft", "E": 150, "nu": 0.45}],
 "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}],
 "neumann": [{"name": "side", "selector": {"box": {"lo": [1, -1, -1], "hi": [2, 2, 2]}}, "traction": [-5, 2, 1]}],
 "body_force": [0, 0, -30]}
JSON
"$B/xfem-sweep" -q patch.vtu --cut sweep.vtp --problem sweep.json --steps 3 -o frames --solutions --cuts ||
  fail "xfem-sweep with two materials"
python3 -c "import sys; sys.exit(0 if 'Name=\"region\"' in open('frames/step_003.vtu', 'rb').read().decode('latin-1') else 1)" ||
  fail "the sweep's frames have no region array"
for k in 002 003; do
  chain patch.vtu frames/cut_$k.vtp sweep.json step_$k
  $PY close-values frames/u_$k.mtx step_$k/u.mtx || fail "sweep step $k differs from the tools' solution"
done
sed 's/"materials": \[[^]]*\],//' sweep.json >sweep_one.json
grep -q materials sweep_one.json && fail "sweep_one.json still has materials"
"$B/xfem-sweep" -q patch.vtu --cut sweep.vtp --problem sweep_one.json --steps 3 -o frames_one --solutions ||
  fail "xfem-sweep with one material"
$PY same-values frames/u_003.mtx frames_one/u_003.mtx >/dev/null && fail "the sweep's solution does not depend on the materials"
sed 's/"region": "soft"/"region": "liver"/' sweep.json >sweep_bad.json
"$B/xfem-sweep" patch.vtu --cut sweep.vtp --problem sweep_bad.json --steps 3 -o frames_bad 2>err.txt
[ $? -eq 1 ] && grep -qF "sweep_bad.json: materials[0].region 'liver' is not a region of patch.vtu (its regions: 1 'stiff', 2 'soft')" err.txt &&
  [ ! -e frames_bad ] || fail "xfem-sweep with an unknown region: $(cat err.txt)"
echo "materials: all checks passed"
