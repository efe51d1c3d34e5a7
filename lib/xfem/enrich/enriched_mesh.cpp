// SPDX-License-Identifier: MIT
#include "xfem/enrich/enriched_mesh.h"

#include "xfem/core/cli.h"

#include <string>

#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/enrich/cut_files.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

namespace {

std::vector<long> to_long(const DataArray& a) { return std::vector<long>(a.values.begin(), a.values.end()); }
std::vector<int> ints(const DataArray& a) { return std::vector<int>(a.values.begin(), a.values.end()); }

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
    // A mesh classified with several cuts is read by read_enriched_mesh_cuts only.
    const auto count = m.field_data.find("cut_count");
    if (count != m.field_data.end() && !count->second.values.empty() && count->second.values[0] > 1)
      fail("classified with " + std::to_string(static_cast<long>(count->second.values[0])) +
           " cuts, but 1 is given (this tool takes one cut)");
    em.cut = std::make_shared<const CutSurface>(read_triangle_mesh(cut_path, warnings));
  }
  return em;
}

EnrichedMesh read_enriched_mesh_cuts(const std::string& vtu, const std::vector<std::string>& cut_paths,
                                     std::vector<std::string>* warnings) {
  EnrichedMesh em = read_enriched_mesh(vtu, "", warnings);
  std::vector<std::string> names;
  std::vector<TriangleMesh> cuts = read_cuts(cut_paths, names, warnings);
  const TetMesh& m = em.mesh;
  const int K = cut_count(m);
  if (K < 1 || K > kMaxCuts)
    throw Error(vtu + ": field array 'cut_count' is " + std::to_string(K) + ", expected 1.." + std::to_string(kMaxCuts));
  if (K == 1) {
    if (cuts.size() > 1)
      throw Error(vtu + ": classified with one cut, but " + std::to_string(cuts.size()) + " cuts are given");
    if (cuts.size() == 1) {
      check_cut_matches(m, vtu, cuts[0], names[0]);
      em.cut = std::make_shared<const CutSurface>(std::move(cuts[0]));
    }
    return em;
  }
  if (static_cast<int>(cuts.size()) != K)
    throw Error(vtu + ": classified with " + std::to_string(K) + " cuts, but " + std::to_string(cuts.size()) +
                " are given (--cut once per cut, in the order given to xfem-classify)");
  const std::size_t V = m.points.rows(), T = m.tets.rows();
  for (int k = 0; k < K; ++k) {
    Fingerprint recorded = 0;
    if (stored_fingerprint(m.field_data, "cut_fingerprint" + cut_suffix(k), &recorded) && fingerprint(cuts[k]) != recorded)
      throw Error(names[k] + ": not cut " + std::to_string(k) + " of " + vtu + " (cut " + to_string(fingerprint(cuts[k])) +
                  ", classified with " + to_string(recorded) + ")");
  }
  const DataArray& blocks = require_array(m.field_data, "cut_dof_blocks", "field", 4, K, vtu, "xfem-enrich");
  const DataArray& pblocks = require_array(m.field_data, "product_dof_blocks", "field", 4, static_cast<std::size_t>(-1), vtu, "xfem-enrich");
  const DataArray& junctions = require_array(m.field_data, "cut_junctions", "field", 2, K, vtu, "xfem-classify");
  long one = 0, branch = 0;
  em.cuts.resize(K);
  for (int k = 0; k < K; ++k) {
    CutLayer& c = em.cuts[k];
    c.side = ints(require_array(m.point_data, "side" + cut_suffix(k), "point", 1, V, vtu, "xfem-classify"));
    c.cut_class = ints(require_array(m.cell_data, "cut_class" + cut_suffix(k), "cell", 1, T, vtu, "xfem-classify"));
    for (std::size_t v = 0; v < V; ++v)
      if (c.side[v] != 1 && c.side[v] != -1)
        throw Error(vtu + ": point array 'side" + cut_suffix(k) + "': point " + std::to_string(v) + " is not +1 or -1");
    for (std::size_t t = 0; t < T; ++t)
      if (c.cut_class[t] < 0 || c.cut_class[t] > 2)
        throw Error(vtu + ": cell array 'cut_class" + cut_suffix(k) + "': tet " + std::to_string(t) + " is not 0, 1 or 2");
    TetMesh view;
    view.field_data["front_segments"] = require_array(m.field_data, "front_segments" + cut_suffix(k), "field", 6, static_cast<std::size_t>(-1), vtu, "xfem-classify");
    view.field_data["front_normals"] = require_array(m.field_data, "front_normals" + cut_suffix(k), "field", 3, static_cast<std::size_t>(-1), vtu, "xfem-classify");
    c.front = read_front(view, vtu);
    c.sign_first = static_cast<long>(blocks(k, 0));
    c.ns = static_cast<long>(blocks(k, 1));
    c.branch_first = static_cast<long>(blocks(k, 2));
    c.nb = static_cast<long>(blocks(k, 3));
    c.ends_on = static_cast<int>(junctions(k, 0));
    c.ends_side = static_cast<int>(junctions(k, 1));
    if (c.ends_on >= K || c.ends_on == k || (c.ends_on >= 0 && c.ends_side != 1 && c.ends_side != -1))
      throw Error(vtu + ": field array 'cut_junctions': cut " + std::to_string(k) + " has a bad junction");
    if (c.nb > 0 && c.front.empty())
      throw Error(vtu + ": cut " + std::to_string(k) + " has " + std::to_string(c.nb) + " branch nodes but no front");
    one += c.ns;
    branch += c.nb;
    c.cut = std::make_shared<const CutSurface>(std::move(cuts[k]));
  }
  for (std::size_t p = 0; p < pblocks.tuples(); ++p) {
    ProductBlock b{static_cast<int>(pblocks(p, 0)), static_cast<int>(pblocks(p, 1)), static_cast<long>(pblocks(p, 2)),
                   static_cast<long>(pblocks(p, 3))};
    if (b.a < 0 || b.b <= b.a || b.b >= K) throw Error(vtu + ": field array 'product_dof_blocks': bad pair");
    one += b.count;
    em.products.push_back(b);
  }
  if (one != em.ns || branch != em.nb)
    throw Error(vtu + ": field arrays 'cut_dof_blocks'/'product_dof_blocks' do not add up to 'dof_counts'");
  em.cut = em.cuts[0].cut;
  em.front = em.cuts[0].front;
  return em;
}

// The cut whose branch block holds `dof` (a branch DOF), or -1.
int branch_cut_of_dof(const EnrichedMesh& em, long dof) {
  for (std::size_t k = 0; k < em.cuts.size(); ++k)
    if (dof >= em.cuts[k].branch_first && dof < em.cuts[k].branch_first + 4 * em.cuts[k].nb) return static_cast<int>(k);
  return -1;
}

int branch_cut_of_tet(const EnrichedMesh& em, int t) {
  for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e) {
    const long dof = em.dofs[e];
    if (dof < em.np + em.ns) continue;
    if (em.cuts.empty()) return 0;
    const int k = branch_cut_of_dof(em, dof);
    if (k >= 0) return k;
  }
  return -1;
}

const CrackFront& front_of_tet(const EnrichedMesh& em, int t) {
  if (em.cuts.empty()) return em.front;
  const int k = branch_cut_of_tet(em, t);
  return k < 0 ? em.front : em.cuts[k].front;
}

const CutSurface* cut_of_tet(const EnrichedMesh& em, int t) {
  if (em.cuts.empty()) return em.cut.get();
  const int k = branch_cut_of_tet(em, t);
  return k < 0 ? em.cut.get() : em.cuts[k].cut.get();
}

EnrichedMesh read_enriched_mesh_to_solve(const std::string& vtu, const std::vector<std::string>& cut_paths) {
  std::vector<std::string> warnings;
  EnrichedMesh em = read_enriched_mesh_cuts(vtu, cut_paths, &warnings);
  for (const auto& w : warnings) cli::warn(w);
  if (cut_paths.empty() && em.n > em.np)
    throw Error(vtu + ": " + std::to_string(em.n - em.np) +
                " enriched displacements (NS + 4 NB > 0) need the cut surface: give --cut");
  return em;
}

}  // namespace xfem
