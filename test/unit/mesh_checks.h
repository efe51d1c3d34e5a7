// SPDX-License-Identifier: MIT
// Checks on tetrahedral meshes shared by the unit tests of the mesh generators and the splitter.
#pragma once
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <map>

#include "xfem/core/mesh.h"

namespace xfem_test {

/// Faces (sorted point ids) -> number of tets using them: 2 for interior faces of a conforming
/// mesh, 1 on its boundary.
inline std::map<std::array<int, 3>, int> face_counts(const xfem::Tets& tets) {
  std::map<std::array<int, 3>, int> faces;
  for (int t = 0; t < tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f[n++] = tets(t, k);
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  return faces;
}

/// Sum of the tets' volumes, checking each is positive.
inline double total_volume(const xfem::TetMesh& m) {
  double volume = 0;
  for (int t = 0; t < m.tets.rows(); ++t) {
    const double v = xfem::signed_volume(m, t);
    CHECK(v > 0);
    volume += v;
  }
  return volume;
}

}  // namespace xfem_test
