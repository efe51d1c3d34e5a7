// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

/// The contact pressure on one cut's faces as xfem-solve computed it (its --contact-pressure file,
/// read by read_contact_pressure of solve/contact_pressure_file.h): one value per contact node of
/// that cut, the multipliers' space of docs/METHOD.md "Contact".
struct FaceContactPressure {
  std::vector<double> pressure;  ///< per mesh node, Pa (>= 0; 0 where contact_node is 0)
  std::vector<char> contact_node;  ///< per mesh node: 1 for a contact node of the cut (an entry of the file)
};

/// Column `cut` of the nodal pressure `nodal` (NP x C) read from `path`. Throws xfem::Error naming
/// `path` when it has no column for that cut or no contact node on it.
FaceContactPressure face_contact_pressure(const SparseMatrix& nodal, int cut, const std::string& path);

/// The pressure at x on the faces, in tet t: p(x) = sum_i s_i(x) p_i over the tet's contact nodes
/// i, s_i = N_i / (sum of N_j over them), N the tet's linear shape functions. These are the shares
/// with which the weighted gap g_i takes the face points (contact_operator.h): a node that sees
/// only slivers of the cut is no contact node, its share goes to the tet's other nodes in
/// proportion to their N, so a uniform nodal pressure is carried exactly, as the solve carried it.
/// 0 in a tet without a contact node.
double face_contact_pressure_at(const FaceContactPressure& p, const TetMesh& mesh, int t, const Eigen::Vector3d& x);

}  // namespace xfem
