// SPDX-License-Identifier: MIT
#include "xfem/progressive/progressive_cut.h"

#include "xfem/progressive/box_grid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "xfem/system/assembly.h"
#include "xfem/integrate/closed_form_stiffness.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/integrate/element_stiffness.h"
#include "xfem/core/error.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/core/parallel_for.h"
#include "xfem/system/pieces.h"
#include "xfem/core/seconds_since.h"

namespace xfem {
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
  // A linear exact field is the same on both sides of a cut (u = translation + G x): its values
  // are fixed, like a `value`'s. Every other exact field takes the node's side.
  for (std::size_t i = 0; i < problem.dirichlet.size(); ++i)
    if (problem.dirichlet[i].exact && problem.dirichlet[i].exact->kind != ExactField::Kind::Linear)
      throw Error(describe(problem, "dirichlet", i) + " prescribes an exact field, whose values depend on the cut: "
                  "a sweep needs fixed values (run the tools per step instead)");
  UncutBody body;
  body.mesh = mesh;
  body.problem = problem;
  body.materials = tet_materials(problem, mesh, "the body");
  const auto t0 = std::chrono::steady_clock::now();
  const EnrichedMesh em = enriched_mesh(mesh, classify_without_cut(mesh), nullptr);
  LinearSystem s = assemble_system(em, problem, body.materials, problem.points, problem.refine);
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

namespace {

// Classifies the body against `cut` (none when empty), enriches it, and checks that every piece of
// the cut body is held by a Dirichlet condition.
// With `growing` (and the cut's triangle ids), the classification reuses the previous cut's; with
// `faces`, the body's shared faces are not found again.
void classify_and_enrich(const UncutBody& body, const std::shared_ptr<const CutSurface>& cut,
                         const ClassifyOptions& options, CutSolution& out, GrowingCutClassifier* growing = nullptr,
                         const std::vector<int>* ids = nullptr, const SharedFaces* faces = nullptr) {
  const auto t0 = std::chrono::steady_clock::now();
  const TetMesh& mesh = body.mesh;
  const bool empty = !cut || cut->mesh().triangles.rows() == 0;
  const Classification c = empty     ? classify_without_cut(mesh)
                           : growing ? growing->classify(*cut, *ids)
                                     : classify(mesh, *cut, options);
  out.counts = c.counts;
  out.classify_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  out.em = enriched_mesh(mesh, c, empty ? nullptr : cut);
  std::vector<char> node_constrained(out.em.np, 0);
  for (long dof : body.fixed) node_constrained[dof / 3] = 1;
  const std::vector<Piece> pieces =
      faces ? find_pieces(out.em, node_constrained, *faces) : find_pieces(out.em, node_constrained);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!pieces[i].constrained)
      throw Error("the cut body falls apart into " + std::to_string(pieces.size()) + " pieces; piece " +
                  std::to_string(i + 1) + " (" + std::to_string(pieces[i].tets) + " tets) has no Dirichlet condition");
  out.enrich_seconds = seconds_since(t1);
}

// The materials of the tets `tets`, in their order (the sub-mesh's tets).
TetMaterials materials_of(const TetMaterials& all, const std::vector<int>& tets) {
  TetMaterials out = all;
  if (all.of_tet.empty()) return out;
  out.of_tet.resize(tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) out.of_tet[i] = all.of_tet[static_cast<std::size_t>(tets[i])];
  return out;
}

// The tets `tets` of `em` alone, in their order, on the points they use renumbered in order (the
// pattern wants every DOF in some tet); enriched DOFs keep their order after them. Element i of
// the result has the same extended connectivity order, so the same element matrix, as tet tets[i].
// `to_full` (optional) receives the sub-mesh point -> point map.
EnrichedMesh sub_mesh(const EnrichedMesh& em, const std::vector<int>& tets, std::vector<long>* to_full_out = nullptr) {
  const TetMesh& mesh = em.mesh;
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
  if (to_full_out) *to_full_out = std::move(to_full);
  return sub;
}

}  // namespace

CutSolution solve_cut(const UncutBody& body, std::shared_ptr<const CutSurface> cut, const ClassifyOptions& options,
                      CutSolver solver) {
  CutSolution out;
  classify_and_enrich(body, cut, options, out);
  const EnrichedMesh& em = out.em;
  auto t0 = std::chrono::steady_clock::now();
  // Only the tets with enriched DOFs contribute to enriched rows and columns: assemble them alone.
  std::vector<int> tets;
  for (int t = 0; t < em.tets(); ++t)
    if (em.size(t) > 4) tets.push_back(t);
  out.enriched_tets = static_cast<long>(tets.size());
  std::vector<long> to_full;
  const EnrichedMesh sub = sub_mesh(em, tets, &to_full);
  const long np_sub = sub.np, shift = em.np - np_sub;
  const Problem& problem = body.problem;
  const bool conforming = problem.rule == Problem::Rule::Conforming;
  const SparseMatrix K = tets.empty() ? SparseMatrix(0, 0)
                                      : stiffness_matrix(sub, materials_of(body.materials, tets),
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

namespace {

// Everything an enriched tet's element matrix is computed from, besides the fixed geometry and
// problem (equal keys, equal matrices):
//  - its cut class, its nodes' sides when it is cut (they shift the sign enrichment, which enters
//    cut tets only) and its extended connectivity's layout (per entry the local node and which
//    function: original, sign, branch 1-4);
//  - the ids of the sweep's triangles whose box meets the tet's box: they make its cut pieces (the
//    conforming rule's pieces and their sides). Where points are given their side by the closest
//    cut point instead, the box is grown by as far as that point can be: the tet's longest edge h
//    for a cut tet under the oversampling rule, 2 h with branch DOFs (a blending tet's points lie
//    within 2 h of the front, so of the cut);
//  - the front segments near it (sorted), where the front matters: with branch DOFs those within
//    (distance to the nearest) + 3 h of its centroid (the crack-tip coordinates come from the
//    nearest front points and the frame interpolated between neighbouring segments of length
//    <= h); a partially cut tet without branch DOFs is split at the front: those within 2 h. A
//    completely cut tet without branch DOFs never looks at the front (one point per cut piece).
std::vector<double> element_key(const EnrichedMesh& em, int t, const std::vector<int>& ids, const BoxGrid& boxes,
                                bool conforming, std::vector<int>& near_triangles) {
  std::vector<double> key;
  key.push_back(em.cut_class[t]);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo, centre = Eigen::Vector3d::Zero();
  double h = 0;
  for (int c = 0; c < 4; ++c) {
    const int p = em.mesh.tets(t, c);
    key.push_back(em.cut_class[t] > 0 ? em.side[p] : 0);  // sides enter sign DOFs, of cut tets only
    const Eigen::Vector3d x = em.mesh.points.row(p).transpose();
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
    centre += 0.25 * x;
    for (int d = c + 1; d < 4; ++d) h = std::max(h, (x - em.mesh.points.row(em.mesh.tets(t, d)).transpose()).norm());
  }
  bool branch = false;
  key.push_back(em.size(t));
  for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) {
    const long d = em.dofs[e];
    const int function = d < em.np ? 0 : d < em.np + em.ns ? 1 : 2 + static_cast<int>((d - em.np - em.ns) % 4);
    branch = branch || function >= 2;
    key.push_back(8 * function + em.local[e]);
  }
  const double grow = branch ? 2 * h : !conforming ? h : 0.0;
  lo.array() -= grow;
  hi.array() += grow;
  key.push_back(-1);
  boxes.meeting(lo, hi, near_triangles);  // the triangles k whose box meets the tet's grown box, increasing
  for (int k : near_triangles) key.push_back(ids[k]);
  key.push_back(-1);
  const auto& segments = em.front.segments();
  if (segments.empty() || (!branch && em.cut_class[t] != 1)) return key;
  std::vector<double> distance(segments.size());
  double nearest = 1e300;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    distance[k] = point_segment_distance(centre, segments[k].p0, segments[k].p1);
    nearest = std::min(nearest, distance[k]);
  }
  const double reach = branch ? nearest + 3 * h : 2 * h;
  std::vector<std::array<double, 9>> near;
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (distance[k] <= reach) {
      const auto& s = segments[k];
      near.push_back({s.p0.x(), s.p0.y(), s.p0.z(), s.p1.x(), s.p1.y(), s.p1.z(), s.b.x(), s.b.y(), s.b.z()});
    }
  std::sort(near.begin(), near.end());
  for (const auto& s : near) key.insert(key.end(), s.begin(), s.end());
  return key;
}

}  // namespace

ProgressiveCut::ProgressiveCut(const UncutBody& body, const ClassifyOptions& options)
    : body_(body),
      options_(options),
      rule_(oversampling_quadrature(body.problem.points, body.problem.refine)),
      schur_(*body.factor),
      classifier_(body.mesh, options),
      faces_(shared_faces(body.mesh)) {}

void ProgressiveCut::prepare(const std::vector<std::shared_ptr<const CutSurface>>& cuts,
                             const std::function<void(double)>& progress, const std::vector<std::vector<int>>* ids) {
  if (ids && ids->size() != cuts.size())
    throw Error("ProgressiveCut::prepare: " + std::to_string(ids->size()) + " triangle id lists for " +
                std::to_string(cuts.size()) + " cuts");
  // The cuts of a sweep grow: each classified from the previous one (classify() from scratch each
  // time found the mesh's edges again and judged every point: most of this loop's time).
  GrowingCutClassifier growing(body_.mesh, options_);
  // The region: free original DOFs of the tets with enriched DOFs at some step (a step's front
  // enriches tets around it that the whole sweep's cut does not: the union over the steps), in the
  // order of the step that first reaches them, so that a step reads only a leading block of the
  // region's response (IncrementalSchur::update).
  std::vector<int> region;
  std::vector<char> in_region(body_.free_dofs.size(), 0);
  long most_enriched = 0;  // scalar enriched DOFs of the largest step: S's size at most
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const auto& cut = cuts[i];
    if (!cut || cut->mesh().triangles.rows() == 0) continue;
    const EnrichedMesh em =
        enriched_mesh(body_.mesh, ids ? growing.classify(*cut, (*ids)[i]) : classify(body_.mesh, *cut, options_), cut);
    most_enriched = std::max(most_enriched, 3 * (em.n - em.np));
    const std::size_t first_new = region.size();
    for (int t = 0; t < em.tets(); ++t)
      if (em.size(t) > 4)
        for (int c = 0; c < 4; ++c)
          for (int i = 0; i < 3; ++i) {
            const int f = body_.reduced[3 * em.mesh.tets(t, c) + i];
            if (f >= 0 && !in_region[f]) {
              in_region[f] = 1;
              region.push_back(f);
            }
          }
    std::sort(region.begin() + static_cast<long>(first_new), region.end());
  }
  schur_.extend_region(region, progress);
  schur_.reserve(most_enriched);
}

void complete_solution(const UncutBody& body, CutSolution& solution) {
  if (solution.pending.size() == 0) return;
  const auto t0 = std::chrono::steady_clock::now();
  const Eigen::VectorXd x = body.factor->solve(solution.pending).col(0);
  for (std::size_t i = 0; i < body.free_dofs.size(); ++i) solution.u[body.free_dofs[i]] -= x[static_cast<long>(i)];
  solution.pending.resize(0);
  solution.back_substitution_seconds = seconds_since(t0);
  if (!solution.u.allFinite()) throw Error("the Schur complement solve gave a non-finite solution (numerically singular)");
}

CutSolution ProgressiveCut::step(std::shared_ptr<const CutSurface> cut, const std::vector<int>& ids, bool complete) {
  CutSolution out;
  out.schur_used = true;
  classify_and_enrich(body_, cut, options_, out, &classifier_, &ids, &faces_);
  const EnrichedMesh& em = out.em;
  const Problem& problem = body_.problem;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<Eigen::Matrix<double, 3, 2>> boxes;
  if (em.cut) {
    const TriangleMesh& tm = em.cut->mesh();
    if (static_cast<long>(ids.size()) != tm.triangles.rows())
      throw Error("ProgressiveCut::step: " + std::to_string(ids.size()) + " triangle ids for " +
                  std::to_string(tm.triangles.rows()) + " triangles");
    boxes.resize(static_cast<std::size_t>(tm.triangles.rows()));
    for (long k = 0; k < tm.triangles.rows(); ++k) {
      boxes[k].col(0) = boxes[k].col(1) = tm.points.row(tm.triangles(k, 0)).transpose();
      for (int c = 1; c < 3; ++c) {
        boxes[k].col(0) = boxes[k].col(0).cwiseMin(tm.points.row(tm.triangles(k, c)).transpose());
        boxes[k].col(1) = boxes[k].col(1).cwiseMax(tm.points.row(tm.triangles(k, c)).transpose());
      }
    }
  }
  // Element matrices: reused where their inputs did not change, computed on a sub-mesh of the others.
  std::vector<int> tets, stale;
  for (int t = 0; t < em.tets(); ++t)
    if (em.size(t) > 4) tets.push_back(t);
  // The triangles' boxes in a grid of cells a few triangles wide: a tet asks only the cells its
  // (grown) box meets, not every triangle of the cut.
  double extent = 0;
  for (const auto& b : boxes) extent += (b.col(1) - b.col(0)).maxCoeff();
  const BoxGrid grid(boxes, boxes.empty() ? 1.0 : 4 * extent / static_cast<double>(boxes.size()));
  std::vector<std::vector<double>> all_keys(tets.size()), keys;
  parallel_for(static_cast<long>(tets.size()), [&](long begin, long end) {
    std::vector<int> near;
    for (long i = begin; i < end; ++i)
      all_keys[i] = element_key(em, tets[i], ids, grid, problem.rule == Problem::Rule::Conforming, near);
  }, {}, 256);
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto it = elements_.find(tets[i]);
    if (it == elements_.end() || it->second.key != all_keys[i]) {
      stale.push_back(tets[i]);
      keys.push_back(std::move(all_keys[i]));
    }
  }
  out.enriched_tets = static_cast<long>(tets.size());
  out.recomputed_tets = static_cast<long>(stale.size());
  out.keys_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  if (!stale.empty()) {
    const EnrichedMesh sub = sub_mesh(em, stale);
    const bool conforming = problem.rule == Problem::Rule::Conforming;
    const CutElementSplits splits = conforming ? split_cut_elements(sub) : CutElementSplits();
    std::vector<Element*> slots(stale.size());
    for (std::size_t i = 0; i < stale.size(); ++i) {
      slots[i] = &elements_[stale[i]];
      slots[i]->key = std::move(keys[i]);
    }
    // Each element matrix depends on its tet alone: computed in a few threads, the same bits.
    parallel_for(static_cast<long>(stale.size()), [&](long begin, long end) {
      PointRule points;
      ClosedFormWorkspace work;
      for (long i = begin; i < end; ++i) {
        Element& element = *slots[i];
        if (conforming) {
          // As xfem-assemble's default (assembly.cpp).
          default_rule_stiffness(sub, splits, static_cast<int>(i), problem.order, body_.materials.lame(stale[i]),
                                 element.k, nullptr, work, points);
        } else {
          element_stiffness(sub, static_cast<int>(i), rule_, body_.materials.lame(stale[i]), element.k);
        }
      }
    }, {}, 8);
  }

  out.elements_seconds = seconds_since(t1);
  // The enriched DOFs' columns of K, summed tet by tet in increasing order (so a column whose tets
  // did not change is bitwise the same): per enriched DOF its point and function give its key.
  const long np = em.np, ne = em.n - np, nf = static_cast<long>(body_.free_dofs.size());
  std::vector<long> point_of(ne, -1);
  std::vector<int> function_of(ne, 0);
  std::vector<long> first(ne + 1, 0);
  for (int t : tets)
    for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e)
      if (em.dofs[e] >= np) {
        const long d = em.dofs[e] - np;
        point_of[d] = em.mesh.tets(t, em.local[e]);
        function_of[d] = em.dofs[e] < np + em.ns ? 0 : 1 + static_cast<int>((em.dofs[e] - np - em.ns) % 4);
        ++first[d + 1];
      }
  for (long d = 0; d < ne; ++d) first[d + 1] += first[d];
  std::vector<std::pair<int, int>> incidence(static_cast<std::size_t>(first[ne]));  // (tet, entry)
  {
    std::vector<long> fill(first.begin(), first.end() - 1);
    for (int t : tets)
      for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e)
        if (em.dofs[e] >= np) incidence[fill[em.dofs[e] - np]++] = {t, static_cast<int>(e - em.offsets[t])};
  }
  const auto key_of = [&](long d, int i) { return (point_of[d] * 5 + function_of[d]) * 3 + i; };
  // Column 3 d + i of every enriched DOF, independently of the others: in a few threads, the same bits.
  // A DOF whose tets (and their entries) are those of the previous step, none integrated anew, has
  // the previous step's columns: its element matrices, their rows' DOFs (the tet's layout is in its
  // key) and so the sums are the same; it is copied, not summed again.
  std::vector<char> recomputed(static_cast<std::size_t>(em.tets()), 0);
  for (int t : stale) recomputed[t] = 1;
  std::vector<EnrichedColumn> all(static_cast<std::size_t>(3 * ne));
  std::vector<double> all_g(static_cast<std::size_t>(3 * ne), 0.0);
  std::vector<char> reused(static_cast<std::size_t>(ne), 0);
  parallel_for(ne, [&](long begin, long end) {
    std::vector<double> free_sum(nf, 0.0), enriched_sum(3 * ne, 0.0);
    std::vector<int> free_rows;
    std::vector<long> enriched_rows;
    for (long d = begin; d < end; ++d) {
      const auto it = columns_.find(point_of[d] * 5 + function_of[d]);
      if (it != columns_.end() &&
          std::equal(incidence.begin() + first[d], incidence.begin() + first[d + 1], it->second.incidence.begin(),
                     it->second.incidence.end()) &&
          std::none_of(incidence.begin() + first[d], incidence.begin() + first[d + 1],
                       [&](const std::pair<int, int>& a) { return recomputed[a.first] != 0; })) {
        for (int i = 0; i < 3; ++i) {
          all[3 * d + i] = it->second.column[i];
          all_g[3 * d + i] = it->second.g[i];
        }
        reused[d] = 1;
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        double g = 0;
        for (long a = first[d]; a < first[d + 1]; ++a) {
          const int t = incidence[a].first, q = incidence[a].second;
          const Eigen::MatrixXd& k = elements_.at(t).k;
          const long base = em.offsets[t];
          for (int r = 0; r < em.size(t); ++r) {
            const long row = em.dofs[base + r];
            for (int j = 0; j < 3; ++j) {
              const double v = k(3 * r + j, 3 * q + i);
              if (v == 0) continue;
              if (row < np) {
                const long s = 3 * row + j;
                const int f = body_.reduced[s];
                if (f < 0) {
                  g -= v * body_.constrained[s];  // the enriched rows' share of K_ec u_c
                } else {
                  if (free_sum[f] == 0) free_rows.push_back(f);
                  free_sum[f] += v;
                }
              } else {
                const long e = 3 * (row - np) + j;
                if (enriched_sum[e] == 0) enriched_rows.push_back(e);
                enriched_sum[e] += v;
              }
            }
          }
        }
        EnrichedColumn& column = all[3 * d + i];
        column.key = key_of(d, i);
        std::sort(free_rows.begin(), free_rows.end());
        free_rows.erase(std::unique(free_rows.begin(), free_rows.end()), free_rows.end());
        for (int f : free_rows) {
          if (free_sum[f] != 0) column.se.emplace_back(f, free_sum[f]);
          free_sum[f] = 0;
        }
        std::sort(enriched_rows.begin(), enriched_rows.end());
        enriched_rows.erase(std::unique(enriched_rows.begin(), enriched_rows.end()), enriched_rows.end());
        for (long e : enriched_rows) {
          if (enriched_sum[e] != 0) column.ee.emplace_back(key_of(e / 3, static_cast<int>(e % 3)), enriched_sum[e]);
          enriched_sum[e] = 0;
        }
        free_rows.clear();
        enriched_rows.clear();
        std::sort(column.ee.begin(), column.ee.end());
        all_g[3 * d + i] = g;
      }
    }
  }, {}, std::max<long>(64, ne / 8));
  {  // this step's columns, for the next
    std::unordered_map<long, Columns> next;
    next.reserve(static_cast<std::size_t>(ne));
    for (long d = 0; d < ne; ++d) {
      Columns& c = next[point_of[d] * 5 + function_of[d]];
      c.incidence.assign(incidence.begin() + first[d], incidence.begin() + first[d + 1]);
      for (int i = 0; i < 3; ++i) {
        c.column[i] = all[3 * d + i];
        c.g[i] = all_g[3 * d + i];
      }
      out.reused_columns += 3 * reused[d];
    }
    columns_ = std::move(next);
  }
  std::vector<EnrichedColumn> columns;
  std::vector<double> g_e;
  for (long c = 0; c < 3 * ne; ++c) {
    // A DOF without support (a zero column: xfem-solve fixes it to 0) is left out.
    if (all[c].se.empty() && all[c].ee.empty()) {
      ++out.unsupported_dofs;
      continue;
    }
    columns.push_back(std::move(all[c]));
    g_e.push_back(all_g[c]);
  }
  out.enriched_dofs = static_cast<long>(columns.size());
  out.assemble_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  schur_.update(columns, &out.incremental);
  const long m = static_cast<long>(columns.size());
  // S u_e = g_e - K_es w, then u_s = w - A^-1 K_se u_e (one solve).
  Eigen::VectorXd r(m);
  for (long c = 0; c < m; ++c) {
    double v = g_e[c];
    for (const auto& e : columns[c].se) v -= e.second * body_.w[e.first];
    r[c] = v;
  }
  const Eigen::VectorXd u_e = m > 0 ? schur_.solve(r) : Eigen::VectorXd();
  out.u = Eigen::VectorXd::Zero(3 * em.n);
  out.u.head(3 * np) = body_.constrained;
  for (long i = 0; i < nf; ++i) out.u[body_.free_dofs[i]] = body_.w[i];
  if (m > 0) {  // u_s = w - A^-1 b: now, or by complete_solution
    out.pending = Eigen::VectorXd::Zero(nf);
    for (long c = 0; c < m; ++c)
      for (const auto& e : columns[c].se) out.pending[e.first] += e.second * u_e[c];
  }
  // Enriched scalar DOF 3 np + 3 d + i has key key_of(d, i); supported ones in `columns` order.
  std::unordered_map<long, long> column_of;
  for (long c = 0; c < m; ++c) column_of[columns[c].key] = c;
  for (long d = 0; d < ne; ++d)
    for (int i = 0; i < 3; ++i) {
      const auto it = column_of.find(key_of(d, i));
      if (it != column_of.end()) out.u[3 * np + 3 * d + i] = u_e[it->second];
    }
  if (!out.u.allFinite()) throw Error("the Schur complement solve gave a non-finite solution (numerically singular)");
  out.solve_seconds = seconds_since(t0);  // the back-substitution apart (back_substitution_seconds)
  if (complete) complete_solution(body_, out);
  return out;
}

}  // namespace xfem
