// SPDX-License-Identifier: MIT
#include "xfem/system/contact_operator.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/integrate/cut_face_quadrature.h"
#include "xfem/system/cut_loads.h"

namespace xfem {
namespace {

std::string join(const std::string& dir, const char* name) { return (std::filesystem::path(dir) / name).string(); }

// Matrix Market `coordinate real general`, entries column after column (values in round-trip form).
void write_general_matrix(const SparseMatrix& A, const std::string& path) {
  write_atomically(path, [&](const std::string& tmp) {
    std::FILE* out = std::fopen(tmp.c_str(), "w");
    if (!out) throw Error(path + ": cannot write");
    std::fprintf(out, "%%%%MatrixMarket matrix coordinate real general\n%ld %ld %ld\n", static_cast<long>(A.rows()),
                 static_cast<long>(A.cols()), static_cast<long>(A.nonZeros()));
    for (int j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        std::fprintf(out, "%ld %d %.17g\n", static_cast<long>(it.row()) + 1, j + 1, it.value());
    const bool failed = std::ferror(out) != 0;
    if (std::fclose(out) != 0 || failed) throw Error(path + ": write failed (disk full?)");
  });
}

}  // namespace

ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem) {
  ContactOperator c;
  const int cuts = cut_count(em);
  check_cut_indices(problem, cuts);
  std::vector<CutFacePoint> points;
  for (int k = 0; k < cuts; ++k)
    if (problem.contact.applies_to(k)) {
      const std::vector<CutFacePoint> more = cut_face_points(em, k, problem.order);
      points.insert(points.end(), more.begin(), more.end());
    }
  const long Q = static_cast<long>(points.size());
  c.weight.resize(Q);
  c.penalty.resize(Q);
  c.x.resize(Q, 3);
  c.tet.resize(static_cast<std::size_t>(Q));
  c.cut.resize(static_cast<std::size_t>(Q));
  std::vector<Eigen::Triplet<double, int>> entries;
  Eigen::VectorXd jump;
  BasisAt scratch;
  for (long q = 0; q < Q; ++q) {
    const CutFacePoint& p = points[static_cast<std::size_t>(q)];
    basis_jump(em, p.tet, p.cut, p.x, jump, scratch);
    const long begin = em.offsets[p.tet];
    for (int e = 0; e < em.size(p.tet); ++e) {
      if (jump[e] == 0.0) continue;
      for (int i = 0; i < 3; ++i)
        if (p.normal[i] != 0.0)
          entries.emplace_back(static_cast<int>(q), static_cast<int>(3 * em.dofs[begin + e] + i), jump[e] * p.normal[i]);
    }
    double h = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        h = std::max(h, (em.mesh.points.row(em.mesh.tets(p.tet, a)) - em.mesh.points.row(em.mesh.tets(p.tet, b))).norm());
    c.weight[q] = p.weight;
    c.penalty[q] = problem.contact.penalty * problem.E / h;
    c.x.row(q) = p.x.transpose();
    c.tet[static_cast<std::size_t>(q)] = p.tet;
    c.cut[static_cast<std::size_t>(q)] = p.cut;
  }
  c.G.resize(Q, 3 * em.n);
  c.G.setFromTriplets(entries.begin(), entries.end());  // a DOF appears once per point: no sums
  c.G.makeCompressed();
  return c;
}

void write_contact_operator(const ContactOperator& c, const std::string& dir) {
  write_general_matrix(c.G, join(dir, kContactGapFile));
  const long Q = c.points();
  SparseMatrix P(Q, 7);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (long q = 0; q < Q; ++q) {
    const double row[7] = {c.weight[q], c.penalty[q], c.x(q, 0), c.x(q, 1), c.x(q, 2),
                           static_cast<double>(c.tet[static_cast<std::size_t>(q)]),
                           static_cast<double>(c.cut[static_cast<std::size_t>(q)])};
    for (int j = 0; j < 7; ++j) entries.emplace_back(static_cast<int>(q), j, row[j]);
  }
  P.setFromTriplets(entries.begin(), entries.end());
  write_general_matrix(P, join(dir, kContactPointsFile));
}

ContactOperator read_contact_operator(const std::string& dir, long dofs) {
  ContactOperator c;
  const std::string gap_path = join(dir, kContactGapFile), points_path = join(dir, kContactPointsFile);
  c.G = read_matrix(gap_path);
  if (c.G.cols() != dofs)
    throw Error(gap_path + ": " + std::to_string(c.G.cols()) + " columns, expected 3N = " + std::to_string(dofs));
  const SparseMatrix P = read_matrix(points_path);
  if (P.rows() != c.G.rows() || P.cols() != 7)
    throw Error(points_path + ": " + std::to_string(P.rows()) + " x " + std::to_string(P.cols()) + ", expected " +
                std::to_string(c.G.rows()) + " x 7 (one row per row of " + kContactGapFile + ")");
  const Eigen::MatrixXd dense = Eigen::MatrixXd(P);
  const long Q = c.G.rows();
  c.weight = dense.col(0);
  c.penalty = dense.col(1);
  c.x = dense.middleCols(2, 3);
  c.tet.resize(static_cast<std::size_t>(Q));
  c.cut.resize(static_cast<std::size_t>(Q));
  for (long q = 0; q < Q; ++q) {
    if (!(c.weight[q] > 0) || !(c.penalty[q] > 0) || !std::isfinite(c.weight[q]) || !std::isfinite(c.penalty[q]))
      throw Error(points_path + ": point " + std::to_string(q + 1) + " has a weight or penalty that is not positive");
    c.tet[static_cast<std::size_t>(q)] = static_cast<int>(dense(q, 5));
    c.cut[static_cast<std::size_t>(q)] = static_cast<int>(dense(q, 6));
  }
  return c;
}

bool has_contact_operator(const std::string& dir) { return std::filesystem::exists(join(dir, kContactGapFile)); }

}  // namespace xfem
