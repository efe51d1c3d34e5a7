// SPDX-License-Identifier: MIT
#include "xfem/enrich/enriched_mesh.h"

#include <string>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

namespace {

std::vector<long> to_long(const DataArray& a) { return std::vector<long>(a.values.begin(), a.values.end()); }

}  // namespace

EnrichedMesh read_enriched_mesh(const std::string& vtu, const std::string& cut_path,
                                std::vector<std::string>* warnings) {
  EnrichedMesh em;
  em.mesh = read_tet_mesh(vtu, warnings);
  const TetMesh& m = em.mesh;
  const std::size_t V = m.points.rows(), T = m.tets.rows();
  auto fail = [&](const std::string& what) { throw Error(vtu + ": " + what); };

  // Decisions of xfem-classify.
  const DataArray& side = require_array(m.point_data, "side", "point", 1, V, vtu, "xfem-classify");
  const DataArray& cls = require_array(m.cell_data, "cut_class", "cell", 1, T, vtu, "xfem-classify");
  em.side.resize(V);
  for (std::size_t i = 0; i < V; ++i) {
    if (side(i) != 1 && side(i) != -1)
      fail("point array 'side': point " + std::to_string(i) + " has " + std::to_string(side(i)) + ", expected +1 or -1");
    em.side[i] = static_cast<int>(side(i));
  }
  em.cut_class.resize(T);
  for (std::size_t t = 0; t < T; ++t) {
    if (cls(t) != 0 && cls(t) != 1 && cls(t) != 2)
      fail("cell array 'cut_class': tet " + std::to_string(t) + " has " + std::to_string(cls(t)) + ", expected 0, 1 or 2");
    em.cut_class[t] = static_cast<int>(cls(t));
  }
  em.front = read_front(m, vtu);

  // The numbering of xfem-enrich.
  const DataArray& counts = require_array(m.field_data, "dof_counts", "field", 1, 4, vtu, "xfem-enrich");
  em.np = static_cast<long>(counts(0));
  em.ns = static_cast<long>(counts(1));
  em.nb = static_cast<long>(counts(2));
  em.n = static_cast<long>(counts(3));
  if (em.np != static_cast<long>(V) || em.ns < 0 || em.nb < 0 || em.n != em.np + em.ns + 4 * em.nb)
    fail("field array 'dof_counts' (" + std::to_string(em.np) + ", " + std::to_string(em.ns) + ", " +
         std::to_string(em.nb) + ", " + std::to_string(em.n) + ") violates NP = #points = " + std::to_string(V) +
         ", N = NP + NS + 4 NB");
  em.offsets = to_long(require_array(m.field_data, "extended_offsets", "field", 1, T + 1, vtu, "xfem-enrich"));
  if (em.offsets[0] != 0) fail("field array 'extended_offsets' does not start at 0");
  for (std::size_t t = 0; t < T; ++t)
    if (em.offsets[t + 1] - em.offsets[t] < 4)
      fail("field array 'extended_offsets': tet " + std::to_string(t) + " has fewer than 4 entries");
  const std::size_t size = static_cast<std::size_t>(em.offsets[T]);
  em.dofs = to_long(require_array(m.field_data, "extended_dofs", "field", 1, size, vtu, "xfem-enrich"));
  const DataArray& local = require_array(m.field_data, "extended_local", "field", 1, size, vtu, "xfem-enrich");
  em.local.assign(local.values.begin(), local.values.end());
  for (std::size_t t = 0; t < T; ++t) {
    const long o = em.offsets[t];
    for (int k = 0; k < 4; ++k)
      if (em.dofs[o + k] != m.tets(t, k) || em.local[o + k] != k)
        fail("field arrays 'extended_dofs'/'extended_local': tet " + std::to_string(t) +
             " does not start with its 4 nodes in order");
    for (long i = o + 4; i < em.offsets[t + 1]; ++i) {
      if (em.dofs[i] < em.np || em.dofs[i] >= em.n)
        fail("field array 'extended_dofs': tet " + std::to_string(t) + " has enriched DOF " +
             std::to_string(em.dofs[i]) + " outside " + std::to_string(em.np) + ".." + std::to_string(em.n - 1));
      if (em.local[i] < 0 || em.local[i] > 3)
        fail("field array 'extended_local': tet " + std::to_string(t) + " has local id " + std::to_string(em.local[i]));
    }
  }
  if (em.nb > 0 && em.front.empty() && !m.field_data.count("cut_count"))  // several cuts: checked per cut
    fail(std::to_string(em.nb) + " branch-enriched points but the fields 'front_segments' are empty");
  if (!cut_path.empty()) {
    // A mesh classified with several cuts is read by read_enriched_mesh_cuts (several_cuts.h) only.
    const auto count = m.field_data.find("cut_count");
    if (count != m.field_data.end() && !count->second.values.empty() && count->second.values[0] > 1)
      fail("classified with " + std::to_string(static_cast<long>(count->second.values[0])) +
           " cuts, but 1 is given (this tool takes one cut)");
    em.cut = std::make_shared<const CutSurface>(read_triangle_mesh(cut_path, warnings));
  }
  return em;
}

}  // namespace xfem
