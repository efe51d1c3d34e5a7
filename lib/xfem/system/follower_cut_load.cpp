// SPDX-License-Identifier: MIT
#include "xfem/system/follower_cut_load.h"

#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/integrate/cut_face_quadrature.h"
#include "xfem/integrate/material_law.h"
#include "xfem/system/cut_loads.h"

namespace xfem {
namespace {

// The side arguments of enriched_basis for the faces above and below cut k at x (as basis_jump).
void face_sides(const EnrichedMesh& em, int k, const Eigen::Vector3d& x, int& above, int& below) {
  above = 1, below = -1;
  if (em.cuts.empty()) return;
  const int K = static_cast<int>(em.cuts.size());
  int sides[kMaxCuts];
  for (int j = 0; j < K; ++j) sides[j] = j == k ? 1 : em.cuts[static_cast<std::size_t>(j)].cut->side(x);
  above = pack_sides(sides, K);
  sides[k] = -1;
  below = pack_sides(sides, K);
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

FollowerCutLoad follower_cut_load(const EnrichedMesh& em, const Problem& problem) {
  FollowerCutLoad load;
  if (problem.cut_loads.empty()) return load;
  Problem pressures = problem;
  for (CutLoad& c : pressures.cut_loads) c.traction.setZero();
  // add_cut_loads' checks (the cut exists, its faces meet an enriched element), on a scratch vector.
  Eigen::VectorXd scratch_f = Eigen::VectorXd::Zero(3 * em.n);
  add_cut_loads(em, pressures, scratch_f);
  BasisAt basis;
  for (const CutLoad& c : problem.cut_loads) {
    if (c.pressure == 0.0) continue;
    for (const CutFacePoint& q : cut_face_points(em, c.cut, problem.order)) {
      FollowerCutLoad::Point p;
      p.tet = q.tet;
      p.normal = q.normal;
      p.wp = q.weight * c.pressure;
      int side[2];
      face_sides(em, c.cut, q.x, side[0], side[1]);
      for (int f = 0; f < 2; ++f) {
        enriched_basis(em, q.tet, q.x, side[f], basis);
        p.N[f] = basis.N;
        p.dN[f] = basis.dN;
      }
      load.area += q.weight;
      load.points.push_back(std::move(p));
    }
  }
  return load;
}

void add_follower_forces(const EnrichedMesh& em, const FollowerCutLoad& load, const Eigen::VectorXd& u, double s,
                         Eigen::VectorXd& f, std::vector<Eigen::Triplet<double, int>>* K) {
  std::vector<Eigen::Matrix3d> block;
  std::vector<Eigen::Vector3d> v[2];
  for (const FollowerCutLoad::Point& p : load.points) {
    const long begin = em.offsets[p.tet];
    const int size = em.size(p.tet);
    Eigen::Matrix3d F[2];
    for (int side = 0; side < 2; ++side) {
      F[side].setIdentity();
      for (int e = 0; e < size; ++e) F[side] += u.segment<3>(3 * em.dofs[begin + e]) * p.dN[side].row(e);
    }
    // The face above is pushed along +cof(F+) n, the face below along -cof(F-) n.
    const Eigen::Vector3d a[2] = {s * p.wp * (cofactor(F[0]) * p.normal), -s * p.wp * (cofactor(F[1]) * p.normal)};
    for (int e = 0; e < size; ++e)
      f.segment<3>(3 * em.dofs[begin + e]) += p.N[0][e] * a[0] + p.N[1][e] * a[1];
    if (!K) continue;
    // d(cof(F) n) = du_b x v_b with v_b = F (n x grad Phi_b) (from cof(F) n = eps eps F F n / 2),
    // so d f_a / d u_b = sum_sides +-s w p Phi_a (-[v_b]x), and the stiffness -df/du has the blocks
    // k_ab = s w p (Phi_a^+ [v_b^+]x - Phi_a^- [v_b^-]x); symmetrised: (k_ab + k_ba^T) / 2.
    for (int side = 0; side < 2; ++side) {
      v[side].resize(static_cast<std::size_t>(size));
      for (int e = 0; e < size; ++e)
        v[side][static_cast<std::size_t>(e)] = F[side] * p.normal.cross(p.dN[side].row(e).transpose());
    }
    const double c = s * p.wp;
    for (int a_ = 0; a_ < size; ++a_)
      for (int b = 0; b < size; ++b) {
        const Eigen::Matrix3d kab = c * (p.N[0][a_] * skew(v[0][static_cast<std::size_t>(b)]) -
                                         p.N[1][a_] * skew(v[1][static_cast<std::size_t>(b)]));
        const Eigen::Matrix3d kba = c * (p.N[0][b] * skew(v[0][static_cast<std::size_t>(a_)]) -
                                         p.N[1][b] * skew(v[1][static_cast<std::size_t>(a_)]));
        const Eigen::Matrix3d sym = 0.5 * (kab + kba.transpose());
        const int ra = static_cast<int>(3 * em.dofs[begin + a_]), cb = static_cast<int>(3 * em.dofs[begin + b]);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (sym(i, j) != 0.0) K->emplace_back(ra + i, cb + j, sym(i, j));
      }
  }
}

void add_dead_cut_tractions(const EnrichedMesh& em, const Problem& problem, Eigen::VectorXd& f) {
  Problem tractions = problem;
  for (CutLoad& c : tractions.cut_loads) c.pressure = 0.0;
  add_cut_loads(em, tractions, f);
}

Eigen::Vector3d follower_face_force(const FollowerCutLoad& load, const EnrichedMesh& em, const Eigen::VectorXd& u) {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const FollowerCutLoad::Point& p : load.points) {
    const long begin = em.offsets[p.tet];
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    for (int e = 0; e < em.size(p.tet); ++e) F += u.segment<3>(3 * em.dofs[begin + e]) * p.dN[0].row(e);
    total += p.wp * (cofactor(F) * p.normal);
  }
  return total;
}

}  // namespace xfem
