// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <string>

#include "xfem/core/mesh.h"

namespace xfem {

/// Unstructured tetrahedral meshes by Delaunay refinement (CGAL Mesh_3, sequential, with CGAL's
/// fixed default seeds: the same arguments give the same mesh bit for bit).
///
/// `size` H (metres) is the target edge length: features (sharp edges) are split into segments
/// of at most H, surface Delaunay balls and tet circumradii are bounded by 0.72 H (calibrated
/// so that the mean edge length is about H: 0.98 H on the beam), surface facets keep angles
/// >= 25 degrees and tets a radius-edge ratio <= 3, then slivers are exuded (no perturbation).
/// Curved surfaces are followed to within 0.05 H.
///
/// The result keeps only the tets of the domain and the vertices they use, validated and
/// positively oriented (validate_tet_mesh), without arrays, numbered in space order
/// (spatially_ordered, mesh_ordering.h: points and tets along a Hilbert curve).
/// All throw xfem::Error when `size` is not positive or finite, or the mesh comes out empty.

/// The box [lo, hi] with its 8 corners and 12 edges kept sharp (they are protected features:
/// the corners are mesh vertices, the edges are unions of mesh edges). Boundary vertices lie
/// exactly on the box's faces (snapped from within 1e-9 of the box size, rounding only).
/// Throws also for an empty box.
TetMesh unstructured_box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double size);

/// The body { p : f(p) < 0 } inside the sphere of `bounding_radius` around the origin, which
/// must contain the body (f(origin) < 0 and f > 0 on the sphere are required by Mesh_3: the
/// origin is checked). `f` should be smooth and its zero set a closed surface (no sharp edges
/// are kept). Units: metres.
TetMesh implicit_mesh(const std::function<double(const Eigen::Vector3d&)>& f, double bounding_radius, double size);

/// The volume enclosed by the closed triangle surface `surface` (as read by
/// read_triangle_mesh), with its sharp edges (dihedral angle deviating more than 60 degrees
/// from flat) kept. `name` names the surface in messages. Throws xfem::Error when the surface
/// is not closed (naming the count of boundary edges and one of them) or not manifold.
TetMesh surface_mesh(const TriangleMesh& surface, double size, const std::string& name);

}  // namespace xfem
