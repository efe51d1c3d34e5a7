#!/bin/bash
# xfem-mesh image and phantom-image: a coarse phantom label map meshed into regions (byte-identical
# reruns), cut and solved through the whole chain; hostile label maps refused with one line naming
# the file and no output left behind.
set -u
B="$XFEM_BIN"
M="$B/xfem-mesh"
S="$XFEM_SCRATCH"
rm -rf "$S" && mkdir -p "$S" && cd "$S" || exit 1
fail=0
source "$XFEM_SOURCE/test/e2e/check_exit.bash"
expect_error() {  # expect_error <description> <text> <command...>: exit 1, one 'error:' line with <text>, no body.vtu
  local what=$1 text=$2
  shift 2
  check 1 "$what" "$@"
  [ "$(wc -l <err.txt)" = 1 ] || { echo "FAIL: $what: not one line on stderr"; cat err.txt; fail=1; }
  grep -qF -- "$text" err.txt || { echo "FAIL: $what: no '$text' on stderr"; cat err.txt; fail=1; }
  [ ! -e body.vtu ] || { echo "FAIL: $what: left body.vtu behind"; rm -f body.vtu; fail=1; }
}

for c in image phantom-image; do
  check 0 "$c --help" "$M" "$c" --help
  grep -q "Example:" out.txt || { echo "FAIL: $c --help shows no example"; fail=1; }
done

# A coarse phantom (4 mm voxels), its body centred at the origin like xfem-mesh organ's, so that
# the organ pipeline's problem and cut apply.
check 0 "phantom-image" "$M" phantom-image --spacing 0.004 0.004 0.004 --origin -0.0835 -0.0585 -0.045 -o phantom.nrrd
head -c 9 phantom.nrrd | grep -q NRRD0004 || { echo "FAIL: phantom.nrrd is not NRRD"; fail=1; }
check 0 "image" "$M" image phantom.nrrd --size 0.012 -o body.vtu
grep -q "region 1 (body): " err.txt && grep -q "region 2 (inclusion): " err.txt ||
  { echo "FAIL: image does not report both regions"; cat err.txt; fail=1; }
grep -q 'Name="region"' body.vtu && grep -q 'Name="region_names"' body.vtu && grep -q 'Name="region_ids"' body.vtu ||
  { echo "FAIL: body.vtu has no region array or names"; fail=1; }
check 0 "image again" "$M" -q image phantom.nrrd --size 0.012 -o again.vtu
cmp -s body.vtu again.vtu || { echo "FAIL: image is not deterministic"; fail=1; }
[ ! -s err.txt ] || { echo "FAIL: -q printed"; cat err.txt; fail=1; }
check 0 "phantom-image, rotated" "$M" -q phantom-image --spacing 0.004 0.003 0.005 --direction 0 1 0 -1 0 0 0 0 1 -o rotated.nrrd
grep -q "space directions: (0,0.0040000000000000001,0) (-0.0030000000000000001,0,0) (0,0,0.0050000000000000001)" rotated.nrrd ||
  { echo "FAIL: phantom-image --direction not in the header"; head -c 400 rotated.nrrd; fail=1; }
check 1 "phantom-image, sheared" "$M" phantom-image --direction 1 0 0 1 1 0 0 0 1 -o sheared.nrrd
grep -q "must be orthonormal" err.txt && [ ! -e sheared.nrrd ] || { echo "FAIL: sheared direction"; cat err.txt; fail=1; }
check 0 "--labels 2" "$M" -q image phantom.nrrd --labels 2 --size 0.006 -o inclusion.vtu

# The whole chain on the phantom's mesh: cut, classified, enriched, assembled, solved.
check 0 "cut" "$M" -q cut-sine -o cut.vtp
check 0 "classify" "$B/xfem-classify" -q body.vtu --cut cut.vtp -o classified.vtu
check 0 "enrich" "$B/xfem-enrich" -q classified.vtu -o enriched.vtu
check 0 "assemble" "$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$XFEM_SOURCE/pipelines/organ/problem.json" -o system
check 0 "solve" "$B/xfem-solve" -q system -o u.mtx
[ -s u.mtx ] || { echo "FAIL: no solution"; fail=1; }

# Hostile label maps (the unit tests check each reader's messages; here the tool's contract).
mv body.vtu good.vtu
printf 'NRRD0004\ntype: uint8\ndimension: 3\nsizes: 20 20 20\nencoding: raw\n\n0123' >truncated.nrrd
expect_error "truncated" "truncated.nrrd: the data holds 4 bytes of voxels, the header says 8000 (truncated file?)" \
  "$M" image truncated.nrrd --size 0.01 -o body.vtu
printf 'NRRD0004\ntype: uint8\ndimension: 2\nsizes: 20 20\nencoding: raw\n\n' >flat.nrrd
expect_error "2D" "flat.nrrd: a 2D image" "$M" image flat.nrrd --size 0.01 -o body.vtu
printf 'NRRD0004\ntype: float\ndimension: 3\nsizes: 20 20 20\nencoding: raw\n\n' >grey.nrrd
expect_error "float" "integer labels" "$M" image grey.nrrd --size 0.01 -o body.vtu
printf 'NRRD0004\ntype: uint8\ndimension: 3\nsizes: 20 20 20\nspacings: 1 nan 1\nencoding: raw\n\n' >nan.nrrd
expect_error "NaN spacing" "nan.nrrd: voxel spacing nan along axis 1 must be positive and finite" "$M" image nan.nrrd --size 0.01 -o body.vtu
printf 'NRRD0004\ntype: uint16\ndimension: 3\nsizes: 4000000 4000000 4000000\nencoding: raw\n\n' >huge.nrrd
expect_error "absurd size" "exceeds the limit" "$M" image huge.nrrd --size 0.01 -o body.vtu
expect_error "unknown label" "phantom.nrrd: label 9 is not in the image (its labels: 1, 2)" \
  "$M" image phantom.nrrd --labels 9 --size 0.01 -o body.vtu
expect_error "too many tets" "requested (limit 2e+07" "$M" -q image phantom.nrrd --size 0.0002 -o body.vtu
expect_error "missing file" "no_such.nii" "$M" image no_such.nii --size 0.01 -o body.vtu

[ "$fail" = 0 ] && echo "xfem_mesh_image: all checks passed"
exit "$fail"
