// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// xfem-solve's CHOLMOD backend: eliminates the Dirichlet DOFs of `s`, factorizes and solves with
/// `ordering` ("metis" or "amd"), ticking on stderr while the factorization runs when `ticking`.
/// Logs the factorization (and warnings: AMD instead of METIS, near-singular K), adds its fields
/// to `report` (ordering, factor size and flops, condition estimate, timings) and returns the
/// full 3N solution; `*residual` = its relative residual on the free DOFs. Throws xfem::Error
/// naming the DOF where K is not positive definite.
Eigen::VectorXd solve_with_cholmod(const LinearSystem& s, const std::string& ordering, bool ticking, Json& report,
                                   double* residual);

}  // namespace xfem
