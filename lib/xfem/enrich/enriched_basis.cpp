// SPDX-License-Identifier: MIT
#include "xfem/enrich/enriched_basis.h"

#include <string>

#include "xfem/enrich/branch_functions.h"
#include "xfem/core/error.h"
#include "xfem/enrich/heaviside.h"
#include "xfem/enrich/side_codes.h"

namespace xfem {

namespace {

/// enriched_basis for a mesh with several cuts: `code` is a side code (side_codes.h).
// `tip` (optional): x's crack-tip coordinates for the tet's branch cut (it holds one cut's branch
// DOFs at most), if the caller has them.
void several_cuts_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int code,
                        const TipCoordinates* tip, BasisAt& out) {
  const int K = static_cast<int>(em.cuts.size());
  const long begin = em.offsets[t];
  const int n = em.size(t);
  out.N.resize(n);
  out.dN.resize(n, 3);
  const Eigen::Vector4d N = shape.values(x);
  int s[kMaxCuts];
  bool have = false;
  auto sides = [&]() -> const int* {
    if (!have) {
      if (code >= 2) {
        for (int k = 0; k < K; ++k) s[k] = code_side(code, k);
      } else if (code == 0) {
        for (int k = 0; k < K; ++k) s[k] = em.cuts[k].cut->side(x);
      } else {
        throw Error("tet " + std::to_string(t) + ": side " + std::to_string(code) +
                    " is not a side code of a mesh with several cuts (0 or >= 2)");
      }
      have = true;
    }
    return s;
  };
  int node_sides[4][kMaxCuts];
  for (int l = 0; l < 4; ++l)
    for (int k = 0; k < K; ++k) node_sides[l][k] = em.cuts[k].side[em.mesh.tets(t, l)];
  bool cutting[kMaxCuts];
  for (int k = 0; k < K; ++k) cutting[k] = em.cuts[k].cut_class[t] != 0;
  int branch_cut = -1;
  BranchValues F;
  for (int e = 0; e < n; ++e) {
    const long dof = em.dofs[begin + e];
    const int l = em.local[begin + e];
    if (dof < em.np) {
      out.N[e] = N[l];
      out.dN.row(e) = shape.grad.row(l);
      continue;
    }
    if (dof < em.np + em.ns) {
      // x's sides, except for the cuts that do not cut the tet: the node's own (the enrichment of
      // a cut jumps only where it cuts; ahead of a front its plane extended is no discontinuity).
      int xs[kMaxCuts];
      // (For a node on the far side of the cut a junction cut ends on, x's own: see classify_cuts.)
      for (int k = 0; k < K; ++k) {
        const int i = em.cuts[k].ends_on;
        const bool far = i >= 0 && node_sides[l][i] != em.cuts[k].ends_side;
        xs[k] = cutting[k] || far ? sides()[k] : node_sides[l][k];
      }
      double psi = 0;
      bool found = false;
      for (int k = 0; k < K && !found; ++k) {
        const CutLayer& c = em.cuts[k];
        if (dof >= c.sign_first && dof < c.sign_first + c.ns) {
          psi = 0.5 * (cut_function(em, k, xs) - cut_function(em, k, node_sides[l]));
          found = true;
        }
      }
      for (std::size_t p = 0; p < em.products.size() && !found; ++p) {
        const ProductBlock& b = em.products[p];
        if (dof >= b.first && dof < b.first + b.count) {
          psi = 0.5 * (cut_function(em, b.a, xs) * cut_function(em, b.b, xs) -
                       cut_function(em, b.a, node_sides[l]) * cut_function(em, b.b, node_sides[l]));
          found = true;
        }
      }
      if (!found) throw Error("tet " + std::to_string(t) + ": DOF " + std::to_string(dof) + " is in no cut's block");
      out.N[e] = N[l] * psi;
      out.dN.row(e) = psi * shape.grad.row(l);
      continue;
    }
    const int k = branch_cut_of_dof(em, dof);
    if (k < 0) throw Error("tet " + std::to_string(t) + ": DOF " + std::to_string(dof) + " is in no cut's block");
    if (k != branch_cut) {
      const CutLayer& c = em.cuts[k];
      const TipCoordinates tc = tip ? *tip : c.front.coordinates(x);
      int side = 0;
      if (code >= 2)
        side = code_side(code, k);
      else if (tc.xa < 0)
        side = sides()[k];
      F = branch_functions(tc, side);
      branch_cut = k;
    }
    const int j = static_cast<int>((dof - em.np - em.ns) % 4);
    out.N[e] = N[l] * F.F[j];
    out.dN.row(e) = F.F[j] * shape.grad.row(l) + N[l] * F.dF.row(j);
  }
}

// enriched_basis of a mesh with one cut; `tip`: x's crack-tip coordinates if the caller has them.
void one_cut_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                   const TipCoordinates* tip, BasisAt& out) {
  const long begin = em.offsets[t];
  const int n = em.size(t);
  out.N.resize(n);
  out.dN.resize(n, 3);
  const Eigen::Vector4d N = shape.values(x);
  // H(x) and the ACTFs are computed once per point, and only if a DOF of this tet needs them.
  int h = side;
  bool have_branch = false;
  BranchValues F;
  for (int k = 0; k < n; ++k) {
    const long dof = em.dofs[begin + k];
    const int l = em.local[begin + k];
    if (dof < em.np) {
      out.N[k] = N[l];
      out.dN.row(k) = shape.grad.row(l);
    } else if (dof < em.np + em.ns) {
      if (h == 0) {
        if (!em.cut) throw Error("tet " + std::to_string(t) + ": sign DOF " + std::to_string(dof) + " needs the cut surface");
        h = em.cut->side(x);
      }
      const double psi = shifted_heaviside(h, em.side[em.mesh.tets(t, l)]);
      out.N[k] = N[l] * psi;
      out.dN.row(k) = psi * shape.grad.row(l);  // grad psi = 0 away from the cut
    } else {
      if (!have_branch) {
        if (em.front.empty())
          throw Error("tet " + std::to_string(t) + ": branch DOF " + std::to_string(dof) + " but the cut has no front");
        // Continuous crack-tip coordinates (crack_front.h); behind the front the point's side
        // decides the face (theta = +-pi on the cut), from the cut surface when not given.
        const TipCoordinates tc = tip ? *tip : em.front.coordinates(x);
        int branch_side = side;
        if (branch_side == 0 && tc.xa < 0 && em.cut) branch_side = h != 0 ? h : (h = em.cut->side(x));
        F = branch_functions(tc, branch_side);
        have_branch = true;
      }
      const int j = static_cast<int>((dof - em.np - em.ns) % 4);
      out.N[k] = N[l] * F.F[j];
      out.dN.row(k) = F.F[j] * shape.grad.row(l) + N[l] * F.dF.row(j);
    }
  }
}

}  // namespace

void enriched_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                    BasisAt& out) {
  if (!em.cuts.empty()) {  // several cuts: side is a side code (side_codes.h)
    several_cuts_basis(em, t, shape, x, side, nullptr, out);
    return;
  }
  one_cut_basis(em, t, shape, x, side, nullptr, out);
}

void enriched_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                    const TipCoordinates& tip, BasisAt& out) {
  if (!em.cuts.empty()) {
    several_cuts_basis(em, t, shape, x, side, &tip, out);
    return;
  }
  one_cut_basis(em, t, shape, x, side, &tip, out);
}

void enriched_basis(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side, BasisAt& out) {
  enriched_basis(em, t, tet_shape(em.mesh, t), x, side, out);
}

namespace {
// A plain tet (most tets of a body) has the linear field, evaluated below without the enriched
// basis's allocations, in the same order and so to the same bits. With several cuts
// enriched_basis dispatches elsewhere: not taken then.
bool linear_field(const EnrichedMesh& em, int t) { return em.cuts.empty() && em.plain(t); }
}  // namespace

Eigen::Vector3d displacement_at(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side,
                                const Eigen::VectorXd& u) {
  const long begin = em.offsets[t];
  if (linear_field(em, t)) {
    const Eigen::Vector4d N = tet_shape(em.mesh, t).values(x);
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) value += N[em.local[begin + k]] * u.segment<3>(3 * em.dofs[begin + k]);
    return value;
  }
  BasisAt b;
  enriched_basis(em, t, x, side, b);
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (int k = 0; k < b.N.size(); ++k) value += b.N[k] * u.segment<3>(3 * em.dofs[begin + k]);
  return value;
}

Eigen::Matrix3d displacement_gradient_at(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side,
                                         const Eigen::VectorXd& u) {
  const long begin = em.offsets[t];
  Eigen::Matrix3d grad = Eigen::Matrix3d::Zero();
  if (linear_field(em, t)) {
    const TetShape shape = tet_shape(em.mesh, t);
    for (int k = 0; k < 4; ++k) grad += u.segment<3>(3 * em.dofs[begin + k]) * shape.grad.row(em.local[begin + k]);
    return grad;
  }
  BasisAt b;
  enriched_basis(em, t, x, side, b);
  for (int k = 0; k < b.N.size(); ++k) grad += u.segment<3>(3 * em.dofs[begin + k]) * b.dN.row(k);
  return grad;
}

}  // namespace xfem
