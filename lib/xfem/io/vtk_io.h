// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

// Tetrahedral meshes and cut surfaces in VTK's formats and the common surface ones. Where each is:
//   tet_mesh_read.cpp    .vtu, legacy .vtk, standard input   tet_mesh_write.cpp  .vtu
//   surface_read.cpp     .vtp, .vtu, .vtk, .stl, .obj, .off  surface_write.cpp   .vtp, .vtu
//   tet_mesh_validate.cpp, surface_validate.cpp   the checks (and repairs) after reading
//   vtk_io_detail.h      what they share; vtk_legacy_check.cpp and vtk_xml_check.h check files
//                        before VTK parses them; gmsh .msh: gmsh_io.h
namespace xfem {

/// Reads a tetrahedral volume mesh from VTK XML `.vtu` or legacy `.vtk` (ASCII or binary) with all
/// its point, cell and field arrays, and validates it. A gmsh `.msh` goes to read_gmsh_tet_mesh.
/// Vertices, lines and triangles beside the tets (a mesher's output) are not part of the body:
/// triangles with a 1-component cell array "group" (or meshio's "gmsh:physical") join the named
/// set group_<value> (boundary_groups.h); points in no tet are then dropped. Throws xfem::Error naming the file and the
/// first problem: unreadable file, no tets, a cell that is not a tet (named with its index and VTK
/// type), a point index out of range, a non-finite coordinate, zero-volume tets (counted).
/// Inverted tets are reoriented (nodes 1 and 2 swapped); each fix adds a line to `warnings`.
TetMesh read_tet_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// Checks what read_tet_mesh checks on an in-memory mesh (`name` is used in messages). Returns
/// the number of inverted tets it reoriented.
int validate_tet_mesh(TetMesh& mesh, const std::string& name, std::vector<std::string>* warnings);

/// How the VTK XML writers compress their appended binary data (docs/FORMATS.md, "Conventions"):
///   ZLib  zlib level 1, what every tool writes;
///   LZ4   VTK's vtkLZ4DataCompressor: written ~9x faster than zlib level 1, files ~1.25x larger;
///         read by VTK >= 8.1, so ParaView >= 5.5 (xfem-sweep's frames, written every step);
///   None  uncompressed.
enum class Compression { ZLib, LZ4, None };
/// The compression of a tool's `--compression` value: "zlib", "lz4" or "none". Throws xfem::Error
/// for another name.
Compression compression_named(const std::string& name);

/// Writes `mesh` as VTK XML `.vtu` (appended raw binary, zlib-compressed unless told), atomically.
void write_tet_mesh(const TetMesh& mesh, const std::string& path, Compression compression = Compression::ZLib);

/// Reads a triangulated surface (a cut) from `.vtp`, `.vtu` or legacy `.vtk` (POLYDATA or
/// UNSTRUCTURED_GRID of triangles), `.stl` (coincident points merged), `.obj`, `.off` or gmsh
/// `.msh` (its triangles, gmsh_io.h), and
/// validates it: triangles only (else the first bad cell is named), indices in range, finite
/// coordinates, no empty surface, no edge shared by more than two triangles. Zero-area triangles
/// are dropped and triangles whose orientation disagrees with their neighbours' are flipped (the
/// lowest-numbered triangle of each connected piece keeps its orientation), each with a warning;
/// a surface that cannot be oriented consistently (a Moebius strip) is an error.
TriangleMesh read_triangle_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// Checks and repairs an in-memory surface as read_triangle_mesh does.
void validate_triangle_mesh(TriangleMesh& mesh, const std::string& name, std::vector<std::string>* warnings);

/// Writes `mesh` as VTK XML `.vtp`, or `.vtu` (an unstructured grid of triangles), atomically.
void write_triangle_mesh(const TriangleMesh& mesh, const std::string& path,
                         Compression compression = Compression::ZLib);

}  // namespace xfem
