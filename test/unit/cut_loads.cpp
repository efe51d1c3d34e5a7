// SPDX-License-Identifier: MIT
// Loads on a cut's faces and frictionless contact between them (issue 33).
#include <catch2/catch.hpp>
#include <cmath>

#include "enriched_test_meshes.h"
#include "xfem/enrich/classification.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/integrate/cut_face_quadrature.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/solve/direct_backend.h"
#include "xfem/system/assembly.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/cut_loads.h"
#include "xfem/system/problem.h"

namespace {

// cut_box (enriched_test_meshes.h): the unit box of 1 x 1 x 2 cubes cut through by z = 0.3.
xfem::Problem box_problem(const std::string& extra) {
  return xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3})" + extra + "}"), "p.json");
}

// The work of f on the displacement v(x) of the piece above the cut (0 below), v linear:
// v = w + W x, written in the X-FEM basis: original DOFs of the nodes above take v(node), every
// sign DOF takes v(node) (its shifted Heaviside is 1 above for a node below, and cancels the
// original DOF below for a node above).
double work_on_upper_piece(const xfem::EnrichedMesh& em, const Eigen::VectorXd& f, const Eigen::Vector3d& w,
                           const Eigen::Matrix3d& W) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(3 * em.n);
  for (int t = 0; t < em.tets(); ++t)
    for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) {
      const long dof = em.dofs[e];
      const int node = em.mesh.tets(t, em.local[e]);
      const Eigen::Vector3d x = em.mesh.points.row(node).transpose();
      if (dof >= em.np || em.side[node] > 0) v.segment<3>(3 * dof) = w + W * x;
    }
  return f.dot(v);
}

}  // namespace

TEST_CASE("cut loads: problem.json's cut_loads and contact, and their bad values", "[cut_loads]") {
  const xfem::Problem p = box_problem(R"(, "cut_loads": [{"cut": 0, "pressure": 2, "traction": [1, 0, 0]},
                                                         {"pressure": -1}], "contact": {"penalty": 100})");
  REQUIRE(p.cut_loads.size() == 2);
  CHECK(p.cut_loads[0].pressure == 2);
  CHECK(p.cut_loads[0].traction == Eigen::Vector3d(1, 0, 0));
  CHECK(p.cut_loads[1].cut == 0);
  CHECK(p.contact.on);
  CHECK(p.contact.applies_to(3));
  CHECK(p.contact.penalty == 100);
  CHECK(!box_problem("").contact.on);
  CHECK(!box_problem(R"(, "contact": false)").contact.applies_to(0));
  const xfem::Problem some = box_problem(R"(, "contact": {"cuts": [1]})");
  CHECK(!some.contact.applies_to(0));
  CHECK(some.contact.applies_to(1));
  CHECK_THROWS_WITH(box_problem(R"(, "cut_loads": [{"cut": -1, "pressure": 1}])"),
                    "p.json: cut_loads[0].cut must be a cut index, an integer in 0..15, got -1");
  CHECK_THROWS_WITH(box_problem(R"(, "cut_loads": [{"cut": 0}])"),
                    "p.json: cut_loads[0] needs a pressure or a traction (or both)");
  CHECK_THROWS_WITH(box_problem(R"(, "cut_loads": [{"pressure": "high"}])"), "p.json: cut_loads[0].pressure must be a number");
  CHECK_THROWS_WITH(box_problem(R"(, "cut_loads": [{"traction": [1, null, 0]}])"),
                    "p.json: cut_loads[0].traction[1] must be a number");
  CHECK_THROWS_WITH(box_problem(R"(, "cut_loads": [{"pressure": 1, "force": 2}])"),
                    "p.json: unknown key 'cut_loads[0].force' (allowed here: cut, pressure, traction)");
  CHECK_THROWS_WITH(box_problem(R"(, "contact": "yes")"),
                    "p.json: contact must be true, false or an object {\"cuts\": [...], \"penalty\": ...}");
  CHECK_THROWS_WITH(box_problem(R"(, "contact": {"penalty": 0.5})"),
                    "p.json: contact.penalty must lie in 1..1e8 (kappa = penalty E / h), got 0.5");
  CHECK_THROWS_WITH(box_problem(R"(, "contact": {"cuts": [0, 0]})"), "p.json: contact.cuts[1] names cut 0 twice");
  CHECK_THROWS_WITH(xfem::check_cut_indices(box_problem(R"(, "cut_loads": [{"pressure": 1}, {"cut": 2, "pressure": 1}])"), 1),
                    "p.json: cut_loads[1].cut is 2, but the mesh has 1 cut (indices 0..0)");
  CHECK_THROWS_WITH(xfem::check_cut_indices(box_problem(R"(, "contact": {"cuts": [1]})"), 1),
                    "p.json: contact.cuts[0] is 1, but the mesh has 1 cut (indices 0..0)");
  CHECK_THROWS_WITH(xfem::add_cut_loads(xfem_test::cut_box(0.3), box_problem(R"(, "cut_loads": [{"cut": 1, "pressure": 1}])"),
                                        *std::make_unique<Eigen::VectorXd>(Eigen::VectorXd::Zero(60))),
                    "p.json: cut_loads[0].cut is 1, but the mesh has 1 cut (indices 0..0)");
}

TEST_CASE("cut loads: the face rule covers the cut's area, and a pressure does the work p A on a rigid motion",
          "[cut_loads]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  for (int order : {1, 2, 3, 5}) {
    double area = 0;
    for (const xfem::CutFacePoint& q : xfem::cut_face_points(em, 0, order)) {
      area += q.weight;
      CHECK(std::abs(q.x.z() - 0.3) < 1e-15);
      CHECK(q.normal == Eigen::Vector3d(0, 0, 1));
    }
    CHECK(std::abs(area - 1.0) < 1e-14);
  }
  const double p = 7.0;
  const Eigen::Vector3d t(0.5, -2, 0.25);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * em.n);
  const double area = xfem::add_cut_loads(em, box_problem(R"(, "cut_loads": [{"pressure": 7, "traction": [0.5, -2, 0.25]}])"), f);
  CHECK(std::abs(area - 1.0) < 1e-14);
  CHECK(f.head(3 * em.np).isZero(0.0));  // equal and opposite on the faces: no net force on a node's original DOF
  // Translations of the upper piece: the force on its face, (p n + t) A.
  for (int i = 0; i < 3; ++i)
    CHECK(std::abs(work_on_upper_piece(em, f, Eigen::Vector3d::Unit(i), Eigen::Matrix3d::Zero()) -
                   (p * Eigen::Vector3d::UnitZ() + t)[i]) < 1e-12);
  // A linear motion of the upper piece, v = x e_z + y e_x: the face rule is exact for the sign part,
  // the work is the integral of (p n + t) . v over the unit square at z = 0.3: (p + t_z) / 2 + t_x / 2.
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  W(2, 0) = 1;
  W(0, 1) = 1;
  CHECK(std::abs(work_on_upper_piece(em, f, Eigen::Vector3d::Zero(), W) - ((p + t.z()) / 2 + t.x() / 2)) < 1e-12);
}

TEST_CASE("cut loads: a cut lying in a node layer is covered once, by the tets below it", "[cut_loads]") {
  // The beam's box of 4 x 8 x 14 cubes: z = 0.1 is a layer of nodes, and the faces of the tets on
  // it carry the cut. The classification puts the nodes on the cut above, so the tets above are
  // plain and those below carry the jump, split by the cut or not. Each face was counted 1/2 in
  // each tet, and only in tets the cut splits: half the area or more was lost.
  const xfem::TetMesh mesh = xfem::box_mesh({4, 8, 14}, {0, 0, 0}, {0.03, 0.06, 0.2});
  struct Case {
    Eigen::Vector3d corner, e1, e2;
    double area;  // inside the body
  };
  const Case cases[] = {
      {{-0.01, -0.01, 0.1}, {0.05, 0, 0}, {0, 0.08, 0}, 0.03 * 0.06},     // through the body
      {{-0.01, 0.012, 0.1}, {0.05, 0, 0}, {0, 0.08, 0}, 0.03 * 0.048},    // from a side face, its front across faces
      {{0.0075, 0.015, 0.1}, {0.015, 0, 0}, {0, 0.03, 0}, 0.015 * 0.03},  // inside, its front on node lines
      {{0.005, 0.012, 0.1}, {0.02, 0, 0}, {0, 0.035, 0}, 0.02 * 0.035},   // inside, its front across faces
  };
  for (const Case& c : cases) {
    const auto cut = std::make_shared<xfem::CutSurface>(
        xfem::cut_parallelogram(c.corner, c.corner + c.e1, c.corner + c.e2, Eigen::Vector2i(1, 1)));
    const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
    for (int order : {2, 3}) {
      double area = 0;
      for (const xfem::CutFacePoint& q : xfem::cut_face_points(em, 0, order)) area += q.weight;
      CHECK(area == Approx(c.area).epsilon(1e-12));
    }
  }
}

TEST_CASE("cut loads: the basis jumps by N_l for a sign DOF and 2 sqrt(r) N_l for the first branch function",
          "[cut_loads]") {
  xfem::EnrichedMesh em = xfem_test::front_inside_box();
  em.cut_class.assign(static_cast<std::size_t>(em.tets()), 1);
  const std::vector<xfem::CutFacePoint> points = xfem::cut_face_points(em, 0, 4);
  double area = 0;
  Eigen::VectorXd jump;
  xfem::BasisAt scratch;
  for (const xfem::CutFacePoint& q : points) {
    area += q.weight;
    CHECK(q.x.x() <= 0.45 + 1e-15);
    xfem::basis_jump(em, q.tet, 0, q.x, jump, scratch);
    const Eigen::Vector4d N = xfem::tet_shape(em.mesh, q.tet).values(q.x);
    const double r = 0.45 - q.x.x();
    for (int e = 0; e < em.size(q.tet); ++e) {
      const int l = em.local[static_cast<std::size_t>(em.offsets[q.tet] + e)];
      const long dof = em.dofs[static_cast<std::size_t>(em.offsets[q.tet] + e)];
      const double expected = dof < em.np ? 0.0 : (dof - em.np) % 4 == 0 ? 2 * std::sqrt(r) * N[l] : 0.0;
      CHECK(std::abs(jump[e] - expected) < 1e-12);
    }
  }
  // The cut inside the box: 0.45 x 1; a cut lying in the faces of the tets at z = 0.5 counted once.
  CHECK(std::abs(area - 0.45) < 1e-13);
}

namespace {

// The box compressed (or pulled) along z by `dz` at its top, on rollers at z = 0, x = 0, y = 0:
// uniaxial stress, u = (-nu e x, -nu e y, e z) with e = dz, reproduced exactly by the plain mesh.
xfem::Problem rollers(double dz) {
  return box_problem(R"(, "contact": true, "dirichlet": [
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [null, null, 0]},
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [0, 2, 2]}}, "value": [0, null, null]},
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 0, 2]}}, "value": [null, 0, null]},
      {"selector": {"box": {"lo": [-1, -1, 1], "hi": [2, 2, 2]}}, "value": [null, null, )" +
                     std::to_string(dz) + "]}]");
}

Eigen::VectorXd contact_solve(const xfem::EnrichedMesh& em, const xfem::Problem& p, xfem::ContactOutcome& out,
                              Eigen::VectorXd* without = nullptr) {
  xfem::LinearSystem s = xfem::assemble_system(em, p, 30, 0);
  s.K = xfem::SparseMatrix(s.K.selfadjointView<Eigen::Lower>());  // the full matrix, as xfem-solve reads it
  const xfem::ContactOperator c = xfem::contact_operator(em, p);
  xfem::Json report;
  double residual = 0;
  if (without) *without = xfem::solve_with_cholmod(s, "amd", false, report, &residual);
  xfem::CholmodPenalisedSolver solver("amd", false);
  const Eigen::VectorXd u = xfem::solve_with_contact(s, c, {}, solver, report, &residual, &out);
  CHECK(residual < 1e-10);
  CHECK(report["contact"]["points"] == c.points());
  return u;
}

}  // namespace

TEST_CASE("contact: a cut pressed closed behaves as no cut; one pulled open is left alone", "[cut_loads][contact]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const double E = 1e3, nu = 0.3, e = -0.01;
  xfem::ContactOutcome out;
  Eigen::VectorXd without;
  const Eigen::VectorXd u = contact_solve(em, rollers(e), out, &without);
  double worst = 0, largest = 0;
  for (long k = 0; k < em.np; ++k) {
    const Eigen::Vector3d x = em.mesh.points.row(k).transpose();
    const Eigen::Vector3d exact(-nu * e * x.x(), -nu * e * x.y(), e * x.z());
    worst = std::max(worst, (u.segment<3>(3 * k) - exact).norm());
    largest = std::max(largest, exact.norm());
  }
  // The faces' penetration is below 1e-8 max |u| (the tolerance), so is the error of u.
  CHECK(worst < 1e-7 * largest);
  CHECK(u.tail(3 * em.ns).norm() < 1e-7 * largest);
  CHECK(out.max_penetration <= out.tolerance);
  CHECK(out.active == static_cast<long>(out.pressure.size()));  // the whole cut in contact
  CHECK(std::abs(out.active_area - 1.0) < 1e-12);
  for (long q = 0; q < out.pressure.size(); ++q) CHECK(std::abs(out.pressure[q] - (-E * e)) < 1e-6 * E * -e);
  CHECK(out.solves > 2);
  // Without contact the upper piece sinks into the lower one (the lower piece carries no load).
  CHECK(without.head(3 * em.np).cwiseAbs().maxCoeff() > 0.5 * largest);

  // Pulled: the cut opens, contact never acts: the solution is the one without contact, bit for bit.
  const Eigen::VectorXd pulled = contact_solve(em, rollers(0.01), out, &without);
  CHECK(out.solves == 1);
  CHECK(out.active == 0);
  CHECK(pulled == without);
  CHECK(out.opened_volume > 0);
}
