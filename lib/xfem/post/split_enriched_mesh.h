// SPDX-License-Identifier: MIT
#pragma once

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/geometry/element_split.h"

namespace xfem {

/// The split mesh of xfem-visualize for an enriched mesh, whatever its cuts:
///   - no cut surface (em.cut null: a plain mesh, or no --cut given): unsplit_mesh on em.side;
///   - one cut: split_mesh of element_split.h on em.side, em.cut_class, the cut and its front;
///   - several cuts (em.cuts): uncut tets whole on the input's nodes, every piece of a cut tet
///     (split_cut_elements) a tet on its own 4 points, evaluated with its side code (side_codes.h);
///     the wound: the pieces' faces lying on a cut where the material opens.
/// The one cut keeps its own implementation: it conforms (neighbours share the points on the cut)
/// and carries +1 / -1 sides, which the pieces of several cuts, with side codes, do not.
SplitMesh split_mesh(const EnrichedMesh& em);

}  // namespace xfem
