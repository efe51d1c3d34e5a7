// SPDX-License-Identifier: MIT
#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/several_cuts.h"

#include <string>

#include "xfem/enrich/branch_functions.h"
#include "xfem/core/error.h"
#include "xfem/enrich/heaviside.h"

namespace xfem {

void enriched_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                    BasisAt& out) {
  if (!em.cuts.empty()) {  // several cuts: side is a side code (several_cuts.h)
    several_cuts_basis(em, t, shape, x, side, out);
    return;
  }
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
        const TipCoordinates tc = em.front.coordinates(x);
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
