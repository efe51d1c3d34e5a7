// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "xfem/fracture/exact_fields.h"
#include "xfem/core/json_io.h"
#include "xfem/core/mesh.h"
#include "xfem/integrate/material_law.h"
#include "xfem/integrate/tet_materials.h"

namespace xfem {

/// Which mesh nodes a boundary condition acts on (problem.json, docs/FORMATS.md).
struct Selector {
  enum class Kind { HalfSpaces, Box, PointArray, Group, Boundary };
  Kind kind = Kind::HalfSpaces;
  /// HalfSpaces: node x selected when (x - point) . normal > 0 strictly for every plane (the
  /// convention of the paper's code). Normals need not be unit vectors.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> planes;  ///< (point, normal), metres
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  ///< Box: lo <= x <= hi (closed)
  std::string array;  ///< PointArray: nodes where this point array of the mesh is nonzero; Group: the group's name,
                      ///< its nodes are where the point array group_<name> is nonzero (boundary_groups.h)
  // Boundary ("boundary": true): the nodes of the mesh's boundary faces (boundary_nodes below).
};

/// A finite rigid motion prescribed node by node (problem.json "rotation"): the node at X moves
/// to R (X - centre) + centre + translation, R the rotation by `angle` about `axis`.
struct PrescribedRotation {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit vector
  double angle = 0.0;                               ///< radians
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

/// Prescribed displacement of the original nodal DOFs of the selected nodes (DESIGN.md: the
/// enriched DOFs stay free). A missing (null) component is left free.
/// Exactly one of `value`, `exact`, `rotation`, `value_array` says what each selected node gets:
/// the constant `value`; the exact field's displacement at the node, on the node's own side of
/// the cut (array `side`); the rigid motion `rotation`'s displacement at the node; the node's
/// tuple of the 3-component point array `value_array` (docs/FORMATS.md "problem.json"). The last
/// three fix every component.
struct DirichletCondition {
  std::string name;  ///< optional, for messages
  Selector selector;
  std::array<std::optional<double>, 3> value;  ///< metres
  std::optional<ExactField> exact;             ///< the exact field prescribed instead of `value`
  std::optional<PrescribedRotation> rotation;  ///< the rigid motion prescribed instead of `value`
  std::string value_array;                     ///< non-empty: the point array prescribed instead of `value`
  /// Whether the condition fixes component i (0, 1, 2 = x, y, z) of its nodes.
  bool fixes(int i) const { return exact || rotation || !value_array.empty() || value[static_cast<std::size_t>(i)]; }
  /// With `exact`: also prescribe the 4 branch DOF vectors of selected branch-enriched nodes
  /// (the field's crack-tip coefficients, WilliamsField::branch_coefficients) and shift the
  /// original DOF so that the discrete field equals the exact one at the node. false: the
  /// enriched DOFs stay free (DESIGN.md), an approximation at branch nodes.
  bool exact_enriched = false;
};

/// Traction on the boundary faces whose three nodes are all selected, Pa (N/m^2).
struct NeumannCondition {
  std::string name;
  Selector selector;
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
};

/// One entry of problem.json `materials`: the material of one region of the mesh (core/regions.h),
/// by id or by name (the mesh's region_names).
struct RegionMaterial {
  int id = -1;       ///< the region's id; -1 when it is named
  std::string name;  ///< the region's name; empty when it is given by id
  double E = 0.0, nu = 0.0;
  MaterialModel model = MaterialModel::Linear;  ///< problem.json's material.model when not given
};

/// A load on the two faces of a cut (problem.json "cut_loads"; docs/METHOD.md "Loads on the cut's
/// faces"): equal and opposite on the faces, so it acts through the jump [[u]] = u+ - u- only.
/// The face above (H = +1) is pushed by pressure p n + traction, the face below by the opposite:
/// its work is the integral over the cut of (p n + t) . [[u]], n the cut's unit normal.
struct CutLoad {
  int cut = 0;                                       ///< index of the cut (as given to xfem-classify)
  double pressure = 0.0;                             ///< Pa; > 0 pushes the faces apart
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();  ///< Pa, on the face above; minus it below
};

/// Frictionless contact between a cut's faces (problem.json "contact"; docs/METHOD.md "Contact"):
/// which cuts, and the penalty of the augmented Lagrangian.
struct ContactSettings {
  bool on = false;            ///< off by default
  std::vector<int> cuts;      ///< the cuts whose faces may touch; empty with `on`: every cut
  double penalty = 1e5;       ///< kappa = penalty * E / h (h the cut tet's longest edge), Pa/m
  /// Coulomb friction between the faces ("contact": {"friction": mu}, or one mu per cut of
  /// "cuts"; docs/METHOD.md "Friction"): given (even 0) turns the frictional solve on.
  bool friction_on = false;
  std::vector<double> friction;  ///< one mu for every cut (size 1), or one per entry of `cuts`
  /// The friction coefficient of cut k (0 without friction or for a cut out of contact).
  double friction_of(int k) const {
    if (!friction_on || !applies_to(k)) return 0.0;
    if (friction.size() == 1) return friction[0];
    for (std::size_t i = 0; i < cuts.size(); ++i)
      if (cuts[i] == k) return friction[i];
    return 0.0;
  }
  /// Whether the faces of cut k may touch.
  bool applies_to(int k) const {
    if (!on) return false;
    if (cuts.empty()) return true;
    for (int c : cuts)
      if (c == k) return true;
    return false;
  }
};

/// A static linear-elastic problem: the contents of problem.json (docs/FORMATS.md).
struct Problem {
  std::string file;     ///< where it was read from, for messages
  double E = 0.0;       ///< Young's modulus, Pa, > 0
  double nu = 0.0;      ///< Poisson's ratio, in (-1, 0.5)
  /// material.model: the law of the nonlinear solve (material_law.h); the linear tools refuse any
  /// other than Linear (require_linear_material).
  MaterialModel model = MaterialModel::Linear;
  /// materials: the regions with a material of their own; E, nu and model above are the material
  /// of every other tet. Read without the mesh: tet_materials() checks the regions.
  std::vector<RegionMaterial> materials;
  /// load_steps: the nonlinear solve applies the loads in this many equal steps (>= 1); the
  /// linear tools ignore it.
  int load_steps = 1;
  int points = 30;      ///< oversampling points requested per enriched tet (paper: 30 for the beam)
  int refine = 0;       ///< levels of refinement at the cut in cut tets (0 = the paper's rule)
  /// How tets with enriched DOFs are integrated: the paper's oversampling (points, refine), or the
  /// cut-conforming, front-singular rule of conforming_quadrature.h with `order` Gauss points per
  /// direction of every sub-tet.
  enum class Rule { Oversampling, Conforming };
  Rule rule = Rule::Conforming;
  int order = 3;        ///< conforming rule: Gauss points per direction (1..20) where branch functions live
  /// Conforming rule: the blocks without branch functions in closed form from the side volumes
  /// and the branch functions' cross terms from one sum per side (closed_form_stiffness.h; the
  /// default, integration.rule "conforming"), or every block from the points (integration.rule
  /// "pieces": the rule before issue 35, the same numbers up to round-off).
  bool closed_form = true;
  /// Conforming rule, closed form: the branch functions' points laid out by TetRuleLayout::graded()
  /// (integration.rule "graded"; `order` unused) instead of the uniform rule of `order`.
  bool graded = false;
  /// Conforming rule, closed form: the branch functions' points laid out by TetRuleLayout::uniform(order)
  /// with the consistent shift on `order` face points: the rule of order n before issue 35 (xfem-assemble
  /// --rule uniform, for comparisons; not a problem.json rule).
  bool uniform = false;
  /// Conforming rule, closed form: the branch functions' points laid out by TetRuleLayout::fast()
  /// (xfem-assemble --rule fast, issue 35: fewer points where the integrand is smooth; `order` unused;
  /// not a problem.json rule).
  bool fast = false;
  std::vector<DirichletCondition> dirichlet;
  std::vector<NeumannCondition> neumann;
  Eigen::Vector3d body_force = Eigen::Vector3d::Zero();  ///< N/m^3
  std::vector<CutLoad> cut_loads;  ///< loads on the cuts' faces (cut indices checked against the mesh later)
  ContactSettings contact;         ///< contact between the cuts' faces (off by default)
};

/// Refuses a problem whose cut_loads or contact name a cut the mesh does not have: throws
/// xfem::Error "<file>: cut_loads[1].cut is 2, but the mesh has 1 cut (indices 0..0)".
void check_cut_indices(const Problem& problem, int cuts);

/// Reads and validates problem.json. Throws xfem::Error with one line naming the file and the
/// item: unknown key, missing field, wrong type, E <= 0, nu outside (-1, 0.5), points < 1, a
/// refine outside 0..8, a rule other than "oversampling" / "conforming" / "graded" / "pieces", an order outside 1..20, a zero normal, an empty box,
/// an unknown material.model, a `materials` entry with a region that is neither a non-negative
/// integer nor a non-empty name, bad E / nu / model, or a region listed twice (the same id or
/// name), a load_steps outside 1..1000000, e.g. "problem.json: material.E must be positive, got -3".
Problem read_problem(const std::string& path);
/// The same from parsed JSON; `file` names it in messages.
Problem parse_problem(const Json& j, const std::string& file);

/// Parses an exact field (docs/FORMATS.md "Exact fields"): {"williams": {...}} or {"rigid": {...}}.
/// `path` locates it in messages ("dirichlet[0].exact"); `material` (E, nu) fills a Williams
/// field's E and nu when they are not given (problem.json), else they are required.
/// Throws xfem::Error "<file>: <path>... <problem>" like parse_problem.
ExactField parse_exact_field(const Json& j, const std::string& file, const std::string& path,
                             const std::optional<std::pair<double, double>>& material = std::nullopt);
/// Reads a JSON file holding one exact field (xfem-rmserror --exact).
ExactField read_exact_field(const std::string& path);

/// Ids of the nodes `selector` selects, increasing. `what` names the condition in messages, e.g.
/// "problem.json: dirichlet[1] ('pulled edge')". Throws xfem::Error "<what> selects no node", or
/// when a named point array is missing or has more than one component, or a group is unknown
/// ("<what>: the mesh has no group 'lid' (its groups: 'fixed', 'pulled')").
std::vector<int> select_nodes(const Selector& selector, const TetMesh& mesh, const std::string& what);

/// Ids of the nodes of the mesh's boundary faces (a face of exactly one tet), increasing: the
/// "boundary" selector. A cut is not part of the mesh, so its faces are not boundary faces; a
/// mesh whose tets share no face (e.g. one tet) has every node on its boundary.
std::vector<int> boundary_nodes(const TetMesh& mesh);

/// Refuses a material.model other than "linear" where a tool would silently apply Hooke's law
/// instead: throws xfem::Error "<file>: <reason>: material.model \"neo-hookean\" is not supported
/// (use \"linear\"; xfem-newton solves \"neo-hookean\")". `reason` says why the tool is
/// small-strain, e.g. "xfem-front's interaction integral is small-strain".
void require_linear_material(const Problem& problem, const std::string& reason);

/// The material of each tet of `mesh` (read from `mesh_file`): the entry of problem.materials
/// naming its region, else problem.json's `material`. Entries with equal model, E and nu share one
/// law; when every tet has the default's law the result has no per-tet table (the single-material
/// path). Throws xfem::Error "<file>: materials[1].region 'tumor' is not a region of body.vtu (its
/// regions: 1 'liver', 2 'tumour')" for a region the mesh has neither as a tet's region nor as a
/// name, or "... names region 2 again (by name)" when an id and a name are the same region.
TetMaterials tet_materials(const Problem& problem, const TetMesh& mesh, const std::string& mesh_file);

/// Refuses cut_loads and contact where a tool would ignore them: throws xfem::Error "<file>: <reason>:
/// cut_loads and contact are solved by xfem-assemble and xfem-solve only". `reason` says why, e.g.
/// "xfem-newton's follower loads on the deformed faces are not implemented".
void refuse_cut_loads_and_contact(const Problem& problem, const std::string& reason);

/// Refuses friction between the cuts' faces (problem.json "contact": {"friction": ...}) where a
/// tool would ignore it: throws xfem::Error "<file>: <reason>: contact.friction is solved by
/// xfem-solve only" (e.g. reason "xfem-newton solves frictionless contact").
void refuse_friction(const Problem& problem, const std::string& reason);

/// "<file>: dirichlet[i]" plus " ('name')" when the condition has a name.
std::string describe(const Problem& p, const char* list, std::size_t i);

}  // namespace xfem
