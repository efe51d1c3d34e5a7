// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

namespace xfem {

/// A matrix whose memory is kept from one use to the next: view(rows, cols) gives a rows x cols
/// matrix over a buffer that only grows. Why: an Eigen::MatrixXd reallocates whenever its size
/// changes, and the enriched tets' matrices change size from tet to tet (the number of points);
/// those of a few hundred points x 3|C| exceed glibc's mmap threshold, so each tet mapped and
/// unmapped fresh pages, and the page faults cost more than the arithmetic (issue 35, eighth part,
/// docs/PERFORMANCE.md). The entries of a view are not initialised. The buffer is aligned as
/// Eigen's own matrices, so vectorised sums run in the same order: the same bits as a MatrixXd.
class ScratchMatrix {
 public:
  Eigen::Map<Eigen::MatrixXd, Eigen::AlignedMax> view(long rows, long cols) {
    // Grown without initialising or copying (the pages are touched only where written).
    if (buffer_.size() < rows * cols) buffer_.resize(rows * cols);
    return Eigen::Map<Eigen::MatrixXd, Eigen::AlignedMax>(buffer_.data(), rows, cols);
  }

 private:
  Eigen::VectorXd buffer_;
};

}  // namespace xfem
