// SPDX-License-Identifier: MIT
#include "xfem/post/sweep_frame.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "xfem/geometry/element_split.h"

namespace xfem {

DeformedBody sweep_frame(const CutSolution& step, const Problem& problem) {
  const EnrichedMesh& em = step.em;
  const SplitMesh split = em.cut ? split_mesh(em.mesh, em.side, em.cut_class, *em.cut, em.front.segments())
                                 : unsplit_mesh(em.mesh, em.side);
  return deformed_body(split, em.cut_class, xfem_displacement(em, step.u), problem.E, problem.nu);
}

std::string numbered(const std::string& stem, int k, const std::string& extension) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", k);
  return stem + buf + extension;
}

SnapshotOptions sweep_pictures(const DeformedBody& frame, double scale, int width, int height) {
  SnapshotOptions picture;
  picture.view = cut_view(frame.wound);
  picture.colour_max = colour_top(frame.volume);
  const auto& u = frame.volume.point_data.at("displacement");
  std::array<double, 6> box{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (Eigen::Index p = 0; p < frame.volume.points.rows(); ++p)
    for (int i = 0; i < 3; ++i) {
      const double x = frame.volume.points(p, i) + scale * u(static_cast<std::size_t>(p), i);
      box[2 * i] = std::min(box[2 * i], x);
      box[2 * i + 1] = std::max(box[2 * i + 1], x);
    }
  picture.frame = box;
  picture.scale = scale;
  picture.width = width;
  picture.height = height;
  picture.edges = SnapshotOptions::Edges::Off;  // Auto would switch them off as the cut adds faces
  return picture;
}

}  // namespace xfem
