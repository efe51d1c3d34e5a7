// SPDX-License-Identifier: MIT
#include "xfem/gmsh_io.h"

#include <gmsh.h>

#include <array>
#include <map>
#include <mutex>

#include "xfem/atomic_file.h"
#include "xfem/boundary_groups.h"
#include "xfem/error.h"
#include "xfem/vtk_io.h"

namespace xfem {
namespace {

constexpr int gmsh_triangle = 2, gmsh_tetrahedron = 4;

// gmsh's library is one global state: one file at a time, initialised quietly (no terminal
// output, no user configuration files) and finalised whatever happens.
class GmshSession {
 public:
  explicit GmshSession(const std::string& path) : lock_(mutex()), path_(path) {
    require_readable(path);  // gmsh::open only logs a missing file and carries on
    gmsh::initialize(0, nullptr, false);
    try {
      gmsh::option::setNumber("General.Terminal", 0);
      guard([&] { gmsh::open(path); }, "cannot read the gmsh file");
    } catch (...) {
      gmsh::finalize();  // the destructor does not run when the constructor throws
      throw;
    }
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Runs a gmsh call; gmsh throws after logging, so its last error is the message.
  template <class F>
  void guard(F&& call, const char* what) const {
    try {
      call();
    } catch (...) {
      std::string message;
      try {
        gmsh::logger::getLastError(message);
      } catch (...) {
      }
      throw Error(path_ + ": " + what + (message.empty() ? std::string() : ": " + message));
    }
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  std::string path_;
};

// All nodes of the model, and a map from gmsh's node tags (any positive numbers) to rows.
struct Nodes {
  Points points;
  std::map<std::size_t, int> row;
};

Nodes read_nodes(const GmshSession& session, const std::string& path) {
  std::vector<std::size_t> tags;
  std::vector<double> coords, params;
  session.guard([&] { gmsh::model::mesh::getNodes(tags, coords, params); }, "cannot read the nodes");
  Nodes n;
  n.points.resize(static_cast<Eigen::Index>(tags.size()), 3);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    n.points.row(static_cast<Eigen::Index>(i)) << coords[3 * i], coords[3 * i + 1], coords[3 * i + 2];
    if (!n.row.emplace(tags[i], static_cast<int>(i)).second)
      throw Error(path + ": node tag " + std::to_string(tags[i]) + " appears twice");
  }
  return n;
}

int row_of(const Nodes& n, std::size_t tag, const std::string& path) {
  const auto it = n.row.find(tag);
  if (it == n.row.end()) throw Error(path + ": an element uses node " + std::to_string(tag) + ", which is not defined");
  return it->second;
}

std::string element_name(const GmshSession& session, int type) {
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  session.guard([&] { gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary); },
                "unknown element type");
  return name + " (gmsh element type " + std::to_string(type) + ")";
}

// Node rows of every element of `type`, N nodes each.
template <std::size_t N>
std::vector<std::array<int, N>> elements(const GmshSession& session, const Nodes& nodes, int type,
                                         const std::string& path) {
  std::vector<std::size_t> tags, node_tags;
  session.guard([&] { gmsh::model::mesh::getElementsByType(type, tags, node_tags); }, "cannot read the elements");
  std::vector<std::array<int, N>> out(tags.size());
  for (std::size_t e = 0; e < tags.size(); ++e)
    for (std::size_t k = 0; k < N; ++k) out[e][k] = row_of(nodes, node_tags[N * e + k], path);
  return out;
}

}  // namespace

TetMesh read_gmsh_tet_mesh(const std::string& path, std::vector<std::string>* warnings) {
  MixedMesh mixed;
  {
    GmshSession session(path);
    std::vector<int> types;
    session.guard([&] { gmsh::model::mesh::getElementTypes(types, 3); }, "cannot read the elements");
    for (int type : types)
      if (type != gmsh_tetrahedron)
        throw Error(path + ": the mesh has " + element_name(session, type) +
                    " elements; only linear tetrahedra are read (mesh with Mesh.ElementOrder = 1 and no recombination)");
    Nodes nodes = read_nodes(session, path);
    mixed.tets = elements<4>(session, nodes, gmsh_tetrahedron, path);
    mixed.tet_cells.resize(mixed.tets.size());
    for (std::size_t t = 0; t < mixed.tets.size(); ++t) mixed.tet_cells[t] = static_cast<long>(t);

    gmsh::vectorpair groups;
    session.guard([&] { gmsh::model::getPhysicalGroups(groups); }, "cannot read the physical groups");
    for (const auto& [dim, tag] : groups) {
      if (dim > 2) continue;
      std::string name;
      session.guard([&, dim = dim, tag = tag] { gmsh::model::getPhysicalName(dim, tag, name); },
                    "cannot read the physical names");
      if (name.empty()) name = std::to_string(tag);
      std::vector<std::size_t> member_tags;
      std::vector<double> coords;
      session.guard([&, dim = dim, tag = tag] { gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, member_tags, coords); },
                    "cannot read the nodes of a physical group");
      auto& members = mixed.groups[name];
      for (std::size_t t : member_tags) members.push_back(row_of(nodes, t, path));
    }
    mixed.points = std::move(nodes.points);
  }
  TetMesh mesh = body_of(mixed, path);
  validate_tet_mesh(mesh, path, warnings);
  return mesh;
}

TriangleMesh read_gmsh_triangle_mesh(const std::string& path, std::vector<std::string>* warnings) {
  TriangleMesh surface;
  {
    GmshSession session(path);
    const Nodes nodes = read_nodes(session, path);
    const auto triangles = elements<3>(session, nodes, gmsh_triangle, path);
    if (triangles.empty()) throw Error(path + ": no triangles (a cut surface needs a 2D mesh: gmsh -2)");
    // Keep only the points the triangles use, in their order.
    std::vector<int> new_id(static_cast<std::size_t>(nodes.points.rows()), -1);
    int used = 0;
    for (const auto& t : triangles)
      for (int v : t)
        if (new_id[v] < 0) new_id[v] = used++;
    surface.points.resize(used, 3);
    for (Eigen::Index i = 0; i < nodes.points.rows(); ++i)
      if (new_id[i] >= 0) surface.points.row(new_id[i]) = nodes.points.row(i);
    surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) surface.triangles(f, k) = new_id[triangles[f][k]];
  }
  validate_triangle_mesh(surface, path, warnings);
  return surface;
}

}  // namespace xfem
