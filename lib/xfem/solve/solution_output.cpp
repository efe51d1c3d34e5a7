// SPDX-License-Identifier: MIT
#include "xfem/solve/solution_output.h"

#include <filesystem>

#include "xfem/core/cli.h"
#include "xfem/core/fingerprint.h"
#include "xfem/io/matrix_market.h"
#include "xfem/io/petsc_binary.h"
#include "xfem/system/reactions.h"

namespace xfem {

void write_solution(const std::string& dir, const LinearSystem& s, bool k_is_diagonal, const Eigen::VectorXd& u,
                    const std::string& output, const std::string& reactions_path, Json& report,
                    const std::string& report_path) {
  // r = K u - f on the constrained DOFs. Each PETSc rank loaded only its rows of K, and `s` holds
  // its diagonal only: the root reads the rows of the constrained DOFs from K again (not all of K:
  // at 1.14M DOFs that took seconds and a gigabyte) for the reactions.
  LinearSystem full;
  if (k_is_diagonal) {
    full = read_linear_system(dir, false);
    full.K = read_petsc_symmetric_matrix_rows(system_matrix_file(dir, SystemFormat::Petsc), full.fixed);
  }
  const Reactions reactions = xfem::reactions(dir, k_is_diagonal ? full : s, u);
  for (const auto& r : reactions.conditions) cli::info(describe_reaction(r, reactions.moments));
  report["reactions"] = reactions_json(reactions.conditions, reactions.applied, reactions.moments);
  if (!reactions_path.empty()) write_vector(reactions.r, reactions_path);
  // The fingerprints of the system's inputs (recorded by xfem-assemble) travel with u.
  Provenance provenance;
  const std::string provenance_path = (std::filesystem::path(dir) / "provenance.json").string();
  if (std::filesystem::exists(provenance_path))
    provenance = provenance_from_json(read_json(provenance_path), provenance_path);
  write_vector(u, output, provenance_comments(provenance));
  if (!report_path.empty()) write_json(report, report_path);
}

}  // namespace xfem
