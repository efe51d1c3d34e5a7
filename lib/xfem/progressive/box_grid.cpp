// SPDX-License-Identifier: MIT
#include "xfem/progressive/box_grid.h"

#include <algorithm>
#include <cmath>

namespace xfem {

BoxGrid::BoxGrid(const std::vector<Box>& boxes, double cell) : boxes_(boxes) {
  if (boxes.empty()) return;
  Eigen::Vector3d lo = boxes[0].col(0), hi = boxes[0].col(1);
  for (const Box& b : boxes) {
    lo = lo.cwiseMin(b.col(0));
    hi = hi.cwiseMax(b.col(1));
  }
  origin_ = lo;
  cell_ = cell > 0 && std::isfinite(cell) ? cell : 1.0;
  const double most = 8.0 * static_cast<double>(boxes.size()) + 64;  // cells: a few per box at most
  for (;;) {
    double count = 1;
    for (int i = 0; i < 3; ++i) count *= std::floor((hi[i] - lo[i]) / cell_) + 1;
    if (count <= most) break;
    cell_ *= 2;
  }
  for (int i = 0; i < 3; ++i) n_[i] = static_cast<long>(std::floor((hi[i] - lo[i]) / cell_)) + 1;
  cells_.resize(static_cast<std::size_t>(n_[0] * n_[1] * n_[2]));
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const Box& b = boxes[k];
    for (long x = cell_of(0, b(0, 0)); x <= cell_of(0, b(0, 1)); ++x)
      for (long y = cell_of(1, b(1, 0)); y <= cell_of(1, b(1, 1)); ++y)
        for (long z = cell_of(2, b(2, 0)); z <= cell_of(2, b(2, 1)); ++z)
          cells_[static_cast<std::size_t>((x * n_[1] + y) * n_[2] + z)].push_back(static_cast<int>(k));
  }
}

long BoxGrid::cell_of(int axis, double x) const {
  const double c = std::floor((x - origin_[axis]) / cell_);
  return static_cast<long>(std::clamp(c, 0.0, static_cast<double>(n_[axis] - 1)));
}

void BoxGrid::meeting(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, std::vector<int>& out) const {
  out.clear();
  if (cells_.empty()) return;
  // A box meeting [lo, hi] shares a point with it, inside the grid: that point's cell is in both
  // ranges (cell_of is monotone, clamped), so the clamped range finds every such box.
  for (int i = 0; i < 3; ++i)
    if (hi[i] < origin_[i] || lo[i] > origin_[i] + static_cast<double>(n_[i]) * cell_) return;
  for (long x = cell_of(0, lo[0]); x <= cell_of(0, hi[0]); ++x)
    for (long y = cell_of(1, lo[1]); y <= cell_of(1, hi[1]); ++y)
      for (long z = cell_of(2, lo[2]); z <= cell_of(2, hi[2]); ++z) {
        const auto& c = cells_[static_cast<std::size_t>((x * n_[1] + y) * n_[2] + z)];
        out.insert(out.end(), c.begin(), c.end());
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](int k) {
                             const Box& b = boxes_[static_cast<std::size_t>(k)];
                             return !((b.col(0).array() <= hi.array()).all() && (b.col(1).array() >= lo.array()).all());
                           }),
            out.end());
}

}  // namespace xfem
