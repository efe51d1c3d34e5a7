#!/usr/bin/env bash
# xfem-front and xfem-sweep never write a value that is not finite and refuse unbounded work
# before doing any (issue "Never a silent wrong answer, round two"): each case exits 1 with one
# "error:" line naming the input or the option, and writes no output file.
#   - xfem-front with a solution scaled to 1e200 m: K finite, G = K^2 ... overflows;
#   - xfem-sweep with 'time' values -1e308 and 1e308: t1 - t0 overflows the steps' times;
#   - xfem-front --order 20, --radius 1e-9, --spacing 1e-9, and xfem-sweep --steps 100000 and 1000000000:
#     refused with the estimate and --allow-large named (front_cost.h, kMaxSweepSteps), each
#     within 10 s; with --allow-large the same request runs (xfem-front --order 20, xfem-sweep
#     --steps 1001: still running after 3 s).
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; M="$B/xfem-mesh -q"
fail() { echo "FAIL: $*"; exit 1; }
# refused <name> <expected text> <output that must not exist> <command...>
refused() {
  local name=$1 text=$2 out=$3; shift 3
  local start=$SECONDS
  timeout 60 "$@" >"$S/$name.out" 2>"$S/$name.err"; local rc=$?
  [ $rc -eq 1 ] || fail "$name: exit $rc, expected 1: $(head -c 300 "$S/$name.err")"
  [ "$(wc -l <"$S/$name.err")" -eq 1 ] && grep -q "error: " "$S/$name.err" || fail "$name: not one error line: $(cat "$S/$name.err")"
  grep -qF -- "$text" "$S/$name.err" || fail "$name: expected '$text': $(cat "$S/$name.err")"
  [ $((SECONDS - start)) -le $((10 + 3 * plain)) ] || fail "$name: took $((SECONDS - start)) s to refuse"
  [ ! -e "$out" ] || fail "$name: $out written"
  echo "ok $name: $(cat "$S/$name.err")"
}

# A box with an edge crack from x = 0 to 0.45 at z = 0.52, pulled apart along z.
$M box --cells 4 4 6 --hi 1 1 1 -o "$S/box.vtu" &&
  $M cut-rect --corner -0.5 -0.5 0.52 --edge1 0.95 0 0 --edge2 0 2 0 -o "$S/cut.vtp" || fail "inputs"
cat >"$S/problem.json" <<'EOF'
{"material": {"E": 1000, "nu": 0.3},
 "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}],
 "neumann": [{"name": "top", "selector": {"box": {"lo": [-1, -1, 1], "hi": [2, 2, 2]}}, "traction": [0, 0, 1]}]}
EOF
"$B/xfem-classify" -q "$S/box.vtu" --cut "$S/cut.vtp" -o "$S/classified.vtu" &&
  "$B/xfem-enrich" -q "$S/classified.vtu" -o "$S/enriched.vtu" &&
  "$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/problem.json" -o "$S/system" &&
  "$B/xfem-solve" -q "$S/system" -o "$S/u.mtx" || fail "solution"
F=("$B/xfem-front" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/problem.json")
# A refusal may take 10 s more than 3 plain runs (front-huge computes the front before it sees G =
# inf; a sanitizer build on a loaded machine takes 10 s for the plain run): never minutes.
plain=$SECONDS
"${F[@]}" --solution "$S/u.mtx" --radius 0.3 --csv "$S/front.csv" || fail "the plain run"
plain=$((SECONDS - plain))
# The solution times 1e200 (comments, with the fingerprints, and the size line kept).
awk '/^%/ { print; next } !n++ { print; next } { printf "%.17g\n", $1 * 1e200 }' "$S/u.mtx" >"$S/huge.mtx"
refused front-huge "huge.mtx: G = inf at the front point" "$S/huge.csv" \
  "${F[@]}" --solution "$S/huge.mtx" --radius 0.3 --csv "$S/huge.csv" -o "$S/huge.vtp"
[ ! -e "$S/huge.vtp" ] || fail "front-huge: huge.vtp written"
refused front-order "integration points" "$S/o.csv" "${F[@]}" --solution "$S/u.mtx" --order 20 --csv "$S/o.csv"
grep -qF -- "--allow-large" "$S/front-order.err" || fail "front-order: --allow-large not named"
refused front-radius "front points" "$S/r.csv" "${F[@]}" --solution "$S/u.mtx" --radius 1e-9 --csv "$S/r.csv"
refused front-spacing "front points" "$S/s.csv" "${F[@]}" --solution "$S/u.mtx" --radius 0.3 --spacing 1e-9 --csv "$S/s.csv"
for n in radius spacing; do grep -qF -- "--allow-large" "$S/front-$n.err" || fail "front-$n: --allow-large not named"; done
# --allow-large lifts the guard: the same request then runs (stopped after 3 s, exit 124 from timeout).
# runs <name> <command...>
runs() {
  local name=$1; shift
  timeout 3 "$@" >"$S/$name.out" 2>"$S/$name.err"; local rc=$?
  # Still running after 3 s (124), or done (0) on a fast machine: either way past the guard.
  [ $rc -eq 124 ] || [ $rc -eq 0 ] || fail "$name: --allow-large must run past the guard (exit $rc): $(head -c 300 "$S/$name.err")"
  echo "ok $name: runs"
}
runs front-order-allowed "${F[@]}" --solution "$S/u.mtx" --order 20 --allow-large --csv "$S/o.csv"

# xfem-sweep: a blade sweep with times from -1e308 to 1e308 (legacy VTK, two triangles).
printf '# vtk DataFile Version 3.0\nhuge times\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n0.43 -0.5 1.2 0.43 0.5 1.2 0.43 0.5 0.6 0.43 -0.5 0.6\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\nCELL_DATA 2\nSCALARS time double 1\nLOOKUP_TABLE default\n-1e308\n1e308\n' >"$S/huge_times.vtk"
$M cut-sweep --path 0.43 0.05 1.2 0.43 0.75 1.2 --depth 0.5 --resolution 0.2 -o "$S/sweep.vtp" || fail "cut-sweep"
W=("$B/xfem-sweep" -q "$S/box.vtu" --problem "$S/problem.json")
refused sweep-times "huge_times.vtk: the time of step 1 is not a finite number" "$S/times/sweep.pvd" \
  "${W[@]}" --cut "$S/huge_times.vtk" --steps 2 -o "$S/times"
[ ! -e "$S/times" ] || fail "sweep-times: the output directory was created"
refused sweep-steps "--steps 100000: 100000 solves" "$S/steps" "${W[@]}" --cut "$S/sweep.vtp" --steps 100000 -o "$S/steps"
grep -qF -- "--allow-large" "$S/sweep-steps.err" || fail "sweep-steps: --allow-large not named"
refused sweep-steps-1e9 "limit 1000 steps" "$S/steps" "${W[@]}" --cut "$S/sweep.vtp" --steps 1000000000 -o "$S/steps"
runs sweep-steps-allowed "${W[@]}" --cut "$S/sweep.vtp" --steps 1001 --allow-large -o "$S/steps"
echo "front and sweep guards: all cases pass"
rm -rf "$S"
