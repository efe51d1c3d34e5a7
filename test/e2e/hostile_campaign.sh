#!/usr/bin/env bash
# The hostile-input campaign (scripts/hostile_campaign.sh) in its short form for CI: every stage
# input of round one and round two (the tools added since: xfem-newton, -front, -probe, -sweep,
# xfem-mesh surface and cut-merge, gmsh files, legacy VTK, rotation and value_array conditions,
# material.model, load_steps) fed truncated at 1/8 of its size and with two seeded byte flips.
# Every run must exit 0 or give one error line; the campaign lists any defect and fails. The full
# campaign (30 mutations per input) is scripts/hostile_campaign.sh BIN_DIR.
set -u
KS="1 9 14" bash "$XFEM_SOURCE/scripts/hostile_campaign.sh" "$XFEM_BIN" 3 "$XFEM_SCRATCH" || { echo "FAIL: defects"; exit 1; }
echo ok
