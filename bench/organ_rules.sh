#!/usr/bin/env bash
# The organ with each integration rule (issue 35), side by side in one run: the whole pipeline
# (xfem-mesh organ, cut-sine, classify, enrich, assemble, solve; no picture) and xfem-assemble's own
# "enriched tets" time per rule, runs alternated, medians, load printed before and after; then the
# RMS of the original DOFs U_k (3 NP values, m) of each rule's solution against the solution with the
# reference rule (assembled once). Usage:
#   bench/organ_rules.sh BIN[:BIN...] SIZE "RULES" "REFERENCE" [RUNS]
#   e.g. bench/organ_rules.sh build/tools 0.022 "--rule=uniform --rule=conforming --rule=graded" "--order=6" 7
# (a rule's options joined by '=' instead of spaces, split again here). OMP_NUM_THREADS is honoured.
# BIN may list several builds separated by ':' (e.g. before:after, /work/main/build/tools:build/tools):
# every build runs every rule, alternated within each round, one row per build and rule, the
# reference assembled with the last build.
set -euo pipefail
bins=$1 size=$2 rules=$3 reference=$4 runs=${5:-7}
IFS=: read -r -a binlist <<< "$bins"
for ((b = 0; b < ${#binlist[@]}; ++b)); do binlist[$b]=$(cd "${binlist[$b]}" && pwd); done
bin=${binlist[-1]}
# Rows: "BUILDINDEX@RULE".
rows=""
for r in $rules; do for ((b = 0; b < ${#binlist[@]}; ++b)); do rows+="$b@$r "; done; done
root=$(cd "$(dirname "$0")/.." && pwd)
problem=$root/pipelines/organ/problem.json
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
declare -A whole enr
echo "load before: $(uptime | sed 's/.*load average: //')"
for ((i = 0; i < runs; ++i)); do
  for row in $rows; do
    bin=${binlist[${row%%@*}]} r=${row#*@}
    start=$(date +%s.%N)
    "$bin/xfem-mesh" -q organ --size "$size" -o organ.vtu
    "$bin/xfem-mesh" -q cut-sine -o cut.vtp
    "$bin/xfem-classify" -q organ.vtu --cut cut.vtp -o classified.vtu
    "$bin/xfem-enrich" -q classified.vtu -o enriched.vtu
    "$bin/xfem-assemble" enriched.vtu --cut cut.vtp --problem "$problem" ${r//=/ } -o sys 2> assemble.log
    "$bin/xfem-solve" -q sys -o "u${row//[^a-z0-9]/_}.mtx"
    whole[$row]+="$(echo "$(date +%s.%N) - $start" | bc) "
    enr[$row]+="$(sed -n 's/.*enriched tets \([0-9.]*\) s.*/\1/p' assemble.log) "
  done
done
bin=${binlist[-1]}
echo "load after: $(uptime | sed 's/.*load average: //')"
"$bin/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$problem" ${reference//=/ } -o ref-sys 2> /dev/null
"$bin/xfem-solve" -q ref-sys -o ref.mtx
np=$(grep -a -o 'NumberOfPoints="[0-9]*"' enriched.vtu | head -1 | tr -dc 0-9)
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf "%-28s %12s %14s %14s   (organ --size %s, reference %s, %d runs)\n" rule "pipeline s" "enriched s" \
  "RMS U vs ref m" "$size" "$reference" "$runs"
for ((b = 0; b < ${#binlist[@]}; ++b)); do echo "build $b: ${binlist[$b]}"; done
for row in $rows; do
  rms=$(python3 - "$np" "u${row//[^a-z0-9]/_}.mtx" ref.mtx <<'PY'
import math, sys
def read(path):
    rows = [l for l in open(path) if not l.startswith("%")]
    return [float(l.split()[-1]) for l in rows[1:]]
n = 3 * int(sys.argv[1]); a, b = read(sys.argv[2])[:n], read(sys.argv[3])[:n]
print("%.3e" % math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / n))
PY
)
  printf "%-28s %12.3f %14.3f %14s\n" "$row" "$(echo ${whole[$row]} | median)" "$(echo ${enr[$row]} | median)" "$rms"
done
