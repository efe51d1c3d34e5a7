// SPDX-License-Identifier: MIT
#include "xfem/integrate/cut_element_splits.h"

#include <string>

#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/geometry/cut_pieces.h"

namespace xfem {

namespace {

/// split_cut_elements for several cuts.
CutElementSplits split_cut_elements_several(const EnrichedMesh& em) {
  const int K = static_cast<int>(em.cuts.size());
  CutElementSplits out;
  const int T = em.tets();
  out.index.assign(T, -1);
  out.first.push_back(0);
  std::vector<const CutSurface*> cuts(K);
  std::vector<const CrackFront*> fronts(K);
  for (int k = 0; k < K; ++k) {
    if (!em.cuts[k].cut) throw Error("several cuts: cut " + std::to_string(k) + " was not given");
    cuts[k] = em.cuts[k].cut.get();
    fronts[k] = &em.cuts[k].front;
  }
  std::vector<int> classes(K);
  std::vector<TetCorners> pieces;
  std::vector<Sides> sides;
  for (int t = 0; t < T; ++t) {
    int count = 0, partial = -1;
    for (int k = 0; k < K; ++k) {
      classes[k] = em.cuts[k].cut_class[t];
      count += classes[k] != 0;
      if (classes[k] == 1) partial = k;
    }
    if (count == 0) continue;
    if (count >= 3 || (partial >= 0 && count > 1))
      throw Error("tet " + std::to_string(t) + ": " + std::to_string(count) + " cuts meet it" +
                  (partial >= 0 ? " and the front of cut " + std::to_string(partial) + " runs through it" : "") +
                  ": not handled (xfem-classify refuses such meshes)");
    out.index[t] = static_cast<int>(out.first.size()) - 1;
    split_by_cuts(tet_corners(em.mesh, t), cuts, classes, fronts, pieces, sides);
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      out.tets.push_back(pieces[q]);
      out.side.push_back(pack_sides(sides[q].data(), K));
    }
    out.first.push_back(static_cast<int>(out.tets.size()));
  }
  return out;
}

}  // namespace

CutElementSplits split_cut_elements(const EnrichedMesh& em) {
  if (!em.cuts.empty()) return split_cut_elements_several(em);
  CutElementSplits out;
  const int tets = em.tets();
  out.index.assign(tets, -1);
  out.first.push_back(0);
  bool any = false;
  if (!em.cut_class.empty())
    for (int t = 0; t < tets && !any; ++t) any = em.cut_class[t] > 0;
  if (!any) return out;
  if (!em.cut) throw Error("conforming integration: the mesh has cut elements but no cut surface was given");
  const std::vector<FrontSegment>& front = em.front.segments();
  // Each cut tet is split on its own (in threads: the cut's queries are read-only), the pieces
  // then appended in tet order, so the result does not depend on the thread count.
  std::vector<int> cut_tets;
  for (int t = 0; t < tets; ++t)
    if (em.cut_class[t] != 0) cut_tets.push_back(t);
  std::vector<CutPieces> split(cut_tets.size());
  parallel_for(static_cast<long>(cut_tets.size()), [&](long begin, long end) {
    for (long i = begin; i < end; ++i) {
      const int t = cut_tets[i];
      TetCorners p;
      for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
      const std::vector<int> meeting = em.cut->triangles_meeting(p);
      split[i] = em.cut_class[t] == 2 ? split_by_cut(p, *em.cut, meeting) : split_at_front(p, *em.cut, meeting, front);
    }
  }, {}, 16);
  for (std::size_t i = 0; i < cut_tets.size(); ++i) {
    out.index[cut_tets[i]] = static_cast<int>(out.first.size()) - 1;
    out.tets.insert(out.tets.end(), split[i].tets.begin(), split[i].tets.end());
    out.side.insert(out.side.end(), split[i].side.begin(), split[i].side.end());
    out.first.push_back(static_cast<int>(out.tets.size()));
  }
  return out;
}

}  // namespace xfem
