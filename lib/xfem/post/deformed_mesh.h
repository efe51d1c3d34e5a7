// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>

#include "xfem/geometry/element_split.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/material_law.h"
#include "xfem/integrate/tet_materials.h"

namespace xfem {

/// A displacement field u(x) in metres, evaluated in input tet `tet` on side `side` of the cut
/// (+1 / -1; 0 = decide with the cut), and its gradient du_i/dx_j (row i, column j).
struct DisplacementField {
  std::function<Eigen::Vector3d(int tet, const Eigen::Vector3d& x, int side)> value;
  std::function<Eigen::Matrix3d(int tet, const Eigen::Vector3d& x, int side)> gradient;
};

/// The X-FEM solution u (3N scalars, 3k + i) on `em` as a field: displacement_at and
/// displacement_gradient_at of enriched_basis.h. Keeps references to `em` and `u`.
DisplacementField xfem_displacement(const EnrichedMesh& em, const Eigen::VectorXd& u);

/// The deformed body for viewing (docs/FORMATS.md, "deformed.vtu" and "wound.vtp").
struct DeformedBody {
  /// The split mesh at its undeformed positions with point array `displacement` (Float64 x 3, m)
  /// and `side` (Int32, the side it was evaluated on), cell arrays `cut_class` (Int32, of the input
  /// tet), `side` (Int32, +1 / -1 piece above / below the cut, 0 whole or joined ahead of the
  /// front), `parent` (Int64, input tet), `strain` (Float64 x 6: xx, yy, zz, xy, yz, xz, the
  /// symmetric small-strain tensor, dimensionless), `stress` (Float64 x 6, same order, Pa) and
  /// `von_mises` (Float64, Pa). Strain and stress are the X-FEM field's at the cell's centroid, on
  /// the cell's side; for a material model other than linear, the Green-Lagrange strain and the
  /// Cauchy stress (cell_stress.h).
  TetMesh volume;
  /// det F = det(I + grad u) per cell of `volume`, at its centroid (not written: deformed_volume.h
  /// counts the inverted cells with it).
  std::vector<double> det_F;
  /// The wound: both faces of the cut inside the body, point array `displacement`, cell array
  /// `side` (Int32 +1 / -1).
  TriangleMesh wound;
};

/// Evaluates `u` on the split mesh: every point copy with its own side, so the two faces of the
/// cut move apart by the solution's jump. E (Pa) > 0 and nu in (-1, 0.5) give the stress
/// (Hooke: sigma = lambda tr(eps) I + 2 mu eps, lambda and mu of DESIGN.md; for `model` other
/// than linear, the model's Cauchy stress, 0 in inverted cells: cell_stress.h). `cut_class` is per
/// input tet; `u` is evaluated from several threads at once (parallel_for.h), so it must not
/// modify shared state. `progress` (optional) is called with the fraction done. Throws xfem::Error for a bad
/// E or nu, or a non-finite displacement (naming the point and its input tet).
/// `wound_offset`: the wound's points are moved by this fraction of the body's diagonal along its
/// faces' outward normal, so that it does not z-fight with deformed.vtu's cut faces (0 keeps the
/// cut's exact geometry, e.g. to measure its area).
DeformedBody deformed_body(const SplitMesh& split, const std::vector<int>& cut_class, const DisplacementField& u,
                           double E, double nu, const std::function<void(double)>& progress = {},
                           double wound_offset = 1e-4, MaterialModel model = MaterialModel::Linear);
/// The same with each input tet's own material (problem.json `materials`): a cell's stress is its
/// parent tet's law's (materials.law(parent)).
DeformedBody deformed_body(const SplitMesh& split, const std::vector<int>& cut_class, const DisplacementField& u,
                           const TetMaterials& materials, const std::function<void(double)>& progress = {},
                           double wound_offset = 1e-4);

/// How far the cut opened: over the points of the cut present once per side (same position),
/// the jump d = u(x, +1) - u(x, -1) and its normal part d . n(x), n the cut's unit normal there
/// (from `normal`, e.g. CutSurface::unit_normal of the closest triangle). Positive = open.
struct CutOpening {
  long pairs = 0;                  ///< points duplicated on the cut
  double min_normal = 0, max_normal = 0, mean_normal = 0;  ///< d . n, m
  double max_jump = 0;             ///< max |d|, m
};
CutOpening cut_opening(const SplitMesh& split, const DataArray& displacement,
                       const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& normal);

/// Von Mises stress of a symmetric stress tensor, Pa.
double von_mises(const Eigen::Matrix3d& stress);

}  // namespace xfem
