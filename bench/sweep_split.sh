#!/usr/bin/env bash
# Where a sweep step's time goes (issue 35): xfem-sweep runs of one or two builds, alternated, on one
# body and sweep, then per build the median over each run's cutting steps of every part of the
# report's `split` (classify, enrich, integrate, gather, Schur update, solve, back-substitution,
# frame), of the step's wall time and (reports from issue 35's third round on) of the process's CPU
# time during the step (every thread's: the measure the load hardly changes), with the load at each
# run's start (docs/PERFORMANCE.md, "Progressive cutting"). A build whose reports have no `split` (before issue 35) is split from
# its older fields (classify with enrich; back-substitution with the frame).
#   bench/sweep_split.sh OUT BODY SWEEP PROBLEM STEPS RUNS XFEM_SWEEP [XFEM_SWEEP_B]
set -eu
out=$1 body=$2 sweep=$3 problem=$4 steps=$5 runs=$6; shift 6
mkdir -p "$out"
for r in $(seq 1 "$runs"); do
  b=0
  for bin in "$@"; do
    b=$((b + 1))
    echo "build $b run $r: load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out/load.txt" >&2
    "$bin" -q "$body" --cut "$sweep" --problem "$problem" --steps "$steps" -o "$out/frames_$b" \
      --report "$out/report_${b}_$r.json"
  done
done
python3 - "$out" "$#" "$runs" <<'PY'
import json, statistics, sys
out, builds, runs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
parts = ["classify", "enrich", "integrate", "gather", "schur_update", "solve", "back_substitution", "frame"]
def split(s):
    if "split" in s:
        return s["split"]
    return {"classify": s["classify_seconds"], "enrich": 0.0, "integrate": s["elements_seconds"],
            "gather": s["assemble_seconds"] - s["elements_seconds"],
            "schur_update": s["schur_columns_seconds"] + s["schur_factor_seconds"],
            "solve": s["solve_seconds"] - s["schur_columns_seconds"] - s["schur_factor_seconds"],
            "back_substitution": 0.0, "frame": s["frame_seconds"]}
for b in range(1, builds + 1):
    for r in range(1, runs + 1):
        rep = json.load(open(f"{out}/report_{b}_{r}.json"))
        steps = [s for s in rep["steps"] if s["enriched_dofs"] > 0]
        med = {p: statistics.median(split(s)[p] for s in steps) for p in parts}
        wall = statistics.median(s["step_seconds"] for s in steps)
        cpu = (f", step CPU {1e3 * statistics.median(s['step_cpu_seconds'] for s in steps):.1f} ms"
               if "step_cpu_seconds" in steps[0] else "")
        integrated = statistics.median(s["recomputed_tets"] for s in steps)
        print(f"build {b} run {r}: {len(steps)} steps, step wall {1e3 * wall:.1f} ms{cpu}, tets integrated {integrated:.0f}; " +
              ", ".join(f"{p} {1e3 * med[p]:.1f}" for p in parts) + " (ms, medians)")
PY
