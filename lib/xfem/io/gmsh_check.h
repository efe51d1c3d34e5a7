// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <string>

namespace xfem {

/// What gmsh knows of one of its element types: its name ("Tetrahedron 10": the shape, then the
/// node count), its dimension and its node count.
struct GmshElementType {
  std::string name;
  int dim = 0;
  int nodes = 0;
};

/// Checks the element sections of a .msh file before gmsh's library reads it. gmsh keeps the
/// elements of one shape in one entity in one list and reads that list as if all had the first
/// one's type: a 10-node tet among 4-node tets (or a 6-node triangle among 3-node ones) makes it
/// write out of bounds. So every entity must hold one element type per shape, and an element's
/// dimension must be its entity's. Reads MSH 2.x and 4.1, ASCII and binary (this machine's byte
/// order); other versions of a file with elements are refused. `element_type` gives gmsh's
/// properties of a type number and throws xfem::Error for an unknown one. A file with no
/// $Elements section is left to gmsh (whose message says what is wrong). Throws xfem::Error
/// "<path>: ..." naming the entity and the element types.
void check_gmsh_elements(const std::string& path, const std::function<GmshElementType(int type)>& element_type);

}  // namespace xfem
