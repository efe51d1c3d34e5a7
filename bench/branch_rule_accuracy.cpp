// SPDX-License-Identifier: MIT
// Accuracy and cost of the branch functions' volume rule (issue 35): for every tet with branch DOFs
// of an enriched mesh, the branch x branch block of its stiffness (closed_form_stiffness.h) with
// each rule asked for, against the same block integrated with the uniform rule of order REF
// (default 8; or any RULE as below): relative Frobenius error per tet (worst, median, 90th percentile), points per tet
// (mean, max) and the time to integrate these tets on one thread (median of RUNS, alternated).
// Usage: branch_rule_accuracy ENRICHED.vtu CUT [--reference N|RULE] [--runs N] RULE...
//   RULE: uniform:N (the conforming rule of order N before issue 35, n points per direction everywhere and
//         on the faces; N >= 2) or order:N (TetRuleLayout::of_order(N): integration.rule "conforming" --order N) or
//         graded (TetRuleLayout::graded(), integration.rule "graded") or fast (TetRuleLayout::fast(), --rule fast) or
//         layout:radial,along,across,far,distant,distant_ratio,near_levels,far_levels[,consistent[,far_squared
//                [,remote,remote_ratio[,remote_symmetric]]]] (consistent: the order whose consistent shift is taken, faces
//                consistent_face_points(consistent) per direction)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/closed_form_stiffness.h"
#include "xfem/integrate/consistent_gradients.h"

namespace {

struct Rule {
  std::string name;
  xfem::TetRuleLayout layout;
  int consistent = 3;  // Gauss points per direction of the face integrals
};

Rule parse(const std::string& s) {
  Rule r;
  r.name = s;
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
  } else if (s.rfind("order:", 0) == 0) {  // the rule of order N (TetRuleLayout::of_order, the default's family)
    const int n = std::stoi(s.substr(6));
    r.layout = xfem::TetRuleLayout::of_order(n);
    r.consistent = n;
  } else if (s.rfind("layout:", 0) == 0) {
    std::stringstream in(s.substr(7));
    std::string item;
    std::vector<double> v;
    while (std::getline(in, item, ',')) v.push_back(std::stod(item));
    if (v.size() < 8 || v.size() > 13) throw std::runtime_error("layout needs 8 to 12 numbers: " + s);
    xfem::TetRuleLayout& l = r.layout;
    l.radial = int(v[0]), l.along = int(v[1]), l.across = int(v[2]), l.far = int(v[3]), l.distant = int(v[4]);
    l.distant_ratio = v[5], l.near_levels = int(v[6]), l.far_levels = int(v[7]);
    if (v.size() >= 9) r.consistent = int(v[8]);
    if (v.size() >= 10) l.far_squared = v[9] != 0;
    if (v.size() >= 12) l.remote = int(v[10]), l.remote_ratio = v[11];
    if (v.size() >= 13) l.remote_symmetric = v[12] != 0;
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
    int runs = 3;
    std::vector<Rule> rules;
    for (int i = 3; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--reference" && i + 1 < argc) {
        reference = argv[++i];
        if (reference.find(':') == std::string::npos && reference != "graded") reference = "uniform:" + reference;
      }
      else if (a == "--runs" && i + 1 < argc) runs = std::atoi(argv[++i]);
      else rules.push_back(parse(a));
    }
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_to_solve(argv[1], {argv[2]});
    const xfem::CutElementSplits splits = xfem::split_cut_elements(em);
    const xfem::Lame material = xfem::lame(3e5, 0.35);
    std::vector<int> tets;
    for (int t = 0; t < em.tets(); ++t)
      if (em.branch(t)) tets.push_back(t);
    std::vector<Eigen::MatrixXd> ref(tets.size());
    {
      xfem::PointRule points;
      Eigen::MatrixXd k;
      const Rule r = parse(reference);
      for (std::size_t i = 0; i < tets.size(); ++i) {
        xfem::conforming_rule(em, splits, tets[i], r.layout, points);
        xfem::closed_form_stiffness(em, splits, tets[i], points, material, k, r.consistent);
        ref[i] = branch_block(em, tets[i], k);
      }
    }
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
        std::vector<double> err;
        double total = 0, most = 0;
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < tets.size(); ++i) {
          xfem::conforming_rule(em, splits, tets[i], rules[r].layout, points);
          xfem::closed_form_stiffness(em, splits, tets[i], points, material, k, rules[r].consistent, &faces);
          if (run == 0) {
            const Eigen::MatrixXd b = branch_block(em, tets[i], k);
            err.push_back((b - ref[i]).norm() / ref[i].norm());
            total += points.size();
            most = std::max<double>(most, points.size());
          }
        }
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
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "branch_rule_accuracy: error: %s\n", e.what());
    return 1;
  }
}
