// SPDX-License-Identifier: MIT
// Accuracy and cost of the branch functions' volume rule (issue 35): for every tet with branch DOFs
// of an enriched mesh, the branch x branch block of its stiffness (closed_form_stiffness.h) with
// each rule asked for, against the same block integrated with the uniform rule of order REF
// (default 8; or any RULE as below): relative Frobenius error per tet (worst, median, 90th percentile), points per tet
// (mean, max) and the time to integrate these tets on one thread (median of RUNS, alternated).
// Usage: branch_rule_accuracy ENRICHED.vtu CUT [--reference N|RULE] [--reference-file PATH] [--runs N] [--worst K]
//        RULE...
//   --reference-file PATH: the reference blocks are read from PATH when it exists (written by an earlier run with
//         the same mesh, cut and reference; checked by the tets' count and block sizes), else computed and written
//         there: an order-8 reference takes minutes.
//   --worst K: then, for the first RULE, its K worst tets, each with its exact pieces by kind (an edge
//         on the front, a vertex on it, neither) and where its error sits: the error again with one part
//         of the rule taken from the reference's layout: the pieces touching the front (radial, along,
//         across, near_levels), the consistent shift's face integrals (consistent), the pieces away from
//         the front (far, distant, remote, their ratios, far_levels, far_squared); and all three (which
//         must give 0: the parts are the whole rule). The worst, 90th percentile and median of each column
//         over the K tets close the list.
//   RULE: uniform:N (the conforming rule of order N before issue 35, n points per direction everywhere and
//         on the faces; N >= 2) or order:N (TetRuleLayout::of_order(N) everywhere: the default before straight fronts) or
//         graded (TetRuleLayout::graded(), integration.rule "graded") or fast (TetRuleLayout::fast(), --rule fast) or
//         layout:radial,along,across,far,distant,distant_ratio,near_levels,far_levels[,consistent[,far_squared
//                [,remote,remote_ratio[,remote_symmetric[,far_split_ratio]]]]] (consistent: the order whose consistent shift is taken, faces
//                consistent_face_points(consistent) per direction)
//         straight:N[:A[:C]] (the default of order N, integration.rule "conforming": a tet by a straight front by
//                straight_front_rule with A angle points per stretch, default straight_front_angle_points(N), and
//                its shift's faces by straight_front_face_integrals; C: the shift's order, 0 none)
//   RULE@N: the same with N points per direction on the faces the front passes near (an experiment:
//         branch_gradient_integrals' near_order), e.g. order:3@5.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/closed_form_stiffness.h"
#include "xfem/integrate/straight_front_rule.h"
#include "xfem/integrate/consistent_gradients.h"

namespace {

struct Rule {
  std::string name;
  xfem::TetRuleLayout layout;
  int consistent = 3;  // Gauss points per direction of the face integrals
  int near_faces = 0;  // points per direction on the faces near the front (0: as the others)
  int straight = 0;    // > 0: straight_front_rule with that many angle points where a tet qualifies
};

Rule parse(const std::string& full) {
  Rule r;
  r.name = full;
  const std::size_t at = full.find('@');
  const std::string s = full.substr(0, at);
  if (at != std::string::npos) r.near_faces = std::stoi(full.substr(at + 1));
  if (s.rfind("uniform:", 0) == 0) {
    const int n = std::stoi(s.substr(8));
    r.layout = xfem::TetRuleLayout::uniform(n);
    r.consistent = n - 1;  // faces consistent_face_points(n - 1) = n per direction, as before issue 35
  } else if (s == "fast") {
    r.layout = xfem::TetRuleLayout::fast();
    r.consistent = xfem::TetRuleLayout::fast_consistent_order;
  } else if (s == "graded") {
    r.layout = xfem::TetRuleLayout::graded();
    r.consistent = xfem::TetRuleLayout::graded_consistent_order;
  } else if (s.rfind("straight:", 0) == 0) {  // straight:N[:A]: order N, straight fronts with A angle points
    const std::size_t colon = s.find(':', 9);
    const int n = std::stoi(s.substr(9, colon - 9));
    r.layout = xfem::TetRuleLayout::of_order(n);
    r.consistent = n;
    r.straight = colon == std::string::npos ? xfem::straight_front_angle_points(n) : std::stoi(s.substr(colon + 1));
    const std::size_t third = colon == std::string::npos ? colon : s.find(':', colon + 1);
    if (third != std::string::npos) r.consistent = std::stoi(s.substr(third + 1));  // straight:N:A:C, C = 0: no shift
  } else if (s.rfind("order:", 0) == 0) {  // the rule of order N (TetRuleLayout::of_order, the default's family)
    const int n = std::stoi(s.substr(6));
    r.layout = xfem::TetRuleLayout::of_order(n);
    r.consistent = n;
  } else if (s.rfind("layout:", 0) == 0) {
    std::stringstream in(s.substr(7));
    std::string item;
    std::vector<double> v;
    while (std::getline(in, item, ',')) v.push_back(std::stod(item));
    if (v.size() < 8 || v.size() > 14) throw std::runtime_error("layout needs 8 to 14 numbers: " + s);
    xfem::TetRuleLayout& l = r.layout;
    l.radial = int(v[0]), l.along = int(v[1]), l.across = int(v[2]), l.far = int(v[3]), l.distant = int(v[4]);
    l.distant_ratio = v[5], l.near_levels = int(v[6]), l.far_levels = int(v[7]);
    if (v.size() >= 9) r.consistent = int(v[8]);
    if (v.size() >= 10) l.far_squared = v[9] != 0;
    if (v.size() >= 12) l.remote = int(v[10]), l.remote_ratio = v[11];
    if (v.size() >= 13) l.remote_symmetric = v[12] != 0;
    if (v.size() >= 14) l.far_split_ratio = v[13];
  } else {
    throw std::runtime_error("unknown rule " + s);
  }
  return r;
}

// The branch x branch block of k (rows and columns of the branch entries of the tet's C).
Eigen::MatrixXd branch_block(const xfem::EnrichedMesh& em, int t, const Eigen::MatrixXd& k) {
  std::vector<int> cols;
  for (int c = 0; c < em.size(t); ++c)
    if (em.dofs[em.offsets[t] + c] >= em.np + em.ns)
      for (int a = 0; a < 3; ++a) cols.push_back(3 * c + a);
  Eigen::MatrixXd b(cols.size(), cols.size());
  for (std::size_t i = 0; i < cols.size(); ++i)
    for (std::size_t j = 0; j < cols.size(); ++j) b(i, j) = k(cols[i], cols[j]);
  return b;
}

// `base` with the pieces touching the front laid out as in `from`.
xfem::TetRuleLayout front_from(xfem::TetRuleLayout base, const xfem::TetRuleLayout& from) {
  base.radial = from.radial, base.along = from.along, base.across = from.across, base.near_levels = from.near_levels;
  return base;
}

// `base` with the pieces without a vertex on the front laid out as in `from`.
xfem::TetRuleLayout away_from(xfem::TetRuleLayout base, const xfem::TetRuleLayout& from) {
  base.far = from.far, base.distant = from.distant, base.distant_ratio = from.distant_ratio;
  base.remote = from.remote, base.remote_ratio = from.remote_ratio, base.remote_symmetric = from.remote_symmetric;
  base.far_levels = from.far_levels, base.far_squared = from.far_squared, base.far_split_ratio = from.far_split_ratio;
  return base;
}

// Tet t's exact pieces (the tet itself when no cut crosses it) by their vertices on the front, as
// append_tet_rule decides it (within 1e-6 of the piece's longest edge): [0] an edge (two or more
// vertices), [1] one vertex, [2] none.
std::array<int, 3> piece_kinds(const xfem::EnrichedMesh& em, const xfem::CutElementSplits& splits, int t) {
  std::array<int, 3> kinds{0, 0, 0};
  const xfem::CrackFront& front = xfem::front_of_tet(em, t);
  auto count = [&](const std::array<Eigen::Vector3d, 4>& q) {
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (q[a] - q[b]).norm());
    int on = 0;
    for (int a = 0; a < 4; ++a) on += !front.empty() && front.distance(q[a]) <= 1e-6 * longest;
    ++kinds[on >= 2 ? 0 : on == 1 ? 1 : 2];
  };
  const int i = splits.index.empty() ? -1 : splits.index[t];
  if (i < 0) {
    std::array<Eigen::Vector3d, 4> q;
    for (int c = 0; c < 4; ++c) q[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
    count(q);
  } else {
    for (int s = splits.first[i]; s < splits.first[i + 1]; ++s) count(splits.tets[s]);
  }
  return kinds;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 4) {
      std::fprintf(stderr, "usage: branch_rule_accuracy ENRICHED.vtu CUT [--reference N|RULE] [--runs N] RULE...\n");
      return 2;
    }
    std::string reference = "uniform:8";  // the order-8 rule before issue 35
    int runs = 3, worst = 0;
    std::string reference_file;
    std::vector<Rule> rules;
    for (int i = 3; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--reference" && i + 1 < argc) {
        reference = argv[++i];
        if (reference.find(':') == std::string::npos && reference != "graded") reference = "uniform:" + reference;
      }
      else if (a == "--runs" && i + 1 < argc) runs = std::atoi(argv[++i]);
      else if (a == "--worst" && i + 1 < argc) worst = std::atoi(argv[++i]);
      else if (a == "--reference-file" && i + 1 < argc) reference_file = argv[++i];
      else rules.push_back(parse(a));
    }
    if (rules.empty()) throw std::runtime_error("no RULE given");
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_to_solve(argv[1], {argv[2]});
    const xfem::CutElementSplits splits = xfem::split_cut_elements(em);
    const xfem::Lame material = xfem::lame(3e5, 0.35);
    std::vector<int> tets;
    for (int t = 0; t < em.tets(); ++t)
      if (em.branch(t)) tets.push_back(t);
    std::vector<Eigen::MatrixXd> ref(tets.size());
    const Rule r_ref = parse(reference);
    // The blocks as raw doubles: per tet its size, then the entries (column-major).
    bool have_reference = false;
    if (!reference_file.empty()) {
      std::ifstream in(reference_file, std::ios::binary);
      if (in) {
        std::size_t count = 0;
        in.read(reinterpret_cast<char*>(&count), sizeof count);
        if (count != tets.size()) throw std::runtime_error(reference_file + ": holds " + std::to_string(count) +
                                                           " blocks, the mesh has " + std::to_string(tets.size()));
        for (std::size_t i = 0; i < tets.size(); ++i) {
          long n = 0;
          in.read(reinterpret_cast<char*>(&n), sizeof n);
          if (!in || n <= 0 || n > 100000) throw std::runtime_error(reference_file + ": bad block size");
          ref[i].resize(n, n);
          in.read(reinterpret_cast<char*>(ref[i].data()), sizeof(double) * n * n);
        }
        if (!in) throw std::runtime_error(reference_file + ": truncated");
        have_reference = true;
      }
    }
    if (!have_reference) {
      xfem::PointRule points;
      Eigen::MatrixXd k;
      const Rule& r = r_ref;
      xfem::ClosedFormWorkspace work;
      for (std::size_t i = 0; i < tets.size(); ++i) {
        const bool straight = r.straight > 0 && xfem::straight_front_rule(em, splits, tets[i], r.straight, work.straight);
        if (straight) points.clear();
        else xfem::conforming_rule(em, splits, tets[i], r.layout, points);
        xfem::closed_form_stiffness(em, splits, tets[i], points, material, k, r.consistent, nullptr, r.near_faces, work,
                                    straight ? &work.straight : nullptr, r.straight);
        ref[i] = branch_block(em, tets[i], k);
      }
      if (!reference_file.empty()) {
        std::ofstream out(reference_file, std::ios::binary);
        const std::size_t count = tets.size();
        out.write(reinterpret_cast<const char*>(&count), sizeof count);
        for (const Eigen::MatrixXd& b : ref) {
          const long n = b.rows();
          out.write(reinterpret_cast<const char*>(&n), sizeof n);
          out.write(reinterpret_cast<const char*>(b.data()), sizeof(double) * n * n);
        }
        if (!out) throw std::runtime_error(reference_file + ": could not write");
      }
    }
    for (std::size_t i = 0; i < tets.size(); ++i)
      if (ref[i].rows() != 3 * static_cast<long>(std::count_if(em.dofs.begin() + em.offsets[tets[i]],
                                                                em.dofs.begin() + em.offsets[tets[i]] + em.size(tets[i]),
                                                                [&](int d) { return d >= em.np + em.ns; })))
        throw std::runtime_error("reference block of tet " + std::to_string(tets[i]) + " has the wrong size");
    std::printf("%zu tets with branch DOFs; reference: %s\n", tets.size(), reference.c_str());
    std::printf("%-40s %10s %10s %10s %8s %8s %9s\n", "rule", "worst", "median", "p90", "pts/tet", "max pts",
                "time s");
    std::vector<std::vector<double>> times(rules.size());
    std::vector<std::vector<double>> errors(rules.size());
    std::vector<double> mean_points(rules.size()), max_points(rules.size());
    for (int run = 0; run < runs; ++run)
      for (std::size_t r = 0; r < rules.size(); ++r) {
        xfem::PointRule points;
        Eigen::MatrixXd k;
        xfem::FaceIntegralCache faces;
        xfem::ClosedFormWorkspace work;
        std::vector<double> err;
        double total = 0, most = 0;
        long straight_tets = 0;
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < tets.size(); ++i) {
          const bool straight = rules[r].straight > 0 &&
                                xfem::straight_front_rule(em, splits, tets[i], rules[r].straight, work.straight);
          if (straight) points.clear();
          else xfem::conforming_rule(em, splits, tets[i], rules[r].layout, points);
          xfem::closed_form_stiffness(em, splits, tets[i], points, material, k, rules[r].consistent, &faces,
                                      rules[r].near_faces, work, straight ? &work.straight : nullptr, rules[r].straight);
          if (run == 0) {
            const Eigen::MatrixXd b = branch_block(em, tets[i], k);
            err.push_back((b - ref[i]).norm() / ref[i].norm());
            const int used = straight ? work.straight.points.size() : points.size();
            total += used;
            most = std::max<double>(most, used);
            straight_tets += straight;
          }
        }
        if (run == 0 && rules[r].straight > 0)
          std::fprintf(stderr, "%s: %ld of %zu tets by the straight-front rule\n", rules[r].name.c_str(), straight_tets,
                       tets.size());
        times[r].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (run == 0) {
          errors[r] = err;
          mean_points[r] = total / tets.size();
          max_points[r] = most;
        }
      }
    for (std::size_t r = 0; r < rules.size(); ++r)
      std::printf("%-40s %10.3e %10.3e %10.3e %8.0f %8.0f %9.3f\n", rules[r].name.c_str(),
                  quantile(errors[r], 1.0), quantile(errors[r], 0.5), quantile(errors[r], 0.9), mean_points[r],
                  max_points[r], quantile(times[r], 0.5));
    if (worst > 0) {
      // Where the first rule's error sits in its worst tets: one part of it at a time from the reference.
      const Rule& base = rules[0];
      Rule parts[4] = {base, base, base, base};
      parts[0].layout = front_from(base.layout, r_ref.layout);
      parts[1].consistent = r_ref.consistent;
      parts[1].near_faces = parts[3].near_faces = 0;
      parts[2].layout = away_from(base.layout, r_ref.layout);
      parts[3].layout = away_from(front_from(base.layout, r_ref.layout), r_ref.layout);
      parts[3].consistent = r_ref.consistent;
      std::vector<std::size_t> order(tets.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return errors[0][a] > errors[0][b]; });
      order.resize(std::min<std::size_t>(order.size(), worst));
      std::printf("\n%s: its %zu worst tets, the error with one part from the reference\n", base.name.c_str(),
                  order.size());
      std::printf("%8s %5s %5s %5s %7s %10s %10s %10s %10s %10s\n", "tet", "edge", "vert", "away", "points",
                  "error", "front ref", "faces ref", "away ref", "all ref");
      std::vector<std::vector<double>> columns(5);
      xfem::PointRule points;
      Eigen::MatrixXd k;
      for (std::size_t i : order) {
        const int t = tets[i];
        const std::array<int, 3> kinds = piece_kinds(em, splits, t);
        xfem::conforming_rule(em, splits, t, base.layout, points);
        const int count = points.size();
        double e[5] = {errors[0][i], 0, 0, 0, 0};
        for (int p = 0; p < 4; ++p) {
          xfem::conforming_rule(em, splits, t, parts[p].layout, points);
          xfem::closed_form_stiffness(em, splits, t, points, material, k, parts[p].consistent, nullptr,
                                      parts[p].near_faces);
          e[p + 1] = (branch_block(em, t, k) - ref[i]).norm() / ref[i].norm();
        }
        std::printf("%8d %5d %5d %5d %7d %10.3e %10.3e %10.3e %10.3e %10.3e\n", t, kinds[0], kinds[1], kinds[2],
                    count, e[0], e[1], e[2], e[3], e[4]);
        for (int c = 0; c < 5; ++c) columns[c].push_back(e[c]);
      }
      for (double q : {1.0, 0.9, 0.5})
        std::printf("%8s %5s %5s %5s %7s %10.3e %10.3e %10.3e %10.3e %10.3e\n",
                    q == 1.0 ? "worst" : q == 0.5 ? "median" : "p90", "", "", "", "", quantile(columns[0], q),
                    quantile(columns[1], q), quantile(columns[2], q), quantile(columns[3], q), quantile(columns[4], q));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "branch_rule_accuracy: error: %s\n", e.what());
    return 1;
  }
}
