// SPDX-License-Identifier: MIT
#include "xfem/system/pieces.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "xfem/core/error.h"
#include "xfem/core/union_find.h"

namespace xfem {

SharedFaces shared_faces(const TetMesh& mesh) {
  const int nt = static_cast<int>(mesh.tets.rows()), nv = static_cast<int>(mesh.points.rows());
  // Sorted node triples, equal neighbours after sorting. The sort is a counting sort by the lowest
  // node followed by small sorts within each node's faces (about 20 each): the same order as one
  // std::sort of all 4T faces, 3-4x faster on the 466k-tet reference (docs/PERFORMANCE.md,
  // "Speed-up").
  std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);  // faces with lowest node v: start[v]..
  const auto face_of = [&](int t, int skip) {
    std::array<int, 4> f{};
    int k = 0;
    for (int c = 0; c < 4; ++c)
      if (c != skip) f[k++] = mesh.tets(t, c);
    std::sort(f.begin(), f.begin() + 3);
    f[3] = t;
    return f;
  };
  for (int t = 0; t < nt; ++t) {
    for (int c = 0; c < 4; ++c)
      if (mesh.tets(t, c) < 0 || mesh.tets(t, c) >= nv)
        throw Error("find_pieces: tet " + std::to_string(t) + " has node " + std::to_string(mesh.tets(t, c)) +
                    " outside the " + std::to_string(nv) + " points");
    for (int skip = 0; skip < 4; ++skip) ++start[face_of(t, skip)[0] + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::array<int, 4>> faces(4 * static_cast<std::size_t>(nt));  // 3 sorted nodes + tet
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t)
      for (int skip = 0; skip < 4; ++skip) {
        const auto f = face_of(t, skip);
        faces[fill[f[0]]++] = f;
      }
  }
  for (int v = 0; v < nv; ++v) std::sort(faces.begin() + start[v], faces.begin() + start[v + 1]);
  SharedFaces out;
  out.tets = nt;
  out.points = nv;
  for (std::size_t k = 0; k + 1 < faces.size(); ++k) {
    const auto &a = faces[k], &b = faces[k + 1];
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) out.faces.push_back({a[0], a[1], a[2], a[3], b[3]});
  }
  return out;
}

std::vector<Piece> find_pieces(const EnrichedMesh& m, const std::vector<char>& node_constrained) {
  return find_pieces(m, node_constrained, shared_faces(m.mesh));
}

std::vector<Piece> find_pieces(const EnrichedMesh& m, const std::vector<char>& node_constrained,
                               const SharedFaces& shared) {
  const int nt = m.tets(), nv = static_cast<int>(m.mesh.points.rows());
  if (static_cast<int>(m.cut_class.size()) != nt)
    throw Error("find_pieces: " + std::to_string(m.cut_class.size()) + " cut classes for " + std::to_string(nt) + " tets");
  if (static_cast<int>(m.side.size()) != nv || static_cast<int>(node_constrained.size()) != nv)
    throw Error("find_pieces: side/constraint arrays do not match the " + std::to_string(nv) + " points");
  if (shared.tets != nt || shared.points != nv)
    throw Error("find_pieces: the shared faces are of another mesh");
  // Part ids: 2t for tet t (the half above the cut if t is completely cut), 2t + 1 the half below.
  const auto complete = [&](int t) { return m.cut_class[t] == 2; };
  const auto part_on = [&](int t, int side) { return complete(t) && side < 0 ? 2 * t + 1 : 2 * t; };
  UnionFind uf(2 * nt);

  // 1. Faces shared by two tets.
  for (const auto& a : shared.faces) {
    int t1 = a[3], t2 = a[4];
    if (complete(t2)) std::swap(t1, t2);  // t1 is the completely cut one, if any
    if (!complete(t1)) {
      uf.join(2 * t1, 2 * t2);
    } else if (complete(t2) || m.cut_class[t2] == 1) {
      // Both halves meet a neighbour's same-side half (complete) or its single part (partial).
      uf.join(2 * t1, 2 * t2);
      uf.join(2 * t1 + 1, part_on(t2, -1));
    } else {
      // An uncut tet has no cut edge, so the shared face lies on one side: its nodes' side.
      const int s = m.side[a[0]] + m.side[a[1]] + m.side[a[2]];
      uf.join(part_on(t1, s >= 0 ? 1 : -1), 2 * t2);
    }
  }

  // 2. Pieces in order of their lowest part id (roots are the lowest ids).
  std::vector<int> piece_of(2 * nt, -1);
  std::vector<Piece> pieces;
  for (int id = 0; id < 2 * nt; ++id) {
    if (id % 2 == 1 && !complete(id / 2)) continue;  // not a part
    const int root = uf.find(id);
    if (piece_of[root] < 0) {
      piece_of[root] = static_cast<int>(pieces.size());
      pieces.emplace_back();
    }
    ++pieces[piece_of[root]].tets;
  }
  // 3. A constrained node holds the part on its own side of every tet around it.
  for (int t = 0; t < nt; ++t)
    for (int c = 0; c < 4; ++c) {
      const int v = m.mesh.tets(t, c);
      if (node_constrained[v]) pieces[piece_of[uf.find(part_on(t, m.side[v]))]].constrained = true;
    }
  return pieces;
}

}  // namespace xfem
