// SPDX-License-Identifier: MIT
// The X-FEM solution as a field for rms_error (declared in rms_error.h).
#include <memory>

#include "xfem/enrich/enriched_basis.h"
#include "xfem/geometry/point_location.h"
#include "xfem/post/rms_error.h"

namespace xfem {

FieldAt xfem_field(const EnrichedMesh& em, const Eigen::VectorXd& u, double radius) {
  auto locator = std::make_shared<PointLocator>(em.mesh);
  return [&em, &u, locator, radius](const Eigen::Vector3d& x, int side,
                                    bool& snapped) -> std::optional<Eigen::Vector3d> {
    snapped = false;
    // The enriched field is continuous across element faces on each side of the cut, so any tet
    // containing x gives the same value.
    const auto candidates = locator->containing(x);
    int t = candidates.empty() ? -1 : candidates.front();
    Eigen::Vector3d at = x;
    if (t < 0) {
      t = locator->nearest(x, radius);
      if (t < 0) return std::nullopt;
      snapped = true;
      Eigen::Vector4d l = locator->barycentric(t, x).cwiseMax(0.0);
      l /= l.sum();
      at.setZero();
      for (int c = 0; c < 4; ++c) at += l[c] * em.mesh.points.row(em.mesh.tets(t, c)).transpose();
    }
    return displacement_at(em, t, at, side, u);
  };
}

}  // namespace xfem
