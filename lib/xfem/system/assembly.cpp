// SPDX-License-Identifier: MIT
#include "xfem/system/assembly.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <mutex>
#include <numeric>

#include "xfem/integrate/closed_form_stiffness.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/consistent_gradients.h"
#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"
#include "xfem/system/cut_loads.h"
#include "xfem/system/pieces.h"
#include "xfem/system/stiffness_pattern.h"
#include "xfem/geometry/tet_shape.h"
#include "xfem/core/seconds_since.h"

namespace xfem {
namespace {

// One chunk's buffers for the enriched tets: the rule's points and the closed form's matrices.
struct Scratch {
  PointRule points;
  ClosedFormWorkspace work;
};

// The buffers of an assembly, lent to its chunks: at most one set per thread at a time, kept from
// batch to batch (a thread_local would die with each batch's threads and fault its pages again).
class ScratchPool {
 public:
  std::unique_ptr<Scratch> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return std::make_unique<Scratch>();
    std::unique_ptr<Scratch> s = std::move(free_.back());
    free_.pop_back();
    return s;
  }
  void give(std::unique_ptr<Scratch> s) {
    std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(s));
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Scratch>> free_;
};

// The closed-form stiffness of a plain tet (tet_stiffness, formula (5) with constant gradients)
// computed block by block straight into K: only the lower blocks the table names, only the lower
// half of diagonal blocks. Same arithmetic as tet_stiffness, about twice as fast as computing the
// full 12 x 12 matrix and scattering it.
void scatter_plain_tet(const EnrichedMesh& em, const Pattern& p, const std::vector<int>& outer, int t,
                       const Lame& material, double* values) {
  const TetShape shape = tet_shape(em.mesh, t);
  const double v = std::abs(shape.volume);
  const double mu = material.mu * v, la = material.lambda * v;
  const Eigen::Matrix<double, 4, 3>& g = shape.grad;
  const int* table = p.table.data() + p.table_offsets[t];
  const long base = em.offsets[t];
  for (int col = 0; col < 4; ++col) {
    const long b = em.dofs[base + col];
    const int lp = em.local[base + col];
    const double gp[3] = {g(lp, 0), g(lp, 1), g(lp, 2)};
    for (int q = 0; q < 4; ++q) {
      const int r = table[q * 4 + col];
      if (r < 0) continue;
      const int lq = em.local[base + q];
      const double gq[3] = {g(lq, 0), g(lq, 1), g(lq, 2)};
      const double dot = mu * (gq[0] * gp[0] + gq[1] * gp[1] + gq[2] * gp[2]);
      for (int i = 0; i < 3; ++i) {
        double* column = values + outer[3 * b + i];
        // k(3q+j, 3col+i) = mu gq_i gp_j + lambda gq_j gp_i + delta_ij mu gq.gp
        const double a = mu * gq[i], c = la * gp[i];
        if (r == 0) {
          column[0] += a * gp[i] + c * gq[i] + dot;
          for (int j = i + 1; j < 3; ++j) column[j - i] += a * gp[j] + c * gq[j];
        } else {
          double* at = column + (3 - i) + 3 * (r - 1);
          for (int j = 0; j < 3; ++j) at[j] += a * gp[j] + c * gq[j] + (i == j ? dot : 0.0);
        }
      }
    }
  }
}

}  // namespace

SparseMatrix stiffness_matrix(const EnrichedMesh& em, const Lame& material, const Quadrature& rule,
                              AssemblyStats* stats, const std::function<void(double)>& progress,
                              int conforming_order, bool closed_form, bool graded, bool uniform, bool fast) {
  return stiffness_matrix(em, TetMaterials(MaterialLaw{MaterialModel::Linear, material}), rule, stats, progress,
                          conforming_order, closed_form, graded, uniform, fast);
}

SparseMatrix stiffness_matrix(const EnrichedMesh& em, const TetMaterials& materials, const Quadrature& rule,
                              AssemblyStats* stats, const std::function<void(double)>& progress,
                              int conforming_order, bool closed_form, bool graded, bool uniform, bool fast) {
  AssemblyStats local;
  AssemblyStats& s = stats ? *stats : local;
  auto clock = std::chrono::steady_clock::now();
  const Pattern p = make_pattern(em);
  std::vector<int> outer;
  SparseMatrix K = pattern_matrix(em, p, outer);
  double* values = K.valuePtr();
  s.pattern_seconds += seconds_since(clock);

  // Plain tets first (closed form), enriched ones second (oversampling), each timed on its own.
  const int tets = em.tets();
  std::vector<int> enriched;
  clock = std::chrono::steady_clock::now();
  for (int t = 0; t < tets; ++t) {
    if (!em.plain(t)) {
      enriched.push_back(t);
      continue;
    }
    scatter_plain_tet(em, p, outer, t, materials.lame(t), values);
    if (progress && (t & 0xffff) == 0) progress(double(t) / tets);
  }
  s.standard_tets += tets - static_cast<long>(enriched.size());
  s.standard_seconds += seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  // The conforming rule (conforming_quadrature.h) splits the cut elements once, then integrates
  // every enriched tet on its own points; otherwise the oversampling `rule`.
  const CutElementSplits splits = conforming_order > 0 ? split_cut_elements(em) : CutElementSplits();
  // Element matrices in a few threads, a batch at a time, then added to K in the tets' order.
  // Each run of `chunk` consecutive tets shares one face-integral cache (a face's integrals
  // computed once for its two tets when both are in the run): the runs do not depend on the
  // thread count, so neither does K, bit for bit.
  const long chunk = 32, batch = 32 * chunk;
  ScratchPool scratches;
  std::vector<Eigen::MatrixXd> ks(static_cast<std::size_t>(std::min<long>(batch, static_cast<long>(enriched.size()))));
  for (long first = 0; first < static_cast<long>(enriched.size()); first += batch) {
    const long count = std::min<long>(batch, static_cast<long>(enriched.size()) - first);
    parallel_for(count, [&](long begin, long end) {
      // The points and the closed form's matrices are kept for the whole assembly (the threads come
      // and go with each batch): allocated per tet they cost more in page faults than their
      // arithmetic (scratch_matrix.h). A chunk takes a set and gives it back.
      std::unique_ptr<Scratch> scratch = scratches.take();
      PointRule& points = scratch->points;
      ClosedFormWorkspace& work = scratch->work;
      FaceIntegralCache faces;
      for (long i = begin; i < end; ++i) {
        const int t = enriched[static_cast<std::size_t>(first + i)];
        if (conforming_order > 0 && closed_form && !graded && !fast && !uniform) {
          default_rule_stiffness(em, splits, t, conforming_order, materials.lame(t), ks[i], &faces, work, points);
        } else if (conforming_order > 0 && closed_form) {
          // The comparison rules: points for the branch functions only, the other blocks from the
          // side volumes alone; no straight-front reduction.
          if (!em.branch(t)) points.clear();
          else if (graded) conforming_rule(em, splits, t, TetRuleLayout::graded(), points);
          else if (fast) conforming_rule(em, splits, t, TetRuleLayout::fast(), points);
          else conforming_rule(em, splits, t, TetRuleLayout::uniform(conforming_order), points);
          // The consistent shift of the rule's order; uniform(n) had n face points (consistent_face_points).
          const int consistent = graded ? TetRuleLayout::graded_consistent_order
                                 : fast ? TetRuleLayout::fast_consistent_order
                                 : conforming_order - 1;
          closed_form_stiffness(em, splits, t, points, materials.lame(t), ks[i], consistent, &faces, 0, work);
        } else if (conforming_order > 0) {
          conforming_rule(em, splits, t, conforming_order, points);
          element_stiffness_at_points(em, t, points, materials.lame(t), ks[i], conforming_order, &faces);
        } else {
          element_stiffness(em, t, rule, materials.lame(t), ks[i]);
        }
      }
      scratches.give(std::move(scratch));
    }, {}, chunk);
    for (long i = 0; i < count; ++i) scatter(em, p, outer, enriched[static_cast<std::size_t>(first + i)], ks[i], values);
    if (progress) progress(static_cast<double>(tets - static_cast<long>(enriched.size()) + first + count) / tets);
  }
  s.enriched_tets += static_cast<long>(enriched.size());
  s.enriched_seconds += seconds_since(clock);
  if (progress) progress(1.0);
  return K;
}

Eigen::VectorXd load_vector(const EnrichedMesh& em, const Problem& problem) {
  const TetMesh& mesh = em.mesh;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * em.n);
  if (problem.body_force.squaredNorm() > 0)
    for (int t = 0; t < em.tets(); ++t) {
      const double v = signed_volume(mesh, t);
      for (int c = 0; c < 4; ++c) f.segment<3>(3 * mesh.tets(t, c)) += problem.body_force * (v / 4.0);
    }
  if (problem.neumann.empty()) return f;
  const std::vector<std::array<int, 3>> faces = boundary_faces(mesh);
  for (std::size_t c = 0; c < problem.neumann.size(); ++c) {
    const NeumannCondition& nc = problem.neumann[c];
    const std::string what = describe(problem, "neumann", c);
    std::vector<char> selected(mesh.points.rows(), 0);
    for (int k : select_nodes(nc.selector, mesh, what)) selected[k] = 1;
    long count = 0;
    for (const auto& v : faces) {
      if (!selected[v[0]] || !selected[v[1]] || !selected[v[2]]) continue;
      const Eigen::Vector3d a = mesh.points.row(v[0]), b = mesh.points.row(v[1]), d = mesh.points.row(v[2]);
      const double area = 0.5 * (b - a).cross(d - a).norm();
      for (int k : v) f.segment<3>(3 * k) += nc.traction * (area / 3.0);
      ++count;
    }
    if (count == 0) throw Error(what + " selects no boundary face (all three nodes of a face must be selected)");
  }
  return f;
}

std::vector<long> unsupported_dofs(const SparseMatrix& K, long first) {
  std::vector<long> out;
  for (long k = first; 3 * k + 2 < K.cols(); ++k) {
    bool zero = true;
    for (int i = 0; i < 3 && zero; ++i) {
      const int c = static_cast<int>(3 * k + i);
      const int begin = K.outerIndexPtr()[c], end = K.outerIndexPtr()[c + 1];
      zero = begin == end || K.innerIndexPtr()[begin] != c || K.valuePtr()[begin] == 0.0;
    }
    if (zero) out.push_back(k);
  }
  return out;
}

LinearSystem assemble_system(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                             AssemblyStats* stats,
                             const std::function<void(double)>& progress) {
  return assemble_system(em, problem, tet_materials(problem, em.mesh, "the mesh"), points, refine, stats, progress);
}

LinearSystem assemble_system(const EnrichedMesh& em, const Problem& problem, const TetMaterials& materials, int points,
                             int refine, AssemblyStats* stats, const std::function<void(double)>& progress) {
  AssemblyStats local;
  AssemblyStats& s = stats ? *stats : local;
  LinearSystem sys;
  sys.np = em.np;
  sys.ns = em.ns;
  sys.nb = em.nb;
  sys.n = em.n;
  const bool conforming = problem.rule == Problem::Rule::Conforming;
  check_cut_indices(problem, cut_count(em));  // before the long part: a cut load or contact on a cut the mesh lacks
  if (!em.cuts.empty() && !conforming)
    throw Error(problem.file + ": several cuts are integrated by the conforming rule only (integration.rule \"conforming\", the default)");
  sys.K = stiffness_matrix(em, materials, oversampling_quadrature(points, refine), &s, progress,
                           conforming ? problem.order : 0, problem.closed_form, problem.graded, problem.uniform,
                           problem.fast);
  const auto clock = std::chrono::steady_clock::now();
  sys.f = load_vector(em, problem);
  add_cut_loads(em, problem, sys.f);  // the cuts' faces (cut_loads.h): enriched DOFs only
  dirichlet_data(em, problem, sys.fixed, sys.fixed_values);
  sys.pieces = find_pieces_held_by(em, sys.fixed);
  sys.coordinates = em.mesh.points;
  s.load_seconds += seconds_since(clock);
  return sys;
}

}  // namespace xfem
