// SPDX-License-Identifier: MIT
#include "xfem/solve/contact_pressure_file.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "xfem/core/error.h"

namespace xfem {

void write_contact_pressure(const ContactOperator& c, const Eigen::VectorXd& pressure, long np, const std::string& path) {
  int columns = 1;
  for (int k : c.cut) columns = std::max(columns, k + 1);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (long i = 0; i < c.points(); ++i)
    entries.emplace_back(c.node[static_cast<std::size_t>(i)], c.cut[static_cast<std::size_t>(i)], pressure[i]);
  SparseMatrix P(np, columns);
  P.setFromTriplets(entries.begin(), entries.end());
  write_general_matrix(P, path);
}

SparseMatrix read_contact_pressure(const std::string& path, long np, int cuts) {
  const SparseMatrix P = read_matrix(path);
  if (P.rows() != np)
    throw Error(path + ": " + std::to_string(P.rows()) + " rows, expected one per mesh node (" + std::to_string(np) + ")");
  if (P.cols() > std::max(cuts, 1))
    throw Error(path + ": " + std::to_string(P.cols()) + " columns (cuts), but the mesh has " + std::to_string(cuts));
  for (int j = 0; j < P.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(P, j); it; ++it)
      if (!(it.value() >= 0) || !std::isfinite(it.value()))
        throw Error(path + ": the pressure of node " + std::to_string(it.row() + 1) + " on cut " + std::to_string(j) +
                    " is not a non-negative number (" + std::to_string(it.value()) + ")");
  return P;
}

}  // namespace xfem
