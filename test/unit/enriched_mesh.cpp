// SPDX-License-Identifier: MIT
#include "xfem/enrich/enriched_mesh.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "xfem/generate/box_mesh.h"
#include "xfem/enrich/classification.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& test) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_enriched_mesh_" + std::to_string(::getpid())) / test;
  fs::create_directories(dir);
  return dir;
}

xfem::TriangleMesh beam_cut() {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << -0.01, -0.01, 0.1, 0.015, -0.01, 0.1, -0.01, 0.07, 0.1, 0.015, 0.07, 0.1;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 3, 0, 3, 2;
  return m;
}

/// The beam 2x4x7 classified and enriched in memory, as xfem-classify + xfem-enrich write it.
xfem::TetMesh enriched_beam(xfem::DofNumbering* numbering = nullptr) {
  xfem::TetMesh mesh = xfem::box_mesh({2, 4, 7}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const auto c = xfem::classify(mesh, xfem::CutSurface(beam_cut()));
  xfem::store_classification(c, mesh);
  std::vector<int> enr, cls;
  for (auto e : c.enrichment) enr.push_back(static_cast<int>(e));
  for (auto k : c.cut_class) cls.push_back(static_cast<int>(k));
  const auto d = xfem::dof_numbering(mesh.tets, mesh.points.rows(), enr, cls);
  xfem::store_dof_numbering(d, mesh);
  if (numbering) *numbering = d;
  return mesh;
}

}  // namespace

TEST_CASE("enriched_mesh: reads back what classify and enrich store", "[enriched_mesh]") {
  const fs::path dir = scratch("roundtrip");
  xfem::DofNumbering d;
  const xfem::TetMesh mesh = enriched_beam(&d);
  xfem::write_tet_mesh(mesh, (dir / "enriched.vtu").string());
  xfem::write_triangle_mesh(beam_cut(), (dir / "cut.vtp").string());
  const auto em = xfem::read_enriched_mesh((dir / "enriched.vtu").string(), (dir / "cut.vtp").string());
  CHECK((em.np == d.np && em.ns == d.ns && em.nb == d.nb && em.n == d.n));
  CHECK(em.nb > 0);
  CHECK(em.offsets == d.offsets);
  CHECK(em.dofs == d.dofs);
  CHECK(em.local == d.local);
  CHECK(em.front.segments().size() == 1);
  REQUIRE(em.cut);
  for (int i = 0; i < em.mesh.points.rows(); ++i) CHECK(em.side[i] == (em.mesh.points(i, 2) > 0.1 ? 1 : -1));
  fs::remove_all(dir);
}

TEST_CASE("enriched_mesh: a broken contract is named", "[enriched_mesh]") {
  const fs::path dir = scratch("broken");
  const std::string path = (dir / "e.vtu").string();
  auto expect = [&](xfem::TetMesh m, const std::string& message) {
    xfem::write_tet_mesh(m, path);
    CHECK_THROWS_WITH(xfem::read_enriched_mesh(path, ""), Catch::Contains(message));
  };
  const xfem::TetMesh good = enriched_beam();
  {
    auto m = good;
    m.field_data.erase("dof_counts");
    expect(m, path + ": field array 'dof_counts' missing (is this xfem-enrich output?)");
  }
  {
    auto m = good;
    m.point_data.erase("side");
    expect(m, path + ": point array 'side' missing (is this xfem-classify output?)");
  }
  {
    auto m = good;
    m.field_data["dof_counts"].values[3] += 1;
    expect(m, "violates NP = #points");
  }
  {
    auto m = good;
    const auto& off = m.field_data["extended_offsets"].values;
    std::size_t t = 0;
    while (off[t + 1] - off[t] == 4) ++t;  // the first tet with enriched entries
    m.field_data["extended_dofs"].values[static_cast<std::size_t>(off[t]) + 4] = 1e6;
    expect(m, "field array 'extended_dofs': tet");
  }
  {
    auto m = good;
    m.field_data["extended_dofs"].values[0] = 5;
    expect(m, "does not start with its 4 nodes in order");
  }
  {
    auto m = good;
    m.cell_data["cut_class"].values[0] = 7;
    expect(m, "cell array 'cut_class': tet 0 has 7");
  }
  fs::remove_all(dir);
}
