// SPDX-License-Identifier: MIT
#include "xfem/io/region_boundary.h"

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "xfem/core/regions.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/io/snapshot.h"

namespace {

using Catch::Matchers::WithinAbs;

// The unit cube in n^3 cubes, region 1 where the tet's centroid passes `inside`, 0 elsewhere.
template <class Inside>
xfem::TetMesh split_box(int n, Inside inside) {
  xfem::TetMesh m = xfem::box_mesh(Eigen::Vector3i(n, n, n), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  std::vector<int> regions(m.tets.rows());
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += m.points.row(m.tets(t, k)).transpose() / 4;
    regions[t] = inside(c) ? 1 : 0;
  }
  xfem::set_tet_regions(m, regions);
  return m;
}

}  // namespace

TEST_CASE("region boundary: a slab of a box is outlined by its 6 sides, the interface included", "[region_boundary]") {
  // Region 1: x < 0.25 (one layer of the 4 x 4 x 4 cubes), the smaller one. Each cube face is 2
  // triangles: x = 0 and the interface x = 0.25 have 2 * 16, the four sides 2 * 4 each: 96.
  const xfem::TetMesh m = split_box(4, [](const Eigen::Vector3d& c) { return c.x() < 0.25; });
  const xfem::RegionBoundary b = xfem::region_boundary(m);
  CHECK(b.majority == 0);
  REQUIRE(b.triangles.rows() == 96);
  REQUIRE(b.region.size() == 96);
  int interface = 0;
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  double flux = 0;  // divergence theorem with F = (x, 0, 0): the enclosed volume, 0.25
  for (Eigen::Index f = 0; f < b.triangles.rows(); ++f) {
    CHECK(b.region[f] == 1);
    const Eigen::Vector3d p = m.points.row(b.triangles(f, 0)), q = m.points.row(b.triangles(f, 1)),
                          r = m.points.row(b.triangles(f, 2));
    const Eigen::Vector3d n = (q - p).cross(r - p) / 2;  // area-weighted, outwards
    normal_sum += n;
    flux += n.x() * (p.x() + q.x() + r.x()) / 3;
    if (std::abs(p.x() - 0.25) < 1e-12 && std::abs(q.x() - 0.25) < 1e-12 && std::abs(r.x() - 0.25) < 1e-12) ++interface;
  }
  CHECK(interface == 32);
  CHECK_THAT(normal_sum.norm(), WithinAbs(0, 1e-12));  // a closed surface
  CHECK_THAT(flux, WithinAbs(0.25, 1e-12));              // oriented out of the region
}

TEST_CASE("region boundary: the largest region by volume is not outlined; one region, nothing", "[region_boundary]") {
  // Region 1 is x >= 0.25: now region 0 (the slab) is the smaller one and is outlined.
  const xfem::TetMesh m = split_box(4, [](const Eigen::Vector3d& c) { return c.x() >= 0.25; });
  const xfem::RegionBoundary b = xfem::region_boundary(m);
  CHECK(b.majority == 1);
  CHECK(b.triangles.rows() == 96);
  // An inner cube [0.25, 0.75]^3: its 6 sides of 2 x 2 cube faces, 2 triangles each.
  const xfem::TetMesh inner = split_box(4, [](const Eigen::Vector3d& c) { return (c.array() - 0.5).abs().maxCoeff() < 0.25; });
  CHECK(xfem::region_boundary(inner).triangles.rows() == 48);
  // A tie: the lowest id is the largest.
  CHECK(xfem::region_boundary(split_box(4, [](const Eigen::Vector3d& c) { return c.x() < 0.5; })).majority == 0);
  xfem::TetMesh one = xfem::box_mesh(Eigen::Vector3i(2, 2, 2), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  CHECK(xfem::region_boundary(one).triangles.rows() == 0);
  xfem::set_tet_regions(one, std::vector<int>(one.tets.rows(), 3));
  const xfem::RegionBoundary b3 = xfem::region_boundary(one);
  CHECK(b3.triangles.rows() == 0);
  CHECK(b3.majority == 3);
}

TEST_CASE("region boundary: the outline of a box seen obliquely is its 6-edge silhouette", "[region_boundary]") {
  const xfem::TetMesh m = split_box(4, [](const Eigen::Vector3d& c) { return c.x() < 0.25; });
  const xfem::RegionBoundary b = xfem::region_boundary(m);
  // From (+,+,+) the slab 0.25 x 1 x 1 (1 x 4 x 4 segments) shows a hexagon of 2 edges along each
  // axis: 2 * 1 + 2 * 4 + 2 * 4 = 18 segments.
  CHECK(xfem::outline_edges(m.points, b.triangles, Eigen::Vector3d(1, 0.3, 0.2).normalized()).size() == 18);
  // An open surface: one triangle is all border.
  xfem::Triangles one(1, 3);
  one << 0, 1, 2;
  CHECK(xfem::outline_edges(m.points, one, Eigen::Vector3d::UnitZ()).size() == 3);
}

// Rendering needs an X display: hidden here, run under xvfb-run by test/e2e/region_picture.sh.
TEST_CASE("region boundary: an inclusion inside the body shows in the picture, one region renders as before",
          "[.region_picture]") {
  REQUIRE(std::getenv("DISPLAY"));
  auto body = [](bool regions, bool inclusion) {
    xfem::TetMesh m = split_box(4, [&](const Eigen::Vector3d& c) {
      return inclusion && (c.array() - 0.5).abs().maxCoeff() < 0.25;
    });
    if (!regions) m.cell_data.erase(xfem::region_array_name);
    else m.region_names = {{0, "organ"}, {1, "inclusion"}};
    m.point_data["displacement"] = xfem::make_array(xfem::DataArray::Type::Float64, 3, m.points.rows());
    m.cell_data["von_mises"] = xfem::make_array(xfem::DataArray::Type::Float64, 1, m.tets.rows(), 1000.0);
    return m;
  };
  const std::string dir = std::getenv("XFEM_SCRATCH") ? std::getenv("XFEM_SCRATCH") : ".";
  xfem::SnapshotOptions o;
  o.width = 320;
  o.height = 240;
  auto render = [&](const xfem::TetMesh& m, const std::string& name) {
    const std::string png = dir + "/" + name + ".png";
    xfem::write_snapshot(m, xfem::TriangleMesh{}, png, o);
    std::ifstream in(png, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  // Pixels of the outline's orange (1, 0.5, 0), drawn unlit, give or take the anti-aliasing.
  auto orange = [&](const std::string& name) {
    auto reader = vtkSmartPointer<vtkPNGReader>::New();
    reader->SetFileName((dir + "/" + name + ".png").c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    int count = 0;
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
        if (p[0] > 225 && std::abs(p[1] - 128) < 35 && p[2] < 50) ++count;
      }
    return count;
  };
  const std::string plain = render(body(false, false), "plain");
  const std::string one = render(body(true, false), "one_region");
  const std::string two = render(body(true, true), "two_regions");
  REQUIRE(!plain.empty());
  CHECK(plain == one);  // a single region (array all 0, named) draws nothing more
  CHECK(two != one);
  CHECK(orange("one_region") == 0);
  CHECK(orange("two_regions") > 100);
}
