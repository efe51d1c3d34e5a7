// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/mesh.h"

namespace xfem {

/// A reference solution sampled at its nodes (DESIGN.md, "The benchmark", RMS (5.1)).
struct ReferenceSamples {
  Points points;                            ///< N_ref x 3
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> displacement;  ///< N_ref x 3, metres
  std::vector<int> side;                    ///< per node: +1 / -1 for nodes on a cut face, else 0
};

/// A discrete solution to compare: u_h at x, evaluated on `side` of the cut (+1 / -1, 0 = no
/// preference). Returns nothing when x lies outside its mesh beyond the snapping radius; sets
/// `snapped` when x lay outside but within it (evaluated at the nearest tet).
using FieldAt = std::function<std::optional<Eigen::Vector3d>(const Eigen::Vector3d& x, int side, bool& snapped)>;

struct RmsReport {
  double rms = 0.0;           ///< sqrt(sum |u_ref - u_h|^2 / (3 N)), N the nodes compared
  double max = 0.0;           ///< max over nodes of |u_ref - u_h|
  long max_node = -1;         ///< reference node of the max
  double reference_rms = 0.0; ///< sqrt(sum |u_ref|^2 / (3 N)): the scale, for relative figures
  long compared = 0;          ///< reference nodes compared
  long snapped = 0;           ///< ... of which lay just outside the mesh (nearest tet used)
  long outside = 0;           ///< reference nodes outside the mesh beyond the radius: left out
};

/// The RMS and max error of `field` against `reference` over the reference nodes.
RmsReport rms_error(const ReferenceSamples& reference, const FieldAt& field);

/// u_h of a plain (CG-FEM) solution: nodal displacements of `mesh` (NP x 3) interpolated
/// linearly. Where the mesh has point array `cut_side` (nodes duplicated along a cut), a point
/// with side s != 0 is evaluated in a tet on that side. `radius`: snapping distance, metres.
FieldAt plain_field(const TetMesh& mesh, const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& u,
                    double radius);

/// u_h of an X-FEM solution (`u`: 3N scalars) with the enriched displacement of DESIGN.md,
/// evaluated on the point's side of the cut (side 0: decided by the cut surface).
FieldAt xfem_field(const EnrichedMesh& mesh, const Eigen::VectorXd& u, double radius);

}  // namespace xfem
