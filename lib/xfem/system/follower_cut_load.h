// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/problem.h"

namespace xfem {

/// The pressures of problem.json `cut_loads` as follower loads at large deformation (xfem-newton;
/// docs/METHOD.md "Contact and pressure on the cut's faces at large deformation"): the pressure
/// acts on the DEFORMED faces. By Nanson's formula n da = J F^{-T} N dA = cof(F) N dA, so on the
/// face above the cut (H = +1, outward normal -n) the force is p cof(F+) n dA and on the face below
/// (outward normal +n) it is -p cof(F-) n dA, F+ and F- each face's own deformation gradient (the
/// faces move apart). Its work on the basis function Phi_e:
///   f_e(u) = sum_q w_q p (cof(F+_q) n_q Phi_e^+(x_q) - cof(F-_q) n_q Phi_e^-(x_q)),
/// on the reference faces' points q (cut_face_points, problem.order's rule). At u = 0 it is
/// add_cut_loads' pressure term exactly. The tractions of cut_loads stay dead loads in the
/// reference configuration (add_cut_loads with the pressures removed: dead_cut_tractions).
struct FollowerCutLoad {
  struct Point {
    int tet = -1;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< reference unit normal n (towards H = +1)
    double wp = 0.0;                                   ///< weight times pressure, N
    /// The tet's basis on the face above ([0]) and below ([1]): values and reference gradients.
    Eigen::VectorXd N[2];
    Eigen::Matrix<double, Eigen::Dynamic, 3> dN[2];
  };
  std::vector<Point> points;  ///< every loaded point, tets in increasing order per load
  double area = 0.0;          ///< the reference area loaded, m^2
  bool empty() const { return points.empty(); }
};

/// The points of every cut_loads entry with a non-zero pressure. Throws xfem::Error as add_cut_loads.
FollowerCutLoad follower_cut_load(const EnrichedMesh& em, const Problem& problem);

/// Adds s f(u) to f (3N). With `K` non-null, appends to *K (triplets of the full matrix, both
/// triangles) the SYMMETRIC PART of the load stiffness -s df/du (the exact one is not symmetric;
/// Newton with it converges linearly where the load dominates), within each tet's DOFs.
void add_follower_forces(const EnrichedMesh& em, const FollowerCutLoad& load, const Eigen::VectorXd& u, double s,
                         Eigen::VectorXd& f, std::vector<Eigen::Triplet<double, int>>* K);

/// problem.cut_loads' tractions only (pressures removed), as add_cut_loads: dead loads on the
/// reference faces. Adds them to f.
void add_dead_cut_tractions(const EnrichedMesh& em, const Problem& problem, Eigen::VectorXd& f);

/// The total force the follower pressure puts on the faces above (H = +1) of cut k at u, N: sum_q
/// w_q p cof(F+_q) n_q (for checks: p times the deformed vector area of that face).
Eigen::Vector3d follower_face_force(const FollowerCutLoad& load, const EnrichedMesh& em, const Eigen::VectorXd& u);

}  // namespace xfem
