#!/usr/bin/env bash
# --threads and OMP_NUM_THREADS (issue 35): every tool takes --threads N; a bad N or a bad
# OMP_NUM_THREADS is one usage-error line; the beam pipeline and a sweep give the same results with 1,
# 2 and 3 threads; and the process holds no more threads than it was given (counted in
# /proc/self/task by the XFEM_COUNT_THREADS hook, docs/PERFORMANCE.md "Threads"). What passes
# through a factorization (u.mtx) agrees to round-off: OpenBLAS's sums depend on its thread count.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }
close() {  # close <a.mtx> <b.mtx> <tol>: same values to tol relative to the largest |value|
  awk -v tol="$3" 'FNR == 1 {k = 0} /^%/ {next} {k++} k == 1 {next}
    NR == FNR {a[k] = $NF; v = $NF < 0 ? -$NF : $NF; if (v > m) m = v; next}
    {d = a[k] - $NF; d = d < 0 ? -d : d; if (d > e) e = d; n++}
    END {exit !(n > 0 && e <= tol * m)}' "$1" "$2"
}
unset OMP_NUM_THREADS XFEM_COUNT_THREADS

# Every tool has the option, and refuses bad counts with one line (exit 2, before any work).
for t in mesh classify enrich assemble solve newton visualize front probe rmserror sweep; do
  "$B/xfem-$t" --help | grep -q -- "--threads N" || fail "xfem-$t --help shows no --threads"
  OMP_NUM_THREADS=x "$B/xfem-$t" --help >/dev/null || fail "xfem-$t --help with a bad OMP_NUM_THREADS"
  for n in 0 -1 1e9 x 1025; do
    "$B/xfem-$t" --threads "$n" >out.txt 2>err.txt; rc=$?
    [ $rc -eq 2 ] || fail "xfem-$t --threads $n: exit $rc, expected 2"
    [ "$(wc -l <err.txt)" -eq 1 ] && grep -q -- "--threads" err.txt || fail "xfem-$t --threads $n: $(cat err.txt)"
  done
  for v in 0 -1 1e9 x; do
    OMP_NUM_THREADS=$v "$B/xfem-$t" body.vtu >/dev/null 2>err.txt; rc=$?
    [ $rc -eq 2 ] || fail "OMP_NUM_THREADS=$v xfem-$t: exit $rc, expected 2"
    # (libgomp, loaded with CHOLMOD, prints its own warning before main: not ours to silence)
    [ "$(grep -vc '^libgomp: \|^$' err.txt)" -eq 1 ] && grep -qF "OMP_NUM_THREADS=$v: not a whole number of threads from 1 to 1024" err.txt \
      || fail "OMP_NUM_THREADS=$v xfem-$t: $(cat err.txt)"
  done
done

# The beam, fine enough (30,720 tets, 6,273 points) for every parallel loop to split its work.
"$B/xfem-mesh" -q --threads 2 box --cells 8 16 40 --hi 0.03 0.06 0.2 -o beam.vtu || fail "mesh"
"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp || fail "cut-rect"
for n in 1 2 3; do
  mkdir -p t$n
  "$B/xfem-classify" -q --threads $n beam.vtu --cut cut.vtp -o t$n/classified.vtu || fail "classify $n"
  "$B/xfem-enrich" -q --threads $n t$n/classified.vtu -o t$n/enriched.vtu || fail "enrich $n"
  "$B/xfem-assemble" -q --threads $n t$n/enriched.vtu --cut cut.vtp --problem "$PROBLEM" -o t$n/system \
    || fail "assemble $n"
  "$B/xfem-solve" -q --threads $n t$n/system -o t$n/u.mtx || fail "solve $n"
  "$B/xfem-visualize" -q --threads $n t1/enriched.vtu --cut cut.vtp --problem "$PROBLEM" --solution t1/u.mtx \
    -o t$n/deformed.vtu || fail "visualize $n"
done
for n in 2 3; do
  for f in classified.vtu enriched.vtu deformed.vtu; do
    cmp -s t1/$f t$n/$f || fail "$f differs between --threads 1 and --threads $n"
  done
  # The factorization's BLAS (OpenBLAS's threaded level-3 and Cholesky kernels) splits its sums by
  # thread count: u agrees to round-off, not to the bit (measured 2e-14 to 4e-14 of max |u|).
  close t1/u.mtx t$n/u.mtx 1e-12 || fail "u.mtx: --threads 1 and $n differ by more than 1e-12 of max |u|"
  for f in t1/system/*; do
    case $f in *.json) continue ;; esac
    cmp -s "$f" "t$n/system/$(basename "$f")" || fail "$f differs between --threads 1 and --threads $n"
  done
done
# OMP_NUM_THREADS alone gives the same bytes too.
OMP_NUM_THREADS=3 "$B/xfem-classify" -q beam.vtu --cut cut.vtp -o omp.vtu || fail "classify OMP_NUM_THREADS=3"
cmp -s t1/classified.vtu omp.vtu || fail "classified.vtu differs with OMP_NUM_THREADS=3"

# The threads the process holds: at most N with --threads N or OMP_NUM_THREADS=N (--threads wins),
# and the N a parallel loop asks for are there (3 on any machine: the count is not the cores').
peak() {  # peak <env...> -- <command...>: the tool's "threads: at most N at once"
  local envs=()
  while [ "$1" != "--" ]; do envs+=("$1"); shift; done; shift
  env XFEM_COUNT_THREADS=1 "${envs[@]}" "$@" 2>&1 >/dev/null | sed -n 's/.*threads: at most \([0-9]*\) at once.*/\1/p'
}
classify=("$B/xfem-classify" -q beam.vtu --cut cut.vtp -o peak.vtu)
solve=("$B/xfem-solve" -q t1/system -o peak.mtx)
[ "$(peak -- "${classify[@]}" --threads 1)" = 1 ] || fail "classify --threads 1: $(peak -- "${classify[@]}" --threads 1)"
[ "$(peak -- "${classify[@]}" --threads 3)" = 3 ] || fail "classify --threads 3: $(peak -- "${classify[@]}" --threads 3)"
[ "$(peak OMP_NUM_THREADS=1 -- "${classify[@]}")" = 1 ] || fail "classify OMP_NUM_THREADS=1"
[ "$(peak OMP_NUM_THREADS=3 -- "${classify[@]}")" -ge 3 ] || fail "classify OMP_NUM_THREADS=3"
[ "$(peak OMP_NUM_THREADS=3 -- "${classify[@]}" --threads 1)" = 1 ] || fail "--threads 1 must win over OMP_NUM_THREADS=3"
p=$(peak -- "${solve[@]}" --threads 1); [ "$p" = 1 ] || fail "solve --threads 1: $p threads (CHOLMOD, BLAS)"
p=$(peak OMP_NUM_THREADS=1 -- "${solve[@]}"); [ "$p" = 1 ] || fail "solve OMP_NUM_THREADS=1: $p threads"
for n in 2 3; do  # BLAS's pool (n - 1 helpers) and CHOLMOD's OpenMP team (4, switched off) within n
  p=$(peak -- "${solve[@]}" --threads $n); [ "$p" -le $n ] || fail "solve --threads $n: $p threads"
done

# A sweep with 1 and 2 threads (1: the frames in the main thread).
"$B/xfem-mesh" -q box --cells 6 6 12 --hi 1 1 2 -o box.vtu || fail "box"
"$B/xfem-mesh" -q cut-sweep --path 0.43 0.05 2.2 0.43 0.75 2.2 --depth 0.7 --resolution 0.1 -o sweep.vtp \
  || fail "cut-sweep"
cat >problem.json <<'JSON'
{
  "material": {"E": 1e3, "nu": 0.3},
  "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}],
  "neumann": [{"name": "left", "selector": {"box": {"lo": [-1, -1, -1], "hi": [0, 2, 3]}}, "traction": [-10, 0, 0]}]
}
JSON
for n in 1 2; do
  "$B/xfem-sweep" -q --threads $n box.vtu --cut sweep.vtp --problem problem.json --steps 4 -o s$n --solutions \
    --report s$n.json || fail "sweep --threads $n"
done
# The uncut factor's BLAS (and its solves for the region's response) split their sums by thread
# count, as in xfem-solve: the solutions agree to round-off (measured 7e-14 of max |u|).
for k in 001 002 003 004; do
  close s1/u_$k.mtx s2/u_$k.mtx 1e-12 || fail "sweep: u_$k.mtx differs by more than 1e-12 between --threads 1 and 2"
done
cmp -s s1/sweep.pvd s2/sweep.pvd || fail "sweep.pvd differs between --threads 1 and 2"
p=$(peak -- "$B/xfem-sweep" -q --threads 1 box.vtu --cut sweep.vtp --problem problem.json --steps 4 -o s3)
[ "$p" = 1 ] || fail "sweep --threads 1: $p threads"
grep -q '"median_step"' s1.json || fail "the sweep's report has no time split"
echo "threads: ok"
