#!/usr/bin/env bash
# compare.sh OUT STEPS EVERY: for steps EVERY, 2 EVERY, ..., STEPS, runs xfem-classify, -enrich, -assemble,
# -solve and -visualize from scratch on the sweep's cut of that step (OUT/timing/cut_NNN.vtp, from the sweep
# run without pictures, as the tools make none: OUT/timing.json), timing the solution (the first four tools)
# and the frame (xfem-visualize) apart, and prints CSV: step, enriched DOFs, the sweep's times for the step
# (s: its solution, its frame files, written in a second thread while the next step is solved, and the
# step's wall time, its share of the sweep's whole time), the from-scratch times of the solution and the
# frame (s), and the ratios sweep / from scratch: solution to solution, and the step's wall time to
# solution + frame. The sweep writes its frames with LZ4, xfem-visualize with zlib (its default, which
# every VTK reader reads): the frame is timed again with --compression lz4, the last two columns are
# the frame time and the step's ratio with it.
set -euo pipefail
OUT=$1; STEPS=$2; EVERY=$3; B=$BIN
now() { date +%s.%N; }
echo "step,enriched_dofs,sweep_solve_seconds,sweep_frame_seconds,sweep_step_seconds,scratch_solve_seconds,scratch_frame_seconds,solve_ratio,total_ratio,scratch_frame_lz4_seconds,total_ratio_lz4"
for ((k = EVERY; k <= STEPS; k += EVERY)); do
  n=$(printf %03d "$k"); D=$OUT/scratch_$n; C=$OUT/timing/cut_$n.vtp
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
  "$B/xfem-visualize" -q "$D/enriched.vtu" --cut "$C" --solution "$D/u.mtx" --problem problem.json \
    -o "$D/deformed_lz4.vtu" --faces "$D/wound_lz4.vtp" --compression lz4
  t3=$(now)
  python3 - "$OUT/timing.json" "$k" "$t0" "$t1" "$t2" "$t3" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["steps"][int(sys.argv[2]) - 1]
t0, t1, t2, t3 = map(float, sys.argv[3:7])
solve, frame, step = s["seconds"], s["frame_seconds"], s["step_seconds"]
print(f"{s['step']},{s['enriched_dofs']},{solve:.3f},{frame:.3f},{step:.3f},{t1 - t0:.3f},{t2 - t1:.3f},"
      f"{solve / (t1 - t0):.3f},{step / (t2 - t0):.3f},{t3 - t2:.3f},{step / (t1 - t0 + t3 - t2):.3f}")
PY
done
