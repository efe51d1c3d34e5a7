// SPDX-License-Identifier: MIT
#include "xfem/system/cut_loads.h"

#include <string>

#include "xfem/core/error.h"
#include "xfem/integrate/cut_face_quadrature.h"

namespace xfem {

int cut_count(const EnrichedMesh& em) {
  if (!em.cuts.empty()) return static_cast<int>(em.cuts.size());
  return em.cut ? 1 : 0;
}

double add_cut_loads(const EnrichedMesh& em, const Problem& problem, Eigen::VectorXd& f) {
  if (problem.cut_loads.empty()) return 0.0;
  check_cut_indices(problem, cut_count(em));
  double total_area = 0.0;
  Eigen::VectorXd jump;
  BasisAt scratch;
  for (std::size_t i = 0; i < problem.cut_loads.size(); ++i) {
    const CutLoad& load = problem.cut_loads[i];
    const std::vector<CutFacePoint> points = cut_face_points(em, load.cut, problem.order);
    if (points.empty())
      throw Error(problem.file + ": cut_loads[" + std::to_string(i) + "]: cut " + std::to_string(load.cut) +
                  " has no face inside an enriched element of the mesh (nothing to load)");
    for (const CutFacePoint& q : points) {
      basis_jump(em, q.tet, load.cut, q.x, jump, scratch);
      // Work of the load on the face above (p n + t) and below (-(p n + t)): (p n + t) . [[u]].
      const Eigen::Vector3d force = q.weight * (load.pressure * q.normal + load.traction);
      const long begin = em.offsets[q.tet];
      for (int e = 0; e < em.size(q.tet); ++e) {
        if (jump[e] == 0.0) continue;
        f.segment<3>(3 * em.dofs[begin + e]) += jump[e] * force;
      }
      total_area += q.weight;
    }
  }
  return total_area;
}

}  // namespace xfem
