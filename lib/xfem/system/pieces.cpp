// SPDX-License-Identifier: MIT
#include "xfem/system/pieces.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>

#include "xfem/core/error.h"
#include "xfem/core/union_find.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/integrate/cut_element_splits.h"

namespace xfem {

namespace {

/// A part's key: per cut, the value g_k + 1 (0..2) for the cuts that cut its tet, 3 (any) for the
/// others (the tet is whole for them), base 4. Two parts are the same region where they meet when
/// every cut has equal values or "any" in either.
using PartKey = std::uint64_t;
constexpr unsigned kAny = 3;
PartKey part_key(const EnrichedMesh& em, int t, const int* sides) {
  PartKey key = 0;
  for (int k = static_cast<int>(em.cuts.size()) - 1; k >= 0; --k)
    key = 4 * key + (em.cuts[k].cut_class[t] != 0 ? static_cast<unsigned>(cut_function(em, k, sides) + 1) : kAny);
  return key;
}
PartKey any_key(int cuts) {
  PartKey key = 0;
  for (int k = 0; k < cuts; ++k) key = 4 * key + kAny;
  return key;
}
bool same_region(PartKey a, PartKey b, int cuts) {
  for (int k = 0; k < cuts; ++k, a /= 4, b /= 4)
    if (a % 4 != kAny && b % 4 != kAny && a % 4 != b % 4) return false;
  return true;
}


/// find_pieces for several cuts: a cut tet is one part per region (the values of every g_k);
/// neighbours connect parts of the same region that both have a face on the shared face.
std::vector<Piece> find_pieces_several(const EnrichedMesh& em, const std::vector<char>& node_constrained) {
  const int K = static_cast<int>(em.cuts.size());
  const int T = em.tets();
  const CutElementSplits splits = split_cut_elements(em);
  // Parts: an uncut tet is one, a tet a front runs through is one touching every region (the
  // material is whole around the front), a cut tet one per region of its pieces.
  struct Part {
    PartKey key;
    std::vector<int> pieces;
  };
  std::vector<std::vector<Part>> parts(T);
  std::vector<int> first_id(T + 1, 0);
  int sides[kMaxCuts];
  for (int t = 0; t < T; ++t) {
    const int i = splits.index[t];
    bool partial = false;
    for (int k = 0; k < K; ++k) partial = partial || em.cuts[k].cut_class[t] == 1;
    if (i < 0 || partial) {
      parts[t].push_back({any_key(K), {}});
    } else {
      for (int q = splits.first[i]; q < splits.first[i + 1]; ++q) {
        for (int k = 0; k < K; ++k) sides[k] = code_side(splits.side[q], k);
        const PartKey key = part_key(em, t, sides);
        auto it = std::find_if(parts[t].begin(), parts[t].end(), [&](const Part& p) { return p.key == key; });
        if (it == parts[t].end())
          parts[t].push_back({key, {q}});
        else
          it->pieces.push_back(q);
      }
    }
    first_id[t + 1] = first_id[t] + static_cast<int>(parts[t].size());
  }
  UnionFind uf(first_id[T]);
  // Faces shared by two tets.
  std::vector<std::array<int, 5>> faces;  // 3 sorted nodes, tet, opposite corner
  faces.reserve(4 * static_cast<std::size_t>(T));
  for (int t = 0; t < T; ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 5> f{};
      for (int c = 0, m = 0; c < 4; ++c)
        if (c != skip) f[m++] = em.mesh.tets(t, c);
      std::sort(f.begin(), f.begin() + 3);
      f[3] = t;
      f[4] = skip;
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  // The parts of tet t with a face on the face opposite corner `skip`, with their keys.
  auto touching = [&](int t, int skip, std::vector<std::pair<int, PartKey>>& out) {
    out.clear();
    const auto& ps = parts[t];
    if (ps.size() == 1 && ps[0].pieces.empty()) {
      out.push_back({first_id[t], ps[0].key});
      return;
    }
    TetCorners p = tet_corners(em.mesh, t);
    const Eigen::Vector3d a = p[(skip + 1) % 4];
    const Eigen::Vector3d nrm = (p[(skip + 2) % 4] - a).cross(p[(skip + 3) % 4] - a).normalized();
    const double tol = 1e-9 * longest_edge(p);
    for (std::size_t j = 0; j < ps.size(); ++j) {
      bool on = false;
      for (int q : ps[j].pieces) {
        int count = 0;
        for (const auto& x : splits.tets[q]) count += std::abs(nrm.dot(x - a)) <= tol;
        on = on || count >= 3;
      }
      if (on) out.push_back({first_id[t] + static_cast<int>(j), ps[j].key});
    }
  };
  std::vector<std::pair<int, PartKey>> A, B;
  for (std::size_t i = 0; i + 1 < faces.size(); ++i) {
    const auto &f = faces[i], &g = faces[i + 1];
    if (f[0] != g[0] || f[1] != g[1] || f[2] != g[2]) continue;
    touching(f[3], f[4], A);
    touching(g[3], g[4], B);
    for (const auto& [pa, ka] : A)
      for (const auto& [pb, kb] : B)
        if (same_region(ka, kb, K)) uf.join(pa, pb);
  }
  std::vector<int> piece_of(first_id[T], -1);
  std::vector<Piece> pieces;
  for (int id = 0; id < first_id[T]; ++id) {
    const int root = uf.find(id);
    if (piece_of[root] < 0) {
      piece_of[root] = static_cast<int>(pieces.size());
      pieces.emplace_back();
    }
    ++pieces[piece_of[root]].tets;
  }
  for (int t = 0; t < T; ++t)
    for (int c = 0; c < 4; ++c) {
      const int v = em.mesh.tets(t, c);
      if (!node_constrained[v]) continue;
      for (int k = 0; k < K; ++k) sides[k] = em.cuts[k].side[v];
      const PartKey own = part_key(em, t, sides);
      for (std::size_t j = 0; j < parts[t].size(); ++j)
        if (same_region(parts[t][j].key, own, K))
          pieces[piece_of[uf.find(first_id[t] + static_cast<int>(j))]].constrained = true;
    }
  return pieces;
}

}  // namespace

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
  if (!m.cuts.empty()) return find_pieces_several(m, node_constrained);
  return find_pieces(m, node_constrained, shared_faces(m.mesh));
}

std::vector<Piece> find_pieces(const EnrichedMesh& m, const std::vector<char>& node_constrained,
                               const SharedFaces& shared) {
  if (!m.cuts.empty()) return find_pieces_several(m, node_constrained);  // finds its own faces
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

std::vector<Piece> find_pieces_held_by(const EnrichedMesh& mesh, const std::vector<long>& fixed) {
  std::vector<char> node_constrained(mesh.mesh.points.rows(), 0);
  for (long dof : fixed)
    if (dof / 3 < mesh.np) node_constrained[dof / 3] = 1;
  return find_pieces(mesh, node_constrained);
}

}  // namespace xfem
