#!/usr/bin/env bash
# Small loads recover the linear solution: for the corotational and neo-Hookean models xfem-newton's
# u differs from the linear path's (xfem-assemble + xfem-solve) by O(s^2) at load scale s, so
# d(s) = max |u_nl - u_lin| / max |u_lin| is O(s) and d(s) / d(s/2) lies in [1.7, 2.3]
# (test/e2e/newton_small_loads.py). Cases, on coarse meshes (size 0.012):
#   beam:  the paper's beam and its cut (pipelines/beam), its pull scaled by S_BEAM;
#   organ: the organ-like body and its sine cut (pipelines/organ), its 1 cm lift scaled by S_ORGAN;
#   two:   the beam with its cut and a second cut from the other side (x >= 0.015) at z = 0.05.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; PY="python3 $XFEM_SOURCE/test/e2e/newton_small_loads.py"; M="$B/xfem-mesh -q"
fail() { echo "FAIL: $*"; exit 1; }
S_BEAM=0.1 S_ORGAN=0.1

$M unstructured-box --hi 0.03 0.06 0.2 --size 0.012 -o beam.vtu && $M cut-rect --beam-cut -o beam-cut.vtp &&
  $M cut-rect --corner 0.015 -0.01 0.05 --edge1 0.03 0 0 --edge2 0 0.08 0 -o second-cut.vtp &&
  $M organ --size 0.012 -o organ.vtu && $M cut-sine -o organ-cut.vtp || fail "meshes and cuts"

# check <name> <mesh> <source problem.json> <s> <cuts...>
check() {
  local name=$1 mesh=$2 source=$3 s=$4; shift 4
  local cuts=() c
  for c in "$@"; do cuts+=(--cut "$c"); done
  "$B/xfem-classify" -q "$mesh" "${cuts[@]}" -o "$name-classified.vtu" &&
    "$B/xfem-enrich" -q "$name-classified.vtu" -o "$name-enriched.vtu" || fail "$name: classify, enrich"
  local half model scale
  half=$(python3 -c "print($s / 2)")
  for scale in "$s" "$half"; do
    $PY scale "$source" "$scale" linear "$name-linear-$scale.json" || fail "$name: problem"
    "$B/xfem-assemble" -q "$name-enriched.vtu" "${cuts[@]}" --problem "$name-linear-$scale.json" -o "$name-system-$scale" &&
      "$B/xfem-solve" -q "$name-system-$scale" -o "$name-linear-$scale.mtx" || fail "$name: linear path at $scale"
    for model in corotational neo-hookean; do
      $PY scale "$source" "$scale" "$model" "$name-$model-$scale.json" || fail "$name: problem"
      "$B/xfem-newton" -q "$name-enriched.vtu" "${cuts[@]}" --problem "$name-$model-$scale.json" \
        -o "$name-$model-$scale.mtx" || fail "$name: xfem-newton $model at $scale"
    done
  done
  for model in corotational neo-hookean; do
    $PY ratio "$name $model" "$name-linear-$s.mtx" "$name-$model-$s.mtx" "$name-linear-$half.mtx" \
      "$name-$model-$half.mtx" || exit 1
  done
}

check beam beam.vtu "$XFEM_SOURCE/pipelines/beam/problem.json" $S_BEAM beam-cut.vtp
check organ organ.vtu "$XFEM_SOURCE/pipelines/organ/problem.json" $S_ORGAN organ-cut.vtp
check two beam.vtu "$XFEM_SOURCE/pipelines/beam/problem.json" $S_BEAM beam-cut.vtp second-cut.vtp
echo "PASS"
