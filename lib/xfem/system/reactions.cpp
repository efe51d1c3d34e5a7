// SPDX-License-Identifier: MIT
#include "xfem/system/reactions.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "xfem/core/error.h"

namespace xfem {
namespace {

std::string join(const std::string& dir) {
  return (std::filesystem::path(dir) / "dirichlet_conditions.json").string();
}

Json vec(const Eigen::Vector3d& v) { return Json::array({v[0], v[1], v[2]}); }

std::string triple(const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v[0], v[1], v[2]);
  return buf;
}

// Resultant of the nodal forces `r` (3N) on `dofs` (original scalar DOFs) at `x` (NP x 3).
Resultant resultant(const std::string& name, const std::vector<long>& dofs, const Eigen::VectorXd& r,
                    const Eigen::MatrixXd& x) {
  Resultant out;
  out.name = name;
  long last_node = -1;
  for (long d : dofs) {
    const long k = d / 3;
    if (k != last_node) ++out.nodes;  // dofs increase, so a node's components are adjacent
    last_node = k;
    Eigen::Vector3d F = Eigen::Vector3d::Zero();
    F[d % 3] = r[d];
    out.force += F;
    if (x.rows() > k) out.moment += Eigen::Vector3d(x(k, 0), x(k, 1), x(k, 2)).cross(F);
  }
  return out;
}

void check_coordinates(const Eigen::MatrixXd& x, long needed) {
  if (x.cols() != 3 || x.rows() < needed)
    throw Error("reactions: the system has no point coordinates (coordinates.mtx) for the moments; "
                "re-run xfem-assemble");
}

}  // namespace

DirichletGroups dirichlet_groups(const TetMesh& mesh, const Problem& problem) {
  DirichletGroups g;
  std::set<long> taken;
  for (std::size_t c = 0; c < problem.dirichlet.size(); ++c) {
    const DirichletCondition& d = problem.dirichlet[c];
    g.names.push_back(d.name.empty() ? "dirichlet[" + std::to_string(c) + "]" : d.name);
    std::vector<long> dofs;
    for (int k : select_nodes(d.selector, mesh, describe(problem, "dirichlet", c)))
      for (int i = 0; i < 3; ++i)
        if (d.fixes(i) && taken.insert(3L * k + i).second) dofs.push_back(3L * k + i);
    g.dofs.push_back(std::move(dofs));  // select_nodes returns increasing ids: dofs increase
  }
  return g;
}

void write_dirichlet_groups(const DirichletGroups& groups, const std::string& dir, const std::string& generator) {
  Json j;
  j["generator"] = generator;
  j["conditions"] = Json::array();
  for (std::size_t c = 0; c < groups.names.size(); ++c)
    j["conditions"].push_back({{"name", groups.names[c]}, {"dofs", groups.dofs[c]}});
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw Error(dir + ": cannot create directory");
  write_json(j, join(dir));
}

DirichletGroups read_dirichlet_groups(const std::string& dir, const LinearSystem& s) {
  const std::string path = join(dir);
  DirichletGroups g;
  if (!std::filesystem::exists(path)) {
    g.names.push_back("constrained DOFs");
    g.dofs.emplace_back();
    for (long d : s.fixed)
      if (d / 3 < s.np) g.dofs.back().push_back(d);
    return g;
  }
  const Json j = read_json(path);
  try {
    for (const auto& c : j.at("conditions")) {
      g.names.push_back(c.at("name").get<std::string>());
      g.dofs.push_back(c.at("dofs").get<std::vector<long>>());
      for (long d : g.dofs.back())
        if (!std::binary_search(s.fixed.begin(), s.fixed.end(), d))
          throw Error("condition '" + g.names.back() + "' lists DOF " + std::to_string(d) +
                      ", which the system does not fix (is this file from another system?)");
    }
  } catch (const Json::exception& e) {
    throw Error(path + ": " + e.what());
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  return g;
}

Eigen::VectorXd nodal_reactions(const LinearSystem& s, const Eigen::VectorXd& u) {
  if (u.size() != s.K.cols())
    throw Error("reactions: " + std::to_string(u.size()) + " solution values, expected 3N = " + std::to_string(s.K.cols()));
  // Only the constrained rows are needed; K is symmetric, so row d is column d.
  Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
  for (long d : s.fixed) r[d] = s.K.col(d).dot(u) - s.f[d];
  return r;
}

std::vector<Resultant> condition_reactions(const DirichletGroups& g, const Eigen::VectorXd& r,
                                           const Eigen::MatrixXd& x) {
  long needed = 0;
  for (const auto& dofs : g.dofs)
    if (!dofs.empty()) needed = std::max(needed, dofs.back() / 3 + 1);
  check_coordinates(x, needed);
  std::vector<Resultant> out;
  for (std::size_t c = 0; c < g.names.size(); ++c) out.push_back(resultant(g.names[c], g.dofs[c], r, x));
  return out;
}

Resultant applied_load(const Eigen::VectorXd& f, const Eigen::MatrixXd& x) {
  check_coordinates(x, 0);
  std::vector<long> dofs;
  for (long d = 0; d < 3 * x.rows() && d < f.size(); ++d)
    if (f[d] != 0) dofs.push_back(d);
  return resultant("applied loads", dofs, f, x);
}

Reactions reactions(const std::string& dir, const LinearSystem& s, const Eigen::VectorXd& u) {
  Reactions out;
  out.moments = s.coordinates.rows() == s.np && s.coordinates.cols() == 3;
  const Eigen::MatrixXd none(0, 3);
  const Eigen::MatrixXd& x = out.moments ? s.coordinates : none;
  out.r = nodal_reactions(s, u);
  const DirichletGroups g = read_dirichlet_groups(dir, s);
  for (std::size_t c = 0; c < g.names.size(); ++c) out.conditions.push_back(resultant(g.names[c], g.dofs[c], out.r, x));
  std::vector<long> loaded;
  for (long d = 0; d < 3 * s.np; ++d)
    if (s.f[d] != 0) loaded.push_back(d);
  out.applied = resultant("applied loads", loaded, s.f, x);
  return out;
}

Json reactions_json(const std::vector<Resultant>& reactions, const Resultant& applied, bool moments) {
  Json j;
  if (moments) j["moment_about"] = Json::array({0.0, 0.0, 0.0});
  j["conditions"] = Json::array();
  for (const auto& r : reactions) {
    Json c = {{"name", r.name}, {"nodes", r.nodes}, {"force", vec(r.force)}};
    if (moments) c["moment"] = vec(r.moment);
    j["conditions"].push_back(c);
  }
  j["applied"] = {{"force", vec(applied.force)}};
  if (moments) j["applied"]["moment"] = vec(applied.moment);
  return j;
}

DataArray reaction_array(const Eigen::VectorXd& r, long np, long points) {
  if (r.size() < 3 * np || points < np)
    throw Error("reaction_array: " + std::to_string(r.size()) + " reactions for " + std::to_string(np) + " nodes");
  DataArray a = make_array(DataArray::Type::Float64, 3, points);
  for (long i = 0; i < 3 * np; ++i) a.values[i] = r[i];
  return a;
}

std::string describe_reaction(const Resultant& r, bool moments) {
  char norm[32];
  std::snprintf(norm, sizeof norm, "%.4g", r.force.norm());
  return "reaction of '" + r.name + "' (" + std::to_string(r.nodes) + " nodes): force " + triple(r.force) +
         " N, |F| = " + norm + " N" + (moments ? "; moment about the origin " + triple(r.moment) + " N m" : "");
}

}  // namespace xfem
