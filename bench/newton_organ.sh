#!/usr/bin/env bash
# xfem-newton (neo-Hookean) against the linear path (xfem-assemble + xfem-solve) on the organ
# example's mesh and cut and its problem.json (issue 32: the nonlinear solve should cost at most
# ~10x the linear one). Runs both N times, alternating, and prints the medians of wall and CPU
# (user + sys) time, then the last Newton report's load steps (iterations, tangents,
# factorizations and their times). BACKENDS: xfem-newton's linear solves, each timed in the same
# alternation: "cholmod", "petscP" (--backend petsc --np P, e.g. petsc1 petsc2).
# Usage: bench/newton_organ.sh [N=3] [SIZE=0.012] [LIFT=0.01] [LOAD_STEPS=2] [BACKENDS=cholmod]
#   env: BUILD (default build) holding tools/.
set -eu
n=${1:-3}
size=${2:-0.012}
lift=${3:-0.01}
steps=${4:-2}
backends=${5:-cholmod}
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
  for b in $backends; do
    case $b in
      cholmod) opts=(--backend cholmod) ;;
      petsc*) opts=(--backend petsc --np "${b#petsc}") ;;
      *) echo "unknown backend $b" >&2; exit 2 ;;
    esac
    timed "newton-$b" "$B/xfem-newton" -q enriched.vtu --cut cut.vtp --problem neo-hookean.json -o u-$b.mtx \
      --report newton-$b.json "${opts[@]}"
  done
done
echo "organ --size $size ($(python3 -c "import json; r=json.load(open('newton-$(echo $backends | cut -d' ' -f1).json')); print(r['dofs'], 'DOFs,', r['integration_points'], 'integration points')")), lift $lift m, $n runs each alternating, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for label in linear $(for b in $backends; do echo newton-$b; done); do
  echo "$label (median): wall $(cut -d' ' -f1 $label.times | median) s, CPU $(cut -d' ' -f2 $label.times | median) s"
done
for b in $backends; do
python3 - newton-$b.json u-$b.mtx u-$(echo $backends | cut -d' ' -f1).mtx <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
def read(p): return [float(l.split()[-1]) for l in open(p) if not l.startswith('%')][1:]
a, b = read(sys.argv[2]), read(sys.argv[3])
d = max(abs(x - y) for x, y in zip(a, b)) / max(abs(y) for y in b)
print(f"newton, {r['backend']} on {r['processes']} process(es): {r['newton_iterations']} iterations, {r['factorizations']} "
      f"solves; integrate {r['integrate_seconds']:.2f} s, analyse {r['analyze_seconds']:.3f} s; u against the first "
      f"backend's: {d:.1e} of the largest; volume {100 * r['volume']['body']['relative_change']:+.3f} %")
for s in r['steps']:
    print(f"  load {s['load']:.3g}: {'converged' if s['converged'] else 'halved'}, {s['iterations']} iterations, "
          f"{s['tangents']} tangents in {s['assemble_seconds']:.2f} s, {s['factorizations']} factorizations in "
          f"{s['factor_seconds']:.2f} s, solves {s['solve_seconds']:.3f} s" +
          (f" ({s['linear_iterations']} CG iterations)" if s['linear_iterations'] else ""))
PY
done
