// SPDX-License-Identifier: MIT
#include "xfem/io/gmsh_io.h"

#include <dlfcn.h>
#include <gmshc.h>

#include <array>
#include <map>
#include <mutex>

#include "xfem/core/atomic_file.h"
#include "xfem/core/boundary_groups.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/io/gmsh_check.h"
#include "xfem/io/vtk_io.h"

#ifndef XFEM_GMSH_LIBRARY
#define XFEM_GMSH_LIBRARY "libgmsh.so"
#endif

namespace xfem {
namespace {

constexpr int gmsh_triangle = 2, gmsh_tetrahedron = 4;

// gmsh's library and the ~90 libraries it needs take longer to load (~80 ms) than a small
// pipeline stage takes in all, and only .msh input needs them: the tools do not link it, it is
// loaded here on the first .msh file (dlopen), and its C API (gmshc.h) called through pointers
// whose types are those of the header the library was built against.
struct GmshApi {
#define XFEM_GMSH_FUNCTIONS(X)                                                                             \
  X(gmshFree) X(gmshInitialize) X(gmshFinalize) X(gmshOpen) X(gmshOptionSetNumber) X(gmshLoggerGetLastError) \
  X(gmshModelMeshGetNodes) X(gmshModelMeshGetElementProperties) X(gmshModelMeshGetElementsByType)           \
  X(gmshModelMeshGetElementTypes) X(gmshModelGetPhysicalGroups) X(gmshModelGetPhysicalName)                 \
  X(gmshModelMeshGetNodesForPhysicalGroup) X(gmshModelGetEntitiesForPhysicalGroup)
#define XFEM_GMSH_POINTER(f) decltype(&::f) f = nullptr;
  XFEM_GMSH_FUNCTIONS(XFEM_GMSH_POINTER)
#undef XFEM_GMSH_POINTER
  std::string error;  ///< why the library could not be loaded; empty when loaded
};

const GmshApi& gmsh_api() {
  static const GmshApi api = [] {
    GmshApi a;
    void* library = ::dlopen(XFEM_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      const char* why = ::dlerror();
      a.error = std::string("gmsh's library ") + XFEM_GMSH_LIBRARY + " cannot be loaded (" + (why ? why : "?") +
                "; install libgmsh-dev, scripts/install-deps.sh)";
      return a;
    }
#define XFEM_GMSH_LOAD(f)                                                         \
  a.f = reinterpret_cast<decltype(&::f)>(::dlsym(library, #f));                   \
  if (!a.f && a.error.empty()) a.error = std::string(XFEM_GMSH_LIBRARY) + " has no " #f;
    XFEM_GMSH_FUNCTIONS(XFEM_GMSH_LOAD)
#undef XFEM_GMSH_LOAD
    return a;  // the library stays loaded for the life of the process
  }();
  return api;
}
#undef XFEM_GMSH_FUNCTIONS

// An array gmsh allocated (gmshMalloc), freed with gmshFree.
template <class T>
struct GmshArray {
  T* data = nullptr;
  std::size_t size = 0;
  GmshArray() = default;
  GmshArray(const GmshArray&) = delete;
  GmshArray& operator=(const GmshArray&) = delete;
  ~GmshArray() {
    if (data) gmsh_api().gmshFree(data);
  }
  T* begin() const { return data; }
  T* end() const { return data + size; }
  T operator[](std::size_t i) const { return data[i]; }
};

// A string gmsh allocated; its text, freed.
std::string take_string(char* s) {
  std::string out = s ? s : "";
  if (s) gmsh_api().gmshFree(s);
  return out;
}

// gmsh's library is one global state: one file at a time, initialised quietly (no terminal
// output, no user configuration files) and finalised whatever happens.
class GmshSession {
 public:
  explicit GmshSession(const std::string& path) : lock_(mutex()), path_(path), api_(gmsh_api()) {
    require_readable(path);  // gmsh's open only logs a missing file and carries on
    if (!api_.error.empty()) throw Error(path + ": cannot read gmsh files: " + api_.error);
    int ierr = 0;
    api_.gmshInitialize(0, nullptr, 0, &ierr);
    if (ierr) throw Error(path + ": cannot start gmsh's library");
    try {
      api_.gmshOptionSetNumber("General.Terminal", 0, &ierr);
      check_gmsh_elements(path, [&](int type) { return element_type(type); });
      guard([&](int* e) { api_.gmshOpen(path.c_str(), e); }, "cannot read the gmsh file");
    } catch (...) {
      api_.gmshFinalize(&ierr);  // the destructor does not run when the constructor throws
      throw;
    }
  }
  ~GmshSession() {
    int ierr = 0;
    api_.gmshFinalize(&ierr);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  const GmshApi& api() const { return api_; }

  // gmsh's name, dimension and node count of an element type number.
  GmshElementType element_type(int type) const {
    char* name = nullptr;
    GmshElementType t;
    int order = 0, primary = 0, ierr = 0;
    GmshArray<double> local;
    api_.gmshModelMeshGetElementProperties(type, &name, &t.dim, &order, &t.nodes, &local.data, &local.size, &primary,
                                           &ierr);
    t.name = take_string(name);
    if (ierr || t.nodes < 1 || t.name.empty())
      throw Error(path_ + ": element type " + std::to_string(type) + " is not a gmsh element type");
    return t;
  }

  // Runs a gmsh call (given its error flag); on failure gmsh's last logged error is the message.
  template <class F>
  void guard(F&& call, const char* what) const {
    int ierr = 0;
    call(&ierr);
    if (ierr == 0) return;
    char* last = nullptr;
    int last_error = 0;
    api_.gmshLoggerGetLastError(&last, &last_error);
    const std::string message = last_error ? std::string() : take_string(last);
    throw Error(path_ + ": " + what + (message.empty() ? std::string() : ": " + message));
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  std::string path_;
  const GmshApi& api_;
};

// All nodes of the model, and a map from gmsh's node tags (any positive numbers) to rows.
struct Nodes {
  Points points;
  std::map<std::size_t, int> row;
};

Nodes read_nodes(const GmshSession& session, const std::string& path) {
  GmshArray<std::size_t> tags;
  GmshArray<double> coords, params;
  session.guard([&](int* e) {
    session.api().gmshModelMeshGetNodes(&tags.data, &tags.size, &coords.data, &coords.size, &params.data, &params.size,
                                        -1, -1, 0, 0, e);
  }, "cannot read the nodes");
  Nodes n;
  n.points.resize(static_cast<Eigen::Index>(tags.size), 3);
  for (std::size_t i = 0; i < tags.size; ++i) {
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
  char* name = nullptr;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  GmshArray<double> local;
  session.guard([&](int* e) {
    session.api().gmshModelMeshGetElementProperties(type, &name, &dim, &order, &nodes, &local.data, &local.size,
                                                    &primary, e);
  }, "unknown element type");
  return take_string(name) + " (gmsh element type " + std::to_string(type) + ")";
}

// The tags of the elements of `type` in the entity `entity` (-1: all entities), and their node
// tags (N per element).
struct ElementTags {
  GmshArray<std::size_t> tags, nodes;
};
void element_tags(const GmshSession& session, int type, int entity, ElementTags& out) {
  session.guard([&](int* e) {
    session.api().gmshModelMeshGetElementsByType(type, &out.tags.data, &out.tags.size, &out.nodes.data,
                                                 &out.nodes.size, entity, 0, 1, e);
  }, "cannot read the elements");
}

// Node rows of every element of `type`, N nodes each; their gmsh tags into `tags` if given.
template <std::size_t N>
std::vector<std::array<int, N>> elements(const GmshSession& session, const Nodes& nodes, int type,
                                         const std::string& path, std::vector<std::size_t>* tags = nullptr) {
  ElementTags e;
  element_tags(session, type, -1, e);
  if (e.nodes.size != N * e.tags.size) throw Error(path + ": gmsh returned elements with a wrong number of nodes");
  std::vector<std::array<int, N>> out(e.tags.size);
  for (std::size_t i = 0; i < e.tags.size; ++i)
    for (std::size_t k = 0; k < N; ++k) out[i][k] = row_of(nodes, e.nodes[N * i + k], path);
  if (tags) tags->assign(e.tags.begin(), e.tags.end());
  return out;
}

// Each physical volume's tag becomes the region of its tets, its name the region's name (docs/
// FORMATS.md "gmsh meshes"); tets in no physical volume are region 0. A tet in two physical
// volumes has no single material: an error. The regions go into `mixed` as the cell array
// "region" (body_of keeps it), the names into `names`; nothing when the file has no physical volume.
void read_physical_volumes(const GmshSession& session, const std::vector<std::size_t>& tet_tags,
                           const std::vector<std::pair<int, std::string>>& volumes, const std::string& path,
                           MixedMesh& mixed, std::map<int, std::string>& names) {
  if (volumes.empty()) return;
  std::map<std::size_t, std::size_t> row;
  for (std::size_t t = 0; t < tet_tags.size(); ++t) row.emplace(tet_tags[t], t);
  std::vector<int> region(tet_tags.size(), 0);
  for (const auto& [tag, name] : volumes) {
    if (tag < 0) throw Error(path + ": physical volume " + std::to_string(tag) + " has a negative tag");
    if (!name.empty()) names[tag] = name;
    GmshArray<int> entities;
    session.guard([&](int* e) {
      session.api().gmshModelGetEntitiesForPhysicalGroup(3, tag, &entities.data, &entities.size, e);
    }, "cannot read the entities of a physical volume");
    for (int entity : entities) {
      ElementTags e;
      element_tags(session, gmsh_tetrahedron, entity, e);
      for (std::size_t element : e.tags) {
        const auto it = row.find(element);
        if (it == row.end()) continue;
        int& r = region[it->second];
        if (r != 0 && r != tag)
          throw Error(path + ": tetrahedron " + std::to_string(element) + " is in the physical volumes " +
                      std::to_string(r) + " and " + std::to_string(tag) + " (one region per tet)");
        r = tag;
      }
    }
  }
  DataArray array = make_array(DataArray::Type::Int32, 1, region.size());
  array.values.assign(region.begin(), region.end());
  mixed.cell_data[region_array_name] = std::move(array);
}

}  // namespace

TetMesh read_gmsh_tet_mesh(const std::string& path, std::vector<std::string>* warnings) {
  MixedMesh mixed;
  std::map<int, std::string> region_names;
  {
    GmshSession session(path);
    GmshArray<int> types;
    session.guard([&](int* e) { session.api().gmshModelMeshGetElementTypes(&types.data, &types.size, 3, -1, e); },
                  "cannot read the elements");
    for (int type : types)
      if (type != gmsh_tetrahedron)
        throw Error(path + ": the mesh has " + element_name(session, type) +
                    " elements; only linear tetrahedra are read (mesh with Mesh.ElementOrder = 1 and no recombination)");
    Nodes nodes = read_nodes(session, path);
    std::vector<std::size_t> tet_tags;
    mixed.tets = elements<4>(session, nodes, gmsh_tetrahedron, path, &tet_tags);
    mixed.tet_cells.resize(mixed.tets.size());
    for (std::size_t t = 0; t < mixed.tets.size(); ++t) mixed.tet_cells[t] = static_cast<long>(t);

    std::vector<std::pair<int, std::string>> volumes;  // physical volumes: tag, name
    GmshArray<int> groups;  // (dim, tag) pairs
    session.guard([&](int* e) { session.api().gmshModelGetPhysicalGroups(&groups.data, &groups.size, -1, e); },
                  "cannot read the physical groups");
    for (std::size_t g = 0; g + 1 < groups.size; g += 2) {
      const int dim = groups[g], tag = groups[g + 1];
      char* raw_name = nullptr;
      session.guard([&](int* e) { session.api().gmshModelGetPhysicalName(dim, tag, &raw_name, e); },
                    "cannot read the physical names");
      std::string name = take_string(raw_name);
      if (dim == 3) {
        volumes.emplace_back(tag, name);
        continue;
      }
      if (name.empty()) name = std::to_string(tag);
      GmshArray<std::size_t> member_tags;
      GmshArray<double> coords;
      session.guard([&](int* e) {
        session.api().gmshModelMeshGetNodesForPhysicalGroup(dim, tag, &member_tags.data, &member_tags.size, &coords.data,
                                                            &coords.size, e);
      }, "cannot read the nodes of a physical group");
      auto& members = mixed.groups[name];
      for (std::size_t t : member_tags) members.push_back(row_of(nodes, t, path));
    }
    mixed.points = std::move(nodes.points);
    read_physical_volumes(session, tet_tags, volumes, path, mixed, region_names);
  }
  TetMesh mesh = body_of(mixed, path);
  mesh.region_names = std::move(region_names);
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
