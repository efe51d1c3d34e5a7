#!/usr/bin/env bash
# The beam's crack opening with each integration rule against an order-8 assembly (issue 35): for
# each unstructured beam size (the well-posed convergence study's problem, pipelines/
# convergence-wellposed), assemble and solve with every rule asked for and with --rule conforming
# --order 8, probe the mouth at mid-width (x = 0, y = 0.03, z = 0.1, both faces) and two points
# along the front (x = 0.015, y = 0.015 / 0.045, z = 0.1 - 0.002 and + 0.002: the opening just
# behind the front is measured at x = 0.012), and print the openings, their relative errors against
# order 8 and the RMS of the original DOFs U_k (3 NP values, m) against the order-8 solution, with the enriched tets'
# integration time (xfem-assemble's own). Usage:
#   bench/beam_opening.sh BIN "SIZES" "RULES" [SCRATCH]
#   e.g. bench/beam_opening.sh build/tools "0.01 0.007 0.005 0.004" "--order=3 --rule=graded"
# A size grid:AxBxC is the structured grid of the study's X-FEM family (xfem-mesh box --cells A B C),
# whose nodes lie in the front's plane x = 0.015: e.g. "grid:2x4x13 grid:4x8x25".
# (a rule's options joined by '=' instead of spaces, split again here).
set -euo pipefail
bin=$1 sizes=$2 rules=$3 scratch=${4:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)
problem=$root/pipelines/convergence-wellposed/problem.json
mkdir -p "$scratch"; cd "$scratch"
"$bin/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp
cat > probes.csv <<'P'
x,y,z,side
0,0.03,0.1,1
0,0.03,0.1,-1
0.012,0.015,0.1,1
0.012,0.015,0.1,-1
0.012,0.045,0.1,1
0.012,0.045,0.1,-1
P
opening() {  # opening <values.csv> <row pair 0..2>: uz above - uz below
  awk -F, -v k="$2" 'NR > 1 {uz[NR - 2] = $7} END {printf "%.9e", uz[2 * k] - uz[2 * k + 1]}' "$1"
}
printf "%-7s %-28s %12s %9s %12s %9s %12s %9s %11s %8s\n" size rule "mouth mm" "err" "front1 mm" "err" "front2 mm" "err" "RMS m" "enr s"
for h in $sizes; do
  [ -f beam-$h-enriched.vtu ] || {
    case $h in
      grid:*) "$bin/xfem-mesh" -q box --cells $(echo "${h#grid:}" | tr x " ") --hi 0.03 0.06 0.2 -o beam-$h.vtu ;;  # e.g. grid:2x4x13
      *) "$bin/xfem-mesh" -q unstructured-box --hi 0.03 0.06 0.2 --size "$h" -o beam-$h.vtu ;;
    esac
    "$bin/xfem-classify" -q beam-$h.vtu --cut cut.vtp -o beam-$h-classified.vtu
    "$bin/xfem-enrich" -q beam-$h-classified.vtu -o beam-$h-enriched.vtu
  }
  for r in "--order=8" $rules; do
    tag=$(echo "$r" | tr -c 'a-z0-9\n' _)
    if [ ! -f "u-$h-$tag.mtx" ]; then
      "$bin/xfem-assemble" beam-$h-enriched.vtu --cut cut.vtp --problem "$problem" ${r//=/ } -o sys-$h-$tag 2> assemble-$h-$tag.log
      "$bin/xfem-solve" -q sys-$h-$tag -o u-$h-$tag.mtx
    fi
    "$bin/xfem-probe" -q beam-$h-enriched.vtu --cut cut.vtp -s u-$h-$tag.mtx -p probes.csv -o values-$h-$tag.csv
    t=$(sed -n 's/.*enriched tets \([0-9.]*\) s.*/\1/p' assemble-$h-$tag.log | head -1)
    np=$(grep -a -o 'NumberOfPoints="[0-9]*"' beam-$h-enriched.vtu | head -1 | tr -dc 0-9)
    rms=$(python3 - "$np" u-$h-$tag.mtx u-$h-__order_8.mtx <<'PY'
import math, sys
def read(path):
    rows = [l for l in open(path) if not l.startswith("%")]
    return [float(l.split()[-1]) for l in rows[1:]]
n = 3 * int(sys.argv[1]); a, b = read(sys.argv[2])[:n], read(sys.argv[3])[:n]
print("%.6e" % math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / n))
PY
)
    line="$(printf "%-7s %-28s" "$h" "$r")"
    for k in 0 1 2; do
      o=$(opening values-$h-$tag.csv $k); ref=$(opening values-$h-__order_8.csv $k)
      line+=$(awk -v o="$o" -v r="$ref" 'BEGIN {printf " %12.6f %9.2e", o * 1e3, (o - r) / r}')
    done
    printf "%s %11.3e %8s\n" "$line" "$rms" "$t"
  done
done
echo "load: $(uptime | sed 's/.*load average: //')"
