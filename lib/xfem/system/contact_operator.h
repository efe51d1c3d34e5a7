// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/problem.h"

namespace xfem {

/// What xfem-solve needs for frictionless contact between a cut's faces (docs/METHOD.md
/// "Contact"; docs/FORMATS.md "system/"): the gap g_q = n_q . [[u]](x_q) at every integration
/// point q of the faces of the cuts in contact, as a row of a sparse matrix acting on u (3N).
/// The gap is measured in the reference configuration (small sliding): both faces start together.
struct ContactOperator {
  SparseMatrix G;                  ///< Q x 3N: g = G u, metres; row q holds n_q . [[Phi]](x_q)
  Eigen::VectorXd weight;          ///< Q: the point's area, m^2
  Eigen::VectorXd penalty;         ///< Q: kappa_q = problem.contact.penalty E / h_t, Pa/m (h_t: the tet's longest edge)
  Eigen::MatrixXd x;               ///< Q x 3: positions, metres
  std::vector<int> tet, cut;       ///< Q: the mesh tet and the cut of each point
  long points() const { return static_cast<long>(weight.size()); }
};

/// The file names in a system directory: contact_gap.mtx (G, `coordinate real general`, Q x 3N)
/// and contact_points.mtx (`coordinate real general`, Q x 7: weight, penalty, x, y, z, tet, cut).
constexpr const char* kContactGapFile = "contact_gap.mtx";
constexpr const char* kContactPointsFile = "contact_points.mtx";

/// The gap operator of the cuts problem.contact applies to, with problem.order's face rule
/// (cut_face_points). Rows of points whose jump is zero on every DOF (none in practice) are kept:
/// their gap is 0 whatever u. Throws xfem::Error for a contact cut the mesh does not have.
ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem);

/// Writes both files into `dir` (atomically each); reads them back, checking their sizes against
/// each other and `dofs` = 3N (xfem::Error naming the file).
void write_contact_operator(const ContactOperator& c, const std::string& dir);
ContactOperator read_contact_operator(const std::string& dir, long dofs);

/// Whether the system directory `dir` holds a contact operator.
bool has_contact_operator(const std::string& dir);

}  // namespace xfem
