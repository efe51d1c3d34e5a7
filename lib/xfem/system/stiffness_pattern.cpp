// SPDX-License-Identifier: MIT
#include "xfem/system/stiffness_pattern.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "xfem/core/error.h"

namespace xfem {

Pattern make_pattern(const EnrichedMesh& em) {
  const long n = em.n;
  const int tets = em.tets();
  // DOF -> (tet, entry) incidence, CSR.
  std::vector<long> first(n + 1, 0);
  for (long d : em.dofs) ++first[d + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<int> incident_tet(em.dofs.size());
  {
    std::vector<long> fill(first.begin(), first.end() - 1);
    for (int t = 0; t < tets; ++t)
      for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) incident_tet[fill[em.dofs[e]]++] = t;
  }
  Pattern p;
  p.table_offsets.resize(tets + 1);
  p.table_offsets[0] = 0;
  for (int t = 0; t < tets; ++t) p.table_offsets[t + 1] = p.table_offsets[t] + long(em.size(t)) * em.size(t);
  p.table.assign(p.table_offsets[tets], -1);
  p.start.resize(n + 1);
  p.start[0] = 0;
  p.rows.reserve(static_cast<std::size_t>(n) * 16);
  std::vector<long> mark(n, -1);
  std::vector<int> index(n, 0);
  for (long b = 0; b < n; ++b) {
    const long begin = static_cast<long>(p.rows.size());
    for (long i = first[b]; i < first[b + 1]; ++i) {
      const int t = incident_tet[i];
      for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) {
        const long a = em.dofs[e];
        if (a >= b && mark[a] != b) {
          mark[a] = b;
          p.rows.push_back(a);
        }
      }
    }
    std::sort(p.rows.begin() + begin, p.rows.end());
    for (long r = begin; r < static_cast<long>(p.rows.size()); ++r) index[p.rows[r]] = static_cast<int>(r - begin);
    p.start[b + 1] = static_cast<long>(p.rows.size());
    for (long i = first[b]; i < first[b + 1]; ++i) {
      const int t = incident_tet[i];
      const int size = em.size(t);
      const long base = em.offsets[t];
      int col = 0;
      while (em.dofs[base + col] != b) ++col;
      for (int q = 0; q < size; ++q) {
        const long a = em.dofs[base + q];
        if (a >= b) p.table[p.table_offsets[t] + q * size + col] = index[a];
      }
    }
  }
  return p;
}

SparseMatrix pattern_matrix(const EnrichedMesh& em, const Pattern& p, std::vector<int>& outer) {
  // Scalar columns: 3b+i holds 3 |rows(b)| - i entries.
  const long n = em.n;
  outer.assign(3 * n + 1, 0);
  for (long b = 0; b < n; ++b) {
    const long count = p.start[b + 1] - p.start[b];
    for (int i = 0; i < 3; ++i) {
      const long next = outer[3 * b + i] + 3 * count - i;
      if (next > std::numeric_limits<int>::max())
        throw Error("stiffness matrix: more than 2^31 nonzeros, too large for one machine");
      outer[3 * b + i + 1] = static_cast<int>(next);
    }
  }
  SparseMatrix K(static_cast<int>(3 * n), static_cast<int>(3 * n));
  K.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), K.outerIndexPtr());
  int* inner = K.innerIndexPtr();
  for (long b = 0; b < n; ++b)
    for (int i = 0; i < 3; ++i) {
      int* at = inner + outer[3 * b + i];
      for (int j = i; j < 3; ++j) *at++ = static_cast<int>(3 * b + j);
      for (long r = p.start[b] + 1; r < p.start[b + 1]; ++r)
        for (int j = 0; j < 3; ++j) *at++ = static_cast<int>(3 * p.rows[r] + j);
    }
  std::fill(K.valuePtr(), K.valuePtr() + outer.back(), 0.0);
  return K;
}

}  // namespace xfem
