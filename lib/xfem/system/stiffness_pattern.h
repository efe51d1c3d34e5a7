// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

/// The sparsity of K, precomputed once from the extended connectivity and shared by every
/// assembly of a matrix with K's pattern (the linear stiffness, the nonlinear tangent).
/// The lower triangle of K at the level of 3-vectors: for DOF column b the rows a >= b of every DOF
/// sharing a tet with b (rows[start[b]] == b), and for each tet a |C| x |C| table giving, for entry
/// pair (row entry q, column entry p) with C[q] >= C[p], the index of C[q] in column C[p]'s rows.
struct Pattern {
  std::vector<long> start;  // N + 1
  std::vector<long> rows;
  std::vector<long> table_offsets;  // T + 1
  std::vector<int> table;
};

/// The pattern of em's extended connectivity.
Pattern make_pattern(const EnrichedMesh& em);

/// K's structure, 3N x 3N, LOWER TRIANGLE ONLY, compressed columns with sorted rows, every value
/// 0; `outer` gets its column starts (scatter writes through them). Throws xfem::Error beyond
/// 2^31 nonzeros.
SparseMatrix pattern_matrix(const EnrichedMesh& em, const Pattern& p, std::vector<int>& outer);

/// Adds the lower part of element matrix k (3|C| x 3|C|) of tet t into the CSC arrays.
template <class Matrix>
inline
void scatter(const EnrichedMesh& em, const Pattern& p, const std::vector<int>& outer, int t, const Matrix& k,
             double* values) {
  const int size = em.size(t);
  const long base = em.offsets[t];
  const int* table = p.table.data() + p.table_offsets[t];
  for (int col = 0; col < size; ++col) {
    const long b = em.dofs[base + col];
    for (int q = 0; q < size; ++q) {
      const int r = table[q * size + col];
      if (r < 0) continue;
      for (int i = 0; i < 3; ++i) {
        // Column 3b+i lists rows 3b+i..3b+2 (its diagonal block), then 3 rows per further DOF.
        double* column = values + outer[3 * b + i];
        if (r == 0) {
          for (int j = i; j < 3; ++j) column[j - i] += k(3 * q + j, 3 * col + i);
        } else {
          double* at = column + (3 - i) + 3 * (r - 1);
          for (int j = 0; j < 3; ++j) at[j] += k(3 * q + j, 3 * col + i);
        }
      }
    }
  }
}


}  // namespace xfem
