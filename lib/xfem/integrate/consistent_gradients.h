// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Dense>
#include <array>
#include <unordered_map>

#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// The integrals over tet t of the (regular) gradients of its branch basis functions N_l F_j,
/// by the divergence theorem: over the tet's four faces and the cut inside it,
///   integral_T grad(N_l F_j) = sum over faces f  integral_f N_l F_j n_f
///                             + integral_(cut in T) N_l (F_j below - F_j above) n_cut,
/// n_f the face's outer normal, n_cut the cut's normal (pointing to side +1).
///
/// Why: the Gauss rules of the branch functions (conforming_quadrature.h) integrate grad F, which
/// is singular like r^(-1/2) at the front, only approximately, so a linear field that the X-FEM
/// space contains exactly is reproduced only to ~1e-5 (the patch test fails). Shifting each branch
/// function's sampled gradient by a constant per element so that its integral is these values
/// (variationally consistent integration, Chen, Hillman and Rueter 2013) restores the patch test
/// to round-off: each face integral depends on the face alone (its points are made from the face's
/// corners in global node order, the face split along the cut's trace by the cut triangles that
/// cross it), so the two tets sharing a face cancel exactly, and the cut's term vanishes against a
/// stress with no traction on the cut. The integrands are bounded (F ~ sqrt(r)), so these
/// integrals are also more accurate than the volume rule's.
///
/// The integrals of N_v F_j over faces, kept between the two tets that share a face: the second
/// takes the first's numbers (with its outward normal reversed) instead of computing them again,
/// which halves the cost of the faces and makes the two contributions cancel bit for bit. Keyed by
/// the face's point ids and the front; an entry is dropped once both tets have used it.
class FaceIntegralCache {
 public:
  struct Key {
    std::array<long, 3> points;  ///< increasing
    const void* front;
    bool operator==(const Key& o) const { return points == o.points && front == o.front; }
  };
  struct Value {
    /// integral over the face of N_v F_j (row v: the face's v-th point in increasing id order,
    /// column j: the function), for the tet whose outward normal is +normal [0] or -normal [1]
    /// (they differ on a face lying on the cut, where each tet sees its own side's F)
    std::array<Eigen::Matrix<double, 3, 4>, 2> integral;
    int uses = 0;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = std::hash<const void*>()(k.front);
      for (long p : k.points) h = h * 1000003u ^ std::hash<long>()(p);
      return h;
    }
  };
  std::unordered_map<Key, Value, Hash> faces;
};

/// Returns |C| x 3 (rows in the order of the tet's C); rows of DOFs other than branch DOFs are 0.
/// `order`: Gauss points per direction on each face triangle (order^2 points per triangle).
/// `cache` (optional): face integrals shared with the tet's neighbours (FaceIntegralCache).
/// `near_order` > order (an experiment of issue 35, not used by the default): that many points per
/// direction instead on the faces the front passes near (closer to the face's centroid than its
/// longest edge), where F ~ sqrt(r) is nearly singular; decided by the face alone, so both tets of a
/// face agree. (The cut loads' face points, cut_face_points, do not follow it.)
/// `straight_angle_points` > 0: a face the front passes by in a straight line
/// (straight_front_face_integrals, decided by the face alone) is integrated exactly but for the
/// angle, with that many points per stretch (the rule of order n: straight_front_angle_points(n)).
Eigen::Matrix<double, Eigen::Dynamic, 3> branch_gradient_integrals(const EnrichedMesh& em, int t, int order,
                                                                   FaceIntegralCache* cache = nullptr,
                                                                   int near_order = 0, int straight_angle_points = 0);

}  // namespace xfem
