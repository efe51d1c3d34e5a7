// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/geometry/element_split.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

/// The contact pressure on each wound triangle of `split` (xfem-visualize --contact-pressure; the
/// cell array `contact_pressure` of wound.vtp, Pa): the mean over its three corners of the nodal
/// pressure (NP x C, read_contact_pressure of contact_pressure_file.h) interpolated with the
/// linear shape functions of the input tet holding the corner (split.point_tet), renormalised over
/// the tet's nodes that have a contact condition (an entry in the file: the sliver nodes merged
/// into their neighbours have none), on the cut the triangle lies on (the nearest one when the mesh
/// has several cuts); 0 where none of the tet's nodes has one.
std::vector<double> wound_contact_pressure(const SplitMesh& split, const EnrichedMesh& em, const SparseMatrix& nodal);

}  // namespace xfem
