#!/bin/bash
# Start-up (issue 35, sixth part): the pipeline's tools do not link VTK's vtkIOGeometry (STL) or
# vtkIOImage (label maps), ~24 and ~12 shared libraries more; they load them on the first .stl cut
# or label map (io/vtk_on_demand.h). Both inputs still work through the tools, byte for byte the
# same as the same surface given as .off.
set -u
B="$XFEM_BIN"
S="$XFEM_SCRATCH"
rm -rf "$S" && mkdir -p "$S" && cd "$S" || exit 1
fail=0
source "$XFEM_SOURCE/test/e2e/check_exit.bash"
if command -v readelf >/dev/null; then
  for t in xfem-mesh xfem-classify xfem-enrich xfem-assemble xfem-solve xfem-probe xfem-front xfem-rmserror; do
    libs=$(readelf -d "$B/$t" | grep NEEDED | grep -E 'vtkIOGeometry|vtkIOImage')
    [ -z "$libs" ] || { echo "FAIL: $t links what it should load only when used: $libs"; fail=1; }
  done
fi
check 0 "organ" "$B/xfem-mesh" -q organ --size 0.03 -o organ.vtu
# A square cut through the organ, as ASCII STL and as OFF (the same points: STL's floats are exact here).
cat >cut.stl <<'STL'
solid square
facet normal 0 0 1
 outer loop
  vertex -0.1 -0.1 0.00390625
  vertex 0.1 -0.1 0.00390625
  vertex 0.1 0.1 0.00390625
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -0.1 -0.1 0.00390625
  vertex 0.1 0.1 0.00390625
  vertex -0.1 0.1 0.00390625
 endloop
endfacet
endsolid square
STL
printf 'OFF\n4 2 0\n-0.1 -0.1 0.00390625\n0.1 -0.1 0.00390625\n0.1 0.1 0.00390625\n-0.1 0.1 0.00390625\n3 0 1 2\n3 0 2 3\n' >cut.off
check 0 "classify, STL cut" "$B/xfem-classify" -q organ.vtu --cut cut.stl --summary stl.json -o stl.vtu
check 0 "classify, OFF cut" "$B/xfem-classify" -q organ.vtu --cut cut.off --summary off.json -o off.vtu
grep -q '"complete": [1-9]' stl.json || { echo "FAIL: the STL cut cuts nothing"; cat stl.json; fail=1; }
# The arrays and counts agree (the cut's name and fingerprint differ with the file).
[ "$(grep -v '"cut"' stl.json)" = "$(grep -v '"cut"' off.json)" ] || { echo "FAIL: STL and OFF cuts classify differently"; fail=1; }
# A label map (NRRD) through xfem-mesh image.
check 0 "phantom-image" "$B/xfem-mesh" -q phantom-image --spacing 0.008 0.008 0.008 --origin -0.0835 -0.0585 -0.045 -o phantom.nrrd
check 0 "image" "$B/xfem-mesh" -q image phantom.nrrd --size 0.02 -o body.vtu
[ -s body.vtu ] || { echo "FAIL: no mesh from the label map"; fail=1; }
rm -rf "$S"
[ "$fail" = 0 ] && echo "vtk_on_demand e2e: ok"
exit "$fail"
