// SPDX-License-Identifier: MIT
// validate_tet_mesh: the checks of a tetrahedral mesh read from any format.
#include <algorithm>
#include <cmath>

#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

int validate_tet_mesh(TetMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows(), nt = mesh.tets.rows();
  if (np == 0 || nt == 0) throw Error(name + ": empty mesh (" + std::to_string(np) + " points, " +
                                      std::to_string(nt) + " tetrahedra)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k)
      if (mesh.tets(t, k) < 0 || mesh.tets(t, k) >= np)
        throw Error(name + ": tetrahedron " + std::to_string(t) + " uses point " +
                    std::to_string(mesh.tets(t, k)) + ", out of range [0, " + std::to_string(np) + ")");
  validate_regions(mesh, name);
  // Zero volume is judged relative to the tet's own longest edge, so the test is scale-free.
  long degenerate = 0, inverted = 0, first_degenerate = -1, first_inverted = -1;
  for (Eigen::Index t = 0; t < nt; ++t) {
    const auto& c = mesh.tets.row(t);
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        longest = std::max(longest, (mesh.points.row(c[a]) - mesh.points.row(c[b])).squaredNorm());
    const double v6 = 6.0 * signed_volume(mesh, static_cast<int>(t));
    if (std::abs(v6) <= 1e-12 * std::pow(longest, 1.5)) {
      if (degenerate++ == 0) first_degenerate = t;
    } else if (v6 < 0) {
      if (inverted++ == 0) first_inverted = t;
      std::swap(mesh.tets(t, 1), mesh.tets(t, 2));
    }
  }
  if (degenerate)
    throw Error(name + ": " + std::to_string(degenerate) + " tetrahedra have zero volume (first: tetrahedron " +
                std::to_string(first_degenerate) + ")");
  if (inverted && warnings)
    warnings->push_back(name + ": " + std::to_string(inverted) +
                        " inverted tetrahedra reoriented (first: tetrahedron " + std::to_string(first_inverted) + ")");
  return static_cast<int>(inverted);
}

}  // namespace xfem
