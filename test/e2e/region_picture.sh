#!/usr/bin/env bash
# The picture of a body with an inclusion (several regions) shows the inclusion through the body,
# and a body of one region renders exactly as one without regions: the hidden unit test
# [.region_picture] (test/unit/region_boundary.cpp) run under a virtual display.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"
fail() { echo "FAIL: $*"; exit 1; }
command -v xvfb-run >/dev/null || { echo "xvfb-run missing: skipped"; exit 0; }
XFEM_SCRATCH=$S xvfb-run -a "$XFEM_BIN/../test/xfem_unit_tests" "[.region_picture]" || fail "region picture"
rm -rf "$S"
echo "ok"
