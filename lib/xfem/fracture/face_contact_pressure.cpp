// SPDX-License-Identifier: MIT
#include "xfem/fracture/face_contact_pressure.h"

#include "xfem/core/error.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {

FaceContactPressure face_contact_pressure(const SparseMatrix& nodal, int cut, const std::string& path) {
  if (cut < 0 || cut >= nodal.cols())
    throw Error(path + ": no contact pressure for cut " + std::to_string(cut) + " (" + std::to_string(nodal.cols()) +
                " column(s): was contact on for that cut when xfem-solve wrote it?)");
  FaceContactPressure p;
  p.pressure.assign(static_cast<std::size_t>(nodal.rows()), 0.0);
  p.contact_node.assign(static_cast<std::size_t>(nodal.rows()), 0);
  long nodes = 0;
  for (SparseMatrix::InnerIterator it(nodal, cut); it; ++it) {  // every contact node is stored, zeros included
    p.pressure[static_cast<std::size_t>(it.row())] = it.value();
    p.contact_node[static_cast<std::size_t>(it.row())] = 1;
    ++nodes;
  }
  if (nodes == 0) throw Error(path + ": no contact node on cut " + std::to_string(cut));
  return p;
}

double face_contact_pressure_at(const FaceContactPressure& p, const TetMesh& mesh, int t, const Eigen::Vector3d& x) {
  const Eigen::Vector4d N = tet_shape(mesh, t).values(x).cwiseMax(0.0);
  double sum = 0.0, value = 0.0;
  for (int a = 0; a < 4; ++a) {
    const std::size_t node = static_cast<std::size_t>(mesh.tets(t, a));
    if (!p.contact_node[node]) continue;
    sum += N[a];
    value += N[a] * p.pressure[node];
  }
  return sum > 0 ? value / sum : 0.0;
}

}  // namespace xfem
