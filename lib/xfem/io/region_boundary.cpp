// SPDX-License-Identifier: MIT
#include "xfem/io/region_boundary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "xfem/core/regions.h"

namespace xfem {
namespace {

// A face by its sorted point ids, for matching the two tets that share it.
using FaceKey = std::array<int, 3>;
struct FaceHash {
  std::size_t operator()(const FaceKey& f) const {
    return (static_cast<std::size_t>(f[0]) * 73856093u) ^ (static_cast<std::size_t>(f[1]) * 19349663u) ^
           (static_cast<std::size_t>(f[2]) * 83492791u);
  }
};

// The faces of a positively oriented tet, each oriented outwards (opposite vertex 3, 2, 1, 0).
constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

}  // namespace

RegionBoundary region_boundary(const TetMesh& mesh) {
  RegionBoundary out;
  const std::vector<int> regions = tet_regions(mesh);
  std::map<int, double> volume;
  const Eigen::Index nt = mesh.tets.rows();
  for (Eigen::Index t = 0; t < nt; ++t) {
    const Eigen::Vector3d p0 = mesh.points.row(mesh.tets(t, 0));
    const Eigen::Matrix3d m = (Eigen::Matrix3d() << mesh.points.row(mesh.tets(t, 1)) - p0.transpose(),
                               mesh.points.row(mesh.tets(t, 2)) - p0.transpose(),
                               mesh.points.row(mesh.tets(t, 3)) - p0.transpose())
                                  .finished();
    volume[regions[t]] += std::abs(m.determinant()) / 6;
  }
  if (volume.size() < 2) {
    if (!volume.empty()) out.majority = volume.begin()->first;
    return out;
  }
  out.majority = volume.begin()->first;
  for (const auto& [r, v] : volume)
    if (v > volume[out.majority]) out.majority = r;
  // Each face with the regions of the tets that use it (a conforming mesh: at most two).
  std::unordered_map<FaceKey, std::array<int, 2>, FaceHash> users;  // tet ids, -1: none
  users.reserve(static_cast<std::size_t>(2 * nt));
  for (Eigen::Index t = 0; t < nt; ++t)
    for (const auto& f : kFaces) {
      FaceKey k = {mesh.tets(t, f[0]), mesh.tets(t, f[1]), mesh.tets(t, f[2])};
      std::sort(k.begin(), k.end());
      auto [it, fresh] = users.try_emplace(k, std::array<int, 2>{static_cast<int>(t), -1});
      if (!fresh) it->second[1] = static_cast<int>(t);
    }
  std::vector<std::array<int, 3>> tris;
  for (Eigen::Index t = 0; t < nt; ++t) {
    if (regions[t] == out.majority) continue;
    for (const auto& f : kFaces) {
      FaceKey k = {mesh.tets(t, f[0]), mesh.tets(t, f[1]), mesh.tets(t, f[2])};
      std::sort(k.begin(), k.end());
      const auto& u = users.at(k);
      const int other = u[0] == t ? u[1] : u[0];
      if (other >= 0 && regions[other] == regions[t]) continue;
      tris.push_back({mesh.tets(t, f[0]), mesh.tets(t, f[1]), mesh.tets(t, f[2])});
      out.region.push_back(regions[t]);
    }
  }
  out.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t i = 0; i < tris.size(); ++i)
    out.triangles.row(static_cast<Eigen::Index>(i)) << tris[i][0], tris[i][1], tris[i][2];
  return out;
}

std::vector<std::array<int, 2>> outline_edges(const Points& points, const Triangles& triangles,
                                              const Eigen::Vector3d& eye) {
  // Per edge: how many triangles use it, and whether any faces the eye / faces away.
  struct Use {
    int count = 0;
    bool front = false, back = false;
  };
  std::map<std::array<int, 2>, Use> edges;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Eigen::Vector3d a = points.row(triangles(f, 0)), b = points.row(triangles(f, 1)),
                          c = points.row(triangles(f, 2));
    const bool front = (b - a).cross(c - a).dot(eye) > 0;
    for (int e = 0; e < 3; ++e) {
      const int p = triangles(f, e), q = triangles(f, (e + 1) % 3);
      Use& u = edges[{std::min(p, q), std::max(p, q)}];
      ++u.count;
      (front ? u.front : u.back) = true;
    }
  }
  std::vector<std::array<int, 2>> out;
  for (const auto& [e, u] : edges)
    if (u.count == 1 || (u.front && u.back)) out.push_back(e);
  return out;
}

}  // namespace xfem
