// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// Spatial renumbering of tet meshes, so that points and tets near each other in space get
/// near ids and the later stages (pattern, scatter into K, per-tet tables) stay in cache.
/// Motivation and measurements: docs/PERFORMANCE.md, "Mesh ordering".

/// Position of the cell `q` (three coordinates of `bits` bits each, 1 <= bits <= 21) along the
/// 3D Hilbert curve through the 2^bits x 2^bits x 2^bits grid (Skilling's transpose
/// algorithm, AIP Conf. Proc. 707, 2004): a bijection onto [0, 2^(3 bits)) in which cells with
/// consecutive indices share a face. Throws xfem::Error for `bits` out of range or a
/// coordinate >= 2^bits.
std::uint64_t hilbert_index(std::array<std::uint32_t, 3> q, int bits);

/// The new-to-old permutations of a spatial order: point_order[new] = old, tet_order[new] = old.
struct MeshOrdering {
  std::vector<int> point_order;
  std::vector<int> tet_order;
};

/// Points sorted by the Hilbert index of their coordinates quantized to 2^21 cells per side of
/// the mesh's bounding cube (the bounding box's largest side; a point mesh of zero extent gets
/// index 0 everywhere), ties by old id; tets by the Hilbert index of their centroid on the same
/// grid, ties by old id. Deterministic: depends only on the coordinates and ids.
/// Throws xfem::Error when a tet names a point outside the mesh or a coordinate is not finite.
MeshOrdering spatial_ordering(const TetMesh& mesh);

/// `mesh` renumbered by `spatial_ordering`: the same points and tets (each tet keeps its
/// local vertex order, so its orientation), point and cell arrays permuted with them.
/// Field arrays are copied unchanged (they may hold ids: only use on meshes without such).
/// Throws also when a point or cell array does not have one tuple per point or tet (naming it).
TetMesh spatially_ordered(const TetMesh& mesh);

}  // namespace xfem
