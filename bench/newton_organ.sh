#!/usr/bin/env bash
# xfem-newton (neo-Hookean) against the linear path (xfem-assemble + xfem-solve) on the organ
# example's mesh and cut and its problem.json (issue 32: the nonlinear solve should cost at most
# ~10x the linear one). Runs both N times, alternating, and prints the medians of wall and CPU
# (user + sys) time, then the last Newton report's load steps (iterations, tangents,
# factorizations and their times).
# Usage: bench/newton_organ.sh [N=3] [SIZE=0.012] [LIFT=0.01] [LOAD_STEPS=2]
#   env: BUILD (default build) holding tools/.
set -eu
n=${1:-3}
size=${2:-0.012}
lift=${3:-0.01}
steps=${4:-2}
build=${BUILD:-build}
B=$(cd "$build/tools" && pwd)
source_dir=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
median() { sort -g | awk '{v[NR]=$1} END{print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }

"$B/xfem-mesh" -q organ --size "$size" -o organ.vtu
"$B/xfem-mesh" -q cut-sine -o cut.vtp
"$B/xfem-classify" -q organ.vtu --cut cut.vtp -o classified.vtu
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu
python3 - "$source_dir/pipelines/organ/problem.json" "$lift" "$steps" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p['dirichlet'][1]['value'] = [None, None, float(sys.argv[2])]
json.dump(p, open('linear.json', 'w'))
p['material']['model'] = 'neo-hookean'
p['load_steps'] = int(sys.argv[3])
json.dump(p, open('neo-hookean.json', 'w'))
PY
timed() {  # timed <label> <command...>: appends "wall cpu" to <label>.times
  local label=$1; shift
  /usr/bin/time -f "%e %U %S" -o t.txt "$@" 2>/dev/null
  awk '{print $1, $2 + $3}' t.txt >> "$label.times"
}
for ((k = 0; k < n; ++k)); do
  rm -rf system
  /usr/bin/time -f "%e %U %S" -o a.txt "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem linear.json -o system
  /usr/bin/time -f "%e %U %S" -o s.txt "$B/xfem-solve" -q system -o u_linear.mtx
  paste a.txt s.txt | awk '{print $1 + $4, $2 + $3 + $5 + $6}' >> linear.times
  timed newton "$B/xfem-newton" -q enriched.vtu --cut cut.vtp --problem neo-hookean.json -o u.mtx --report newton.json
done
echo "organ --size $size ($(python3 -c "import json; r=json.load(open('newton.json')); print(r['dofs'], 'DOFs,', r['integration_points'], 'integration points')")), lift $lift m, $n runs each alternating, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for label in linear newton; do
  echo "$label (median): wall $(cut -d' ' -f1 $label.times | median) s, CPU $(cut -d' ' -f2 $label.times | median) s"
done
python3 - <<'PY'
import json
r = json.load(open('newton.json'))
print(f"newton: {r['newton_iterations']} iterations, {r['factorizations']} factorizations; integrate {r['integrate_seconds']:.2f} s, analyse {r['analyze_seconds']:.3f} s")
for s in r['steps']:
    print(f"  load {s['load']:.3g}: {'converged' if s['converged'] else 'halved'}, {s['iterations']} iterations, "
          f"{s['tangents']} tangents in {s['assemble_seconds']:.2f} s, {s['factorizations']} factorizations in "
          f"{s['factor_seconds']:.2f} s, solves {s['solve_seconds']:.3f} s")
PY
