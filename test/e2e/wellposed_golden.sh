#!/usr/bin/env bash
# Golden file of the well-posed convergence study (pipelines/convergence-wellposed): its coarsest
# X-FEM run on a structured grid not aligned to the cut (2x4x13) and CG-FEM run (2x4x14), with the
# study's own problem.json and probes.csv, sampled by xfem-probe and compared with the committed
# probe values. Tolerance 1e-9 m per value (displacements ~1e-2 m: round-off room, nothing more).
# Also: the probe's bad-input paths, and physical checks that hold whatever the golden file says.
# Regenerate on purpose only: XFEM_UPDATE_GOLDEN=1 ctest -R e2e.wellposed_golden, then review.
set -euo pipefail
B=$XFEM_BIN
G=$XFEM_SOURCE/test/golden
P=$XFEM_SOURCE/pipelines/convergence-wellposed
TOL=1e-9
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" && cd "$XFEM_SCRATCH"

"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp
run_case() {  # name, then the xfem-mesh arguments; X-FEM when the name starts with xgrid
  local name=$1; shift
  mkdir -p "$name"
  "$B/xfem-mesh" -q "$@" -o "$name/mesh.vtu"
  if [[ $name == xgrid* ]]; then
    "$B/xfem-classify" -q "$name/mesh.vtu" --cut cut.vtp -o "$name/classified.vtu"
    "$B/xfem-enrich" -q "$name/classified.vtu" -o "$name/enriched.vtu"
    "$B/xfem-assemble" -q "$name/enriched.vtu" --cut cut.vtp --problem "$P/problem.json" -o "$name/system" 2>/dev/null
    "$B/xfem-solve" -q "$name/system" -o "$name/u.mtx" 2>/dev/null
    "$B/xfem-probe" -q "$name/enriched.vtu" --cut cut.vtp --solution "$name/u.mtx" --points "$P/probes.csv" -o "$name/probe.csv"
  else
    "$B/xfem-classify" -q "$name/mesh.vtu" -o "$name/classified.vtu"
    "$B/xfem-enrich" -q "$name/classified.vtu" -o "$name/enriched.vtu"
    "$B/xfem-assemble" -q "$name/enriched.vtu" --problem "$P/problem.json" -o "$name/system"
    "$B/xfem-solve" -q "$name/system" -o "$name/u.mtx"
    "$B/xfem-probe" -q "$name/classified.vtu" --solution "$name/u.mtx" --points "$P/probes.csv" -o "$name/probe.csv"
  fi
  # Whatever the golden file: the crack opens (upper face above the lower one at the mouth), and
  # the top corner moves exactly by the prescribed 0.02 m.
  awk -F, -v name="$name" 'NR == 2 { up = $7 } NR == 3 { low = $7 } NR == 6 { top = $7 }
    END { if (!(up - low > 1e-3)) { print "wellposed_golden: " name ": crack opening " up - low " m, expected > 1 mm" > "/dev/stderr"; exit 1 }
          if (!(top > 0.02 - 1e-12 && top < 0.02 + 1e-12)) { print "wellposed_golden: " name ": top corner uz " top ", expected 0.02" > "/dev/stderr"; exit 1 } }' \
    "$name/probe.csv"
  if [[ ${XFEM_UPDATE_GOLDEN:-0} == 1 ]]; then
    mkdir -p "$G/wellposed-$name" && cp "$name/probe.csv" "$G/wellposed-$name/" && echo "wellposed_golden: updated $G/wellposed-$name"
    return
  fi
  compare "$name/probe.csv" "$G/wellposed-$name/probe.csv" || { echo "wellposed_golden: $name differs from $G/wellposed-$name/probe.csv by more than $TOL m" >&2; exit 1; }
  echo "wellposed_golden: $name matches its golden probe values within $TOL m"
}
compare() {  # same points and sides, displacements within TOL
  awk -F, -v tol=$TOL 'NR == FNR { a[FNR] = $0; n = FNR; next }
    { split(a[FNR], r, ","); if (FNR == 1) { if ($0 != a[1]) bad = 1; next }
      for (c = 1; c <= 4; ++c) if (r[c] != $c) bad = 1
      for (c = 5; c <= 7; ++c) { d = r[c] - $c; if (d < 0) d = -d; if (!(d <= tol)) bad = 1 } }
    END { exit bad || FNR != n }' "$1" "$2"
}

run_case xgrid-2x4x13 box --cells 2 4 13 --hi 0.03 0.06 0.2
run_case cg-2x4x14 box --cells 2 4 14 --hi 0.03 0.06 0.2 --beam-cut

if [[ ${XFEM_UPDATE_GOLDEN:-0} != 1 ]]; then
  # The comparison must be able to fail: a value off by 1e-8 m is refused.
  awk -F, 'BEGIN { OFS = "," } NR == 2 { $7 = $7 + 1e-8 } { print }' cg-2x4x14/probe.csv > off.csv
  if compare off.csv "$G/wellposed-cg-2x4x14/probe.csv"; then
    echo "wellposed_golden: a probe value off by 1e-8 m passed the comparison" >&2; exit 1
  fi
fi

# Points from a .vtp (the 4 corners of a rectangle inside the beam) give the same values as the
# same points from a CSV.
"$B/xfem-mesh" -q cut-rect --corner 0.005 0.01 0.05 --edge1 0.01 0 0 --edge2 0 0.02 0 -o points.vtp
printf 'x,y,z\n0.005,0.01,0.05\n0.015,0.01,0.05\n0.015,0.03,0.05\n0.005,0.03,0.05\n' > points.csv
"$B/xfem-probe" -q cg-2x4x14/classified.vtu --solution cg-2x4x14/u.mtx --points points.vtp -o from_vtp.csv
"$B/xfem-probe" -q cg-2x4x14/classified.vtu --solution cg-2x4x14/u.mtx --points points.csv -o from_csv.csv
[[ $(sort from_vtp.csv | md5sum) == $(sort from_csv.csv | md5sum) ]] || {
  echo "wellposed_golden: .vtp and .csv points give different values:" >&2; paste -d'|' from_vtp.csv from_csv.csv >&2; exit 1; }

# xfem-probe's bad input: one line on stderr naming the file, exit 1, no output file.
expect_error() {  # expected message, then the xfem-probe arguments
  local want=$1; shift
  if "$B/xfem-probe" -q "$@" -o bad.csv 2> err.txt; then echo "wellposed_golden: xfem-probe $* succeeded" >&2; exit 1; fi
  grep -q "^xfem-probe: error: .*$want" err.txt || { echo "wellposed_golden: expected '$want', got: $(cat err.txt)" >&2; exit 1; }
  [[ $(wc -l < err.txt) == 1 && ! -e bad.csv ]] || { echo "wellposed_golden: xfem-probe $*: more than one line or an output file" >&2; exit 1; }
}
printf 'x,y,z\n0.04,0.01,0.01\n' > outside.csv
expect_error "outside.csv: point 1 (0.04, 0.01, 0.01) lies outside the mesh" \
  cg-2x4x14/classified.vtu --solution cg-2x4x14/u.mtx --points outside.csv
printf 'x,y,z,side\n0,0,0,3\n' > side.csv
expect_error "side.csv: line 2: side must be -1, 0 or 1" cg-2x4x14/classified.vtu --solution cg-2x4x14/u.mtx --points side.csv
expect_error "an X-FEM mesh needs its cut" xgrid-2x4x13/enriched.vtu --solution xgrid-2x4x13/u.mtx --points "$P/probes.csv"
expect_error "values, expected 3 x" cg-2x4x14/classified.vtu --solution xgrid-2x4x13/u.mtx --points "$P/probes.csv"
echo "wellposed_golden: ok"
