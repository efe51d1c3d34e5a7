#!/bin/bash
# xfem-mesh: CLI contract, determinism (byte-identical reruns), the paper's meshes and cuts.
set -u
M="$XFEM_BIN/xfem-mesh"
S="$XFEM_SCRATCH"
rm -rf "$S" && mkdir -p "$S" && cd "$S" || exit 1
fail=0
source "$XFEM_SOURCE/test/e2e/check_exit.bash"
expect_error() {  # expect_error <description> <output file> <command...>: exit 1, 'error:', no file
  local what=$1 file=$2
  shift 2
  check 1 "$what" "$@"
  grep -q "error:" err.txt || { echo "FAIL: $what: no 'error:' on stderr"; cat err.txt; fail=1; }
  [ ! -e "$file" ] || { echo "FAIL: $what: left $file behind"; fail=1; }
}

check 0 "--help" "$M" --help
grep -q "Example:" out.txt || { echo "FAIL: --help shows no example"; fail=1; }
for c in box unstructured-box organ surface cut-rect cut-sine cut-disc; do
  check 0 "$c --help" "$M" "$c" --help
  grep -q "Example:" out.txt || { echo "FAIL: $c --help shows no example"; fail=1; }
done
check 0 "--version" "$M" --version
check 2 "bad flag" "$M" box --no-such-flag -o x.vtu
check 2 "no command" "$M"
check 2 "cut-rect without geometry" "$M" cut-rect -o x.vtp
check 2 "--beam-cut with --split-z" "$M" box --cells 2 4 14 --hi 0.03 0.06 0.2 --beam-cut --split-z 0.1 -o x.vtu
expect_error "zero cells" bad.vtu "$M" box --cells 0 4 14 --hi 0.03 0.06 0.2 -o bad.vtu
expect_error "cut off the grid" bad.vtu "$M" box --cells 2 4 13 --hi 0.03 0.06 0.2 --beam-cut -o bad.vtu
grep -q "not an interior grid plane" err.txt || { echo "FAIL: off-grid cut message"; cat err.txt; fail=1; }
check 2 "negative size" "$M" unstructured-box --hi 0.03 0.06 0.2 --size -0.006 -o bad.vtu
check 2 "zero size" "$M" organ --size 0 -o bad.vtu
expect_error "missing surface" bad.vtu "$M" surface nothing.stl --size 0.01 -o bad.vtu
check 2 "negative radius" "$M" cut-disc --radius -1 -o bad.vtp

# An open surface is refused.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > open.off
expect_error "open surface" bad.vtu "$M" surface open.off --size 0.1 -o bad.vtu
grep -q "not closed" err.txt || { echo "FAIL: open surface message"; cat err.txt; fail=1; }

# Every command twice: byte-identical outputs.
run_twice() {  # run_twice <file> <args...>
  local f=$1
  shift
  check 0 "$*" "$M" -q "$@" -o "a_$f" && check 0 "$* (again)" "$M" -q "$@" -o "b_$f"
  cmp -s "a_$f" "b_$f" || { echo "FAIL: $* is not deterministic"; fail=1; }
}
printf 'OFF\n4 4 0\n0 0 0\n0.1 0 0\n0 0.1 0\n0 0 0.1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > tet.off
run_twice box.vtu box --cells 2 4 14 --hi 0.03 0.06 0.2 --beam-cut
run_twice ubox.vtu unstructured-box --hi 0.03 0.06 0.2 --size 0.006
run_twice organ.vtu organ --size 0.012
run_twice tet.vtu surface tet.off --size 0.02
run_twice rect.vtp cut-rect --beam-cut
run_twice rect4.vtp cut-rect --corner 0 0 0.1 --edge1 0.03 0 0 --edge2 0 0.06 0 --divisions 4 2
run_twice sine.vtp cut-sine
run_twice disc.vtp cut-disc --rings 4

# cut-zigzag and cut-merge: help, bad input, determinism, counts (the default zig-zag: 4 strips of
# 0.0125 x 0.08 m rising or falling 0.04 m: area 4 * 0.08 * sqrt(0.0125^2 + 0.04^2) = 0.01341).
for c in cut-zigzag cut-merge; do
  check 0 "$c --help" "$M" "$c" --help
  grep -q "Example:" out.txt || { echo "FAIL: $c --help shows no example"; fail=1; }
done
expect_error "negative folds" bad.vtp "$M" cut-zigzag --folds -1 -o bad.vtp
expect_error "empty zig-zag" bad.vtp "$M" cut-zigzag --lo 1 0 --hi 0 1 -o bad.vtp
expect_error "missing merge input" bad.vtp "$M" cut-merge a_rect.vtp nothing.vtp -o bad.vtp
grep -q "nothing.vtp" err.txt || { echo "FAIL: missing merge input not named"; cat err.txt; fail=1; }
check 2 "cut-merge of one file" "$M" cut-merge a_rect.vtp -o bad.vtp
run_twice zigzag.vtp cut-zigzag --folds 5 --divisions 3
run_twice merged.vtp cut-merge a_rect.vtp a_disc.vtp
"$M" cut-zigzag -o zz.vtp 2>err.txt
grep -q "8 triangles, area 0.01341" err.txt || { echo "FAIL: zig-zag count/area"; cat err.txt; fail=1; }
"$M" cut-merge a_rect.vtp a_disc.vtp -o merged.vtp 2>err.txt
grep -q "98 triangles" err.txt || { echo "FAIL: merged count"; cat err.txt; fail=1; }

# Counts: the pipelines' invocations; the 2x4x14 grid by hand: 3*5*15 = 225 nodes + 5 copies, 6*2*4*14 tets.
"$M" unstructured-box --hi 0.03 0.06 0.2 --size 0.006 -o beam.vtu 2>err.txt || { echo "FAIL: beam"; fail=1; }
grep -q "tets" err.txt || { echo "FAIL: no tet count on stderr"; cat err.txt; fail=1; }
"$M" box --cells 2 4 14 --hi 0.03 0.06 0.2 --beam-cut -o ref.vtu 2>err.txt
grep -q "672 tets, 230 points" err.txt || { echo "FAIL: 2x4x14 counts"; cat err.txt; fail=1; }
"$M" cut-rect --beam-cut -o cut.vtp 2>err.txt
grep -q "2 triangles, area 0.002000" err.txt || { echo "FAIL: beam cut"; cat err.txt; fail=1; }
"$M" cut-disc --rings 3 -o disc.vtp 2>err.txt
grep -q "54 triangles" err.txt || { echo "FAIL: disc count"; cat err.txt; fail=1; }

# -q silences the report.
"$M" -q cut-rect --beam-cut -o quiet.vtp 2>err.txt
[ ! -s err.txt ] || { echo "FAIL: -q still printed"; cat err.txt; fail=1; }

[ $fail = 0 ] && rm -rf "$S"
exit $fail
