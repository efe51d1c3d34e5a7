#!/usr/bin/env bash
# The catalogue of real cuts (issue 14): each case on a structured (4x4x4 cubes) and an
# unstructured unit box, run through classify, enrich, assemble (default rule), solve, visualize
# and rmserror, every tool without -q. Each case must show
#   - no "warning" on any tool's stderr, every tool exit 0;
#   - cuts through the body: the discontinuous patch test (every outer face moved rigidly, each
#     side by its own small rotation + translation): nodal displacement exact to 1e-10 of max|u|,
#     zero strain in every cell of deformed.vtu and in xfem-rmserror's samples, the gap exact;
#     deformed.vtu's volume on each side = the body's volume on that side (1e-12 relative, the true
#     volume integrated from the cut's own triangles), no cell straddling the cut, wound.vtp's
#     area on each side = the cut's area inside the body;
#   - cuts with a front inside the body (disc, ending on a face, a front through a node; all
#     horizontal or tilted about x): uniaxial tension
#     along x (traction-free on the cut, so the cut stays closed) on all faces is reproduced exactly:
#     nodes, the strain of every cell; total volume, wound area and the pieces behind the front as above;
#   - a cut missing the body: no enrichment, the plain linear solution, every cell whole.
# Checks: test/e2e/cut_catalogue.py. Cases failing today are listed in KNOWN_FAIL: they run, their
# failures are printed, and the suite stays green; a listed case that passes fails the suite
# (remove it from the list). CATALOGUE_CASES="s-zigzag u-disc" runs only those. CATALOGUE_RULE="--rule fast"
# assembles with that rule instead of the default (test e2e.cut_catalogue_fast).
set -u
# No case fails today (the cuts whose front ends inside the body pass since partially cut
# elements are split exactly and the branch gradients integrated consistently).
# CATALOGUE_KNOWN_FAIL="" runs every case as a real test.
KNOWN_FAIL="${CATALOGUE_KNOWN_FAIL-}"
KNOWN_FAIL=$(echo $KNOWN_FAIL)
ASSEMBLE_RULE="${CATALOGUE_RULE-}"
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; PY="python3 $XFEM_SOURCE/test/e2e/cut_catalogue.py"
BOX="0 0 0 1 1 1"
die() { echo "FAIL: $*"; exit 1; }

# Meshes: 384 structured tets; an unstructured box of a few hundred tets.
"$B/xfem-mesh" -q box --cells 4 4 4 --hi 1 1 1 -o "$S/s.vtu" || die "structured mesh"
"$B/xfem-mesh" -q unstructured-box --hi 1 1 1 --size 0.2 -o "$S/u.vtu" || die "unstructured mesh"
$PY problem $BOX -o "$S/problem.json" --exact "$S/exact.json" || die "problem.json"
$PY problem $BOX --linear -o "$S/problem_linear.json" --exact "$S/exact_linear.json" || die "problem_linear.json"

# Cuts: name -> how it is made ("@" = on the unstructured mesh, by cut_catalogue.py).
M="$B/xfem-mesh -q"
make_cut() {  # make_cut <case> <mesh s|u> <out>
  local c=$1 m=$2 o=$3
  case "$c" in
    nodes)  # z = x/8 + y/4 + 0.375 through grid nodes such as (0.5, 0.25, 0.5), containing no edge
      [ "$m" = s ] && $M cut-rect --corner -0.5 -0.5 0.1875 --edge1 2 0 0.25 --edge2 0 2 0.5 -o "$o" \
                   || $PY cut "$S/u.vtu" --through node -o "$o" ;;
    faces)  # the grid plane z = 0.5: along faces; unstructured: the plane of an interior face
      [ "$m" = s ] && $M cut-rect --corner -0.5 -0.5 0.5 --edge1 2 0 0 --edge2 0 2 0 -o "$o" \
                   || $PY cut "$S/u.vtu" --through face -o "$o" ;;
    edge)   # z = 2y - x - 0.25 contains the cubes' main diagonals (edges) but no face
      [ "$m" = s ] && $M cut-rect --corner -0.5 -0.5 -0.75 --edge1 2 0 -2 --edge2 0 2 4 -o "$o" \
                   || $PY cut "$S/u.vtu" --through edge -o "$o" ;;
    zigzag) $M cut-zigzag --lo -0.13 -0.1 --hi 1.07 1.1 --z0 0.47 --amplitude 0.13 --folds 3 -o "$o" ;;
    zigzag-dense)  # strips 0.15 wide: several folds inside one tet
      $M cut-zigzag --lo -0.13 -0.1 --hi 1.07 1.1 --z0 0.47 --amplitude 0.06 --folds 7 --divisions 2 -o "$o" ;;
    sine)   $M cut-sine --lo -0.1 -0.1 --hi 1.1 1.1 --z0 0.47 --amplitude 0.1 --wavelength 0.6 --divisions 24 2 -o "$o" ;;
    # Fronts inside: enriched nodes must stay off the faces x = 0, 1, where the linear field's
    # traction is not zero (free enriched DOFs there would take load the exact field does not have).
    disc)   $M cut-disc --center 0.47 0.52 0.49 --normal 0 0 1 --radius 0.2 --rings 4 -o "$o" ;;
    face-end)  # z = 0.47, x in [0.29, 0.5], y in [0.29, 0.71]: the front x = 0.5 lies on grid faces
      [ "$m" = s ] && $M cut-rect --corner 0.29 0.29 0.47 --edge1 0.21 0 0 --edge2 0 0.42 0 -o "$o" \
                   || $PY cut "$S/u.vtu" --through front-on-face -o "$o" ;;
    front-node)  # the front passes through an interior node: z = 0.375 + y/4 for 0.3 <= x <= 0.5,
      # the front x = 0.5 through the node (0.5, 0.5, 0.5) only; unstructured: z = N_z for
      # N_x - 0.12 <= x <= N_x, N the interior node nearest the centre. Horizontal or tilted about x:
      # traction-free under tension along x; across the body in y, off the faces x = 0, 1.
      [ "$m" = s ] && $M cut-rect --corner 0.3 -0.5 0.25 --edge1 0.2 0 0 --edge2 0 2 0.5 -o "$o" \
                   || $PY cut "$S/u.vtu" --through front-node -o "$o" ;;
    blade-node)  # issue 36 item 8: a blade (0.6 deep) swept along an arc ending above the top face's
      # node (0.5, 0.5, 1): its front, vertical, passes through that node (structured: and the
      # nodes below it). The elements that touch the front only at a node were split face by face,
      # 19 faces (structured) with one split edge and no front point. No height field: checked
      # for warnings, the split body's volume and the pair's fingerprints only (mode clean).
      $M cut-sweep --arc-centre 0.5 -0.5 1.1 --arc-radius 1 --arc-angles 30 90 --depth 0.6 --resolution 0.05 -o "$o" ;;
    two-pieces)  # z = 0.3 (normal +z) and z = 0.7 (normal -z): the middle slab is the +1 side
      $M cut-rect --corner -0.5 -0.5 0.3 --edge1 2 0 0 --edge2 0 2 0 -o "$o.a.vtp" &&
      $M cut-rect --corner -0.5 -0.5 0.7 --edge1 0 2 0 --edge2 2 0 0 -o "$o.b.vtp" &&
      $M cut-merge "$o.a.vtp" "$o.b.vtp" -o "$o" ;;
    touching)  # z = 0.47 for x <= 1: the cut's edge lies on the body's face x = 1
      $M cut-rect --corner -0.5 -0.5 0.47 --edge1 1.5 0 0 --edge2 0 2 0 -o "$o" ;;
    miss)   $M cut-rect --corner -0.5 -0.5 1.5 --edge1 2 0 0 --edge2 0 2 0 -o "$o" ;;
  esac
}
mode_of() {
  case "$1" in disc|face-end|front-node) echo front ;; miss) echo miss ;; blade-node) echo clean ;; *) echo through ;; esac
}

# One case: every stage without -q, stderr kept; prints the case's failures, returns 1 if any.
run_case() {  # run_case <mesh s|u> <cut name>
  local m=$1 c=$2 d="$S/$1-$2" mode problem exact
  mkdir -p "$d"; mode=$(mode_of "$c")
  problem="$S/problem.json"; exact="$S/exact.json"
  [ "$mode" = front ] || [ "$mode" = miss ] && { problem="$S/problem_linear.json"; exact="$S/exact_linear.json"; }
  local cut="$d/cut.vtp"; [ "$m" = u ] && case "$c" in nodes|faces|edge|face-end|front-node) cut="$d/cut.obj" ;; esac
  make_cut "$c" "$m" "$cut" 2>"$d/cut.err" || { echo "making the cut failed: $(head -1 "$d/cut.err")"; return 1; }
  local stage
  stage() {  # stage <name> <command...>: run, keep stderr in $d/<name>.err
    local name=$1; shift
    "$@" >"$d/$name.out" 2>"$d/$name.err" || { echo "$name exits $?: $(grep -m1 "error:" "$d/$name.err" || grep -m1 . "$d/$name.err")"; return 1; }
  }
  stage classify "$B/xfem-classify" "$S/$m.vtu" --cut "$cut" -o "$d/classified.vtu" --summary "$d/classify.json" &&
  stage enrich "$B/xfem-enrich" "$d/classified.vtu" -o "$d/enriched.vtu" &&
  stage assemble "$B/xfem-assemble" "$d/enriched.vtu" --cut "$cut" --problem "$problem" $ASSEMBLE_RULE -o "$d/system" &&
  stage solve "$B/xfem-solve" "$d/system" -o "$d/u.mtx" --report "$d/solve.json" &&
  stage visualize "$B/xfem-visualize" "$d/enriched.vtu" --cut "$cut" --solution "$d/u.mtx" --problem "$problem" --wound-offset 0 \
        -o "$d/deformed.vtu" --faces "$d/wound.vtp" &&
  stage rmserror "$B/xfem-rmserror" "$d/enriched.vtu" --cut "$cut" --solution "$d/u.mtx" --exact "$exact" -o "$d/error.json"
  local rc=$?
  # Warnings of every stage that ran, one line each.
  grep -H -i "warning" "$d"/*.err 2>/dev/null | sed "s|^$d/||; s|\.err:| stderr: |"
  grep -qi "warning" "$d"/*.err && rc=1
  if [ -e "$d/deformed.vtu" ]; then  # the opened cut; the patch test's figures if rmserror ran
    local rms=(); [ -e "$d/error.json" ] && rms=(--rms "$d/error.json" --exact "$exact")
    $PY check --cut "$cut" --deformed "$d/deformed.vtu" --wound "$d/wound.vtp" --box $BOX --mode "$mode" \
      "${rms[@]}" 2>"$d/check.err" || rc=1
    grep -v "^volumes:" "$d/check.err" | grep . && rc=1
  fi
  if [ "$mode" = miss ] && [ -e "$d/classify.json" ]; then
    python3 -c "import json,sys; c=json.load(open(sys.argv[1])); sys.exit(c['sign']+c['branch']+c['cut_edges'])" \
      "$d/classify.json" || { echo "a cut missing the body enriches nodes or cuts edges"; rc=1; }
  fi
  return $rc
}

CASES="nodes faces edge zigzag zigzag-dense sine disc face-end front-node blade-node two-pieces touching miss"
failed=""; known=""; fixed=""
for c in $CASES; do
  for m in s u; do
    name="$m-$c"
    [ -n "${CATALOGUE_CASES:-}" ] && [[ " $CATALOGUE_CASES " != *" $name "* ]] && continue
    out=$(run_case "$m" "$c")
    rc=$?
    listed=no; [[ " $KNOWN_FAIL " == *" $name "* ]] && listed=yes
    if [ $rc -eq 0 ] && [ $listed = no ]; then
      echo "ok          $name"
    elif [ $rc -eq 0 ]; then
      echo "NOW PASSES  $name: remove it from KNOWN_FAIL"; fixed="$fixed $name"
    elif [ $listed = yes ]; then
      echo "KNOWN FAIL  $name (skipped, listed in KNOWN_FAIL):"; echo "$out" | sed 's/^/              /'; known="$known $name"
    else
      echo "FAIL        $name:"; echo "$out" | sed 's/^/              /'; failed="$failed $name"
    fi
  done
done
# The checker can fail: s-two-pieces' opened mesh judged against another cut (z = 0.47 through).
if [ -e "$S/s-two-pieces/deformed.vtu" ] && [ -e "$S/s-touching/cut.vtp" ]; then
  $PY check --cut "$S/s-touching/cut.vtp" --deformed "$S/s-two-pieces/deformed.vtu" --wound "$S/s-two-pieces/wound.vtp" \
    --box $BOX --mode through >"$S/self.out" 2>&1 && die "cut_catalogue.py check passes a mesh cut elsewhere"
  grep -q "volume" "$S/self.out" || die "cut_catalogue.py check: no volume failure for a mesh cut elsewhere"
fi
[ -n "$known" ] && echo "skipped (known to fail):$known"
[ -z "$failed$fixed" ] || die "failed:$failed; passing but listed in KNOWN_FAIL:$fixed"
echo "cut catalogue: every case not in KNOWN_FAIL passes"
