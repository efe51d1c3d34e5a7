// SPDX-License-Identifier: MIT
#include "xfem/enrich/growing_classification.h"

#include <algorithm>
#include <string>
#include <utility>

#include "xfem/core/error.h"
#include "xfem/geometry/point_location.h"

namespace xfem {

double CutGrowth::distance(const Eigen::Vector3d& x, double bound) const {
  double d = bound;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const GrowthBox& b = boxes[k];
    if (((b.col(0) - x).array() > d).any() || ((x - b.col(1)).array() > d).any()) continue;  // its box is farther
    const auto& t = corners[k];
    d = std::min(d, (closest_on_triangle(x, t[0], t[1], t[2]) - x).norm());
  }
  return d;
}

GrowingCutClassifier::GrowingCutClassifier(const TetMesh& mesh, const ClassifyOptions& options)
    : mesh_(&mesh), options_(options), memory_(std::make_unique<ClassificationMemory>()) {
  memory_->keep_distances = true;
}
GrowingCutClassifier::~GrowingCutClassifier() = default;
GrowingCutClassifier::GrowingCutClassifier(GrowingCutClassifier&&) noexcept = default;
GrowingCutClassifier& GrowingCutClassifier::operator=(GrowingCutClassifier&&) noexcept = default;

Classification GrowingCutClassifier::classify(const CutSurface& cut, const std::vector<int>& ids) {
  const TriangleMesh& tm = cut.mesh();
  const long F = tm.triangles.rows();
  if (static_cast<long>(ids.size()) != F)
    throw Error("GrowingCutClassifier: " + std::to_string(ids.size()) + " triangle ids for " + std::to_string(F) +
                " triangles");
  // The triangles by id, with their corners; the new ones are those the previous cut lacked.
  std::vector<std::pair<int, std::array<double, 9>>> now(static_cast<std::size_t>(F));
  for (long k = 0; k < F; ++k) {
    now[k].first = ids[k];
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) now[k].second[3 * c + i] = tm.points(tm.triangles(k, c), i);
  }
  std::sort(now.begin(), now.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (long k = 1; k < F; ++k)
    if (now[k].first == now[k - 1].first)
      throw Error("GrowingCutClassifier: triangle id " + std::to_string(now[k].first) + " given twice");
  ClassificationMemory& m = *memory_;
  bool grows = m.classified;
  CutGrowth growth;
  growth.all.col(0).setConstant(1e300);
  growth.all.col(1).setConstant(-1e300);
  std::size_t old = 0;
  for (const auto& [id, corners] : now) {
    if (old < m.ids.size() && m.ids[old] == id) {
      grows = grows && m.corners[old] == corners;
      ++old;
      continue;
    }
    if (old < m.ids.size() && m.ids[old] < id) grows = false;  // an old triangle is missing
    GrowthBox b;
    for (int i = 0; i < 3; ++i) {
      b(i, 0) = std::min({corners[i], corners[3 + i], corners[6 + i]});
      b(i, 1) = std::max({corners[i], corners[3 + i], corners[6 + i]});
    }
    growth.all.col(0) = growth.all.col(0).cwiseMin(b.col(0));
    growth.all.col(1) = growth.all.col(1).cwiseMax(b.col(1));
    growth.boxes.push_back(b);
    growth.corners.push_back({Eigen::Vector3d(corners[0], corners[1], corners[2]),
                              Eigen::Vector3d(corners[3], corners[4], corners[5]),
                              Eigen::Vector3d(corners[6], corners[7], corners[8])});
  }
  grows = grows && old == m.ids.size();
  m.ids.clear();
  m.corners.clear();
  m.classified = false;  // until classify_with has finished (it may throw)
  Classification c = classify_with(*mesh_, cut, options_, m, grows ? &growth : nullptr, stats_);
  for (const auto& [id, corners] : now) {
    m.ids.push_back(id);
    m.corners.push_back(corners);
  }
  return c;
}

}  // namespace xfem
