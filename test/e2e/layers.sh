#!/usr/bin/env bash
# The layering rule of lib/xfem (docs/ARCHITECTURE.md): every include keeps the stage order in the
# tree as it is; and the check itself fails, naming the file and the include, on a copy of the tree
# with a deliberately broken include, and on a file outside the stage folders.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
CHECK="python3 $XFEM_SOURCE/scripts/check_layers.py"
fail() { echo "FAIL: $*"; exit 1; }

$CHECK "$XFEM_SOURCE/lib/xfem" > ok.txt 2> ok.err || fail "the tree breaks the stage order: $(cat ok.err)"

# core/mesh.h made to include a header of the solve stage: a break, named with its line.
cp -r "$XFEM_SOURCE/lib/xfem" broken
sed -i '0,/#include/s//#include "xfem\/solve\/cholmod_solver.h"\n#include/' broken/core/mesh.h
$CHECK broken > /dev/null 2> broken.err && fail "a core file including a solve file passed the check"
grep -q 'broken/core/mesh.h:[0-9]*: #include "xfem/solve/cholmod_solver.h": stage core may not use the later stage solve' broken.err \
  || fail "the break is not named: $(cat broken.err)"
[ "$(wc -l < broken.err)" -eq 1 ] || fail "one break, but: $(cat broken.err)"

# A file beside the stage folders, and an include of a folder that is no stage.
cp -r "$XFEM_SOURCE/lib/xfem" loose
echo '#include "xfem/misc/thing.h"' > loose/geometry/extra.h
touch loose/stray.h
$CHECK loose > /dev/null 2> loose.err && fail "a file outside the stages passed the check"
grep -q 'loose/stray.h: not in a stage folder' loose.err || fail "stray file not named: $(cat loose.err)"
grep -q 'loose/geometry/extra.h:1: #include "xfem/misc/thing.h" names no stage' loose.err || fail "unknown stage not named: $(cat loose.err)"
echo "layers: ok ($(cat ok.txt))"
