#!/usr/bin/env bash
# Large deformation through the pipeline (xfem-mesh, -classify, -enrich, xfem-newton,
# xfem-visualize): rigid motions are stress-free and homogeneous deformations match their closed
# forms in deformed.vtu (docs/VERIFICATION.md "Large deformation"; the checks and their
# tolerances: test/e2e/large_deformation.py). E = 1e3 Pa, nu = 0.3.
#   rotation:  an uncut 0.1 x 0.1 x 0.2 m box, every boundary node turned by 90 degrees about a
#              vertical axis (through x = 0.03, y = 0.06): corotational and neo-Hookean max von Mises < 1e-8 E;
#              the linear model's sigma_xx = 2 (lambda + mu)(cos theta - 1) to 1e-6;
#   cut:       the same box cut clean through at z = 0.09, the same rotation: stress-free;
#   open book: the cut box, its boundary nodes above the cut turned by +30 degrees, below by -30
#              degrees about the x axis on the cut: stress-free, the cut faces apart by the two
#              rotations' difference at every cut point;
#   uniaxial:  a neo-Hookean bar stretched to 1.5 (uncut, and cut along the load, the cut inside the
#              bar away from its loaded ends): lateral stretch, P11 and every displacement against the
#              closed form to 1e-8;
#   shear:     simple shear gamma = 0.5 on every boundary node of the uncut box: sigma_xy = mu gamma
#              to 1e-8 (not with a cut: Dirichlet values hold the original DOFs only, so the boundary
#              of a cut element is not fully prescribed and the pieces relax: the sheared state is
#              no longer the discrete solution; a rigid motion, of zero energy, still is);
# and xfem-visualize's volume line (relative change 0, or J - 1; per side when cut; 0 inverted).
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN
PY="python3 $XFEM_SOURCE/test/e2e/large_deformation.py"
fail() { echo "FAIL: $*"; exit 1; }

"$B/xfem-mesh" -q box --cells 2 2 4 --hi 0.1 0.1 0.2 -o box.vtu || fail "xfem-mesh box"
"$B/xfem-mesh" -q box --cells 4 2 2 --hi 0.2 0.1 0.1 -o bar.vtu || fail "xfem-mesh bar"
"$B/xfem-mesh" -q cut-rect --corner -0.05 -0.05 0.09 --edge1 0.2 0 0 --edge2 0 0.2 0 -o through.vtp || fail "cut z = 0.09"
"$B/xfem-mesh" -q cut-rect --corner 0.06 0.045 -0.05 --edge1 0.08 0 0 --edge2 0 0 0.2 -o along.vtp || fail "cut y = 0.045"
$PY problems || fail "writing the problems"

enrich() {  # enrich <mesh> <prefix> [cut]
  "$B/xfem-classify" -q "$1" ${3:+--cut "$3"} -o "$2classified.vtu" || fail "classify $2"
  "$B/xfem-enrich" -q "$2classified.vtu" -o "$2enriched.vtu" || fail "enrich $2"
}
# run <enriched prefix> <problem> <name> [cut] [newton options]: xfem-newton, then xfem-visualize
# into <name>.vtu with its stderr in <name>.txt.
run() {
  local e=$1 p=$2 n=$3 c=${4:-}; shift 4
  "$B/xfem-newton" -q "${e}enriched.vtu" ${c:+--cut "$c"} --problem "$p" -o "$n-u.mtx" "$@" || fail "xfem-newton $n"
  "$B/xfem-visualize" "${e}enriched.vtu" ${c:+--cut "$c"} --solution "$n-u.mtx" --problem "$p" -o "$n.vtu" \
    --faces "$n-wound.vtp" 2>"$n.txt" || fail "xfem-visualize $n: $(cat "$n.txt")"
}
enrich box.vtu box-
enrich box.vtu cut- through.vtp
enrich bar.vtu bar-
enrich bar.vtu along- along.vtp

# Rigid motions: no load at all, the default tolerance (the residual's scale has a floor).
for model in corotational neo-hookean; do
  run box- "rotation-$model.json" "rotation-$model" ""
  $PY rotation "rotation-$model.vtu" "$model" || exit 1
  $PY volume "rotation-$model.txt" 0 0 || exit 1
  run cut- "rotation-$model.json" "cut-rotation-$model" through.vtp
  $PY rotation "cut-rotation-$model.vtu" "$model" || exit 1
  $PY volume "cut-rotation-$model.txt" 0 3 || exit 1
done
# The linear model through the linear tools: Hooke's stress of the rotation, in closed form.
"$B/xfem-assemble" -q box-enriched.vtu --problem rotation-linear.json -o linear-system || fail "xfem-assemble linear"
"$B/xfem-solve" -q linear-system -o rotation-linear-u.mtx || fail "xfem-solve linear"
"$B/xfem-visualize" -q box-enriched.vtu --solution rotation-linear-u.mtx --problem rotation-linear.json \
  -o rotation-linear.vtu || fail "xfem-visualize linear"
$PY rotation rotation-linear.vtu linear || exit 1

run cut- book.json book through.vtp
$PY book book.vtu || exit 1
$PY volume book.txt 0 3 || exit 1
grep -q "cut opening (u+ - u-) . n at [1-9]" book.txt || fail "open book: no cut opening reported: $(cat book.txt)"

run bar- uniaxial.json uniaxial ""
$PY uniaxial uniaxial.vtu uniaxial.txt 0 || exit 1
run along- uniaxial.json uniaxial-cut along.vtp
$PY uniaxial uniaxial-cut.vtu uniaxial-cut.txt 3 || exit 1

run box- shear.json shear ""
$PY shear shear.vtu || exit 1
$PY volume shear.txt 0 0 || exit 1

echo "PASS"
