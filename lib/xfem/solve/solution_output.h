// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// xfem-solve's outputs for the solution `u` (3N) of the system directory `dir`: the reactions
/// r = K u - f on the constrained DOFs (each condition's resultant logged, all of them in
/// `report`, r written to `reactions_path` unless empty), u to `output` with the fingerprints of
/// the system's inputs (dir/provenance.json, recorded by xfem-assemble), then `report` to
/// `report_path` unless empty. `s` is the system solved; `k_is_diagonal`: its K holds only the
/// diagonal (the PETSc backend's distributed load), so the rows of the constrained DOFs are read
/// from dir's K again.
void write_solution(const std::string& dir, const LinearSystem& s, bool k_is_diagonal, const Eigen::VectorXd& u,
                    const std::string& output, const std::string& reactions_path, Json& report,
                    const std::string& report_path);

}  // namespace xfem
