// SPDX-License-Identifier: MIT
// validate_triangle_mesh: the checks and repairs (zero-area triangles, orientation) of a cut surface.
#include <algorithm>
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"

namespace xfem {
namespace {

// Keeps the rows of every cell array whose triangle survives.
void keep_cells(DataArrays& arrays, const std::vector<int>& kept) {
  for (auto& [name, a] : arrays) {
    std::vector<double> values;
    values.reserve(kept.size() * a.components);
    for (int f : kept)
      for (int c = 0; c < a.components; ++c) values.push_back(a(f, c));
    a.values = std::move(values);
  }
}

}  // namespace

void validate_triangle_mesh(TriangleMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows();
  if (np == 0 || mesh.triangles.rows() == 0)
    throw Error(name + ": empty surface (" + std::to_string(np) + " points, " +
                std::to_string(mesh.triangles.rows()) + " triangles)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<int> kept;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) < 0 || mesh.triangles(f, k) >= np)
        throw Error(name + ": triangle " + std::to_string(f) + " uses point " +
                    std::to_string(mesh.triangles(f, k)) + ", out of range [0, " + std::to_string(np) + ")");
    const Eigen::Vector3d a = mesh.points.row(mesh.triangles(f, 0)), b = mesh.points.row(mesh.triangles(f, 1)),
                          c = mesh.points.row(mesh.triangles(f, 2));
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() > 1e-12 * longest) kept.push_back(static_cast<int>(f));
  }
  if (kept.empty()) throw Error(name + ": every triangle has zero area");
  if (kept.size() != static_cast<std::size_t>(mesh.triangles.rows())) {
    if (warnings)
      warnings->push_back(name + ": " + std::to_string(mesh.triangles.rows() - kept.size()) +
                          " zero-area triangles dropped");
    Triangles t(kept.size(), 3);
    for (std::size_t i = 0; i < kept.size(); ++i) t.row(i) = mesh.triangles.row(kept[i]);
    mesh.triangles = t;
    keep_cells(mesh.cell_data, kept);
  }

  // Orientation: two triangles sharing an edge agree when they run along it in opposite
  // directions. Breadth-first from the lowest-numbered triangle of each piece, flipping as needed.
  // The edges by sorting (undirected edge, face) pairs, not by a map of vectors: a cut of thousands
  // of triangles is read by every stage, and the map's allocations were a visible part of it.
  const int nf = static_cast<int>(mesh.triangles.rows());
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  };
  std::vector<std::pair<std::uint64_t, int>> edges;  // (undirected edge, face), by edge then face
  edges.reserve(3 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) edges.emplace_back(key(mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3)), f);
  std::sort(edges.begin(), edges.end());
  // across[3 f + k]: the other face on f's edge k (from vertex k to k + 1), or -1 on the boundary.
  std::vector<int> across(3 * static_cast<std::size_t>(nf), -1);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    if (j - i > 2)
      throw Error(name + ": edge (" + std::to_string(edges[i].first >> 32) + ", " +
                  std::to_string(edges[i].first & 0xffffffffu) + ") is shared by " + std::to_string(j - i) +
                  " triangles; a cut must be a manifold surface");
    if (j - i == 2)
      for (std::size_t e = i; e < j; ++e) {
        const int f = edges[e].second, g = edges[i + j - 1 - e].second;
        for (int k = 0; k < 3; ++k)
          if (key(mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3)) == edges[i].first) across[3 * f + k] = g;
      }
    i = j;
  }
  auto runs_forward = [&](int f, int a, int b) {  // does triangle f traverse a -> b?
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) == a && mesh.triangles(f, (k + 1) % 3) == b) return true;
    return false;
  };
  std::vector<int> flip(nf, -1);  // -1 unvisited, 0 keep, 1 flip
  int flipped = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (flip[seed] != -1) continue;
    flip[seed] = 0;
    std::queue<int> todo;
    todo.push(seed);
    while (!todo.empty()) {
      const int f = todo.front();
      todo.pop();
      for (int k = 0; k < 3; ++k) {
        int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
        if (flip[f]) std::swap(a, b);  // f's direction along the edge after its own flip
        {
          const int g = across[3 * f + k];
          if (g < 0 || g == f) continue;
          const int needed = runs_forward(g, a, b) ? 1 : 0;  // g must run b -> a
          if (flip[g] == -1) {
            flip[g] = needed;
            flipped += needed;
            todo.push(g);
          } else if (flip[g] != needed) {
            throw Error(name + ": the surface cannot be oriented consistently (a Moebius strip?) at edge (" +
                        std::to_string(a) + ", " + std::to_string(b) + ")");
          }
        }
      }
    }
  }
  for (int f = 0; f < nf; ++f)
    if (flip[f] == 1) std::swap(mesh.triangles(f, 1), mesh.triangles(f, 2));
  if (flipped && warnings)
    warnings->push_back(name + ": " + std::to_string(flipped) +
                        " triangles flipped to agree with their neighbours' orientation");
}

}  // namespace xfem
