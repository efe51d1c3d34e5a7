#!/usr/bin/env bash
# Installs the Debian 12 packages the toolchain builds and runs with; installs only what is missing.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev  # exact geometry, AABB trees, Mesh_3
  libcgal-demo                                     # CGAL's data: the liver label map of the scan pipeline
  libeigen3-dev                                    # dense and sparse linear algebra
  libsuitesparse-dev libmetis-dev                  # CHOLMOD with METIS ordering
  liblapack-dev libblas-dev                        # dense Cholesky updates of progressive cutting (xfem-sweep)
  libopenblas0-pthread                             # fast BLAS for CHOLMOD (the reference BLAS is ~30x slower)
  libvtk9-dev                                      # mesh I/O, point location, rendering
  libpetsc-real-dev openmpi-bin                    # iterative, MPI-capable solve
  libgmsh-dev gmsh                                 # .msh input (gmsh's library), the gmsh pipeline's mesher
  catch2 libcli11-dev nlohmann-json3-dev           # tests, arguments, JSON
  xvfb xauth gnuplot-nox python3                   # headless PNG snapshots, plots, tables
  imagemagick                                      # convert: the sweep's PNG frames into an animated GIF
  time                                             # GNU /usr/bin/time: peak memory in bench/bench.py
  clang libclang-rt-14-dev                         # make sanitize (ASan, UBSan) and make fuzz (libFuzzer)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install-deps: error: missing packages (${missing[*]}); run as root or install sudo" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
