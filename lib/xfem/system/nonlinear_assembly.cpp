// SPDX-License-Identifier: MIT
#include "xfem/system/nonlinear_assembly.h"

#include <algorithm>
#include <atomic>
#include <limits>

#include "xfem/core/parallel_for.h"
#include "xfem/integrate/consistent_gradients.h"

namespace xfem {

BodyIntegration integrate_body(const EnrichedMesh& em, int order, const std::function<void(double)>& progress) {
  BodyIntegration body;
  body.pattern = make_pattern(em);
  const int tets = em.tets();
  body.tets.resize(static_cast<std::size_t>(tets));
  const CutElementSplits splits = split_cut_elements(em);
  // Runs of 32 consecutive tets share a face-integral cache, as in the linear assembly.
  const long chunk = 32;
  parallel_for(tets, [&](long begin, long end) {
    FaceIntegralCache faces;
    for (long t = begin; t < end; ++t)
      element_points(em, splits, static_cast<int>(t), order, &faces, body.tets[static_cast<std::size_t>(t)]);
  }, {}, chunk);
  for (const ElementPoints& e : body.tets) body.points += e.size();
  if (progress) progress(1.0);
  return body;
}

bool internal_forces(const EnrichedMesh& em, const BodyIntegration& body, const MaterialLaw& law,
                     const Eigen::VectorXd& u, double& energy, Eigen::VectorXd& r, SparseMatrix* K, double* min_J,
                     Tangent kind) {
  const int tets = em.tets();
  r.setZero(3 * em.n);
  energy = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  std::vector<int> outer;
  if (K) {
    // The column starts of K's pattern: K was made by pattern_matrix with this pattern.
    outer.assign(K->outerIndexPtr(), K->outerIndexPtr() + K->cols() + 1);
    std::fill(K->valuePtr(), K->valuePtr() + K->nonZeros(), 0.0);
  }
  // Element results in threads, a batch at a time, added in the tets' order: the sums do not
  // depend on the thread count.
  const long batch = 1024;
  std::vector<ElementForces> results(static_cast<std::size_t>(std::min<long>(batch, tets)));
  std::atomic<bool> inverted{false};
  for (long first = 0; first < tets && !inverted; first += batch) {
    const long count = std::min<long>(batch, tets - first);
    parallel_for(count, [&](long begin, long end) {
      Eigen::VectorXd ue;
      for (long i = begin; i < end && !inverted; ++i) {
        const int t = static_cast<int>(first + i);
        const long base = em.offsets[t];
        const int n = em.size(t);
        ue.resize(3 * n);
        for (int c = 0; c < n; ++c) ue.segment<3>(3 * c) = u.segment<3>(3 * em.dofs[base + c]);
        const MaterialLaw& tet_law = body.materials ? body.materials->law(t) : law;
        if (!element_forces(body.tets[static_cast<std::size_t>(t)], tet_law, ue, K != nullptr, results[i], kind))
          inverted = true;
      }
    }, {}, 64);
    if (inverted) break;
    for (long i = 0; i < count; ++i) {
      const int t = static_cast<int>(first + i);
      const ElementForces& e = results[static_cast<std::size_t>(i)];
      const long base = em.offsets[t];
      for (int c = 0; c < em.size(t); ++c) r.segment<3>(3 * em.dofs[base + c]) += e.r.segment<3>(3 * c);
      energy += e.energy;
      smallest = std::min(smallest, e.min_J);
      if (K) scatter(em, body.pattern, outer, t, e.k, K->valuePtr());
    }
  }
  if (min_J) *min_J = smallest;
  return !inverted;
}

}  // namespace xfem
