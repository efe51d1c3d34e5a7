#!/usr/bin/env bash
# Issue 8 checks at small sizes: every node branch-enriched reproduces Williams modes I-III (below
# 1e-6 relative L2 with xfem-assemble --rule conforming), a body cut through and moved rigidly has
# zero strain and the imposed gap;
# plus the xfem-rmserror --exact CLI contract.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" || exit 1
P="$XFEM_SOURCE/pipelines/verification"
make -s -C "$P" BIN="$XFEM_BIN" OUT="$XFEM_SCRATCH/out" check || fail "verification checks"
O="$XFEM_SCRATCH/out"
"$XFEM_BIN/xfem-assemble" "$O/s3-all/enriched.vtu" --cut "$O/cut.vtp" --problem "$P/data/mode1.json" --rule gauss \
  -o "$XFEM_SCRATCH/sys" 2>/dev/null; [ $? -eq 2 ] || fail "xfem-assemble --rule gauss must exit 2"
R="$XFEM_BIN/xfem-rmserror"
"$R" --help >/dev/null || fail "--help"
"$R" "$O/rigid-s4/enriched.vtu" --bogus 2>/dev/null; [ $? -eq 2 ] || fail "bad flag must exit 2"
"$R" "$O/rigid-s4/enriched.vtu" 2>/dev/null; [ $? -eq 2 ] || fail "neither --reference nor --exact must exit 2"
echo '{"williams": {"origin": [0,0,0], "ahead": [1,0,0], "normal": [1,0,0], "K1": 1, "E": 1, "nu": 0.3}}' > "$XFEM_SCRATCH/bad.json"
"$R" "$O/rigid-s4/enriched.vtu" --cut "$O/cut-through.vtp" --solution "$O/rigid-s4/u.mtx" --exact "$XFEM_SCRATCH/bad.json" \
  -o "$XFEM_SCRATCH/e.json" 2>"$XFEM_SCRATCH/err" >/dev/null; [ $? -eq 1 ] || fail "bad exact file must exit 1"
grep -q "error:.*perpendicular" "$XFEM_SCRATCH/err" || fail "bad exact file message: $(cat "$XFEM_SCRATCH/err")"
[ ! -e "$XFEM_SCRATCH/e.json" ] || fail "output left behind"
rm -rf "$XFEM_SCRATCH"
