// SPDX-License-Identifier: MIT
#include "xfem/progressive_cut.h"

#include <chrono>

#include "xfem/assembly.h"
#include "xfem/cholmod_solver.h"
#include "xfem/dof_numbering.h"
#include "xfem/element_stiffness.h"
#include "xfem/error.h"
#include "xfem/oversampling_quadrature.h"
#include "xfem/pieces.h"

namespace xfem {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

EnrichedMesh enriched_mesh(const TetMesh& mesh, const Classification& c, std::shared_ptr<const CutSurface> cut) {
  std::vector<int> enrichment(c.enrichment.size()), cut_class(c.cut_class.size());
  for (std::size_t k = 0; k < enrichment.size(); ++k) enrichment[k] = static_cast<int>(c.enrichment[k]);
  for (std::size_t t = 0; t < cut_class.size(); ++t) cut_class[t] = static_cast<int>(c.cut_class[t]);
  const DofNumbering d = dof_numbering(mesh.tets, mesh.points.rows(), enrichment, cut_class);
  EnrichedMesh em;
  em.mesh = mesh;
  em.side = c.side;
  em.cut_class = cut_class;
  em.np = d.np;
  em.ns = d.ns;
  em.nb = d.nb;
  em.n = d.n;
  em.offsets = d.offsets;
  em.dofs = d.dofs;
  em.local = d.local;
  em.front = c.front;
  em.cut = std::move(cut);
  return em;
}

UncutBody factorize_uncut(const TetMesh& mesh, const Problem& problem, Ordering ordering) {
  for (std::size_t i = 0; i < problem.dirichlet.size(); ++i)
    if (problem.dirichlet[i].exact)
      throw Error(describe(problem, "dirichlet", i) + " prescribes an exact field, whose values depend on the cut: "
                  "a sweep needs fixed values (run the tools per step instead)");
  UncutBody body;
  body.mesh = mesh;
  body.problem = problem;
  const auto t0 = std::chrono::steady_clock::now();
  const EnrichedMesh em = enriched_mesh(mesh, classify_without_cut(mesh), nullptr);
  LinearSystem s = assemble_system(em, problem, problem.points, problem.refine);
  body.assemble_seconds = seconds_since(t0);
  require_constrained(s);
  body.fixed = s.fixed;
  body.fixed_values = s.fixed_values;
  body.constrained = Eigen::VectorXd::Zero(3 * em.np);
  for (std::size_t k = 0; k < s.fixed.size(); ++k) body.constrained[s.fixed[k]] = s.fixed_values[k];
  const SparseMatrix K = SparseMatrix(s.K.selfadjointView<Eigen::Lower>());
  ReducedSystem r = eliminate_dirichlet(K, s.f, s.fixed, s.fixed_values);
  body.free_dofs = r.free_dofs;
  body.reduced = r.reduced;
  body.factor = std::make_unique<CholeskyFactor>(r.K, ordering);
  const auto t1 = std::chrono::steady_clock::now();
  body.w = body.factor->solve(r.f).col(0);
  body.solve_seconds = seconds_since(t1);
  body.K_ss = r.K.triangularView<Eigen::Lower>();
  body.g_s = r.f;
  return body;
}

CutSolution solve_cut(const UncutBody& body, std::shared_ptr<const CutSurface> cut, const ClassifyOptions& options,
                      CutSolver solver) {
  CutSolution out;
  const TetMesh& mesh = body.mesh;
  auto t0 = std::chrono::steady_clock::now();
  const bool empty = !cut || cut->mesh().triangles.rows() == 0;
  const Classification c = empty ? classify_without_cut(mesh) : classify(mesh, *cut, options);
  out.counts = c.counts;
  out.em = enriched_mesh(mesh, c, empty ? nullptr : cut);
  const EnrichedMesh& em = out.em;
  out.classify_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  {  // every piece of the cut body must be held by a Dirichlet condition
    std::vector<char> node_constrained(em.np, 0);
    for (long dof : body.fixed) node_constrained[dof / 3] = 1;
    const std::vector<Piece> pieces = find_pieces(em, node_constrained);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (!pieces[i].constrained)
        throw Error("the cut body falls apart into " + std::to_string(pieces.size()) + " pieces; piece " +
                    std::to_string(i + 1) + " (" + std::to_string(pieces[i].tets) + " tets) has no Dirichlet condition");
  }
  // Only the tets with enriched DOFs contribute to enriched rows and columns: assemble them alone,
  // in their order (the same sums as the whole assembly's), on the points they use, renumbered in
  // order (the pattern wants every DOF in some tet); enriched DOFs keep their order after them.
  std::vector<int> tets;
  for (int t = 0; t < em.tets(); ++t)
    if (em.size(t) > 4) tets.push_back(t);
  out.enriched_tets = static_cast<long>(tets.size());
  std::vector<long> to_sub(em.np, -1), to_full;  // original DOF <-> sub-mesh point
  for (int t : tets)
    for (int c = 0; c < 4; ++c) to_sub[mesh.tets(t, c)] = 0;
  for (long k = 0; k < em.np; ++k)
    if (to_sub[k] == 0) {
      to_sub[k] = static_cast<long>(to_full.size());
      to_full.push_back(k);
    }
  const long np_sub = static_cast<long>(to_full.size()), shift = em.np - np_sub;
  EnrichedMesh sub;
  sub.mesh.points.resize(np_sub, 3);
  for (long q = 0; q < np_sub; ++q) {
    sub.mesh.points.row(q) = mesh.points.row(to_full[q]);
    sub.side.push_back(em.side[to_full[q]]);
  }
  sub.mesh.tets.resize(static_cast<long>(tets.size()), 4);
  sub.offsets.push_back(0);
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const int t = tets[i];
    for (int c = 0; c < 4; ++c) sub.mesh.tets(static_cast<long>(i), c) = static_cast<int>(to_sub[mesh.tets(t, c)]);
    sub.cut_class.push_back(em.cut_class[t]);
    for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) {
      sub.dofs.push_back(em.dofs[e] < em.np ? to_sub[em.dofs[e]] : em.dofs[e] - shift);
      sub.local.push_back(em.local[e]);
    }
    sub.offsets.push_back(static_cast<long>(sub.dofs.size()));
  }
  sub.np = np_sub;
  sub.ns = em.ns;
  sub.nb = em.nb;
  sub.n = em.n - shift;
  sub.front = em.front;
  sub.cut = em.cut;
  const Problem& problem = body.problem;
  const bool conforming = problem.rule == Problem::Rule::Conforming;
  const SparseMatrix K = tets.empty() ? SparseMatrix(0, 0)
                                      : stiffness_matrix(sub, lame(problem.E, problem.nu),
                                                         oversampling_quadrature(problem.points, problem.refine),
                                                         nullptr, {}, conforming ? problem.order : 0);
  // Scalar DOF of the sub-mesh -> scalar DOF of the whole system.
  const auto full = [&](long d) { return d < 3 * np_sub ? 3 * to_full[d / 3] + d % 3 : d + 3 * shift; };

  // Enriched scalar DOFs with a non-zero row of K are solved for; the others have no support
  // (xfem-solve fixes them to 0, which leaves every other value unchanged).
  const long first = 3 * em.np, dofs = 3 * em.n;
  std::vector<char> supported(dofs - first, 0);
  for (int c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it)
      if (it.value() != 0) {
        const long row = full(it.row()), col = full(c);
        if (row >= first) supported[row - first] = 1;
        if (col >= first) supported[col - first] = 1;
      }
  std::vector<long> index(dofs - first, -1);
  long m = 0;
  for (long d = 0; d < dofs - first; ++d)
    if (supported[d]) index[d] = m++;
  out.enriched_dofs = m;
  out.unsupported_dofs = dofs - first - m;
  const long nf = static_cast<long>(body.free_dofs.size());
  std::vector<Eigen::Triplet<double, int>> se, ee;
  Eigen::VectorXd g_e = Eigen::VectorXd::Zero(m);
  for (int c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it) {
      const long row = full(it.row()), col = full(c);
      if (row < first) continue;  // the standard block: the uncut body's, already factorized
      const long e = index[row - first];
      if (e < 0) continue;
      if (col < first) {
        const int f = body.reduced[col];
        if (f >= 0) se.emplace_back(f, static_cast<int>(e), it.value());
        else g_e[e] -= it.value() * body.constrained[col];  // the enriched rows' share of K_ec u_c
      } else if (index[col - first] >= 0) {
        ee.emplace_back(static_cast<int>(e), static_cast<int>(index[col - first]), it.value());
      }
    }
  SparseMatrix K_se(nf, m), K_ee(m, m);
  K_se.setFromTriplets(se.begin(), se.end());
  K_ee.setFromTriplets(ee.begin(), ee.end());
  out.assemble_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  // S costs about m solves with the factor (in blocks, cheaper per column than one alone); a new
  // factorization about what the uncut one took.
  out.schur_used = solver == CutSolver::Schur ||
                   (solver == CutSolver::Auto &&
                    m * body.solve_seconds < body.factor->analyze_seconds + body.factor->factor_seconds);
  Eigen::VectorXd x;
  if (out.schur_used) {
    x = schur_solve(*body.factor, body.w, K_se, K_ee, g_e, &out.schur);
  } else {  // [K_ss K_se; K_es K_ee], lower triangle, factorized anew
    std::vector<Eigen::Triplet<double, int>> all;
    all.reserve(static_cast<std::size_t>(body.K_ss.nonZeros() + K_se.nonZeros() + K_ee.nonZeros()));
    for (int c = 0; c < body.K_ss.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(body.K_ss, c); it; ++it) all.emplace_back(it.row(), c, it.value());
    for (int c = 0; c < K_se.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(K_se, c); it; ++it) all.emplace_back(static_cast<int>(nf) + c, it.row(), it.value());
    for (int c = 0; c < K_ee.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(K_ee, c); it; ++it)
        all.emplace_back(static_cast<int>(nf) + it.row(), static_cast<int>(nf) + c, it.value());
    SparseMatrix M(nf + m, nf + m);
    M.setFromTriplets(all.begin(), all.end());
    Eigen::VectorXd g(nf + m);
    g << body.g_s, g_e;
    try {
      x = cholmod_solve(M, g, body.factor->ordering == "amd" ? Ordering::Amd : Ordering::Metis).x;
    } catch (const NotPositiveDefinite&) {
      throw Error("the cut body's stiffness matrix is not positive definite: a piece of it can move freely (no "
                  "Dirichlet condition on it) or an enrichment is degenerate");
    }
  }
  out.u = Eigen::VectorXd::Zero(dofs);
  out.u.head(first) = body.constrained;
  for (long i = 0; i < nf; ++i) out.u[body.free_dofs[i]] = x[i];
  for (long d = 0; d < dofs - first; ++d)
    if (index[d] >= 0) out.u[first + d] = x[nf + index[d]];
  out.solve_seconds = seconds_since(t0);
  return out;
}

}  // namespace xfem
