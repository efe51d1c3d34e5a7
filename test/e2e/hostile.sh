#!/usr/bin/env bash
# Hostile input (issue "Never a silent wrong answer"): each case the bad-input campaign found is
# refused with one line "<tool>: error: ..." (exit 1) or "<tool>: usage error: ..." (exit 2)
# naming what is wrong, and leaves no output behind. Small inputs: the whole script takes seconds.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
B=$XFEM_BIN; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }

# expect <exit code> <text> <command...>: exactly one line on stderr, containing <text>.
expect() {
  local code=$1 text=$2; shift 2
  "$@" >"$S/out.txt" 2>"$S/err.txt"; local rc=$?
  [ $rc -eq "$code" ] || fail "expected exit $code, got $rc: $* -> $(cat "$S/err.txt")"
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] || fail "expected one line on stderr: $* -> $(cat "$S/err.txt")"
  grep -qF -- "$text" "$S/err.txt" || fail "expected '$text': $* -> $(cat "$S/err.txt")"
}
absent() { for f in "$@"; do [ ! -e "$f" ] || fail "$f left behind"; done; }

# A small cut beam and a second, different cut (the same plane, shifted).
"$B/xfem-mesh" -q box --cells 3 5 13 --hi 0.03 0.06 0.2 -o "$S/beam.vtu" || fail "xfem-mesh box"
"$B/xfem-mesh" -q cut-rect --beam-cut -o "$S/cut.vtp" || fail "cut-rect"
"$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.11 --edge1 0.025 0 0 --edge2 0 0.08 0 -o "$S/other.vtp" || fail "other cut"
"$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/classified.vtu" || fail "classify"
"$B/xfem-enrich" -q "$S/classified.vtu" -o "$S/enriched.vtu" || fail "enrich"
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --format mtx -o "$S/system" || fail "assemble"
"$B/xfem-solve" -q "$S/system" -o "$S/u.mtx" || fail "solve"
grep -q "^% xfem-fingerprint enriched fnv1a64:" "$S/u.mtx" || fail "u.mtx records no fingerprint: $(head -3 "$S/u.mtx")"

# 1. A stale system directory: xfem-assemble replaces a system as a whole (written under a
# temporary name, system.json last, renamed into place). Killed at any moment while assembling
# another problem into it, the directory holds the old system or the new one, never a mix: the
# solution is u.mtx or u2.mtx exactly. A directory without its completion marker is refused.
sed 's/"E": 300e3/"E": 400e3/' "$PROBLEM" >"$S/stiffer.json"
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/stiffer.json" --format mtx -o "$S/system2" || fail "assemble 2"
"$B/xfem-solve" -q "$S/system2" -o "$S/u2.mtx" || fail "solve 2"
# Kills spread over the run, most of them near its end, where the files are written and the
# directory is swapped in (provenance.json and dirichlet_conditions.json once came after the swap:
# a kill there left a system whose u.mtx carried no fingerprints).
t0=$(date +%s.%N)
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/stiffer.json" --format mtx -o "$S/system3" || fail "assemble 3"
run=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
for fraction in 0.1 0.5 0.8 0.9 0.95 0.98 1.0 1.02 1.05 1.1 2; do
  delay=$(awk -v r="$run" -v f="$fraction" 'BEGIN { print r * f }')
  rm -rf "$S/killed"; cp -r "$S/system" "$S/killed"
  ( timeout -s KILL "$delay" "$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/stiffer.json" \
    --format mtx -o "$S/killed" ) 2>/dev/null
  "$B/xfem-solve" -q "$S/killed" -o "$S/u_killed.mtx" || fail "the system directory after a kill at $delay s is unreadable"
  cmp -s "$S/u_killed.mtx" "$S/u.mtx" || cmp -s "$S/u_killed.mtx" "$S/u2.mtx" \
    || fail "after a kill at $delay s the system directory is neither the old nor the new system"
  grep -q "^% xfem-fingerprint problem fnv1a64:" "$S/u_killed.mtx" \
    || fail "after a kill at $delay s the solution records no fingerprints (provenance.json missing)"
done
# Every state a kill in the old order could leave, and any file lost since: a system missing one
# of its files (provenance.json and dirichlet_conditions.json included) is refused, naming it.
for f in K.mtx f.mtx dirichlet.mtx coordinates.mtx provenance.json dirichlet_conditions.json; do
  [ -e "$S/system/$f" ] || fail "the system has no $f"
  rm -rf "$S/lost"; cp -r "$S/system" "$S/lost"; rm "$S/lost/$f"
  "$B/xfem-solve" -q "$S/lost" -o "$S/n.mtx" 2>"$S/err.txt" && fail "a system without $f was solved"
  [ "$(wc -l <"$S/err.txt")" -eq 1 ] && grep -qF "lost/$f" "$S/err.txt" || fail "without $f: $(cat "$S/err.txt")"
  absent "$S/n.mtx"
done
rm -rf "$S/lost"; cp -r "$S/system" "$S/lost"; rm "$S/lost/provenance.json" "$S/lost/dirichlet_conditions.json"
expect 1 "lost/dirichlet_conditions.json: missing, but listed in system.json's manifest" "$B/xfem-solve" "$S/lost" -o "$S/n.mtx"
# A file of another assembly (E 400e3 instead of 300e3) put into the system: refused.
rm -rf "$S/mixed"; cp -r "$S/system" "$S/mixed"; cp "$S/system2/K.mtx" "$S/mixed/K.mtx"
expect 1 "mixed/K.mtx: " "$B/xfem-solve" "$S/mixed" -o "$S/n.mtx"
grep -qF "system.json's manifest" "$S/err.txt" || fail "mixed K: $(cat "$S/err.txt")"
absent "$S/n.mtx"
rm -rf "$S/partial"; cp -r "$S/system" "$S/partial"; rm "$S/partial/system.json"
expect 1 "partial: no system.json, the marker xfem-assemble writes last: the directory is incomplete" \
  "$B/xfem-solve" "$S/partial" -o "$S/n.mtx"
absent "$S/n.mtx"

# 2. Files that do not belong together: refused, naming both files.
expect 1 "other.vtp: not the cut $S/enriched.vtu was classified with" \
  "$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/other.vtp" --problem "$PROBLEM" -o "$S/sys2"
absent "$S/sys2"
expect 1 "other.vtp: not the cut" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/other.vtp" -s "$S/u.mtx" -p "$PROBLEM" -o "$S/d.vtu"
expect 1 "other.vtp: not the cut" \
  "$B/xfem-rmserror" -q "$S/enriched.vtu" --cut "$S/other.vtp" -s "$S/u.mtx" --exact "$XFEM_SOURCE/pipelines/verification/data/rigid_exact.json"
absent "$S/d.vtu"
# A solution of another system of the same size: the same mesh and cut, another problem.
expect 1 "u2.mtx: does not belong to $PROBLEM (made for the problem" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u2.mtx" -p "$PROBLEM" -o "$S/d.vtu"
absent "$S/d.vtu"
# ... and of another mesh of the same size (the same grid, moved): its enriched fingerprint differs.
"$B/xfem-mesh" -q box --cells 3 5 13 --lo 0 0.001 0 --hi 0.03 0.061 0.2 -o "$S/moved.vtu" || fail "moved box"
"$B/xfem-classify" -q "$S/moved.vtu" --cut "$S/cut.vtp" -o "$S/moved_c.vtu" || fail "classify moved"
"$B/xfem-enrich" -q "$S/moved_c.vtu" -o "$S/moved_e.vtu" || fail "enrich moved"
"$B/xfem-assemble" -q "$S/moved_e.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" -o "$S/system3" || fail "assemble 3"
"$B/xfem-solve" -q "$S/system3" -o "$S/u3.mtx" || fail "solve 3"
expect 1 "u3.mtx: does not belong to $S/enriched.vtu" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u3.mtx" -p "$PROBLEM" -o "$S/d.vtu"
# The matching files still work, and files without fingerprints (earlier versions) are accepted.
"$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -p "$PROBLEM" -o "$S/d.vtu" || fail "visualize"
grep -v "^% xfem-fingerprint" "$S/u.mtx" >"$S/u_old.mtx"
"$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u_old.mtx" -p "$PROBLEM" -o "$S/d_old.vtu" \
  || fail "a u.mtx without fingerprints must be accepted"

# 3. Crashes: deeply nested JSON, absurd coordinates.
python3 -c "print('[' * 100000 + ']' * 100000)" >"$S/deep.json"
expect 1 "deep.json: JSON nested deeper than 64 levels" \
  "$B/xfem-assemble" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/deep.json" -o "$S/sys4"
expect 1 "deep.json: JSON nested deeper" \
  "$B/xfem-rmserror" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" --exact "$S/deep.json"
expect 1 "coordinates must lie within 1e6 m" \
  "$B/xfem-mesh" unstructured-box --hi 1e300 1e300 1e300 --size 1e299 -o "$S/huge.vtu"
absent "$S/sys4" "$S/huge.vtu"

# 4. Non-finite values: options, problem, solution.
expect 2 "--hi nan: not a finite number" "$B/xfem-mesh" box --cells 1 1 1 --hi nan 1 1 -o "$S/n.vtu"
expect 2 "--amplitude inf: not a finite number" "$B/xfem-mesh" cut-sine --amplitude inf -o "$S/n.vtp"
expect 2 "--tip-radius nan: not a finite number" \
  "$B/xfem-classify" "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/n.vtu" --tip-radius nan
expect 2 "--drop-tiny-enrichment NaN: not a finite number" \
  "$B/xfem-solve" "$S/system" -o "$S/n.mtx" --drop-tiny-enrichment NaN
expect 2 "--rtol nan: not a finite number" "$B/xfem-solve" "$S/system" -o "$S/n.mtx" --rtol nan
expect 2 "--scale nan: not a finite number" \
  "$B/xfem-visualize" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -p "$PROBLEM" -o "$S/n.vtu" --scale=nan
expect 2 "--max nan: not a finite number" \
  "$B/xfem-rmserror" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -r "$S/d.vtu" --max nan
expect 2 "--radius 1e999: not a finite number" \
  "$B/xfem-rmserror" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -r "$S/d.vtu" --radius 1e999
expect 2 "value -5 is not a non-negative number" \
  "$B/xfem-rmserror" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -r "$S/d.vtu" --radius -5
absent "$S/n.vtu" "$S/n.vtp" "$S/n.mtx"
sed 's/"E": 300e3/"E": 1e308/' "$PROBLEM" >"$S/huge_e.json"
expect 1 "refusing to write a non-finite value" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u_old.mtx" -p "$S/huge_e.json" -o "$S/n.vtu"
awk 'NR <= 2 { print; next } { print ($1 == 0 ? 0 : $1 * 1e196) }' "$S/u_old.mtx" >"$S/u_huge.mtx"
expect 1 "refusing to write a non-finite value" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u_huge.mtx" -p "$PROBLEM" -o "$S/n.vtu"
absent "$S/n.vtu"
expect 1 "u_huge.mtx: the RMS error is not finite (overflow in the solution?)" \
  "$B/xfem-rmserror" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u_huge.mtx" --exact "$XFEM_SOURCE/pipelines/verification/data/rigid_exact.json"
expect 1 "u_huge.mtx: the RMS error is not finite (overflow in the solution?)" \
  "$B/xfem-rmserror" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u_huge.mtx" -r "$S/d.vtu"
sed 's/"E": 300e3/"E": 1e999/' "$PROBLEM" >"$S/overflow.json"
expect 1 "overflow.json: a number in the JSON is too large for a double" \
  "$B/xfem-assemble" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/overflow.json" -o "$S/sys5"

# 5. Unbounded cost: refused with the estimate, before any work.
expect 1 "tets requested (limit 2e+07" "$B/xfem-mesh" unstructured-box --hi 1 1 1 --size 1e-9 -o "$S/big.vtu"
expect 1 "tets requested (limit 2e+07" "$B/xfem-mesh" organ --size 1e-9 -o "$S/big.vtu"
expect 1 "triangles requested" "$B/xfem-mesh" cut-disc --rings 100000 -o "$S/big.vtp"
expect 2 "value 100000 is not in [1, 1000]" \
  "$B/xfem-rmserror" "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" --exact "$S/deep.json" --samples 100000
expect 1 "integration points in" \
  "$B/xfem-assemble" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --points 100000 --refine 8 -o "$S/sys6"
absent "$S/big.vtu" "$S/big.vtp" "$S/sys6"
# A deliberate long run says so (progress after 3 s); killed, it leaves no system behind.
timeout 6 "$B/xfem-assemble" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --rule conforming --order 20 \
  -o "$S/sys20" 2>"$S/err.txt"
grep -q "xfem-assemble: assembling [0-9]*%" "$S/err.txt" || fail "--order 20 shows no progress: $(cat "$S/err.txt")"
absent "$S/sys20"
[ -z "$(ls -A "$S" | grep "^\.sys20")" ] || fail "a killed xfem-assemble left $(ls -A "$S" | grep "^\.sys20")"

# 6. Malformed input.
printf '# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 104 double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n' >"$S/phantom.vtk"
expect 1 "phantom.vtk: POINTS claims 104 points but only 12 coordinates follow (312 expected)" \
  "$B/xfem-classify" "$S/phantom.vtk" -o "$S/n.vtu"
{ cat "$S/u.mtx"; echo 1.5; } >"$S/extra.mtx"
expect 1 "extra.mtx: line" "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/extra.mtx" -p "$PROBLEM" -o "$S/n.vtu"
printf '%%%%MatrixMarket matrix coordinate real general\n3 1 1\n1 1 0.5\n' >"$S/sparse_u.mtx"
expect 1 "sparse_u.mtx: a sparse (coordinate) Matrix Market file" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/sparse_u.mtx" -p "$PROBLEM" -o "$S/n.vtu"
cp -r "$S/system" "$S/dup"; awk 'NR == 2 { $3 = $3 + 1 } { print } NR == 3 { print }' "$S/system/K.mtx" >"$S/dup/K.mtx"
expect 1 "K.mtx: an entry appears twice" "$B/xfem-solve" "$S/dup" -o "$S/n.mtx"
cp -r "$S/system" "$S/upper"; awk 'NR == 4 && $1 != $2 { t = $1; $1 = $2; $2 = t } { print }' "$S/system/K.mtx" >"$S/upper/K.mtx"
expect 1 "above the diagonal in a symmetric file" "$B/xfem-solve" "$S/upper" -o "$S/n.mtx"
cp -r "$S/system" "$S/unsorted"; awk 'NR == 4 { held = $0; next } { print } NR == 5 { print held }' "$S/system/dirichlet.mtx" >"$S/unsorted/dirichlet.mtx"
expect 1 "unsorted/dirichlet.mtx: line 5: row 1 after row 2 (the rows must be strictly increasing)" \
  "$B/xfem-solve" "$S/unsorted" -o "$S/n.mtx"
absent "$S/n.vtu" "$S/n.mtx"

# 7. Outputs checked before any work: nothing left behind.
expect 1 "missing_dir/s.json: directory" \
  "$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/cut.vtp" -o "$S/c7.vtu" --summary "$S/missing_dir/s.json"
absent "$S/c7.vtu"
expect 1 "missing_dir/r.json: directory" "$B/xfem-solve" -q "$S/system" -o "$S/u7.mtx" --report "$S/missing_dir/r.json"
expect 1 "missing_dir/u.mtx: directory" "$B/xfem-solve" -q "$S/system" -o "$S/missing_dir/u.mtx"
absent "$S/u7.mtx"
expect 1 "faces.txt: unknown extension '.txt'" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -p "$PROBLEM" -o "$S/d7.vtu" --faces "$S/faces.txt"
absent "$S/d7.vtu"

# 8. Clear messages: header sizes checked before allocating; short numbers; -q shows errors only.
printf 'OFF\n4 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n' >"$S/huge.off"
expect 1 "huge.off: the OFF header claims 4 vertices and 2000000000 faces" \
  "$B/xfem-classify" "$S/beam.vtu" --cut "$S/huge.off" -o "$S/n.vtu"
printf '%%%%MatrixMarket matrix array real general\n1000000000000 1\n1\n' >"$S/rows.mtx"
expect 1 "rows.mtx: the size line claims 1000000000000 values" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/rows.mtx" -p "$PROBLEM" -o "$S/n.vtu"
expect 2 "--refine: value 1e+300 is not in [0, 8]" \
  "$B/xfem-assemble" "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$PROBLEM" --refine 1e300 -o "$S/n"
absent "$S/n.vtu" "$S/n"
# CLI11's own range checks print their bounds with std::to_string: DBL_MAX in 309 digits.
expect 2 "--radius: Value -1 not in range 0 to 1.79769e+308" "$B/xfem-front" "$S/enriched.vtu" --cut "$S/cut.vtp" \
  -s "$S/u.mtx" -p "$PROBLEM" --radius -1 -o "$S/n.vtp"
[ "$(wc -c <"$S/err.txt")" -lt 200 ] || fail "a long number in: $(cat "$S/err.txt")"
# The bytes of a corrupt file a message quotes are escaped: one printable line.
sed 's/NumberOfCells="\([0-9]*\)"/NumberOfCells="\1\x01\xff"/' "$S/beam.vtu" >"$S/bytes.vtu"
expect 1 "\\x01\\xff' is not a count" "$B/xfem-classify" "$S/bytes.vtu" --cut "$S/cut.vtp" -o "$S/n.vtu"
! LC_ALL=C grep -q '[^[:print:]]' "$S/err.txt" || fail "raw bytes in: $(cat -v "$S/err.txt")"
"$B/xfem-classify" -q "$S/beam.vtu" --cut "$S/other.vtp" -o "$S/miss.vtu" --summary "$S/missing_dir/x.json" 2>"$S/err.txt"
[ "$(grep -c warning "$S/err.txt")" -eq 0 ] || fail "-q printed a warning: $(cat "$S/err.txt")"

# The command line: "did you mean", no default shown on required options.
expect 2 "unknown command 'boxx' (did you mean 'box'?)" "$B/xfem-mesh" boxx --cells 1 1 1 --hi 1 1 1 -o "$S/n.vtu"
expect 2 "unknown option --cuts (did you mean --cut?)" "$B/xfem-classify" "$S/beam.vtu" --cuts "$S/cut.vtp" -o "$S/n.vtu"
"$B/xfem-mesh" box --help | grep -- "--hi" | grep -q "REQUIRED" || fail "--hi must show REQUIRED"
! "$B/xfem-mesh" box --help | grep -- "--hi" | grep -q "\[0,0,0\]" || fail "--hi shows a default: $("$B/xfem-mesh" box --help | grep -- --hi)"

# 9. xfem-visualize's two outputs appear together (issue 36 item 4): deformed.vtu and wound.vtp are
# written to temporaries and renamed into place only once both are complete, and both carry the
# field array inputs_fingerprint. Killed at any moment while visualizing another solution over the
# pair of u.mtx, the pair is the old one or the new one (each byte-identical to a full run), or
# (between the two renames only) a pair whose fingerprints differ: never an undetectable mix.
PAIR="python3 $XFEM_SOURCE/test/e2e/cut_catalogue.py pair"
viz() { "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$1" -p "$2" -o "$3.vtu" --faces "$3_wound.vtp"; }
viz "$S/u.mtx" "$PROBLEM" "$S/pa" || fail "visualize u.mtx"
t0=$(date +%s.%N)
viz "$S/u2.mtx" "$S/stiffer.json" "$S/pb" || fail "visualize u2.mtx"
run=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
$PAIR "$S/pa.vtu" "$S/pa_wound.vtp" >/dev/null || fail "one run's pair: $($PAIR "$S/pa.vtu" "$S/pa_wound.vtp")"
cmp -s "$S/pa.vtu" "$S/pb.vtu" && fail "two solutions gave the same deformed.vtu"
# A mixed pair (what a kill between the renames leaves) is detected.
$PAIR "$S/pb.vtu" "$S/pa_wound.vtp" >"$S/out.txt"; [ $? -eq 1 ] || fail "a mixed pair passed: $(cat "$S/out.txt")"
grep -qF "pa_wound.vtp (fnv1a64:" "$S/out.txt" || fail "mixed pair: $(cat "$S/out.txt")"
old=0 new=0
kill_at() {  # kill_at FRACTION: kill a visualize run at FRACTION of the measured run time
  local delay
  delay=$(awk -v r="$run" -v f="$1" 'BEGIN { print r * f }')
  cp "$S/pa.vtu" "$S/k.vtu"; cp "$S/pa_wound.vtp" "$S/k_wound.vtp"
  ( timeout -s KILL "$delay" "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u2.mtx" \
      -p "$S/stiffer.json" -o "$S/k.vtu" --faces "$S/k_wound.vtp" ) 2>/dev/null
  if $PAIR "$S/k.vtu" "$S/k_wound.vtp" >"$S/out.txt"; then
    if cmp -s "$S/k.vtu" "$S/pa.vtu" && cmp -s "$S/k_wound.vtp" "$S/pa_wound.vtp"; then old=$((old + 1))
    elif cmp -s "$S/k.vtu" "$S/pb.vtu" && cmp -s "$S/k_wound.vtp" "$S/pb_wound.vtp"; then new=$((new + 1))
    else fail "after a kill at $delay s the pair matches its fingerprints but neither run's bytes"; fi
  else
    grep -q "is not of the run that wrote" "$S/out.txt" || fail "after a kill at $delay s: $(cat "$S/out.txt")"
  fi
  rm -f "$S"/.k.tmp* "$S"/.k_wound.tmp*  # a killed writer's temporaries (never under the final names)
}
for fraction in 0.2 0.5 0.8 0.9 0.95 0.98 0.99 1.0 1.01 1.02 1.05 1.1 1.5; do kill_at $fraction; done
# The run time was measured once: on a loaded machine a run can take several times as long (or be
# quicker), so the kills may all land on one side of the write. Go further out until both states
# have been seen, so that the kills are known to span the window.
for fraction in 2 3 5 10 20; do [ $new -gt 0 ] && break; kill_at $fraction; done
for fraction in 0.1 0.05 0.02 0.01; do [ $old -gt 0 ] && break; kill_at $fraction; done
[ $old -gt 0 ] && [ $new -gt 0 ] || fail "the kills hit only one state (old $old, new $new): the timing is off"
expect 1 "d9.vtu: given as both -o and --faces" \
  "$B/xfem-visualize" -q "$S/enriched.vtu" --cut "$S/cut.vtp" -s "$S/u.mtx" -p "$PROBLEM" -o "$S/d9.vtu" --faces "$S/d9.vtu"
absent "$S/d9.vtu"

# 10. No load at all (f_free = 0, u_c = 0): the exact u_free is 0 and the relative residual would be
# 0/0; xfem-solve reports the absolute residual, 0, with either backend.
sed 's/"value": \[0, 0, 0.02\]/"value": [0, 0, 0]/' "$PROBLEM" >"$S/unloaded.json"
"$B/xfem-assemble" -q "$S/enriched.vtu" --cut "$S/cut.vtp" --problem "$S/unloaded.json" --format mtx -o "$S/sys10" \
  || fail "assemble unloaded"
for backend in cholmod petsc; do
  "$B/xfem-solve" -q "$S/sys10" -o "$S/u10.mtx" --backend $backend --report "$S/r10.json" || fail "solve unloaded ($backend)"
  grep -q '"relative_residual": 0.0' "$S/r10.json" || fail "unloaded ($backend): $(grep residual "$S/r10.json")"
  ! grep -v "^%" "$S/u10.mtx" | grep -qi "nan\|inf" || fail "unloaded ($backend): non-finite values in u.mtx"
done
echo "ok"
