// SPDX-License-Identifier: MIT
#include "xfem/enrich/split_by_cuts.h"

#include <algorithm>

namespace xfem {

TetCorners tet_corners(const TetMesh& mesh, int t) {
  TetCorners p;
  for (int c = 0; c < 4; ++c) p[c] = mesh.points.row(mesh.tets(t, c)).transpose();
  return p;
}

double longest_edge(const TetCorners& p) {
  double h = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) h = std::max(h, (p[i] - p[j]).norm());
  return h;
}

void split_by_cuts(const TetCorners& p, const std::vector<const CutSurface*>& cuts, const std::vector<int>& classes,
                   const std::vector<const CrackFront*>& fronts, std::vector<TetCorners>& pieces, std::vector<Sides>& sides) {
  const int K = static_cast<int>(cuts.size());
  Sides base{};
  std::vector<int> cutters;
  for (int k = 0; k < K; ++k)
    if (classes[k] != 0) cutters.push_back(k);
  pieces.clear();
  sides.clear();
  // The cuts that do not cut the tet: their side at each piece's centroid. Not at the tet's: a tet
  // next to a junction can straddle the plane of the secondary cut extended beyond its end, and its
  // pieces on the primary cut's far side must not inherit a side from the near one.
  const auto finish = [&] {
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      const Eigen::Vector3d c = 0.25 * (pieces[q][0] + pieces[q][1] + pieces[q][2] + pieces[q][3]);
      for (int k = 0; k < K; ++k)
        if (classes[k] == 0) sides[q][k] = cuts[k]->side(c);
    }
  };
  if (cutters.size() == 1 && classes[cutters[0]] == 1) {
    const int k = cutters[0];
    const CutPieces cp = split_at_front(p, *cuts[k], cuts[k]->triangles_meeting(p), fronts[k]->segments());
    for (std::size_t i = 0; i < cp.tets.size(); ++i) {
      pieces.push_back(cp.tets[i]);
      Sides s = base;
      s[k] = cp.side[i];
      sides.push_back(s);
    }
    finish();
    return;
  }
  pieces.push_back(p);
  sides.push_back(base);
  std::vector<TetCorners> next_pieces;
  std::vector<Sides> next_sides;
  for (const int k : cutters) {
    const std::vector<int> meeting = cuts[k]->triangles_meeting(p);
    next_pieces.clear();
    next_sides.clear();
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      const CutPieces cp = split_by_cut(pieces[q], *cuts[k], meeting);
      for (std::size_t i = 0; i < cp.tets.size(); ++i) {
        next_pieces.push_back(cp.tets[i]);
        Sides s = sides[q];
        s[k] = cp.side[i];
        next_sides.push_back(s);
      }
    }
    pieces.swap(next_pieces);
    sides.swap(next_sides);
  }
  finish();
}

}  // namespace xfem
