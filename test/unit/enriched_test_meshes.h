// SPDX-License-Identifier: MIT
// Enriched meshes built by hand for the unit tests of assembly and quadrature, so that those tests
// do not depend on xfem-classify and xfem-enrich.
#pragma once
#include <memory>
#include <vector>

#include "xfem/core/regions.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/enrich/enriched_mesh.h"

namespace xfem_test {

/// An enriched mesh without enrichment: C = the tet's 4 points, every side +1, every tet uncut.
inline xfem::EnrichedMesh plain(const xfem::TetMesh& mesh) {
  xfem::EnrichedMesh em;
  em.mesh = mesh;
  const long np = mesh.points.rows();
  em.np = em.n = np;
  em.side.assign(np, 1);
  em.cut_class.assign(mesh.tets.rows(), 0);
  for (int t = 0; t < mesh.tets.rows(); ++t) {
    em.offsets.push_back(4L * t);
    for (int c = 0; c < 4; ++c) {
      em.dofs.push_back(mesh.tets(t, c));
      em.local.push_back(c);
    }
  }
  em.offsets.push_back(4L * mesh.tets.rows());
  return em;
}

/// `mesh` with every node branch enriched: C = the tet's 4 points, then the 4 branch DOFs of each
/// of its nodes (node k's at NP + 4k .. NP + 4k + 3); the caller sets the front and the cut.
inline xfem::EnrichedMesh all_branch(const xfem::TetMesh& mesh) {
  xfem::EnrichedMesh em = plain(mesh);
  em.nb = em.np;
  em.n = em.np + 4 * em.nb;
  std::vector<long> offsets{0}, dofs;
  std::vector<int> local;
  for (int t = 0; t < em.tets(); ++t) {
    for (int c = 0; c < 4; ++c) {
      dofs.push_back(em.mesh.tets(t, c));
      local.push_back(c);
    }
    for (int c = 0; c < 4; ++c)
      for (int j = 0; j < 4; ++j) {
        dofs.push_back(em.np + 4L * em.mesh.tets(t, c) + j);
        local.push_back(c);
      }
    offsets.push_back(static_cast<long>(dofs.size()));
  }
  em.offsets = offsets;
  em.dofs = dofs;
  em.local = local;
  return em;
}

/// The plane z = `z` (normal +z) as two triangles reaching out of the unit box on every side.
inline std::shared_ptr<xfem::CutSurface> plane_cut(double z) {
  xfem::TriangleMesh cut;
  cut.points.resize(4, 3);
  cut.points << -1, -1, z, 2, -1, z, 2, 2, z, -1, 2, z;
  cut.triangles.resize(2, 3);
  cut.triangles << 0, 1, 2, 0, 2, 3;
  return std::make_shared<xfem::CutSurface>(cut);
}

/// The box [0,1]^2 x [0,1] of 1 x 1 x 2 cubes, cut completely by the plane z = `cut_z` (normal
/// +z) inside the lower cube (0 < cut_z < 0.5): its 6 tets completely cut and its 8 nodes sign
/// enriched, with DOFs NP.. in node order; C lists the 4 originals, then the 4 sign DOFs.
inline xfem::EnrichedMesh cut_box(double cut_z) {
  xfem::EnrichedMesh em = plain(xfem::box_mesh({1, 1, 2}, {0, 0, 0}, {1, 1, 1}));
  const int np = static_cast<int>(em.np);
  std::vector<long> sign(np, -1);
  for (int k = 0; k < np; ++k) {
    em.side[k] = em.mesh.points(k, 2) > cut_z ? 1 : -1;
    if (em.mesh.points(k, 2) < 0.75) sign[k] = em.np + em.ns++;
  }
  em.n = em.np + em.ns;
  std::vector<long> offsets{0}, dofs;
  std::vector<int> local;
  for (int t = 0; t < em.tets(); ++t) {
    bool cut = true;
    for (int c = 0; c < 4; ++c) cut = cut && sign[em.mesh.tets(t, c)] >= 0;
    em.cut_class[t] = cut ? 2 : 0;
    for (int c = 0; c < 4; ++c) {
      dofs.push_back(em.mesh.tets(t, c));
      local.push_back(c);
    }
    if (cut)
      for (int c = 0; c < 4; ++c) {
        dofs.push_back(sign[em.mesh.tets(t, c)]);
        local.push_back(c);
      }
    offsets.push_back(static_cast<long>(dofs.size()));
  }
  em.offsets = offsets;
  em.dofs = dofs;
  em.local = local;
  em.cut = plane_cut(cut_z);
  return em;
}

/// Gives each tet of `mesh` the region `below` or `above` by its centroid's coordinate `axis`
/// (0, 1, 2) against `at` (a plane of nodes, so that the interface is a mesh interface), as the
/// cell array "region"; returns the regions.
inline std::vector<int> split_regions(xfem::TetMesh& mesh, int axis, double at, int below, int above) {
  std::vector<int> region(static_cast<std::size_t>(mesh.tets.rows()));
  for (long t = 0; t < mesh.tets.rows(); ++t) {
    double c = 0;
    for (int k = 0; k < 4; ++k) c += mesh.points(mesh.tets(t, k), axis) / 4;
    region[static_cast<std::size_t>(t)] = c < at ? below : above;
  }
  xfem::set_tet_regions(mesh, region);
  return region;
}

/// The unit box of 4^3 cubes, every node branch enriched, cut by the half-plane z = 0.5, x <= 0.45:
/// the front x = 0.45 runs through the middle of a layer of elements.
inline xfem::EnrichedMesh front_inside_box() {
  xfem::EnrichedMesh em = all_branch(xfem::box_mesh({4, 4, 4}, {0, 0, 0}, {1, 1, 1}));
  xfem::TriangleMesh cut;
  cut.points.resize(4, 3);
  cut.points << -1, -1, 0.5, 0.45, -1, 0.5, 0.45, 2, 0.5, -1, 2, 0.5;
  cut.triangles.resize(2, 3);
  cut.triangles << 0, 1, 2, 0, 2, 3;
  em.cut = std::make_shared<xfem::CutSurface>(cut);
  em.front = xfem::CrackFront({xfem::FrontSegment{{0.45, 2.0, 0.5}, {0.45, -1.0, 0.5}, {0, 0, 1}}});
  return em;
}

}  // namespace xfem_test
