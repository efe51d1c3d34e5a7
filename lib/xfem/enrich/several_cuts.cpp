// SPDX-License-Identifier: MIT
#include "xfem/enrich/several_cuts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <cstdint>
#include <cstdio>
#include <set>

#include "xfem/enrich/branch_functions.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/core/error.h"
#include "xfem/core/union_find.h"
#include "xfem/core/fingerprint.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

namespace {

using Sides = std::array<int, kMaxCuts>;

std::string suffix(int k) { return k == 0 ? std::string() : "_" + std::to_string(k); }
std::string pair_suffix(int a, int b) { return "_" + std::to_string(a) + "_" + std::to_string(b); }

double diagonal(const Points& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

TetCorners corners(const TetMesh& mesh, int t) {
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

/// The enrichment value g_k given the sides of every cut and the junctions.
int junction_value(const std::vector<int>& ends_on, const std::vector<int>& ends_side, int k, const int* s) {
  if (ends_on[k] >= 0 && s[ends_on[k]] != ends_side[k]) return 0;
  return s[k];
}

/// Region code of the values g_0..g_{K-1} in {-1, 0, 1}: base 3.
int region_code(const std::vector<int>& ends_on, const std::vector<int>& ends_side, const int* s, int K) {
  int code = 0;
  for (int k = K - 1; k >= 0; --k) code = 3 * code + junction_value(ends_on, ends_side, k, s) + 1;
  return code;
}
int region_value(int code, int k) {
  for (int i = 0; i < k; ++i) code /= 3;
  return code % 3 - 1;
}

/// The pieces of tet p split by every cut that cuts it (classes[k] != 0), each with the side of
/// every cut; a tet only one cut's front runs through is split at that front (split_at_front).
void split_tet(const TetCorners& p, const std::vector<const CutSurface*>& cuts, const std::vector<int>& classes,
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

/// Does segment [a, b] run through the inside of tet p (a piece of positive length whose middle
/// lies strictly inside)?
bool segment_inside(const TetCorners& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Matrix3d J;
  J << p[1] - p[0], p[2] - p[0], p[3] - p[0];
  const Eigen::Matrix3d Ji = J.inverse();
  auto bary = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d l = Ji * (x - p[0]);
    return Eigen::Vector4d(1 - l.sum(), l[0], l[1], l[2]);
  };
  const Eigen::Vector4d la = bary(a), lb = bary(b);
  double t0 = 0, t1 = 1;
  for (int i = 0; i < 4; ++i) {  // l_i(t) = la_i + t (lb_i - la_i) >= 0
    const double d = lb[i] - la[i];
    if (std::abs(d) < 1e-15) {
      if (la[i] < 0) return false;
      continue;
    }
    const double t = -la[i] / d;
    if (d > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  if (t1 - t0 < 1e-9) return false;
  const Eigen::Vector4d mid = bary(a + 0.5 * (t0 + t1) * (b - a));
  return mid.minCoeff() > 1e-10;
}

std::vector<int> ints(const DataArray& a) { return std::vector<int>(a.values.begin(), a.values.end()); }

DataArray int_array(DataArray::Type type, const std::vector<long>& v, int components = 1) {
  DataArray a = make_array(type, components, v.size() / components);
  std::copy(v.begin(), v.end(), a.values.begin());
  return a;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Reading cuts

std::vector<TriangleMesh> read_cuts(const std::vector<std::string>& paths, std::vector<std::string>& names,
                                    std::vector<std::string>* warnings) {
  std::vector<TriangleMesh> out;
  names.clear();
  for (const std::string& path : paths) {
    TriangleMesh m = read_triangle_mesh(path, warnings);
    const auto id = m.cell_data.find("cut_id");
    if (id == m.cell_data.end()) {
      out.push_back(std::move(m));
      names.push_back(path);
      continue;
    }
    const DataArray& a = id->second;
    if (a.components != 1) throw Error(path + ": cell array 'cut_id' has " + std::to_string(a.components) + " components, expected 1");
    std::set<long> values;
    for (std::size_t t = 0; t < a.values.size(); ++t) {
      if (!std::isfinite(a.values[t]) || a.values[t] != std::floor(a.values[t]))
        throw Error(path + ": cell array 'cut_id' of triangle " + std::to_string(t) + " is not a whole number");
      values.insert(static_cast<long>(a.values[t]));
    }
    for (const long v : values) {
      std::vector<int> keep, map(m.points.rows(), -1);
      for (int t = 0; t < m.triangles.rows(); ++t)
        if (static_cast<long>(a.values[t]) == v) keep.push_back(t);
      TriangleMesh piece;
      int np = 0;
      for (int t : keep)
        for (int c = 0; c < 3; ++c)
          if (map[m.triangles(t, c)] < 0) map[m.triangles(t, c)] = np++;
      piece.points.resize(np, 3);
      for (int i = 0; i < m.points.rows(); ++i)
        if (map[i] >= 0) piece.points.row(map[i]) = m.points.row(i);
      piece.triangles.resize(static_cast<int>(keep.size()), 3);
      for (std::size_t r = 0; r < keep.size(); ++r)
        for (int c = 0; c < 3; ++c) piece.triangles(static_cast<int>(r), c) = map[m.triangles(keep[r], c)];
      out.push_back(std::move(piece));
      names.push_back(path + "#" + std::to_string(v));
    }
  }
  if (out.size() > static_cast<std::size_t>(kMaxCuts))
    throw Error(std::to_string(out.size()) + " cuts given, at most " + std::to_string(kMaxCuts) + " are handled");
  return out;
}

// ---------------------------------------------------------------------------------------------
// Classification

CutsClassification classify_cuts(const TetMesh& mesh, const std::vector<const CutSurface*>& cuts,
                                 const ClassifyOptions& options) {
  const int K = static_cast<int>(cuts.size());
  if (K < 2 || K > kMaxCuts) throw Error("classify_cuts: " + std::to_string(K) + " cuts, expected 2.." + std::to_string(kMaxCuts));
  const int V = static_cast<int>(mesh.points.rows()), T = static_cast<int>(mesh.tets.rows());
  CutsClassification out;
  out.cuts.resize(K);
  for (int k = 0; k < K; ++k) {
    ClassifyOptions o = options;
    o.progress = [&options, k, K](double f) {
      if (options.progress) options.progress((k + f) / (K + 1));
    };
    try {
      out.cuts[k] = classify(mesh, *cuts[k], o);
    } catch (const Error& e) {
      throw Error("cut " + std::to_string(k) + ": " + e.what());
    }
  }

  // 1. T-junctions: front segments of cut k lying on cut i.
  const double tol = 1e-8 * diagonal(mesh.points);
  out.ends_on.assign(K, -1);
  out.ends_side.assign(K, 0);
  for (int k = 0; k < K; ++k) {
    std::vector<FrontSegment> remaining;
    bool dropped = false;
    for (const FrontSegment& s : out.cuts[k].front.segments()) {
      int on = -1;
      for (int i = 0; i < K && on < 0; ++i)
        if (i != k && cuts[i]->closest(s.p0).distance <= tol && cuts[i]->closest(s.p1).distance <= tol &&
            cuts[i]->closest(0.5 * (s.p0 + s.p1)).distance <= tol)
          on = i;
      if (on < 0) {
        remaining.push_back(s);
        continue;
      }
      if (out.ends_on[k] >= 0 && out.ends_on[k] != on)
        throw Error("cut " + std::to_string(k) + " ends on cuts " + std::to_string(out.ends_on[k]) + " and " +
                    std::to_string(on) + ": a cut ending on two cuts is not handled");
      out.ends_on[k] = on;
      dropped = true;
    }
    if (!dropped) continue;
    const int i = out.ends_on[k];
    // The side of cut i the cut lies on: at its triangle centroid farthest from cut i.
    const TriangleMesh& cm = cuts[k]->mesh();
    double far = -1;
    for (int t = 0; t < cm.triangles.rows(); ++t) {
      const Eigen::Vector3d c =
          (cm.points.row(cm.triangles(t, 0)) + cm.points.row(cm.triangles(t, 1)) + cm.points.row(cm.triangles(t, 2))).transpose() / 3.0;
      const double d = cuts[i]->closest(c).distance;
      if (d > far) {
        far = d;
        out.ends_side[k] = cuts[i]->side(c);
      }
    }
    // A cut that ends on cut i and also reaches its other side would lose that part (its function
    // is 0 there).
    for (int t = 0; t < cm.triangles.rows(); ++t)
      for (int n = 0; n < 3; ++n) {
        const Eigen::Vector3d x = cm.points.row(cm.triangles(t, n)).transpose();
        if (cuts[i]->closest(x).distance > tol && cuts[i]->side(x) != out.ends_side[k])
          throw Error("cut " + std::to_string(k) + " ends on cut " + std::to_string(i) + " and also reaches its other side "
                      "(triangle " + std::to_string(t) + "): not handled; split it into two cuts");
      }
    // Its tets along the junction are cut through now; branch nodes only where a front remains.
    Classification& c = out.cuts[k];
    c.front = CrackFront(remaining);
    for (int t = 0; t < T; ++t) {
      if (c.cut_class[t] != CutClass::Partial) continue;
      const TetCorners p = corners(mesh, t);
      bool inside = false;
      for (const FrontSegment& s : remaining) inside = inside || segment_inside(p, s.p0, s.p1);
      if (!inside) c.cut_class[t] = CutClass::Complete;
    }
    std::vector<char> branch(V, 0);
    for (int t = 0; t < T; ++t)
      if (c.cut_class[t] == CutClass::Partial)
        for (int n = 0; n < 4; ++n) branch[mesh.tets(t, n)] = 1;
    for (int v = 0; v < V; ++v)
      if (c.enrichment[v] == Enrichment::Branch && !branch[v]) c.enrichment[v] = Enrichment::None;  // decided below
    c.counts.front_segments = static_cast<long>(remaining.size());
  }
  for (int k = 0; k < K; ++k)
    if (out.ends_on[k] >= 0 && out.ends_on[out.ends_on[k]] == k)
      throw Error("cuts " + std::to_string(std::min(k, out.ends_on[k])) + " and " + std::to_string(std::max(k, out.ends_on[k])) +
                  " end on each other (a V-shaped junction): not handled; give them as one surface whose "
                  "triangles share the junction's points, or let one cut reach through the other");

  // 2. Every tet some cut meets, split by all cuts: volumes per region around each node.
  std::vector<const CrackFront*> fronts(K);
  for (int k = 0; k < K; ++k) fronts[k] = &out.cuts[k].front;
  std::vector<double> support(V, 0.0);
  std::vector<std::vector<std::pair<int, double>>> region(V);  // per node: (region code, volume)
  std::vector<char> in_cut_tet(T, 0);
  std::vector<TetCorners> pieces;
  std::vector<Sides> sides;
  std::vector<int> classes(K);
  for (int t = 0; t < T; ++t) {
    const double vol = std::abs(signed_volume(mesh, t));
    for (int n = 0; n < 4; ++n) support[mesh.tets(t, n)] += vol;
    std::vector<int> cutters;
    int partial = -1;
    for (int k = 0; k < K; ++k) {
      classes[k] = static_cast<int>(out.cuts[k].cut_class[t]);
      if (classes[k] != 0) cutters.push_back(k);
      if (classes[k] == 1) partial = k;
    }
    if (cutters.empty()) continue;
    if (cutters.size() >= 3)
      throw Error("tet " + std::to_string(t) + " meets cuts " + std::to_string(cutters[0]) + ", " +
                  std::to_string(cutters[1]) + " and " + std::to_string(cutters[2]) +
                  ": three cuts in one tet are not handled (refine the mesh there)");
    if (partial >= 0 && cutters.size() > 1)
      throw Error("tet " + std::to_string(t) + ": the front of cut " + std::to_string(partial) + " runs through it and cut " +
                  std::to_string(cutters[0] == partial ? cutters[1] : cutters[0]) +
                  " meets it: a front meeting another cut inside a tet is not handled (keep fronts a tet away from "
                  "other cuts, or let the cut reach through)");
    in_cut_tet[t] = 1;
    split_tet(corners(mesh, t), cuts, classes, fronts, pieces, sides);
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      const double v = std::abs(signed_volume(pieces[q][0], pieces[q][1], pieces[q][2], pieces[q][3]));
      for (int n = 0; n < 4; ++n) {
        // A cut that does not cut the tet has the node's own side all over it (as a sign DOF of one
        // cut enters cut tets only): ahead of a front its plane extended is no discontinuity. Not
        // for a node on the far side of the cut a junction cut ends on: its own side of the
        // junction cut means nothing there (the plane extended); the piece's is the tet's.
        Sides e = sides[q];
        const int node = mesh.tets(t, n);
        for (int k = 0; k < K; ++k) {
          const int i = out.ends_on[k];
          if (classes[k] == 0 && !(i >= 0 && out.cuts[i].side[node] != out.ends_side[k])) e[k] = out.cuts[k].side[node];
        }
        const int code = region_code(out.ends_on, out.ends_side, e.data(), K);
        auto& r = region[mesh.tets(t, n)];
        auto it = std::find_if(r.begin(), r.end(), [&](const auto& e) { return e.first == code; });
        if (it == r.end())
          r.push_back({code, v});
        else
          it->second += v;
      }
    }
    if (options.progress && t % 1024 == 0) options.progress((K + double(t) / T) / (K + 1));
  }

  // 3. Enrichments from the volumes. The regions of a node's support that hold at least
  // tiny_support of it; the node's functions, in the order cut 0, cut 1, ..., then the products
  // (a, b), each taken when it is not constant on those regions and not a combination of 1 and the
  // functions taken before (at a junction H_k restricted to its side of cut i can equal
  // (H_i + 1) / 2 on a support the secondary cut does not reach into: K would be singular).
  auto node_code = [&](int v) {
    Sides s{};
    for (int k = 0; k < K; ++k) s[k] = out.cuts[k].side[v];
    return region_code(out.ends_on, out.ends_side, s.data(), K);
  };
  for (int t = 0; t < T; ++t) {  // the rest of each support lies in the node's own region
    bool cut = false;
    for (int k = 0; k < K; ++k) cut = cut || out.cuts[k].cut_class[t] != CutClass::Uncut;
    if (cut) continue;
    const double vol = std::abs(signed_volume(mesh, t));
    for (int n = 0; n < 4; ++n) {
      const int v = mesh.tets(t, n);
      if (region[v].empty()) continue;
      const int own = node_code(v);
      auto it = std::find_if(region[v].begin(), region[v].end(), [&](const auto& e) { return e.first == own; });
      if (it == region[v].end())
        region[v].push_back({own, vol});
      else
        it->second += vol;
    }
  }
  std::vector<std::vector<char>> product_node(K * K);
  std::vector<long> product_count(K * K, 0);
  for (int k = 0; k < K; ++k) out.cuts[k].counts.sign_tiny = 0;
  for (int v = 0; v < V; ++v) {
    std::vector<int> kept;  // region codes holding enough of the support
    bool any = false;
    for (const auto& [code, vol] : region[v]) {
      if (vol > 0 && vol >= options.tiny_support * support[v]) kept.push_back(code);
      any = any || vol > 0;
    }
    // Gram-Schmidt on the value vectors over the kept regions, starting from the constant.
    std::vector<Eigen::VectorXd> basis;
    const int R = static_cast<int>(kept.size());
    auto independent = [&](Eigen::VectorXd f) {
      if (R == 0) return false;
      for (const auto& q : basis) f -= q.dot(f) * q;
      if (f.norm() <= 1e-9 * std::sqrt(static_cast<double>(R))) return false;
      basis.push_back(f / f.norm());
      return true;
    };
    independent(Eigen::VectorXd::Ones(R));
    for (int k = 0; k < K; ++k) {
      Classification& c = out.cuts[k];
      if (c.enrichment[v] == Enrichment::Branch) continue;
      Eigen::VectorXd f(R);
      for (int r = 0; r < R; ++r) f[r] = region_value(kept[r], k);
      if (independent(f)) {
        c.enrichment[v] = Enrichment::Sign;
        continue;
      }
      c.enrichment[v] = Enrichment::None;
      // Counted as tiny when the function varies only through regions below tiny_support.
      bool varies = false;
      const int own = region_value(node_code(v), k);
      for (const auto& [code, vol] : region[v]) varies = varies || (vol > 0 && region_value(code, k) != own);
      if (varies && any) {
        bool varies_kept = false;
        for (int r = 0; r < R; ++r) varies_kept = varies_kept || region_value(kept[r], k) != region_value(kept[0], k);
        if (!varies_kept) ++c.counts.sign_tiny;
      }
    }
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b) {
        if (out.cuts[a].enrichment[v] != Enrichment::Sign || out.cuts[b].enrichment[v] != Enrichment::Sign) continue;
        Eigen::VectorXd f(R);
        for (int r = 0; r < R; ++r) f[r] = region_value(kept[r], a) * region_value(kept[r], b);
        if (!independent(f)) {
          // All four sign combinations there, but one below tiny_support: not enriched (counted).
          int combos = 0;
          for (const auto& [code, vol] : region[v])
            if (vol > 0 && region_value(code, a) != 0 && region_value(code, b) != 0) ++combos;
          if (combos == 4) ++out.product_tiny;
          continue;
        }
        auto& node = product_node[a * K + b];
        if (node.empty()) node.assign(V, 0);
        node[v] = 1;
        ++product_count[a * K + b];
      }
  }
  for (int k = 0; k < K; ++k) {
    Classification& c = out.cuts[k];
    c.counts.none = c.counts.sign = c.counts.branch = 0;
    c.counts.partial = c.counts.complete = c.counts.uncut = 0;
    for (int v = 0; v < V; ++v) {
      c.counts.none += c.enrichment[v] == Enrichment::None;
      c.counts.sign += c.enrichment[v] == Enrichment::Sign;
      c.counts.branch += c.enrichment[v] == Enrichment::Branch;
    }
    for (int t = 0; t < T; ++t) {
      c.counts.uncut += c.cut_class[t] == CutClass::Uncut;
      c.counts.partial += c.cut_class[t] == CutClass::Partial;
      c.counts.complete += c.cut_class[t] == CutClass::Complete;
    }
  }
  for (int a = 0; a < K; ++a)
    for (int b = a + 1; b < K; ++b)
      if (product_count[a * K + b] > 0) {
        CutsClassification::Product p;
        p.a = a;
        p.b = b;
        p.node = std::move(product_node[a * K + b]);
        p.count = product_count[a * K + b];
        out.products.push_back(std::move(p));
      }

  // 4. Branch enrichments of two cuts in one tet would need two fronts' functions together.
  for (int t = 0; t < T; ++t) {
    int first = -1;
    for (int k = 0; k < K; ++k)
      for (int n = 0; n < 4; ++n)
        if (out.cuts[k].enrichment[mesh.tets(t, n)] == Enrichment::Branch) {
          if (first >= 0 && first != k)
            throw Error("tet " + std::to_string(t) + " has branch-enriched nodes of cuts " + std::to_string(first) + " and " +
                        std::to_string(k) + ": the fronts of two cuts this close are not handled (refine the mesh there)");
          first = k;
        }
  }
  if (options.progress) options.progress(1.0);
  return out;
}

void store_cuts_classification(const CutsClassification& c, TetMesh& mesh) {
  const int K = static_cast<int>(c.cuts.size());
  store_classification(c.cuts[0], mesh);
  for (int k = 1; k < K; ++k) {
    TetMesh scratch;
    scratch.points = mesh.points;
    scratch.tets = mesh.tets;
    store_classification(c.cuts[k], scratch);
    for (auto& [name, a] : scratch.point_data) mesh.point_data[name + suffix(k)] = std::move(a);
    for (auto& [name, a] : scratch.cell_data) mesh.cell_data[name + suffix(k)] = std::move(a);
    for (auto& [name, a] : scratch.field_data) mesh.field_data[name + suffix(k)] = std::move(a);
  }
  mesh.field_data["cut_count"] = make_array(DataArray::Type::Int32, 1, 1, K);
  DataArray j = make_array(DataArray::Type::Int32, 2, K);
  for (int k = 0; k < K; ++k) {
    j.values[2 * k] = c.ends_on[k];
    j.values[2 * k + 1] = c.ends_side[k];
  }
  mesh.field_data["cut_junctions"] = std::move(j);
  for (const auto& p : c.products) {
    DataArray a = make_array(DataArray::Type::Int32, 1, p.node.size());
    for (std::size_t v = 0; v < p.node.size(); ++v) a.values[v] = p.node[v];
    mesh.point_data["product_enrichment" + pair_suffix(p.a, p.b)] = std::move(a);
  }
}

int cut_count(const TetMesh& mesh) {
  const auto it = mesh.field_data.find("cut_count");
  if (it == mesh.field_data.end() || it->second.values.empty()) return 1;
  return static_cast<int>(it->second.values[0]);
}

void store_cut_fingerprints(const std::vector<TriangleMesh>& cuts, TetMesh& mesh) {
  for (std::size_t k = 0; k < cuts.size(); ++k)
    store_fingerprint(mesh.field_data, "cut_fingerprint" + suffix(static_cast<int>(k)), fingerprint(cuts[k]));
}

// ---------------------------------------------------------------------------------------------
// Numbering

namespace {

/// The product pairs present on a mesh (point arrays product_enrichment_a_b), sorted by (a, b).
std::vector<std::pair<int, int>> product_pairs(const DataArrays& point_data, const std::string& prefix) {
  std::vector<std::pair<int, int>> out;
  for (const auto& [name, a] : point_data) {
    if (name.rfind(prefix, 0) != 0) continue;
    int x = -1, y = -1;
    if (std::sscanf(name.c_str() + prefix.size(), "%d_%d", &x, &y) == 2 && x >= 0 && y > x) out.push_back({x, y});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

DofNumbering number_several_cuts(TetMesh& mesh, const std::string& file) {
  const int K = cut_count(mesh);
  if (K < 2 || K > kMaxCuts)
    throw Error(file + ": field array 'cut_count' is " + std::to_string(K) + ", expected 2.." + std::to_string(kMaxCuts));
  const long V = mesh.points.rows(), T = mesh.tets.rows();
  std::vector<std::vector<int>> enr(K), cls(K);
  for (int k = 0; k < K; ++k) {
    enr[k] = ints(require_array(mesh.point_data, "enrichment" + suffix(k), "point", 1, V, file, "xfem-classify"));
    cls[k] = ints(require_array(mesh.cell_data, "cut_class" + suffix(k), "cell", 1, T, file, "xfem-classify"));
    for (long v = 0; v < V; ++v)
      if (enr[k][v] < 0 || enr[k][v] > 2)
        throw Error(file + ": point array 'enrichment" + suffix(k) + "': point " + std::to_string(v) + " has " +
                    std::to_string(enr[k][v]) + ", expected 0, 1 or 2");
    for (long t = 0; t < T; ++t)
      if (cls[k][t] < 0 || cls[k][t] > 2)
        throw Error(file + ": cell array 'cut_class" + suffix(k) + "': tet " + std::to_string(t) + " has " +
                    std::to_string(cls[k][t]) + ", expected 0, 1 or 2");
  }
  const auto pairs = product_pairs(mesh.point_data, "product_enrichment_");
  std::vector<std::vector<int>> prod;
  for (const auto& [a, b] : pairs) {
    if (b >= K) throw Error(file + ": point array 'product_enrichment" + pair_suffix(a, b) + "' names a cut beyond the " + std::to_string(K));
    prod.push_back(ints(require_array(mesh.point_data, "product_enrichment" + pair_suffix(a, b), "point", 1, V, file, "xfem-classify")));
  }

  DofNumbering d;
  d.np = V;
  std::vector<std::vector<long>> sign(K, std::vector<long>(V, -1)), branch(K, std::vector<long>(V, -1)),
      product(pairs.size(), std::vector<long>(V, -1));
  std::vector<long> blocks(4 * K), pblocks;
  long next = V;
  for (int k = 0; k < K; ++k) {
    blocks[4 * k] = next;
    for (long v = 0; v < V; ++v)
      if (enr[k][v] == 1) sign[k][v] = next++;
    blocks[4 * k + 1] = next - blocks[4 * k];
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const long first = next;
    for (long v = 0; v < V; ++v)
      if (prod[p][v]) product[p][v] = next++;
    pblocks.insert(pblocks.end(), {pairs[p].first, pairs[p].second, first, next - first});
  }
  d.ns = next - V;
  for (int k = 0; k < K; ++k) {
    blocks[4 * k + 2] = next;
    for (long v = 0; v < V; ++v)
      if (enr[k][v] == 2) {
        branch[k][v] = next;
        next += 4;
      }
    blocks[4 * k + 3] = (next - blocks[4 * k + 2]) / 4;
  }
  d.nb = (next - V - d.ns) / 4;
  d.n = next;
  d.sign_dof = sign[0];
  d.branch_dof = branch[0];

  d.offsets.push_back(0);
  std::vector<std::pair<long, int>> extra;  // (first DOF, local node)
  for (long t = 0; t < T; ++t) {
    bool cut = false;
    for (int k = 0; k < K; ++k) cut = cut || cls[k][t] != 0;
    extra.clear();
    for (int c = 0; c < 4; ++c) {
      const int m = mesh.tets(t, c);
      d.dofs.push_back(m);
      d.local.push_back(c);
      for (int k = 0; k < K; ++k) {
        if (cut && sign[k][m] >= 0) extra.push_back({sign[k][m], c});
        if (branch[k][m] >= 0) extra.push_back({branch[k][m], c});
      }
      for (std::size_t p = 0; p < pairs.size(); ++p)
        if (cut && product[p][m] >= 0) extra.push_back({product[p][m], c});
    }
    std::sort(extra.begin(), extra.end());
    for (const auto& [dof, c] : extra)
      for (int j = 0; j < (dof >= d.np + d.ns ? 4 : 1); ++j) {
        d.dofs.push_back(dof + j);
        d.local.push_back(c);
      }
    d.offsets.push_back(static_cast<long>(d.dofs.size()));
  }
  for (int k = 0; k < K; ++k) {
    TetMesh view;
    view.field_data["front_segments"] = mesh.field_data["front_segments" + suffix(k)];
    view.field_data["front_normals"] = mesh.field_data["front_normals" + suffix(k)];
    if (blocks[4 * k + 3] > 0 && read_front(view, file).empty())
      throw Error(file + ": cut " + std::to_string(k) + " has " + std::to_string(blocks[4 * k + 3]) +
                  " branch nodes but field array 'front_segments" + suffix(k) + "' is empty");
  }
  store_dof_numbering(d, mesh);
  for (int k = 1; k < K; ++k) {
    mesh.point_data["sign_dof" + suffix(k)] = int_array(DataArray::Type::Int64, sign[k]);
    mesh.point_data["branch_dof" + suffix(k)] = int_array(DataArray::Type::Int64, branch[k]);
  }
  for (std::size_t p = 0; p < pairs.size(); ++p)
    mesh.point_data["product_dof" + pair_suffix(pairs[p].first, pairs[p].second)] = int_array(DataArray::Type::Int64, product[p]);
  mesh.field_data["cut_dof_blocks"] = int_array(DataArray::Type::Int64, blocks, 4);
  mesh.field_data["product_dof_blocks"] = int_array(DataArray::Type::Int64, pblocks, 4);
  return d;
}

// ---------------------------------------------------------------------------------------------
// Reading an enriched mesh with its cuts

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
    if (stored_fingerprint(m.field_data, "cut_fingerprint" + suffix(k), &recorded) && fingerprint(cuts[k]) != recorded)
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
    c.side = ints(require_array(m.point_data, "side" + suffix(k), "point", 1, V, vtu, "xfem-classify"));
    c.cut_class = ints(require_array(m.cell_data, "cut_class" + suffix(k), "cell", 1, T, vtu, "xfem-classify"));
    for (std::size_t v = 0; v < V; ++v)
      if (c.side[v] != 1 && c.side[v] != -1)
        throw Error(vtu + ": point array 'side" + suffix(k) + "': point " + std::to_string(v) + " is not +1 or -1");
    for (std::size_t t = 0; t < T; ++t)
      if (c.cut_class[t] < 0 || c.cut_class[t] > 2)
        throw Error(vtu + ": cell array 'cut_class" + suffix(k) + "': tet " + std::to_string(t) + " is not 0, 1 or 2");
    TetMesh view;
    view.field_data["front_segments"] = require_array(m.field_data, "front_segments" + suffix(k), "field", 6, static_cast<std::size_t>(-1), vtu, "xfem-classify");
    view.field_data["front_normals"] = require_array(m.field_data, "front_normals" + suffix(k), "field", 3, static_cast<std::size_t>(-1), vtu, "xfem-classify");
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

// ---------------------------------------------------------------------------------------------
// Basis

int pack_sides(const int* sides, int cuts) {
  int code = 0;
  for (int k = 0; k < cuts; ++k)
    if (sides[k] > 0) code |= 1 << k;
  return code + 2;
}

int cut_function(const EnrichedMesh& em, int k, const int* sides) {
  const CutLayer& c = em.cuts[k];
  if (c.ends_on >= 0 && sides[c.ends_on] != c.ends_side) return 0;
  return sides[k];
}

namespace {

// The cut whose branch block holds `dof` (a branch DOF), or -1.
int branch_cut_of_dof(const EnrichedMesh& em, long dof) {
  for (std::size_t k = 0; k < em.cuts.size(); ++k)
    if (dof >= em.cuts[k].branch_first && dof < em.cuts[k].branch_first + 4 * em.cuts[k].nb) return static_cast<int>(k);
  return -1;
}

}  // namespace

void several_cuts_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int code,
                        BasisAt& out) {
  const int K = static_cast<int>(em.cuts.size());
  const long begin = em.offsets[t];
  const int n = em.size(t);
  out.N.resize(n);
  out.dN.resize(n, 3);
  const Eigen::Vector4d N = shape.values(x);
  int s[kMaxCuts];
  bool have = false;
  auto sides = [&]() -> const int* {
    if (!have) {
      if (code >= 2) {
        for (int k = 0; k < K; ++k) s[k] = code_side(code, k);
      } else if (code == 0) {
        for (int k = 0; k < K; ++k) s[k] = em.cuts[k].cut->side(x);
      } else {
        throw Error("tet " + std::to_string(t) + ": side " + std::to_string(code) +
                    " is not a side code of a mesh with several cuts (0 or >= 2)");
      }
      have = true;
    }
    return s;
  };
  int node_sides[4][kMaxCuts];
  for (int l = 0; l < 4; ++l)
    for (int k = 0; k < K; ++k) node_sides[l][k] = em.cuts[k].side[em.mesh.tets(t, l)];
  bool cutting[kMaxCuts];
  for (int k = 0; k < K; ++k) cutting[k] = em.cuts[k].cut_class[t] != 0;
  int branch_cut = -1;
  BranchValues F;
  for (int e = 0; e < n; ++e) {
    const long dof = em.dofs[begin + e];
    const int l = em.local[begin + e];
    if (dof < em.np) {
      out.N[e] = N[l];
      out.dN.row(e) = shape.grad.row(l);
      continue;
    }
    if (dof < em.np + em.ns) {
      // x's sides, except for the cuts that do not cut the tet: the node's own (the enrichment of
      // a cut jumps only where it cuts; ahead of a front its plane extended is no discontinuity).
      int xs[kMaxCuts];
      // (For a node on the far side of the cut a junction cut ends on, x's own: see classify_cuts.)
      for (int k = 0; k < K; ++k) {
        const int i = em.cuts[k].ends_on;
        const bool far = i >= 0 && node_sides[l][i] != em.cuts[k].ends_side;
        xs[k] = cutting[k] || far ? sides()[k] : node_sides[l][k];
      }
      double psi = 0;
      bool found = false;
      for (int k = 0; k < K && !found; ++k) {
        const CutLayer& c = em.cuts[k];
        if (dof >= c.sign_first && dof < c.sign_first + c.ns) {
          psi = 0.5 * (cut_function(em, k, xs) - cut_function(em, k, node_sides[l]));
          found = true;
        }
      }
      for (std::size_t p = 0; p < em.products.size() && !found; ++p) {
        const ProductBlock& b = em.products[p];
        if (dof >= b.first && dof < b.first + b.count) {
          psi = 0.5 * (cut_function(em, b.a, xs) * cut_function(em, b.b, xs) -
                       cut_function(em, b.a, node_sides[l]) * cut_function(em, b.b, node_sides[l]));
          found = true;
        }
      }
      if (!found) throw Error("tet " + std::to_string(t) + ": DOF " + std::to_string(dof) + " is in no cut's block");
      out.N[e] = N[l] * psi;
      out.dN.row(e) = psi * shape.grad.row(l);
      continue;
    }
    const int k = branch_cut_of_dof(em, dof);
    if (k < 0) throw Error("tet " + std::to_string(t) + ": DOF " + std::to_string(dof) + " is in no cut's block");
    if (k != branch_cut) {
      const CutLayer& c = em.cuts[k];
      const TipCoordinates tc = c.front.coordinates(x);
      int side = 0;
      if (code >= 2)
        side = code_side(code, k);
      else if (tc.xa < 0)
        side = sides()[k];
      F = branch_functions(tc, side);
      branch_cut = k;
    }
    const int j = static_cast<int>((dof - em.np - em.ns) % 4);
    out.N[e] = N[l] * F.F[j];
    out.dN.row(e) = F.F[j] * shape.grad.row(l) + N[l] * F.dF.row(j);
  }
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

// ---------------------------------------------------------------------------------------------
// Integration pieces, connected pieces, visualization

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
    split_tet(corners(em.mesh, t), cuts, classes, fronts, pieces, sides);
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      out.tets.push_back(pieces[q]);
      out.side.push_back(pack_sides(sides[q].data(), K));
    }
    out.first.push_back(static_cast<int>(out.tets.size()));
  }
  return out;
}

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

}  // namespace

std::vector<Piece> find_pieces_several(const EnrichedMesh& em, const std::vector<char>& node_constrained) {
  const int K = static_cast<int>(em.cuts.size());
  const int T = em.tets();
  const CutElementSplits splits = split_cut_elements_several(em);
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
    TetCorners p = corners(em.mesh, t);
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

SplitMesh split_mesh_several(const EnrichedMesh& em) {
  const int K = static_cast<int>(em.cuts.size());
  const int T = em.tets(), V = static_cast<int>(em.mesh.points.rows());
  const CutElementSplits splits = split_cut_elements_several(em);
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
    const double tol = 1e-9 * longest_edge(corners(em.mesh, t));
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

}  // namespace xfem
