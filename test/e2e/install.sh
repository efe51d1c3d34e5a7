#!/usr/bin/env bash
# cmake --install into a temporary prefix: the installed tools run a small beam through the
# pipeline, and a consumer project (test/consumer) finds the package with find_package(xfem),
# links xfem::xfem and runs.
set -u
S=$XFEM_SCRATCH; rm -rf "$S"; mkdir -p "$S"; cd "$S" || exit 1
BUILD=$(dirname "$XFEM_BIN"); P=$S/prefix
fail() { echo "FAIL: $*"; exit 1; }
cmake --install "$BUILD" --prefix "$P" >install.log 2>&1 || fail "cmake --install: $(tail -5 install.log)"
for f in bin/xfem-mesh bin/xfem-classify bin/xfem-enrich bin/xfem-assemble bin/xfem-solve bin/xfem-visualize \
         include/xfem/core/mesh.h include/xfem/core/version.h lib/cmake/xfem/xfemConfig.cmake; do
  [ -e "$P/$f" ] || fail "not installed: $f"
done
ls "$P"/lib*/libxfem.a >/dev/null 2>&1 || fail "libxfem.a not installed"

# The installed tools on the beam: a coarse box cut as in the paper, pulled at its top edge.
B=$P/bin
"$B/xfem-mesh" -q box --cells 3 6 19 --hi 0.03 0.06 0.2 -o beam.vtu || fail "installed xfem-mesh box"
"$B/xfem-mesh" -q cut-rect --beam-cut -o cut.vtp || fail "installed xfem-mesh cut-rect"
"$B/xfem-classify" -q beam.vtu --cut cut.vtp -o classified.vtu || fail "installed xfem-classify"
"$B/xfem-enrich" -q classified.vtu -o enriched.vtu || fail "installed xfem-enrich"
"$B/xfem-assemble" -q enriched.vtu --cut cut.vtp --problem "$XFEM_SOURCE/pipelines/beam/problem.json" --points 10 \
  -o system || fail "installed xfem-assemble"
"$B/xfem-solve" -q system -o u.mtx || fail "installed xfem-solve"
[ -s u.mtx ] || fail "no solution"

# A consumer project. Its build type matches ours so that the same configuration is linked, and
# so do its compiler and flags (a sanitizer build's library needs the sanitizer runtime).
cmake -S "$XFEM_SOURCE/test/consumer" -B consumer -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$P" \
  -DCMAKE_CXX_COMPILER="${XFEM_CXX:-c++}" -DCMAKE_CXX_FLAGS="${XFEM_CXX_FLAGS:-}" \
  >consumer.log 2>&1 || fail "consumer configure: $(tail -20 consumer.log)"
cmake --build consumer >>consumer.log 2>&1 || fail "consumer build: $(tail -20 consumer.log)"
out=$(consumer/consumer box.vtu) || fail "consumer run"
echo "$out" | grep -q "72 tets, volume 0.006000" || fail "consumer printed: $out"
echo "install: ok ($out)"
