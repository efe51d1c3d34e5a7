// SPDX-License-Identifier: MIT
#include "xfem/solve/cholmod_view.h"

namespace xfem {

cholmod_sparse lower_triangle_view(const SparseMatrix& A_in) {
  SparseMatrix& A = const_cast<SparseMatrix&>(A_in);  // CHOLMOD's API is not const; it does not write
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<size_t>(A.rows());
  a.nzmax = static_cast<size_t>(A.nonZeros());
  a.p = A.outerIndexPtr();
  a.i = A.innerIndexPtr();
  a.x = A.valuePtr();
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

}  // namespace xfem
