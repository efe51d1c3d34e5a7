#!/usr/bin/env bash
# xfem-solve against the bare library calls on the same system/ directory, side by side in one run
# (issue 5: the tool's overhead should be within 1.1x). Runs each program N times, alternating,
# and prints the medians (and minima) of the whole-process wall time and of the library part (CHOLMOD analyse +
# factor + solve; PETSc matrix build + GAMG setup + CG solve), and the ratios tool / bare.
# Usage: bench/solve_overhead.sh SYSTEM_DIR [N=3] [BACKENDS="cholmod petsc"]
#   env: BUILD (default build) holding tools/xfem-solve and bench/bare_*; RTOL for PETSc (1e-10).
set -eu
dir=${1:?usage: solve_overhead.sh SYSTEM_DIR [N] [BACKENDS]}
n=${2:-3}
backends=${3:-cholmod petsc}
build=${BUILD:-build}
rtol=${RTOL:-1e-10}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
median() { sort -g | awk '{v[NR]=$1} END{print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }
num() { sed -n "s/.*\"$1\": *\([-0-9.e+]*\).*/\1/p" "$2"; }

echo "system: $dir ($(sed -n 's/.*"dofs": *\([0-9]*\).*/\1/p' "$dir/system.json") DOFs), $n runs each, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for backend in $backends; do
  : >"$tmp/tool_wall"; : >"$tmp/tool_lib"; : >"$tmp/bare_wall"; : >"$tmp/bare_lib"
  for run in $(seq "$n"); do
    /usr/bin/time -f %e -o "$tmp/t" "$build/tools/xfem-solve" -q "$dir" -o "$tmp/u.mtx" --report "$tmp/r.json" \
      --backend "$backend" --rtol "$rtol"
    cat "$tmp/t" >>"$tmp/tool_wall"
    awk -v a="$(num setup_seconds "$tmp/r.json")" -v b="$(num solve_seconds "$tmp/r.json")" 'BEGIN{print a+b}' >>"$tmp/tool_lib"
    if [ "$backend" = cholmod ]; then
      /usr/bin/time -f %e -o "$tmp/t" "$build/bench/bare_cholmod" "$dir" >"$tmp/b.json"
      awk -v a="$(num analyze_seconds "$tmp/b.json")" -v b="$(num factor_seconds "$tmp/b.json")" \
        -v c="$(num solve_seconds "$tmp/b.json")" 'BEGIN{print a+b+c}' >>"$tmp/bare_lib"
    else
      /usr/bin/time -f %e -o "$tmp/t" "$build/bench/bare_petsc" "$dir" "$rtol" >"$tmp/b.json"
      awk -v a="$(num setup_seconds "$tmp/b.json")" -v b="$(num solve_seconds "$tmp/b.json")" 'BEGIN{print a+b}' >>"$tmp/bare_lib"
    fi
    cat "$tmp/t" >>"$tmp/bare_wall"
    echo "  $backend run $run: tool $(tail -1 "$tmp/tool_wall") s wall ($(tail -1 "$tmp/tool_lib") s library), bare $(tail -1 "$tmp/bare_wall") s wall ($(tail -1 "$tmp/bare_lib") s library)"
  done
  tw=$(median <"$tmp/tool_wall"); tl=$(median <"$tmp/tool_lib"); bw=$(median <"$tmp/bare_wall"); bl=$(median <"$tmp/bare_lib")
  # The minimum too: on a machine shared with other jobs it is the least disturbed run.
  mtw=$(sort -g "$tmp/tool_wall" | head -1); mbw=$(sort -g "$tmp/bare_wall" | head -1)
  mtl=$(sort -g "$tmp/tool_lib" | head -1); mbl=$(sort -g "$tmp/bare_lib" | head -1)
  awk -v b="$backend" -v tw="$tw" -v tl="$tl" -v bw="$bw" -v bl="$bl" 'BEGIN{
    if (bw <= 0) bw = 0.005; if (bl <= 0) bl = 1e-9
    printf "%s medians: wall tool %.2f s / bare %.2f s = %.3fx; library part tool %.2f s / bare %.2f s = %.3fx\n",
      b, tw, bw, tw/bw, tl, bl, tl/bl}'
  awk -v b="$backend" -v tw="$mtw" -v tl="$mtl" -v bw="$mbw" -v bl="$mbl" 'BEGIN{
    if (bw <= 0) bw = 0.005; if (bl <= 0) bl = 1e-9
    printf "%s minima:  wall tool %.2f s / bare %.2f s = %.3fx; library part tool %.2f s / bare %.2f s = %.3fx\n",
      b, tw, bw, tw/bw, tl, bl, tl/bl}'
done
