// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/tet_materials.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/problem.h"

namespace xfem {

/// What xfem-solve needs for frictionless contact between a cut's faces (docs/METHOD.md
/// "Contact"; docs/FORMATS.md "system/"): one contact condition per mesh node i whose shape
/// function's support meets the faces of a cut k in contact (a "contact node"), on the weighted
/// (mortar-like) gap
///   g_i = sum_q w_q N_i(x_q) g_q / W_i,   W_i = sum_q w_q N_i(x_q),
/// the sums over the integration points q of cut k's faces in the tets around node i (N_i the
/// linear shape function, g_q = n_q . [[u]](x_q) the normal gap at the point): a length, the gap
/// averaged over the part of the cut near node i. Row i of G holds it as a combination of the
/// DOFs of every cut tet around the node. The gap is measured in the reference configuration
/// (small sliding): both faces start together.
struct ContactOperator {
  SparseMatrix G;                  ///< M x 3N: g = G u, metres; row i the weighted gap of contact node i
  Eigen::VectorXd weight;          ///< M: W_i, the area the node stands for, m^2 (sum: the cuts' area)
  Eigen::VectorXd penalty;         ///< M: kappa_i, Pa/m: the points' kappa_q = penalty E_t / h_t averaged with w_q N_i
  Eigen::MatrixXd x;               ///< M x 3: the node's position, metres
  std::vector<int> node, cut;      ///< M: the mesh node and the cut of each condition
  /// Coulomb friction (problem.json "contact": {"friction": mu}; docs/METHOD.md "Friction"),
  /// empty without: row 2i + a of T the weighted tangential jump of contact node i along its
  /// tangent t_a,
  ///   s_ia = sum_q w_q N_i(x_q) t_a^T (I - n_q n_q^T) [[u]](x_q) / W_i,
  /// the same points and shares as G_i (t_1, t_2 unit, orthogonal to each other and to the node's
  /// averaged normal sum_q w_q N_i n_q), a length: the faces' slip averaged near the node.
  SparseMatrix T;                  ///< 2M x 3N, metres
  Eigen::MatrixXd tangents;        ///< M x 6: t_1, t_2 of each contact node
  Eigen::VectorXd friction;        ///< M: mu of the node's cut (>= 0)
  long points() const { return static_cast<long>(weight.size()); }
  bool has_friction() const { return friction.size() > 0; }
};

/// The file names in a system directory: contact_gap.mtx (G, `coordinate real general`, M x 3N)
/// and contact_points.mtx (`coordinate real general`, M x 7: weight, penalty, x, y, z, node, cut).
constexpr const char* kContactGapFile = "contact_gap.mtx";
constexpr const char* kContactPointsFile = "contact_points.mtx";
/// With friction only: contact_slip.mtx (T, `coordinate real general`, 2M x 3N) and
/// contact_friction.mtx (`coordinate real general`, M x 7: mu, t_1 (3), t_2 (3)).
constexpr const char* kContactSlipFile = "contact_slip.mtx";
constexpr const char* kContactFrictionFile = "contact_friction.mtx";

/// The contact conditions of the cuts problem.contact applies to, from problem.order's face rule
/// (cut_face_points), conditions sorted by cut, then node. kappa_q uses the material of the
/// point's tet (`materials`, problem.json `materials` per region: E of that tet's law). Nodes whose
/// W_i is zero (the cut passes through the node's support only where N_i = 0) get no condition.
/// With problem.contact.friction_on, also T, tangents and friction (above). Throws xfem::Error
/// for a contact cut the mesh does not have.
ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem, const TetMaterials& materials);
/// The same with problem.json's `material` everywhere.
ContactOperator contact_operator(const EnrichedMesh& em, const Problem& problem);

/// Writes both files into `dir` (atomically each; with friction the two friction files too);
/// reads them back (the friction files when contact_slip.mtx is there), checking their sizes
/// against each other and `dofs` = 3N, and mu >= 0 (xfem::Error naming the file).
void write_contact_operator(const ContactOperator& c, const std::string& dir);
ContactOperator read_contact_operator(const std::string& dir, long dofs);

/// Writes `A` in Matrix Market `coordinate real general` form, every stored entry (explicit zeros
/// too), column after column, values in round-trip form. Atomic.
void write_general_matrix(const SparseMatrix& A, const std::string& path);

/// Whether the system directory `dir` holds a contact operator.
bool has_contact_operator(const std::string& dir);

}  // namespace xfem
