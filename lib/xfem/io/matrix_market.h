// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace xfem {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Writes `K` in Matrix Market `coordinate real symmetric` form: only entries with row >= column
/// are written (1-based), sorted by column then row, values in shortest round-trip form. `K` must
/// hold at least its lower triangle; its upper triangle is ignored. Atomic; "-" is stdout.
void write_symmetric_matrix(const SparseMatrix& K, const std::string& path);

/// Reads a Matrix Market `coordinate real` matrix, `general` or `symmetric`. A symmetric file is
/// returned as its full matrix (both triangles). Throws xfem::Error naming the file and line; also
/// for a size line claiming more entries than the file holds (before allocating), extra values,
/// a duplicated entry, an entry above the diagonal of a symmetric file. With `rows_increasing`
/// (a sparse column such as dirichlet.mtx, whose format requires it) an entry whose row does not
/// follow the previous entry's row is refused too, naming its line.
SparseMatrix read_matrix(const std::string& path, bool rows_increasing = false);

/// Writes `v` as a Matrix Market `array real general` n x 1 vector. Atomic; "-" is stdout.
/// `comments` (each starting with '%') go after the banner. Refuses non-finite values.
void write_vector(const Eigen::VectorXd& v, const std::string& path, const std::vector<std::string>& comments = {});

/// Reads an n x 1 Matrix Market vector in `array` form. Throws xfem::Error naming the file for a
/// `coordinate` file, a size line claiming more values than the file holds, missing or extra
/// values, non-finite values.
Eigen::VectorXd read_vector(const std::string& path);

}  // namespace xfem
