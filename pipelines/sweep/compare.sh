#!/usr/bin/env bash
# compare.sh OUT STEPS EVERY: for steps EVERY, 2 EVERY, ..., STEPS, runs xfem-classify, -enrich, -assemble,
# -solve and -visualize from scratch on the sweep's cut of that step (OUT/frames/cut_NNN.vtp), timing the
# solution (the first four tools) and the frame (xfem-visualize) apart, and prints CSV: step, enriched DOFs,
# the sweep's time for the step's solution and for its frame files (s, from OUT/sweep.json; the picture
# left out: the tools make none), the from-scratch times of the same two parts (s), and the ratios
# sweep / from scratch for the solution and for solution + frame.
set -euo pipefail
OUT=$1; STEPS=$2; EVERY=$3; B=$BIN
now() { date +%s.%N; }
echo "step,enriched_dofs,sweep_solve_seconds,sweep_frame_seconds,scratch_solve_seconds,scratch_frame_seconds,solve_ratio,total_ratio"
for ((k = EVERY; k <= STEPS; k += EVERY)); do
  n=$(printf %03d "$k"); D=$OUT/scratch_$n; C=$OUT/frames/cut_$n.vtp
  mkdir -p "$D"
  t0=$(now)
  "$B/xfem-classify" -q "$OUT/organ.vtu" --cut "$C" -o "$D/classified.vtu"
  "$B/xfem-enrich" -q "$D/classified.vtu" -o "$D/enriched.vtu"
  "$B/xfem-assemble" -q "$D/enriched.vtu" --cut "$C" --problem problem.json -o "$D/system"
  "$B/xfem-solve" -q "$D/system" -o "$D/u.mtx"
  t1=$(now)
  "$B/xfem-visualize" -q "$D/enriched.vtu" --cut "$C" --solution "$D/u.mtx" --problem problem.json \
    -o "$D/deformed.vtu" --faces "$D/wound.vtp"
  t2=$(now)
  python3 - "$OUT/sweep.json" "$k" "$t0" "$t1" "$t2" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["steps"][int(sys.argv[2]) - 1]
t0, t1, t2 = map(float, sys.argv[3:6])
solve, frame = s["seconds"], s["frame_seconds"]
print(f"{s['step']},{s['enriched_dofs']},{solve:.3f},{frame:.3f},{t1 - t0:.3f},{t2 - t1:.3f},"
      f"{solve / (t1 - t0):.3f},{(solve + frame) / (t2 - t0):.3f}")
PY
done
