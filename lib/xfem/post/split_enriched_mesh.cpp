// SPDX-License-Identifier: MIT
#include "xfem/post/split_enriched_mesh.h"

#include <array>
#include <utility>
#include <vector>

#include "xfem/enrich/side_codes.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/integrate/cut_element_splits.h"

namespace xfem {

namespace {

SplitMesh split_mesh_several(const EnrichedMesh& em) {
  const int K = static_cast<int>(em.cuts.size());
  const int T = em.tets(), V = static_cast<int>(em.mesh.points.rows());
  const CutElementSplits splits = split_cut_elements(em);
  SplitMesh out;
  std::vector<Eigen::Vector3d> pts;
  for (int v = 0; v < V; ++v) pts.push_back(em.mesh.points.row(v).transpose());
  out.point_tet.assign(V, -1);
  out.point_side.assign(V, 0);
  for (int t = 0; t < T; ++t)
    for (int c = 0; c < 4; ++c)
      if (out.point_tet[em.mesh.tets(t, c)] < 0) out.point_tet[em.mesh.tets(t, c)] = t;
  for (int v = 0; v < V; ++v) {
    int s[kMaxCuts];
    for (int k = 0; k < K; ++k) s[k] = em.cuts[k].side[v];
    out.point_side[v] = pack_sides(s, K);
  }
  std::vector<std::array<int, 4>> tets;
  std::vector<std::array<int, 3>> wound;
  for (int t = 0; t < T; ++t) {
    const int i = splits.index[t];
    if (i < 0) {
      tets.push_back({em.mesh.tets(t, 0), em.mesh.tets(t, 1), em.mesh.tets(t, 2), em.mesh.tets(t, 3)});
      out.parent.push_back(t);
      out.tet_side.push_back(0);
      continue;
    }
    bool partial = false;
    for (int k = 0; k < K; ++k) partial = partial || em.cuts[k].cut_class[t] == 1;
    partial ? ++out.split_partial : ++out.split_complete;
    const double tol = 1e-9 * longest_edge(tet_corners(em.mesh, t));
    for (int q = splits.first[i]; q < splits.first[i + 1]; ++q) {
      TetCorners p = splits.tets[q];
      if (signed_volume(p[0], p[1], p[2], p[3]) < 0) std::swap(p[1], p[2]);
      const int code = splits.side[q];
      const int base = static_cast<int>(pts.size());
      for (int c = 0; c < 4; ++c) {
        pts.push_back(p[c]);
        out.point_side.push_back(code);
        out.point_tet.push_back(t);
      }
      tets.push_back({base, base + 1, base + 2, base + 3});
      out.parent.push_back(t);
      out.tet_side.push_back(code);
      int s[kMaxCuts];
      for (int k = 0; k < K; ++k) s[k] = code_side(code, k);
      // Faces of the piece on a cut whose function is not 0 here: the wound (this side's face).
      for (int skip = 0; skip < 4; ++skip) {
        std::array<int, 3> f{};
        for (int c = 0, m = 0; c < 4; ++c)
          if (c != skip) f[m++] = c;
        const Eigen::Vector3d centre = (p[f[0]] + p[f[1]] + p[f[2]]) / 3.0;
        bool on = false;
        for (int k = 0; k < K && !on; ++k) {
          if (cut_function(em, k, s) == 0) continue;
          const CutSurface& cut = *em.cuts[k].cut;
          on = cut.closest(centre).distance <= tol && cut.closest(p[f[0]]).distance <= tol &&
               cut.closest(p[f[1]]).distance <= tol && cut.closest(p[f[2]]).distance <= tol;
        }
        if (!on) continue;
        Eigen::Vector3d nrm = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
        if (nrm.dot(p[skip] - p[f[0]]) > 0) std::swap(f[1], f[2]);  // normal out of the piece
        wound.push_back({base + f[0], base + f[1], base + f[2]});
        out.wound_side.push_back(code);
      }
    }
  }
  out.points.resize(static_cast<int>(pts.size()), 3);
  for (std::size_t i = 0; i < pts.size(); ++i) out.points.row(static_cast<int>(i)) = pts[i].transpose();
  out.tets.resize(static_cast<int>(tets.size()), 4);
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (int c = 0; c < 4; ++c) out.tets(static_cast<int>(i), c) = tets[i][c];
  out.wound.resize(static_cast<int>(wound.size()), 3);
  for (std::size_t i = 0; i < wound.size(); ++i)
    for (int c = 0; c < 3; ++c) out.wound(static_cast<int>(i), c) = wound[i][c];
  return out;
}

}  // namespace

SplitMesh split_mesh(const EnrichedMesh& em) {
  if (!em.cut) return unsplit_mesh(em.mesh, em.side);
  if (!em.cuts.empty()) return split_mesh_several(em);
  return split_mesh(em.mesh, em.side, em.cut_class, *em.cut, em.front.segments());
}

}  // namespace xfem
