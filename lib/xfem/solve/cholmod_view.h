// SPDX-License-Identifier: MIT
#pragma once
#include <cholmod.h>

#include "xfem/io/matrix_market.h"

namespace xfem {

/// A view of Eigen's compressed columns (int indices, sorted) as CHOLMOD's symmetric matrix of
/// their lower triangle (stype -1; CHOLMOD ignores the rest), without a copy. `A` must stay alive
/// and compressed while the view is used; CHOLMOD's API is not const, but it does not write A.
/// (For code that calls CHOLMOD itself: CholeskyFactor's, and benches of orderings.)
cholmod_sparse lower_triangle_view(const SparseMatrix& A);

}  // namespace xfem
