// SPDX-License-Identifier: MIT
#include "xfem/system/contact_operator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/geometry/tet_shape.h"
#include "xfem/integrate/cut_face_quadrature.h"
#include "xfem/system/cut_loads.h"

namespace xfem {
namespace {

// Relative weight below which a node's share of a tet's face points goes to the tet's other nodes
// (contact_operator; measured on the organ's sine incision, docs/METHOD.md "Contact").
constexpr double kSliverWeight = 0.3;

std::string join(const std::string& dir, const char* name) { return (std::filesystem::path(dir) / name).string(); }

// The share N of each of its tet's nodes in each face point of a cut (points grouped by tet, as
// cut_face_points gives them): the linear shape functions, except that a node whose raw weight
// sum_q w_q N_i(x_q) is below kSliverWeight times its reference (the largest raw weight among the
// nodes of the cut tets around it) sees only slivers of the cut: a condition of its own would hold
// next to nothing (its penalty kappa W ~ 0) and its multiplier would not converge. Its share of
// the tet's points goes to the tet's other nodes, in proportion to their shape functions (the
// shares still sum to 1: a uniform pressure is still carried exactly); all to the node of largest
// raw weight when the tet has only such nodes. One function for the gap rows G and the slip rows
// T, so that both see the same nodes with the same weights.
std::vector<Eigen::Vector4d> point_shares(const EnrichedMesh& em, const std::vector<CutFacePoint>& points) {
  const long np = em.mesh.points.rows();
  // The nodes' raw weights sum_q w_q N_i(x_q), to find the nodes that see only slivers.
  std::vector<double> raw(static_cast<std::size_t>(np), 0.0);
  for (const CutFacePoint& p : points) {
    const Eigen::Vector4d N = tet_shape(em.mesh, p.tet).values(p.x).cwiseMax(0.0);
    for (int a = 0; a < 4; ++a) raw[static_cast<std::size_t>(em.mesh.tets(p.tet, a))] += p.weight * N[a];
  }
  // Each node's reference: the largest raw weight among the nodes of the cut tets around it.
  std::vector<double> reference(static_cast<std::size_t>(np), 0.0);
  for (const CutFacePoint& p : points) {
    double largest = 0;
    for (int a = 0; a < 4; ++a) largest = std::max(largest, raw[static_cast<std::size_t>(em.mesh.tets(p.tet, a))]);
    for (int a = 0; a < 4; ++a) {
      double& r = reference[static_cast<std::size_t>(em.mesh.tets(p.tet, a))];
      r = std::max(r, largest);
    }
  }
  std::vector<Eigen::Vector4d> shares(points.size());
  for (std::size_t first = 0; first < points.size();) {
    const int t = points[first].tet;
    std::size_t end = first;
    while (end < points.size() && points[end].tet == t) ++end;
    const TetShape shape = tet_shape(em.mesh, t);
    Eigen::Vector4d keep;
    int biggest = 0;
    for (int a = 0; a < 4; ++a) {
      const std::size_t node = static_cast<std::size_t>(em.mesh.tets(t, a));
      keep[a] = raw[node] >= kSliverWeight * reference[node] ? 1.0 : 0.0;
      if (raw[node] > raw[static_cast<std::size_t>(em.mesh.tets(t, biggest))]) biggest = a;
    }
    for (std::size_t q = first; q < end; ++q) {
      Eigen::Vector4d N = shape.values(points[q].x).cwiseMax(0.0).cwiseProduct(keep);  // >= 0: the point lies in the tet
      if (N.sum() > 0) N /= N.sum();
      else N = Eigen::Vector4d::Unit(biggest);  // the point sits on the sliver nodes' face: all to the biggest
      shares[q] = N;
    }
    first = end;
  }
  return shares;
}

// Two unit tangents orthogonal to each other and to n (unit): t_1 along the coordinate axis
// least aligned with n, projected; t_2 = n x t_1.
void tangents_of(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  t1 = Eigen::Vector3d::Unit(axis) - n[axis] * n;
  t1.normalize();
  t2 = n.cross(t1);
}

// The friction part of `c` (ContactOperator::T, tangents, friction), its rows in c's order.
void add_slip_rows(const EnrichedMesh& em, const Problem& problem, int cuts, ContactOperator& c) {
  const long np = em.mesh.points.rows(), M = c.points();
  std::vector<int> row_of(static_cast<std::size_t>(cuts) * static_cast<std::size_t>(np), -1);
  for (long i = 0; i < M; ++i)
    row_of[static_cast<std::size_t>(c.cut[static_cast<std::size_t>(i)]) * static_cast<std::size_t>(np) +
           static_cast<std::size_t>(c.node[static_cast<std::size_t>(i)])] = static_cast<int>(i);
  std::vector<std::vector<CutFacePoint>> points(static_cast<std::size_t>(cuts));
  std::vector<std::vector<Eigen::Vector4d>> shares(static_cast<std::size_t>(cuts));
  // The nodes' averaged normals sum_q w_q N_i n_q (their tangents span the slip).
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(M, 3);
  for (int k = 0; k < cuts; ++k) {
    if (!problem.contact.applies_to(k)) continue;
    points[static_cast<std::size_t>(k)] = cut_face_points(em, k, problem.order);
    shares[static_cast<std::size_t>(k)] = point_shares(em, points[static_cast<std::size_t>(k)]);
    const auto& P = points[static_cast<std::size_t>(k)];
    for (std::size_t q = 0; q < P.size(); ++q)
      for (int a = 0; a < 4; ++a) {
        const int row = row_of[static_cast<std::size_t>(k) * static_cast<std::size_t>(np) +
                               static_cast<std::size_t>(em.mesh.tets(P[q].tet, a))];
        const double share = shares[static_cast<std::size_t>(k)][q][a];
        if (row >= 0 && share > 0) normal.row(row) += P[q].weight * share * P[q].normal.transpose();
      }
  }
  c.tangents.resize(M, 6);
  c.friction.resize(M);
  for (long i = 0; i < M; ++i) {
    Eigen::Vector3d t1, t2;
    tangents_of(Eigen::Vector3d(normal.row(i).transpose()).normalized(), t1, t2);
    c.tangents.row(i) << t1.transpose(), t2.transpose();
    c.friction[i] = problem.contact.friction_of(c.cut[static_cast<std::size_t>(i)]);
  }
  std::vector<Eigen::Triplet<double, int>> entries;
  Eigen::VectorXd jump;
  BasisAt scratch;
  for (int k = 0; k < cuts; ++k) {
    const auto& P = points[static_cast<std::size_t>(k)];
    for (std::size_t q = 0; q < P.size(); ++q) {
      const int t = P[q].tet, size = em.size(t);
      const long begin = em.offsets[t];
      basis_jump(em, t, k, P[q].x, jump, scratch);
      const Eigen::Matrix3d tangential = Eigen::Matrix3d::Identity() - P[q].normal * P[q].normal.transpose();
      for (int a = 0; a < 4; ++a) {
        const int row = row_of[static_cast<std::size_t>(k) * static_cast<std::size_t>(np) +
                               static_cast<std::size_t>(em.mesh.tets(t, a))];
        const double share = shares[static_cast<std::size_t>(k)][q][a];
        if (row < 0 || !(share > 0)) continue;
        const double scale = P[q].weight * share / c.weight[row];
        for (int b = 0; b < 2; ++b) {
          const Eigen::Vector3d direction = tangential * c.tangents.row(row).segment<3>(3 * b).transpose();
          for (int e = 0; e < size; ++e) {
            if (jump[e] == 0.0) continue;
            for (int d = 0; d < 3; ++d)
              if (direction[d] != 0.0)
                entries.emplace_back(2 * row + b, static_cast<int>(3 * em.dofs[begin + e] + d), scale * jump[e] * direction[d]);
          }
        }
      }
    }
  }
  c.T.resize(2 * M, 3 * em.n);
  c.T.setFromTriplets(entries.begin(), entries.end());  // sums the points around each node
  c.T.makeCompressed();
}

}  // namespace

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

ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem) {
  return contact_operator(em, problem, TetMaterials(problem.model, problem.E, problem.nu));
}

ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem, const TetMaterials& materials) {
  const int cuts = cut_count(em);
  check_cut_indices(problem, cuts);
  const long np = em.mesh.points.rows();
  // Row of each (cut, node) in the order first met, the sums W_i and sum w N_i kappa_q, and G's
  // entries sum_q w_q N_i(x_q) n_q . [[Phi_e]](x_q) (scaled by 1 / W_i at the end).
  std::vector<int> row_of(static_cast<std::size_t>(cuts) * static_cast<std::size_t>(np), -1);
  std::vector<long> key;  // k np + node of each row
  std::vector<double> W, kappa_sum;
  std::vector<Eigen::Triplet<double, int>> entries;
  Eigen::VectorXd jump;
  BasisAt scratch;
  for (int k = 0; k < cuts; ++k) {
    if (!problem.contact.applies_to(k)) continue;
    const std::vector<CutFacePoint> points = cut_face_points(em, k, problem.order);
    const std::vector<Eigen::Vector4d> shares = point_shares(em, points);
    for (std::size_t first = 0; first < points.size();) {
      const int t = points[first].tet;
      std::size_t end = first;
      while (end < points.size() && points[end].tet == t) ++end;
      double h = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          h = std::max(h, (em.mesh.points.row(em.mesh.tets(t, a)) - em.mesh.points.row(em.mesh.tets(t, b))).norm());
      // The penalty of the tet's own material (problem.json `materials` per region).
      const double kappa = problem.contact.penalty * materials.E[static_cast<std::size_t>(materials.index(t))] / h;
      const int size = em.size(t);
      const long begin = em.offsets[t];
      Eigen::MatrixXd R = Eigen::MatrixXd::Zero(4, 3 * size);  // row a: node a's combination of the tet's DOFs
      Eigen::Vector4d Wt = Eigen::Vector4d::Zero();
      for (std::size_t q = first; q < end; ++q) {
        const CutFacePoint& p = points[q];
        basis_jump(em, t, k, p.x, jump, scratch);
        const Eigen::Vector4d& N = shares[q];  // the node's share (point_shares: sliver nodes merged)
        Wt += p.weight * N;
        for (int e = 0; e < size; ++e) {
          if (jump[e] == 0.0) continue;
          for (int i = 0; i < 3; ++i) R.col(3 * e + i) += (p.weight * jump[e] * p.normal[i]) * N;
        }
      }
      for (int a = 0; a < 4; ++a) {
        if (!(Wt[a] > 0)) continue;
        const long node = em.mesh.tets(t, a);
        int& row = row_of[static_cast<std::size_t>(k * np + node)];
        if (row < 0) {
          row = static_cast<int>(key.size());
          key.push_back(k * np + node);
          W.push_back(0.0);
          kappa_sum.push_back(0.0);
        }
        W[static_cast<std::size_t>(row)] += Wt[a];
        kappa_sum[static_cast<std::size_t>(row)] += Wt[a] * kappa;
        for (int e = 0; e < size; ++e)
          for (int i = 0; i < 3; ++i)
            if (R(a, 3 * e + i) != 0.0)
              entries.emplace_back(row, static_cast<int>(3 * em.dofs[begin + e] + i), R(a, 3 * e + i));
      }
      first = end;
    }
  }
  // Rows sorted by cut, then node: the order does not depend on how the tets were visited.
  const long M = static_cast<long>(key.size());
  std::vector<int> order(static_cast<std::size_t>(M)), rank(static_cast<std::size_t>(M));
  for (int i = 0; i < M; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)]; });
  for (int i = 0; i < M; ++i) rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
  for (auto& entry : entries) {
    const int r = rank[static_cast<std::size_t>(entry.row())];
    entry = Eigen::Triplet<double, int>(r, entry.col(), entry.value() / W[static_cast<std::size_t>(order[static_cast<std::size_t>(r)])]);
  }
  ContactOperator c;
  c.weight.resize(M);
  c.penalty.resize(M);
  c.x.resize(M, 3);
  c.node.resize(static_cast<std::size_t>(M));
  c.cut.resize(static_cast<std::size_t>(M));
  for (long i = 0; i < M; ++i) {
    const std::size_t old = static_cast<std::size_t>(order[static_cast<std::size_t>(i)]);
    c.weight[i] = W[old];
    c.penalty[i] = kappa_sum[old] / W[old];
    c.node[static_cast<std::size_t>(i)] = static_cast<int>(key[old] % np);
    c.cut[static_cast<std::size_t>(i)] = static_cast<int>(key[old] / np);
    c.x.row(i) = em.mesh.points.row(c.node[static_cast<std::size_t>(i)]);
  }
  c.G.resize(M, 3 * em.n);
  c.G.setFromTriplets(entries.begin(), entries.end());  // sums the tets around each node
  c.G.makeCompressed();
  if (problem.contact.friction_on) add_slip_rows(em, problem, cuts, c);
  return c;
}

void write_contact_operator(const ContactOperator& c, const std::string& dir) {
  write_general_matrix(c.G, join(dir, kContactGapFile));
  const long Q = c.points();
  SparseMatrix P(Q, 7);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (long q = 0; q < Q; ++q) {
    const double row[7] = {c.weight[q], c.penalty[q], c.x(q, 0), c.x(q, 1), c.x(q, 2),
                           static_cast<double>(c.node[static_cast<std::size_t>(q)]),
                           static_cast<double>(c.cut[static_cast<std::size_t>(q)])};
    for (int j = 0; j < 7; ++j) entries.emplace_back(static_cast<int>(q), j, row[j]);
  }
  P.setFromTriplets(entries.begin(), entries.end());
  write_general_matrix(P, join(dir, kContactPointsFile));
  if (!c.has_friction()) return;  // frictionless: the two files above only, as before friction
  write_general_matrix(c.T, join(dir, kContactSlipFile));
  SparseMatrix F(Q, 7);
  entries.clear();
  for (long q = 0; q < Q; ++q) {
    entries.emplace_back(static_cast<int>(q), 0, c.friction[q]);
    for (int j = 0; j < 6; ++j) entries.emplace_back(static_cast<int>(q), j + 1, c.tangents(q, j));
  }
  F.setFromTriplets(entries.begin(), entries.end());
  write_general_matrix(F, join(dir, kContactFrictionFile));
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
  c.node.resize(static_cast<std::size_t>(Q));
  c.cut.resize(static_cast<std::size_t>(Q));
  for (long q = 0; q < Q; ++q) {
    if (!(c.weight[q] > 0) || !(c.penalty[q] > 0) || !std::isfinite(c.weight[q]) || !std::isfinite(c.penalty[q]))
      throw Error(points_path + ": point " + std::to_string(q + 1) + " has a weight or penalty that is not positive");
    c.node[static_cast<std::size_t>(q)] = static_cast<int>(dense(q, 5));
    c.cut[static_cast<std::size_t>(q)] = static_cast<int>(dense(q, 6));
  }
  const std::string slip_path = join(dir, kContactSlipFile), friction_path = join(dir, kContactFrictionFile);
  if (!std::filesystem::exists(slip_path)) return c;  // frictionless
  c.T = read_matrix(slip_path);
  if (c.T.rows() != 2 * Q || c.T.cols() != dofs)
    throw Error(slip_path + ": " + std::to_string(c.T.rows()) + " x " + std::to_string(c.T.cols()) + ", expected " +
                std::to_string(2 * Q) + " x " + std::to_string(dofs) + " (two rows per row of " + kContactGapFile + ")");
  if (!std::filesystem::exists(friction_path)) throw Error(friction_path + ": missing (" + kContactSlipFile + " needs it)");
  const SparseMatrix F = read_matrix(friction_path);
  if (F.rows() != Q || F.cols() != 7)
    throw Error(friction_path + ": " + std::to_string(F.rows()) + " x " + std::to_string(F.cols()) + ", expected " +
                std::to_string(Q) + " x 7 (one row per row of " + kContactGapFile + ")");
  const Eigen::MatrixXd f = Eigen::MatrixXd(F);
  c.friction = f.col(0);
  c.tangents = f.rightCols(6);
  for (long q = 0; q < Q; ++q)
    if (!(c.friction[q] >= 0) || !std::isfinite(c.friction[q]))
      throw Error(friction_path + ": point " + std::to_string(q + 1) + " has a friction coefficient that is negative or not finite");
  return c;
}

bool has_contact_operator(const std::string& dir) { return std::filesystem::exists(join(dir, kContactGapFile)); }

}  // namespace xfem
