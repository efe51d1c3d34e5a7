// SPDX-License-Identifier: MIT
// Coulomb friction between a cut's faces (issue 33, docs/METHOD.md "Friction"): the weighted slip
// rows beside the gap rows, their files, and problem.json's "friction".
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "enriched_test_meshes.h"
#include "xfem/core/error.h"
#include "xfem/fracture/exact_fields.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/problem.h"

namespace {

xfem::Problem problem(const std::string& contact) {
  return xfem::parse_problem(
      xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3}, "contact": )" + contact + "}"), "p.json");
}

// The piece above the cut z = 0.3 of xfem_test::cut_box moved rigidly by v: every sign DOF takes v
// (as in contact_nodes.cpp), the original DOFs above too.
Eigen::VectorXd upper_piece_moved(const xfem::EnrichedMesh& em, const Eigen::Vector3d& v) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * em.n);
  for (long k = 0; k < em.n; ++k)
    if (k >= em.np || em.side[k] > 0) u.segment<3>(3 * k) = v;
  return u;
}

}  // namespace

TEST_CASE("friction: the slip rows measure the tangential jump, the gap rows are unchanged", "[friction]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::ContactOperator plain = xfem::contact_operator(em, problem("true"));
  const xfem::ContactOperator c = xfem::contact_operator(em, problem(R"({"friction": 0.4})"));
  REQUIRE(!plain.has_friction());
  REQUIRE(c.has_friction());
  const long M = c.points();
  REQUIRE(M == plain.points());
  // The gap rows, weights and penalties do not depend on friction, bit for bit.
  CHECK(xfem::SparseMatrix(c.G - plain.G).norm() == 0.0);
  CHECK((c.weight - plain.weight).norm() == 0.0);
  CHECK((c.penalty - plain.penalty).norm() == 0.0);
  REQUIRE(c.T.rows() == 2 * M);
  REQUIRE(c.T.cols() == 3 * em.n);
  CHECK((c.friction.array() == 0.4).all());
  // The tangents: unit, orthogonal to each other and to the cut's normal (0, 0, 1).
  for (long i = 0; i < M; ++i) {
    const Eigen::Vector3d t1 = c.tangents.row(i).head<3>(), t2 = c.tangents.row(i).tail<3>();
    CHECK(std::abs(t1.norm() - 1) < 1e-14);
    CHECK(std::abs(t2.norm() - 1) < 1e-14);
    CHECK(std::abs(t1.dot(t2)) < 1e-14);
    CHECK(std::abs(t1.z()) < 1e-14);
    CHECK(std::abs(t2.z()) < 1e-14);
  }
  // The piece above slid by v in the cut's plane: every node's slip is (t1 . v, t2 . v), its gap 0;
  // moved along the normal: no slip.
  const Eigen::Vector3d v(2e-3, -1e-3, 0);
  const Eigen::VectorXd s = c.T * upper_piece_moved(em, v);
  for (long i = 0; i < M; ++i) {
    CHECK(std::abs(s[2 * i] - c.tangents.row(i).head<3>().dot(v)) < 1e-15);
    CHECK(std::abs(s[2 * i + 1] - c.tangents.row(i).tail<3>().dot(v)) < 1e-15);
  }
  CHECK((c.G * upper_piece_moved(em, v)).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((c.T * upper_piece_moved(em, Eigen::Vector3d(0, 0, 1e-3))).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("friction: the slip files round-trip, a frictionless system has none", "[friction]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const auto dir = std::filesystem::temp_directory_path() / "xfem_contact_friction";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "plain");
  std::filesystem::create_directories(dir / "friction");
  xfem::write_contact_operator(xfem::contact_operator(em, problem("true")), (dir / "plain").string());
  CHECK(!std::filesystem::exists(dir / "plain" / xfem::kContactSlipFile));
  CHECK(!std::filesystem::exists(dir / "plain" / xfem::kContactFrictionFile));
  CHECK(!xfem::read_contact_operator((dir / "plain").string(), 3 * em.n).has_friction());
  const xfem::ContactOperator c = xfem::contact_operator(em, problem(R"({"friction": 0.25})"));
  xfem::write_contact_operator(c, (dir / "friction").string());
  const xfem::ContactOperator back = xfem::read_contact_operator((dir / "friction").string(), 3 * em.n);
  REQUIRE(back.has_friction());
  CHECK(xfem::SparseMatrix(back.T - c.T).norm() == 0.0);
  CHECK((back.tangents - c.tangents).norm() == 0.0);
  CHECK((back.friction - c.friction).norm() == 0.0);
  // Without its friction file the slip file is refused, naming the file.
  std::filesystem::remove(dir / "friction" / xfem::kContactFrictionFile);
  CHECK_THROWS_WITH(xfem::read_contact_operator((dir / "friction").string(), 3 * em.n),
                    Catch::Contains("contact_friction.mtx: missing"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("friction: problem.json's coefficient per cut and its bad values", "[friction]") {
  const xfem::Problem one = problem(R"({"friction": 0.3})");
  CHECK(one.contact.friction_on);
  CHECK(one.contact.friction_of(0) == 0.3);
  CHECK(one.contact.friction_of(5) == 0.3);
  const xfem::Problem two = problem(R"({"cuts": [2, 0], "friction": [0.1, 0.7]})");
  CHECK(two.contact.friction_of(2) == 0.1);
  CHECK(two.contact.friction_of(0) == 0.7);
  CHECK(two.contact.friction_of(1) == 0.0);  // no contact there
  CHECK(!problem("true").contact.friction_on);
  CHECK(problem(R"({"friction": 0})").contact.friction_on);  // given: the frictional solve, mu = 0
  CHECK_THROWS_WITH(problem(R"({"friction": -0.1})"), Catch::Contains("p.json: contact.friction must lie in 0..1e3"));
  CHECK_THROWS_WITH(problem(R"({"friction": 1e9})"), Catch::Contains("must lie in 0..1e3"));
  CHECK_THROWS_WITH(problem(R"({"friction": null})"), Catch::Contains("contact.friction must be a number"));
  CHECK_THROWS_WITH(problem(R"({"friction": [0.1, 0.2]})"), Catch::Contains("one coefficient per entry of \"cuts\""));
  CHECK_THROWS_WITH(problem(R"({"cuts": [0], "friction": [-1]})"), Catch::Contains("contact.friction[0] must lie in 0..1e3"));
  CHECK_THROWS_WITH(xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3}, "friction": 0.3})"), "p.json"),
                    Catch::Contains("p.json: friction must be given inside \"contact\""));
}

TEST_CASE("friction: refused where a tool would ignore it", "[friction]") {
  CHECK_NOTHROW(xfem::refuse_friction(problem("true"), "xfem-newton solves frictionless contact"));
  CHECK_THROWS_WITH(xfem::refuse_friction(problem(R"({"friction": 0.2})"), "xfem-newton solves frictionless contact"),
                    Catch::Equals("p.json: xfem-newton solves frictionless contact: contact.friction is solved by xfem-solve only"));
}

TEST_CASE("friction: the penny field pressed shut with friction slides by the effective shear", "[friction]") {
  xfem::PennyField p;
  p.centre = Eigen::Vector3d(0.5, 0.5, 0.47);
  p.radius = 0.3;
  p.sigma = -0.5;
  p.shear = Eigen::Vector3d(-0.5, 0, 0);
  p.closed = true;
  const Eigen::Vector3d x(0.95, 0.2, 0.9);  // on the box's boundary, 0.25 a and more from the disc
  const Eigen::Vector3d free = p.displacement(x);
  // The uniform field alone: sigma n n^T + tau n^T + n tau^T.
  const Eigen::Vector3d n = p.normal, d = x - p.centre;
  const Eigen::Matrix3d eps = p.sigma / p.E * ((1 + p.nu) * n * n.transpose() - p.nu * Eigen::Matrix3d::Identity()) +
                              (1 + p.nu) / p.E * (p.shear * n.transpose() + n * p.shear.transpose());
  const Eigen::Vector3d uniform = eps * d;
  // mu >= tan beta = 1: the faces stick, the uniform field (as an uncut body).
  p.friction = 1.2;
  CHECK((p.displacement(x) - uniform).norm() < 1e-15);
  p.friction = 1.0;
  CHECK((p.displacement(x) - uniform).norm() < 1e-15);
  // mu = 0.5: half the shear slides, so half the crack's perturbation.
  p.friction = 0.5;
  const Eigen::Vector3d half = p.displacement(x);
  CHECK((half - uniform - 0.5 * (free - uniform)).norm() < 1e-12 * free.norm());
  CHECK((free - uniform).norm() > 1e-3 * free.norm());  // the perturbation is there to halve
}
