#!/usr/bin/env bash
# compare.sh OUT STEPS EVERY: for steps EVERY, 2 EVERY, ..., STEPS, runs xfem-classify, -enrich, -assemble,
# -solve and -visualize from scratch on the sweep's cut of that step (OUT/frames/cut_NNN.vtp) and prints
# CSV: step, the sweep's time for the step (solve + write, s, from OUT/sweep.json), the from-scratch time (s).
set -euo pipefail
OUT=$1; STEPS=$2; EVERY=$3; B=$BIN
echo "step,sweep_seconds,from_scratch_seconds"
for ((k = EVERY; k <= STEPS; k += EVERY)); do
  n=$(printf %03d "$k"); D=$OUT/scratch_$n; C=$OUT/frames/cut_$n.vtp
  mkdir -p "$D"
  t0=$(date +%s.%N)
  "$B/xfem-classify" -q "$OUT/organ.vtu" --cut "$C" -o "$D/classified.vtu"
  "$B/xfem-enrich" -q "$D/classified.vtu" -o "$D/enriched.vtu"
  "$B/xfem-assemble" -q "$D/enriched.vtu" --cut "$C" --problem problem.json -o "$D/system"
  "$B/xfem-solve" -q "$D/system" -o "$D/u.mtx"
  "$B/xfem-visualize" -q "$D/enriched.vtu" --cut "$C" --solution "$D/u.mtx" --problem problem.json \
    -o "$D/deformed.vtu" --faces "$D/wound.vtp"
  t1=$(date +%s.%N)
  sweep=$(python3 -c "import json,sys; s=json.load(open('$OUT/sweep.json'))['steps'][$k-1]; print(s['seconds'] + s['write_seconds'])")
  echo "$k,$sweep,$(python3 -c "print($t1 - $t0)")"
done
