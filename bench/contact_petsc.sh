#!/usr/bin/env bash
# Contact on xfem-solve's backends (issue 33): the organ's sine incision pressed closed
# (pipelines/contact "pressed", the same system assembled with and without "contact"), solved by
# each backend N times, alternating, and prints the medians of wall and CPU (user + sys) time of
# xfem-solve with and without contact, the contact solves, the time per contact solve ((with -
# without) / (solves - 1): each contact solve after the first), and PETSc's CG iterations per
# solve (the first: without contact; then the penalised ones). The solutions against CHOLMOD's.
# BACKENDS: "cholmod", "petscP" (--backend petsc --np P, e.g. petsc1 petsc2).
# Usage: bench/contact_petsc.sh [N=3] [SIZE=0.006] [BACKENDS="cholmod petsc1"] [RTOL=1e-10]
#   env: BUILD (default build) holding tools/.
set -eu
n=${1:-3}
size=${2:-0.006}
backends=${3:-cholmod petsc1}
rtol=${4:-1e-10}
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
for k in pressed pressed-free; do
  python3 "$source_dir/pipelines/contact/problems.py" $k "$source_dir/pipelines/organ/problem.json" 30 > $k.json
  "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem $k.json -o $k
done
options() {  # the backend's options
  case $1 in
    cholmod) echo "--backend cholmod" ;;
    petsc*) echo "--backend petsc --np ${1#petsc} --rtol $rtol" ;;
  esac
}
for ((run = 0; run < n; ++run)); do
  for b in $backends; do
    for k in pressed pressed-free; do
      # shellcheck disable=SC2046
      /usr/bin/time -f "%e %U %S" -o t.txt "$B/xfem-solve" -q $k -o "u-$b-$k.mtx" --report "$b-$k.json" $(options "$b") 2>/dev/null
      awk '{print $1, $2 + $3}' t.txt >> "$b-$k.times"
    done
  done
done
echo "organ --size $size, pressed closed; $n runs per backend, alternating; load $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-9s %12s %12s %12s %12s %7s %14s  %s\n' backend "wall" "CPU" "wall free" "CPU free" solves "wall/solve" \
  "CG iterations (free | contact solves); u vs CHOLMOD"
for b in $backends; do
  wall=$(cut -d' ' -f1 "$b-pressed.times" | median); cpu=$(cut -d' ' -f2 "$b-pressed.times" | median)
  wall0=$(cut -d' ' -f1 "$b-pressed-free.times" | median); cpu0=$(cut -d' ' -f2 "$b-pressed-free.times" | median)
  python3 - "$b" "$wall" "$cpu" "$wall0" "$cpu0" <<'PY'
import json, os, sys
b, wall, cpu, wall0, cpu0 = sys.argv[1], *map(float, sys.argv[2:])
r, r0 = json.load(open(b + '-pressed.json')), json.load(open(b + '-pressed-free.json'))
c = r['contact']
def vector(p): return [float(l.split()[-1]) for l in open(p) if not l.startswith('%')][1:]
vs = '-'
if os.path.exists('u-cholmod-pressed.mtx'):
    u, v = vector('u-cholmod-pressed.mtx'), vector('u-%s-pressed.mtx' % b)
    vs = '%.2g of max |u|' % (max(abs(x - y) for x, y in zip(u, v)) / max(abs(x) for x in u))
its = c.get('cg_iterations')
cg = '%s | %s' % (r0.get('iterations', '-'), '-' if its is None else '%d..%d (median %d)' % (
    min(its[1:]), max(its[1:]), sorted(its[1:])[len(its[1:]) // 2]))
print('%-9s %11.2fs %11.2fs %11.2fs %11.2fs %7d %13.3fs  %s; %s' % (
    b, wall, cpu, wall0, cpu0, c['solves'], (wall - wall0) / max(1, c['solves'] - 1), cg, vs))
PY
done
