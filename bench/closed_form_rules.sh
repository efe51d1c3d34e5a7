#!/usr/bin/env bash
# Cost of the conforming rule's variants on one enriched mesh (issue 35): xfem-assemble's whole wall
# time and its own "enriched tets" time for --rule uniform (the points of order 3 before issue 35,
# closed-form blocks), pieces (every block from the points), conforming (the default) and graded,
# runs alternated, medians printed with the load; ratios against uniform. Usage: bench/closed_form_rules.sh BIN ENRICHED.vtu CUT PROBLEM [RUNS]
#   e.g. bench/closed_form_rules.sh build/tools organ-enriched.vtu cut.vtp pipelines/organ/problem.json 7
# BIN may list several builds separated by ':' (before:after): each runs each rule, alternated,
# rows "BUILDINDEX@RULE"; ratios against the first build's uniform. RULES (environment, ';'
# separated) replaces the list of rules.
set -euo pipefail
bins=$1 enriched=$2 cut=$3 problem=$4 runs=${5:-7}
IFS=: read -r -a binlist <<< "$bins"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
declare -A wall enr
IFS=';' read -r -a onerules <<< "${RULES:---rule uniform;--rule pieces;--rule conforming;--rule graded}"
rules=()
for r in "${onerules[@]}"; do for ((b = 0; b < ${#binlist[@]}; ++b)); do rules+=("$b@$r"); done; done
for ((b = 0; b < ${#binlist[@]}; ++b)); do echo "build $b: ${binlist[$b]}"; done
echo "load before: $(uptime | sed 's/.*load average: //')"
for ((i = 0; i < runs; ++i)); do
  for row in "${rules[@]}"; do
    bin=${binlist[${row%%@*}]} r=${row#*@}
    start=$(date +%s.%N)
    t=$("$bin/xfem-assemble" "$enriched" --cut "$cut" --problem "$problem" $r -o "$tmp/sys" 2>&1 |
        sed -n 's/.*enriched tets \([0-9.]*\) s.*/\1/p')
    wall[$row]+="$(echo "$(date +%s.%N) - $start" | bc) "
    enr[$row]+="$t "
  done
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
base=$(echo ${enr[${rules[0]}]} | median)
for r in "${rules[@]}"; do
  m=$(echo ${enr[$r]} | median); w=$(echo ${wall[$r]} | median)
  awk -v r="$r" -v m="$m" -v w="$w" -v b="$base" \
    'BEGIN {printf "%-22s xfem-assemble median %6.3f s, enriched tets %6.3f s (%.2fx the first row)\n", r, w, m, m / b}'
done
echo "load after: $(uptime | sed 's/.*load average: //')"
