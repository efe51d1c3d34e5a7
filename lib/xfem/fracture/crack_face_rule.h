// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// One integration point on the faces of the evaluated cut (em.cut), for the interaction
/// integral's crack-face term (stress_intensity.h).
struct CrackFacePoint {
  int tet = -1;                                      ///< the mesh tet it lies in
  Eigen::Vector3d x = Eigen::Vector3d::Zero();       ///< metres, on the cut
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< the cut triangle's unit normal (towards H = +1)
  double weight = 0.0;                               ///< m^2, > 0
};

/// Integration points of em.cut's faces (the evaluated cut: select_front_of), tet by tet: the same
/// clipped geometry as the loads of cut_face_points (cut_face_quadrature.h): every cut triangle
/// clipped to every tet the cut splits (em.cut_class != 0) that has enriched DOFs, a polygon lying
/// in a face of the tet counted half in each of its two tets. The rule differs: the face term's
/// integrand, the jump of the auxiliary gradient, is singular like rho^-1/2 along the front (a line,
/// not a point), where the loads' integrand, the jump sqrt(rho) N_l, is finite. Each polygon is
/// fanned from its corner with the most front edges (else polygon_fan_apex), each fan triangle
/// (A, B, C) mapped by x = A + s (B - A) + s t (C - B) with s = sigma^2 and t graded towards both 0
/// and 1 (t = tau^2 / 2, 1 - tau^2 / 2): a rho^-1/2 singularity at A, along AB (t = 0) or along AC
/// (t = 1) becomes a smooth integrand, and `order` Gauss points per direction (per half in t)
/// converge fast. Linear integrands (areas, the weight q) are exact from order 3 on.
/// `wanted` (one flag per tet, or empty: all): the tets to integrate (xfem-front: those within the
/// domain radius of the front, where the weight q can be positive).
std::vector<CrackFacePoint> crack_face_rule(const EnrichedMesh& em, int order, const std::vector<char>& wanted = {});

}  // namespace xfem
