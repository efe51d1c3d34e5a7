// SPDX-License-Identifier: MIT
#include "xfem/solve/contact_solve.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/solve/direct_backend.h"
#include "xfem/system/dirichlet.h"

namespace xfem {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// The points of one tet on one cut (consecutive rows of G) and the DOFs their rows touch: the
// penalty's block for them is one dense matrix, added to K at `position` (column-major over
// columns x columns: the entries' places in the values of the contact pattern).
struct Block {
  long first = 0, end = 0;
  std::vector<int> columns;
  std::vector<long> position;
};

std::vector<Block> point_blocks(const RowMatrix& G, const ContactOperator& c) {
  std::vector<Block> blocks;
  const long Q = c.points();
  for (long q = 0; q < Q;) {
    Block b;
    b.first = q;
    while (q < Q && c.tet[static_cast<std::size_t>(q)] == c.tet[static_cast<std::size_t>(b.first)] &&
           c.cut[static_cast<std::size_t>(q)] == c.cut[static_cast<std::size_t>(b.first)]) {
      for (RowMatrix::InnerIterator it(G, static_cast<int>(q)); it; ++it) b.columns.push_back(static_cast<int>(it.col()));
      ++q;
    }
    b.end = q;
    std::sort(b.columns.begin(), b.columns.end());
    b.columns.erase(std::unique(b.columns.begin(), b.columns.end()), b.columns.end());
    blocks.push_back(std::move(b));
  }
  return blocks;
}

// K with explicit zeros wherever a block may add something: the one pattern of every solve, so
// that CHOLMOD analyses it once. Fills each block's positions in its values.
SparseMatrix contact_pattern(const SparseMatrix& K, std::vector<Block>& blocks) {
  std::vector<Eigen::Triplet<double, int>> zeros;
  for (const Block& b : blocks)
    for (int col : b.columns)
      for (int row : b.columns) zeros.emplace_back(row, col, 0.0);
  SparseMatrix Z(K.rows(), K.cols());
  Z.setFromTriplets(zeros.begin(), zeros.end());
  SparseMatrix P = K + Z;
  P.makeCompressed();
  for (Block& b : blocks) {
    b.position.clear();
    for (int col : b.columns) {
      const int* begin = P.innerIndexPtr() + P.outerIndexPtr()[col];
      const int* end = P.innerIndexPtr() + P.outerIndexPtr()[col + 1];
      for (int row : b.columns) b.position.push_back(std::lower_bound(begin, end, row) - P.innerIndexPtr());
    }
  }
  return P;
}

}  // namespace

Eigen::VectorXd solve_with_contact(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                   const std::string& ordering, bool ticking, Json& report, double* residual,
                                   ContactOutcome* outcome) {
  using cli::three_digits;
  Eigen::VectorXd u = solve_with_cholmod(s, ordering, ticking, report, residual);
  ContactOutcome out;
  out.solves = 1;
  const RowMatrix G = c.G;
  const long Q = c.points();
  double scale = 0;
  for (long d = 0; d < 3 * s.np; ++d) scale = std::max(scale, std::abs(u[d]));
  out.tolerance = settings.tolerance > 0 ? settings.tolerance : 1e-8 * scale;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(Q), g = G * u;
  std::vector<char> active(static_cast<std::size_t>(Q), 0);
  // The error the iteration must bring below the tolerance: penetration anywhere, and a gap
  // open where the faces still press (g p = 0).
  const auto violation = [&]() {
    double worst = 0;
    for (long q = 0; q < Q; ++q) worst = std::max(worst, active[static_cast<std::size_t>(q)] ? std::abs(g[q]) : -g[q]);
    return worst;
  };
  const auto update_active = [&]() {
    bool changed = false;
    for (long q = 0; q < Q; ++q) {
      const char now = lambda[q] - c.penalty[q] * g[q] > 0;
      changed = changed || now != active[static_cast<std::size_t>(q)];
      active[static_cast<std::size_t>(q)] = now;
    }
    return changed;
  };
  if (violation() > out.tolerance) {
    std::vector<Block> blocks = point_blocks(G, c);
    const SparseMatrix pattern = contact_pattern(s.K, blocks);
    SparseMatrix K = pattern;
    std::unique_ptr<CholeskyFactor> factor;
    int inner = 0;
    update_active();
    for (;;) {
      if (out.solves >= settings.max_solves)
        throw Error("contact: no convergence in " + std::to_string(out.solves) + " solves (largest penetration or "
                    "open gap under pressure " + three_digits(violation()) + " m, tolerance " +
                    three_digits(out.tolerance) + " m); raise --contact-iterations or the contact penalty");
      // (K + sum_A kappa w G_q^T G_q) u = f + sum_A w lambda G_q^T
      std::copy(pattern.valuePtr(), pattern.valuePtr() + pattern.nonZeros(), K.valuePtr());
      Eigen::VectorXd f = s.f;
      for (const Block& b : blocks) {
        const std::size_t n = b.columns.size();
        Eigen::MatrixXd D = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        Eigen::VectorXd row(static_cast<Eigen::Index>(n));
        bool any = false;
        for (long q = b.first; q < b.end; ++q) {
          if (!active[static_cast<std::size_t>(q)]) continue;
          any = true;
          row.setZero();
          for (RowMatrix::InnerIterator it(G, static_cast<int>(q)); it; ++it)
            row[std::lower_bound(b.columns.begin(), b.columns.end(), static_cast<int>(it.col())) - b.columns.begin()] =
                it.value();
          D.noalias() += (c.penalty[q] * c.weight[q]) * row * row.transpose();
          for (RowMatrix::InnerIterator it(G, static_cast<int>(q)); it; ++it)
            f[it.col()] += c.weight[q] * lambda[q] * it.value();
        }
        if (!any) continue;
        for (std::size_t j = 0, k = 0; j < n; ++j)
          for (std::size_t i = 0; i < n; ++i, ++k) K.valuePtr()[b.position[k]] += D(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      }
      const ReducedSystem reduced = eliminate_dirichlet(K, f, s.fixed, s.fixed_values);
      if (!factor)
        factor = std::make_unique<CholeskyFactor>(reduced.K, ordering == "amd" ? Ordering::Amd : Ordering::Metis);
      else
        factor->refactor(reduced.K);
      if (factor->rcond < 1e-14)
        cli::warn("contact: K with the penalty is near-singular (CHOLMOD reciprocal condition estimate " +
                  three_digits(factor->rcond) + "): lower the contact penalty");
      u = expand_solution(reduced, factor->solve(reduced.f), s.fixed, s.fixed_values);
      *residual = relative_residual(K, f, u, reduced);
      ++out.solves;
      g = G * u;
      const bool changed = update_active();
      cli::detail("contact: solve " + std::to_string(out.solves) + ": " +
                  std::to_string(std::count(active.begin(), active.end(), 1)) + " points active" +
                  (changed ? " (changed)" : "") + ", largest violation " + three_digits(violation()) + " m");
      if (violation() <= out.tolerance) break;
      // The inner (semismooth Newton) iteration while A changes; a few times at most: on a curved
      // cut points near zero gap can flip in and out for ever, and the multiplier update then
      // makes progress where the inner loop does not (an inexact Uzawa step).
      if (changed && ++inner < 5) continue;
      inner = 0;
      for (long q = 0; q < Q; ++q) lambda[q] = std::max(0.0, lambda[q] - c.penalty[q] * g[q]);  // Uzawa
      ++out.updates;
      update_active();
    }
  }
  out.opened_volume = Q > 0 ? c.weight.dot(g) : 0.0;
  out.pressure.resize(Q);
  for (long q = 0; q < Q; ++q) {
    out.pressure[q] = std::max(0.0, lambda[q] - c.penalty[q] * g[q]);
    out.force += c.weight[q] * out.pressure[q];
    if (active[static_cast<std::size_t>(q)]) {
      ++out.active;
      out.active_area += c.weight[q];
    }
    out.max_penetration = std::max(out.max_penetration, -g[q]);
  }
  cli::info("contact: " + std::to_string(out.active) + " of " + std::to_string(Q) + " points in contact (area " +
            three_digits(out.active_area) + " m^2), " + std::to_string(out.solves) + " solves, " +
            std::to_string(out.updates) + " multiplier updates; largest penetration " +
            three_digits(out.max_penetration) + " m (tolerance " + three_digits(out.tolerance) + " m), normal force " +
            three_digits(out.force) + " N");
  report["contact"] = Json{{"points", Q},
                           {"active_points", out.active},
                           {"active_area", out.active_area},
                           {"solves", out.solves},
                           {"multiplier_updates", out.updates},
                           {"max_penetration", out.max_penetration},
                           {"tolerance", out.tolerance},
                           {"opened_volume", out.opened_volume},
                           {"force", out.force},
                           {"max_pressure", Q > 0 ? out.pressure.maxCoeff() : 0.0}};
  if (outcome) *outcome = out;
  return u;
}

}  // namespace xfem
