// SPDX-License-Identifier: MIT
#include "xfem/system/dirichlet.h"

#include <algorithm>
#include <iterator>

#include "xfem/core/error.h"

namespace xfem {

ReducedSystem eliminate_dirichlet(const SparseMatrix& K, const Eigen::VectorXd& f, const std::vector<long>& fixed,
                                  const std::vector<double>& values) {
  const int n = static_cast<int>(K.rows());
  ReducedSystem r;
  r.reduced.assign(n, 0);
  for (long d : fixed) r.reduced[d] = -1;
  for (int d = 0; d < n; ++d)
    if (r.reduced[d] == 0) {
      r.reduced[d] = static_cast<int>(r.free_dofs.size());
      r.free_dofs.push_back(d);
    }
  const int nf = static_cast<int>(r.free_dofs.size());
  if (nf == 0) throw Error("every DOF is constrained: nothing to solve");
  r.f.resize(nf);
  for (int a = 0; a < nf; ++a) r.f[a] = f[r.free_dofs[a]];

  // 1. Move the known values to the right-hand side: f_f -= K_fc u_c (column by column of K).
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    if (values[k] == 0.0) continue;
    for (SparseMatrix::InnerIterator it(K, static_cast<int>(fixed[k])); it; ++it)
      if (r.reduced[it.row()] >= 0) r.f[r.reduced[it.row()]] -= it.value() * values[k];
  }
  // 2. K_ff straight into compressed storage: the map to reduced indices is increasing, so each
  //    column stays sorted and no triplet sort is needed (11M entries on the 256k-DOF beam).
  long nnz = 0;
  for (int d : r.free_dofs)
    for (SparseMatrix::InnerIterator it(K, d); it; ++it) nnz += r.reduced[it.row()] >= 0;
  r.K.resize(nf, nf);
  r.K.resizeNonZeros(nnz);
  int* outer = r.K.outerIndexPtr();
  int* inner = r.K.innerIndexPtr();
  double* value = r.K.valuePtr();
  long pos = 0;
  for (int a = 0; a < nf; ++a) {
    outer[a] = static_cast<int>(pos);
    for (SparseMatrix::InnerIterator it(K, r.free_dofs[a]); it; ++it) {
      const int row = r.reduced[it.row()];
      if (row < 0) continue;
      inner[pos] = row;
      value[pos] = it.value();
      ++pos;
    }
  }
  outer[nf] = static_cast<int>(pos);
  return r;
}

Eigen::VectorXd expand_solution(const ReducedSystem& r, const Eigen::VectorXd& u_free, const std::vector<long>& fixed,
                                const std::vector<double>& values) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(r.reduced.size()));
  for (std::size_t a = 0; a < r.free_dofs.size(); ++a) u[r.free_dofs[a]] = u_free[static_cast<Eigen::Index>(a)];
  for (std::size_t k = 0; k < fixed.size(); ++k) u[fixed[k]] = values[k];
  return u;
}

double relative_residual(const SparseMatrix& K, const Eigen::VectorXd& f, const Eigen::VectorXd& u,
                         const ReducedSystem& r) {
  const Eigen::VectorXd res = K * u - f;
  double num = 0;
  for (int d : r.free_dofs) num += res[d] * res[d];
  const double den = r.f.squaredNorm();
  return den > 0 ? std::sqrt(num / den) : std::sqrt(num);
}

void require_constrained(const LinearSystem& s) {
  if (s.fixed.empty())
    throw Error("no Dirichlet condition: the body can move rigidly, K is singular (fix some nodes in the problem's "
                "boundary conditions)");
  std::vector<std::size_t> loose;
  for (std::size_t p = 0; p < s.pieces.size(); ++p)
    if (!s.pieces[p].constrained) loose.push_back(p);
  if (loose.empty()) return;
  std::string what = "the body falls apart into " + std::to_string(s.pieces.size()) + " pieces; ";
  for (std::size_t k = 0; k < loose.size(); ++k) {
    if (k > 0) what += ", ";
    what += "piece " + std::to_string(loose[k] + 1) + " (" + std::to_string(s.pieces[loose[k]].tets) + " tets)";
  }
  what += loose.size() == 1 ? " has no Dirichlet condition" : " have no Dirichlet condition";
  throw Error(what + " (it can move rigidly: K is singular)");
}

std::string describe_dof(const LinearSystem& s, long dof) {
  const long k = dof / 3;
  const char component = "xyz"[dof % 3];
  std::string kind;
  if (k < s.np) {
    kind = "original, mesh point " + std::to_string(k);
  } else if (k < s.np + s.ns) {
    kind = "sign-enriched vector " + std::to_string(k - s.np) + " of " + std::to_string(s.ns);
  } else {
    const long b = k - s.np - s.ns;
    kind = "branch-enriched node " + std::to_string(b / 4) + " of " + std::to_string(s.nb) + ", function F" +
           std::to_string(b % 4 + 1);
  }
  return "DOF " + std::to_string(dof) + " (vector " + std::to_string(k) + ", " + kind + ", component " + component + ")";
}

std::vector<long> zero_rows(const LinearSystem& s) {
  // K is stored with both triangles, so a column holds the whole row.
  std::vector<long> zero;
  for (int j = 0; j < s.K.outerSize(); ++j) {
    bool any = false;
    for (SparseMatrix::InnerIterator it(s.K, j); it && !any; ++it) any = it.value() != 0.0;
    if (!any) zero.push_back(j);
  }
  return zero;
}

std::vector<long> fix_unsupported_enrichment(LinearSystem& s) {
  std::vector<long> enriched;
  for (long d : zero_rows(s)) {
    if (std::binary_search(s.fixed.begin(), s.fixed.end(), d)) continue;  // its value is known anyway
    if (d < 3 * s.np)
      throw Error("K has an exactly zero row at " + describe_dof(s, d) +
                  ": the mesh point belongs to no tet of non-zero volume, so nothing determines its displacement "
                  "(K is singular; check the mesh)");
    enriched.push_back(d);
  }
  fix_to_zero(s, enriched);
  return enriched;
}

std::vector<long> tiny_enriched_dofs(const LinearSystem& s, double tolerance) {
  const Eigen::VectorXd diag = s.K.diagonal();
  const long original = std::min<long>(3 * s.np, diag.size());
  if (original == 0) return {};
  const double mean = diag.head(original).mean();
  std::vector<long> tiny;
  for (long d = original; d < diag.size(); ++d)
    if (diag[d] < tolerance * mean && !std::binary_search(s.fixed.begin(), s.fixed.end(), d)) tiny.push_back(d);
  return tiny;
}

void fix_to_zero(LinearSystem& s, const std::vector<long>& extra) {
  std::vector<std::pair<long, double>> all;
  for (std::size_t k = 0; k < s.fixed.size(); ++k) all.emplace_back(s.fixed[k], s.fixed_values[k]);
  for (long d : extra) all.emplace_back(d, 0.0);
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  all.erase(std::unique(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
            all.end());
  s.fixed.clear();
  s.fixed_values.clear();
  for (const auto& [d, v] : all) {
    s.fixed.push_back(d);
    s.fixed_values.push_back(v);
  }
}

}  // namespace xfem
