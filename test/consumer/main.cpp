// SPDX-License-Identifier: MIT
// Uses the installed library: writes a box mesh through VTK and reads it back (so the static
// library's private dependencies must link), then prints its volume, which must be 0.006 m^3.
#include <cstdio>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/version.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const xfem::TetMesh box = xfem::box_mesh({2, 2, 3}, {0, 0, 0}, {0.1, 0.2, 0.3});
  xfem::write_tet_mesh(box, argv[1]);
  const xfem::TetMesh back = xfem::read_tet_mesh(argv[1]);
  double volume = 0;
  for (int t = 0; t < back.tets.rows(); ++t) volume += xfem::signed_volume(back, t);
  std::printf("xfem %s: %ld tets, volume %.6f\n", xfem::version, static_cast<long>(back.tets.rows()), volume);
  return 0;
}
