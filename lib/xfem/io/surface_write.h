// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/mesh.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

/// write_triangle_mesh (vtk_io.h) with VTK field arrays as well, e.g. the inputs_fingerprint that
/// ties xfem-visualize's wound.vtp to its deformed.vtu (docs/FORMATS.md "wound.vtp").
void write_triangle_mesh(const TriangleMesh& mesh, const DataArrays& field_data, const std::string& path,
                         Compression compression = Compression::ZLib);

}  // namespace xfem
