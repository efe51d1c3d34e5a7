#!/usr/bin/env bash
# The sweep's bench (issue 35; docs/PERFORMANCE.md "Progressive cutting"): pipelines/sweep's blade
# through the organ at ~100k tets (xfem-mesh organ --size 0.004, as pipelines/sweep) and at ~10k
# (--size 0.0085), 40 steps: per organ the step's time split by part over alternated runs of one or
# two builds' xfem-sweep (bench/sweep_split.sh, load stated per run), the growing classifier against
# classify from scratch on every step (bench/sweep_classify, thread CPU, equality checked), the Schur
# factor update's floor (bench/schur_floor: its flops at the machine's dgemm peak, from the first
# run's report) and nnz(L) with and without a sweep-aware ordering (bench/sweep_ordering). Inputs are generated once into OUT.
#   bench/sweep_bench.sh BUILD OUT [RUNS [OTHER_XFEM_SWEEP]]   (make -f Makefile.examples bench-sweep)
set -eu
build=$(cd "$1" && pwd) out=$2 runs=${3:-3} other=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
problem=$here/../pipelines/sweep/problem.json
mkdir -p "$out"
cd "$out"
[ -f sweep.vtp ] || "$build/tools/xfem-mesh" -q cut-sweep --arc-centre 0 -0.09 0.06 --arc-radius 0.1 \
  --arc-angles 40 140 --depth 0.05 --resolution 0.003 --duration 4 -o sweep.vtp
for size in 0.0085 0.004; do
  body=organ-$size.vtu
  [ -f "$body" ] || "$build/tools/xfem-mesh" -q organ --size "$size" -o "$body"
  echo "== organ --size $size: $(grep -ao 'NumberOfCells="[0-9]*"' "$body" | head -1)" >&2
  "$here/sweep_split.sh" "split-$size" "$body" sweep.vtp "$problem" 40 "$runs" "$build/tools/xfem-sweep" $other
  "$build/bench/sweep_classify" "$body" sweep.vtp 40 | tail -1
  "$build/bench/schur_floor" "split-$size/report_1_1.json" | sed -n '1p;$p'
  "$build/bench/sweep_ordering" "$body" "$problem" sweep.vtp 40
done
