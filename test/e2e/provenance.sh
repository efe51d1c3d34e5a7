#!/usr/bin/env bash
# Issue 36, item 3: every tool that reads a solution checks that it belongs to the files it is read
# with (lib/xfem/post/solution_provenance_check.h, docs/FORMATS.md "Fingerprints"):
#   - xfem-front with E doubled in problem.json (it reported K_I doubled), and with a u.mtx whose
#     fingerprint lines are tampered with, conflicting or malformed (the same three for every reader);
#   - xfem-probe with another cut (a point 0.5 mm below the real cut got the upper face's value);
#   - xfem-rmserror with an X-FEM solution as the reference of a mesh given without its cut (it
#     dropped the enrichment and reported an RMS), on either side;
# each refused with one line "<tool>: error: <file>: ...", exit 1, no output. The matching files,
# and xfem-newton's u.mtx, are still taken.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
B=$XFEM_BIN; PROBLEM=$XFEM_SOURCE/pipelines/beam/problem.json
fail() { echo "FAIL: $*"; exit 1; }

# refuse <text> <output> <command...>: exit 1, one line on stderr containing <text>, nothing on
# stdout, <output> not written.
refuse() {
  local text=$1 output=$2; shift 2
  rm -f "$output"
  "$@" >out.txt 2>err.txt; local rc=$?
  [ $rc -eq 1 ] || fail "expected exit 1, got $rc: $* -> $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "expected one line on stderr: $* -> $(cat err.txt)"
  grep -qF -- "$text" err.txt || fail "expected '$text': $* -> $(cat err.txt)"
  [ ! -s out.txt ] || fail "output on stdout: $* -> $(cat out.txt)"
  [ ! -e "$output" ] || fail "$output written: $*"
}

# The beam on a small grid with the paper's cut (its front x = 0.015 inside), solved.
"$B/xfem-mesh" -q box --cells 3 5 13 --hi 0.03 0.06 0.2 -o beam.vtu || fail "xfem-mesh box"
"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp || fail "cut-rect"
"$B/xfem-classify" -q beam.vtu --cut cut.vtp -o classified.vtu || fail "classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "enrich"
"$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$PROBLEM" --format mtx -o system 2>/dev/null || fail "assemble"
"$B/xfem-solve" -q system -o u.mtx || fail "solve"
"$B/xfem-visualize" -q enriched.vtu --cut cut.vtp -s u.mtx -p "$PROBLEM" -o deformed.vtu || fail "visualize"
grep -q "^% xfem-fingerprint cut fnv1a64:" u.mtx || fail "u.mtx records no cut: $(head -4 u.mtx)"

# Every reader of u.mtx, with the matching files: each runs (exit 0).
front() { "$B/xfem-front" -q enriched.vtu --cut cut.vtp --radius 0.012 "$@"; }
printf 'x,y,z\n0.005,0.03,0.0995\n0.005,0.03,0.1005\n' > points.csv
front -s u.mtx -p "$PROBLEM" --csv front_ok.csv 2>/dev/null || fail "xfem-front on matching files"
"$B/xfem-probe" -q enriched.vtu --cut cut.vtp -s u.mtx -p points.csv -o probe_ok.csv || fail "xfem-probe on matching files"
"$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp -s u.mtx -r deformed.vtu -o rms.json >/dev/null \
  || fail "xfem-rmserror on matching files"

# 1. xfem-front, E doubled: K_I would double. Refused, naming the problem file.
sed 's/"E": 300e3/"E": 600e3/' "$PROBLEM" > doubled.json
cmp -s doubled.json "$PROBLEM" && fail "doubled.json is the beam's problem"
refuse "u.mtx: does not belong to doubled.json (made for the problem with fingerprint" front.csv \
  front -s u.mtx -p doubled.json --csv front.csv

# 2. Tampered, conflicting and malformed fingerprint lines, against every reader.
awk '/^% xfem-fingerprint enriched / { last = substr($0, length($0)); $0 = substr($0, 1, length($0) - 1) (last == "0" ? "1" : "0") } { print }' \
  u.mtx > tampered.mtx
cmp -s tampered.mtx u.mtx && fail "tampered.mtx equals u.mtx"
awk 'NR == 2 { print "% xfem-fingerprint cut fnv1a64:0123456789abcdef" } { print }' u.mtx > conflicting.mtx
awk 'NR == 2 { print "% xfem-fingerprint cut fnv1a64:0123" } { print }' u.mtx > malformed.mtx
# The same name twice with the same value is no conflict (a file concatenated from its own header).
awk 'NR == 2 { line = $0 } { print } NR == 2 { print line }' u.mtx > repeated.mtx
grep -q "^% xfem-fingerprint" repeated.mtx || fail "repeated.mtx"
for case in tampered conflicting malformed; do
  case $case in
    tampered) text="$case.mtx: does not belong to enriched.vtu (made for the enriched with fingerprint" ;;
    conflicting) text="$case.mtx: conflicting fingerprint lines for 'cut' (" ;;
    malformed) text="$case.mtx: malformed fingerprint line '% xfem-fingerprint cut fnv1a64:0123'" ;;
  esac
  refuse "$text" front.csv front -s $case.mtx -p "$PROBLEM" --csv front.csv
  refuse "$text" probe.csv "$B/xfem-probe" -q enriched.vtu --cut cut.vtp -s $case.mtx -p points.csv -o probe.csv
  refuse "$text" rms.json "$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp -s $case.mtx -r deformed.vtu -o rms.json
  refuse "$text" d.vtu "$B/xfem-visualize" -q enriched.vtu --cut cut.vtp -s $case.mtx -p "$PROBLEM" -o d.vtu
  # ... and as xfem-rmserror's reference solution.
  refuse "$text" rms.json "$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp -s u.mtx --standard-dofs-only \
    -r enriched.vtu --reference-solution $case.mtx -o rms.json
done
front -s repeated.mtx -p "$PROBLEM" --csv front2.csv 2>/dev/null || fail "xfem-front refuses a repeated, equal line"
cmp -s front_ok.csv front2.csv || fail "the same u.mtx with a repeated line gives another front.csv"

# 3. xfem-probe with another cut: the cut at z = 0.099 would put the point 0.5 mm below the real
#    cut (z = 0.0995) on its upper side. Refused, by the mesh's record and by the solution's.
"$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.099 --edge1 0.025 0 0 --edge2 0 0.08 0 -o other.vtp || fail "other cut"
refuse "other.vtp: not the cut $S/enriched.vtu was classified with" probe.csv \
  "$B/xfem-probe" -q "$S/enriched.vtu" --cut other.vtp -s u.mtx -p points.csv -o probe.csv
# A mesh classified without the record (an older xfem-classify): the solution's own record refuses.
python3 - <<'PY' || fail "enriched_norecord.vtu"
data = open("enriched.vtu", "rb").read()  # binary: the appended data must keep every byte
if b'Name="cut_fingerprint"' not in data: raise SystemExit("no cut_fingerprint array in enriched.vtu")
open("enriched_norecord.vtu", "wb").write(data.replace(b'Name="cut_fingerprint"', b'Name="cut_fingerprinx"'))
PY
refuse "u.mtx: does not belong to other.vtp (made for the cut with fingerprint" probe.csv \
  "$B/xfem-probe" -q enriched_norecord.vtu --cut other.vtp -s u.mtx -p points.csv -o probe.csv
refuse "u.mtx: does not belong to other.vtp (made for the cut with fingerprint" front.csv \
  "$B/xfem-front" -q enriched_norecord.vtu --cut other.vtp -s u.mtx -p "$PROBLEM" --csv front.csv
"$B/xfem-probe" -q enriched_norecord.vtu --cut cut.vtp -s u.mtx -p points.csv -o probe2.csv || fail "probe without the record"
cmp -s probe_ok.csv probe2.csv || fail "the mesh without its record probes differently"
# A u.mtx solved without a cut, given one with a mesh classified with it: refused.
grep -v "^% xfem-fingerprint cut " u.mtx > nocut.mtx
refuse "nocut.mtx: does not belong to cut.vtp (solved without a cut, but enriched.vtu was classified with cut.vtp)" \
  probe.csv "$B/xfem-probe" -q enriched.vtu --cut cut.vtp -s nocut.mtx -p points.csv -o probe.csv
# A mesh classified, assembled and solved without a cut, read with one (bench/bench.py's reference
# case: no enriched DOFs, the cut changes nothing): taken.
"$B/xfem-classify" -q beam.vtu -o plain_c.vtu && "$B/xfem-enrich" -q plain_c.vtu -o plain_e.vtu &&
  "$B/xfem-assemble" -q plain_e.vtu --problem "$PROBLEM" -o plain_system && "$B/xfem-solve" -q plain_system -o plain_u.mtx \
  || fail "the mesh without a cut"
"$B/xfem-visualize" -q plain_e.vtu --cut cut.vtp -s plain_u.mtx -p "$PROBLEM" -o plain_d.vtu \
  || fail "xfem-visualize, a mesh classified without a cut read with one"
"$B/xfem-rmserror" -q plain_e.vtu --cut cut.vtp -s plain_u.mtx -r plain_e.vtu --reference-solution plain_u.mtx >/dev/null \
  || fail "xfem-rmserror, a mesh classified without a cut read with one"

# 4. xfem-rmserror with an X-FEM solution for a mesh given without its cut: the enrichment would be
#    dropped. Refused as the reference (naming the reference) and as the solution.
refuse "$S/enriched.vtu: given without the cut its solution $S/u.mtx needs (" rms.json \
  "$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp -s u.mtx -r "$S/enriched.vtu" --reference-solution "$S/u.mtx" -o rms.json
refuse "classified.vtu: given without the cut its solution u.mtx needs (" rms.json \
  "$B/xfem-rmserror" -q classified.vtu -s u.mtx -r deformed.vtu -o rms.json
# ... unless asked for the standard DOFs only (test/e2e/golden.sh's regression check): then u
# against itself is 0.
self=$("$B/xfem-rmserror" -q classified.vtu -s u.mtx --standard-dofs-only -r classified.vtu --reference-solution u.mtx) \
  || fail "--standard-dofs-only"
awk -v r="$self" 'BEGIN { exit !(r < 1e-15) }' || fail "u.mtx against itself, standard DOFs: RMS $self, not 0"

# 5. xfem-newton's u.mtx (the fingerprints of enriched, cut and problem) is taken by every reader.
"$B/xfem-newton" -q enriched.vtu --cut cut.vtp --problem "$PROBLEM" -o u_newton.mtx 2>/dev/null || fail "xfem-newton"
grep -q "^% xfem-fingerprint cut fnv1a64:" u_newton.mtx || fail "xfem-newton's u.mtx records no cut"
front -s u_newton.mtx -p "$PROBLEM" --csv front_newton.csv 2>/dev/null || fail "xfem-front refuses xfem-newton's u"
"$B/xfem-probe" -q enriched.vtu --cut cut.vtp -s u_newton.mtx -p points.csv -o probe_newton.csv \
  || fail "xfem-probe refuses xfem-newton's u"
"$B/xfem-rmserror" -q enriched.vtu --cut cut.vtp -s u_newton.mtx -r deformed.vtu >/dev/null \
  || fail "xfem-rmserror refuses xfem-newton's u"
"$B/xfem-visualize" -q enriched.vtu --cut cut.vtp -s u_newton.mtx -p "$PROBLEM" -o d_newton.vtu \
  || fail "xfem-visualize refuses xfem-newton's u"
refuse "u_newton.mtx: does not belong to doubled.json" front.csv front -s u_newton.mtx -p doubled.json --csv front.csv
echo "provenance: ok"
