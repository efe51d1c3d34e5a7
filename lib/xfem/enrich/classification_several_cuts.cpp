// SPDX-License-Identifier: MIT
#include "xfem/enrich/classification_several_cuts.h"

#include "xfem/core/cli.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "xfem/core/error.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/core/parallel_for.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

namespace {

double diagonal(const Points& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

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

}  // namespace

std::string cut_suffix(int k) { return k == 0 ? std::string() : "_" + std::to_string(k); }
std::string pair_suffix(int a, int b) { return "_" + std::to_string(a) + "_" + std::to_string(b); }

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
      const TetCorners p = tet_corners(mesh, t);
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
  // The tets some cut meets, each with its cuts' classes (and the cases not handled refused, in tet
  // order); then each split on its own in threads (chunks of 4: a few hundred cut tets among a
  // mesh's thousands); then the pieces' volumes added to the nodes' regions in tet order, so the
  // sums do not depend on the thread count.
  std::vector<int> cut_tets, cut_classes;  // K classes per cut tet
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
    cut_tets.push_back(t);
    cut_classes.insert(cut_classes.end(), classes.begin(), classes.end());
  }
  const long C = static_cast<long>(cut_tets.size());
  std::vector<std::vector<TetCorners>> tet_pieces(C);
  std::vector<std::vector<Sides>> tet_sides(C);
  auto progress = options.progress ? std::function<void(double)>([&](double f) { options.progress((K + f) / (K + 1)); })
                                   : std::function<void(double)>();
  parallel_for(C, [&](long b, long e) {
    for (long i = b; i < e; ++i) {
      const std::vector<int> tet_classes(cut_classes.begin() + K * i, cut_classes.begin() + K * (i + 1));
      split_by_cuts(tet_corners(mesh, cut_tets[i]), cuts, tet_classes, fronts, tet_pieces[i], tet_sides[i]);
    }
  }, progress, 4);
  for (long i = 0; i < C; ++i) {
    const int t = cut_tets[i];
    const int* tet_classes = cut_classes.data() + K * i;
    const std::vector<TetCorners>& pieces = tet_pieces[i];
    const std::vector<Sides>& sides = tet_sides[i];
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
          const int j = out.ends_on[k];
          if (tet_classes[k] == 0 && !(j >= 0 && out.cuts[j].side[node] != out.ends_side[k])) e[k] = out.cuts[k].side[node];
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
    for (auto& [name, a] : scratch.point_data) mesh.point_data[name + cut_suffix(k)] = std::move(a);
    for (auto& [name, a] : scratch.cell_data) mesh.cell_data[name + cut_suffix(k)] = std::move(a);
    for (auto& [name, a] : scratch.field_data) mesh.field_data[name + cut_suffix(k)] = std::move(a);
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

void report_cuts_classification(const CutsClassification& c, const std::vector<std::string>& cut_names, Json& j) {
  j["cuts"] = Json::array();
  const auto names = count_names();
  for (std::size_t k = 0; k < c.cuts.size(); ++k) {
    const auto& n = c.cuts[k].counts;
    cli::info("cut " + std::to_string(k) + " (" + cut_names[k] + "): " + std::to_string(n.partial) + " partially and " +
              std::to_string(n.complete) + " completely cut tets; " + std::to_string(n.sign) + " sign, " +
              std::to_string(n.branch) + " branch nodes; " + std::to_string(n.front_segments) +
              " front segments" +
              (c.ends_on[k] >= 0 ? "; ends on cut " + std::to_string(c.ends_on[k]) + " (junction)" : ""));
    Json cj;
    cj["cut"] = cut_names[k];
    cj["ends_on"] = c.ends_on[k];
    const auto values = count_values(n);
    for (std::size_t i = 0; i < names.size(); ++i) cj[names[i]] = values[i];
    j["cuts"].push_back(cj);
  }
  j["products"] = Json::array();
  for (const auto& p : c.products) {
    cli::info("cuts " + std::to_string(p.a) + " and " + std::to_string(p.b) + " cross: " +
              std::to_string(p.count) + " nodes with the junction enrichment H_" + std::to_string(p.a) + " H_" +
              std::to_string(p.b));
    j["products"].push_back(Json{{"a", p.a}, {"b", p.b}, {"nodes", p.count}});
  }
  j["product_tiny"] = c.product_tiny;
  if (c.product_tiny > 0)
    cli::detail(std::to_string(c.product_tiny) +
                " nodes are not given a junction enrichment: one of the four sign combinations of two "
                "crossing cuts holds less than --tiny-support of their support (the cuts' pieces stay "
                "joined inside that sliver)");
}

}  // namespace xfem
