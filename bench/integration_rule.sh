#!/usr/bin/env bash
# Cost of the default integration rule (--rule conforming) (exact cut pieces, front-singular Gauss order 3) against the
# paper's oversampling, on the enriched tets only (xfem-assemble's own "enriched tets" time), runs
# alternated, medians printed. Usage: bench/integration_rule.sh BIN ENRICHED.vtu CUT PROBLEM [RUNS]
#   e.g. bench/integration_rule.sh build/tools pipelines/beam/out/enriched.vtu \
#        pipelines/beam/out/cut.vtp pipelines/beam/problem.json 7
set -euo pipefail
bin=$1 enriched=$2 cut=$3 problem=$4 runs=${5:-7}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
declare -A times
rules=("--rule oversampling --points 30" "--rule oversampling --points 100" "--rule conforming")
for ((i = 0; i < runs; ++i)); do
  for r in "${rules[@]}"; do
    t=$("$bin/xfem-assemble" "$enriched" --cut "$cut" --problem "$problem" $r -o "$tmp/sys" 2>&1 |
        sed -n 's/.*enriched tets \([0-9.]*\) s.*/\1/p')
    times[$r]+="$t "
  done
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
base=$(echo ${times["--rule oversampling --points 30"]} | median)
for r in "${rules[@]}"; do
  m=$(echo ${times[$r]} | median)
  awk -v r="$r" -v m="$m" -v b="$base" 'BEGIN {printf "%-34s median %6.3f s  (%.2fx oversampling 30)\n", r, m, m / b}'
done
echo "load: $(uptime | sed 's/.*load average: //')"
