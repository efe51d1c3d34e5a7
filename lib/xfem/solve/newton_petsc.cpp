// SPDX-License-Identifier: MIT
#include "xfem/solve/newton_petsc.h"

#include <chrono>

#include "xfem/core/seconds_since.h"
#include "xfem/solve/cholmod_solver.h"

namespace xfem {

namespace {

class PetscTangentSolver : public TangentSolver {
 public:
  PetscTangentSolver(const EnrichedMesh& em, PetscSolveOptions options) : options_(std::move(options)) {
    system_.n = em.n, system_.np = em.np, system_.ns = em.ns, system_.nb = em.nb;
    system_.coordinates = em.mesh.points;
    if (options_.enriched_block == "auto") options_.enriched_block = em.n > em.np ? "direct" : "gamg";
  }
  Eigen::VectorXd solve(const SparseMatrix& K, const Eigen::VectorXd& rhs, const std::vector<long>& fixed,
                        const std::vector<double>& change, LoadStep& step) override {
    const auto clock = std::chrono::steady_clock::now();
    system_.f = rhs;
    system_.fixed = fixed;
    system_.fixed_values = change;
    PetscMatrix distributed = petsc_matrix(K);
    const double distribute_seconds = seconds_since(clock);
    ++step.factorizations;
    PetscResult p;
    try {
      p = petsc_solve(std::move(distributed), system_, options_);
    } catch (const PetscNotConverged& e) {  // collective: every rank gets here alike
      step.factor_seconds += seconds_since(clock);
      throw NotPositiveDefinite(e.what(), -1);
    }
    step.factor_seconds += distribute_seconds + p.setup_seconds;
    step.solve_seconds += p.solve_seconds;
    step.linear_iterations += p.iterations;
    return petsc_broadcast(p.u, 3 * system_.n);
  }

 private:
  PetscSolveOptions options_;
  LinearSystem system_;  // n, coordinates; f and the Dirichlet data of the solve at hand
};

}  // namespace

std::unique_ptr<TangentSolver> petsc_tangent_solver(const EnrichedMesh& em, PetscSolveOptions options) {
  return std::make_unique<PetscTangentSolver>(em, std::move(options));
}

}  // namespace xfem
