// SPDX-License-Identifier: MIT
#include "xfem/system/dirichlet_data.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "xfem/core/error.h"
#include "xfem/enrich/branch_functions.h"

namespace xfem {
namespace {

// Per node, the first of its 4 branch DOF vectors (paper 3.3 numbering), or -1.
std::vector<long> branch_dof_of_node(const EnrichedMesh& em) {
  std::vector<long> first(em.mesh.points.rows(), -1);
  for (int t = 0; t < em.tets(); ++t)
    for (long e = em.offsets[t]; e < em.offsets[t + 1]; ++e)
      if (em.dofs[e] >= em.np + em.ns) {
        long& f = first[em.mesh.tets(t, em.local[e])];
        f = f < 0 ? em.dofs[e] : std::min(f, em.dofs[e]);
      }
  return first;
}

// The point array a value_array condition names, checked: present, 3 components per point.
const DataArray& value_array(const TetMesh& mesh, const std::string& name, const std::string& what) {
  const auto it = mesh.point_data.find(name);
  if (it == mesh.point_data.end()) throw Error(what + ": the mesh has no point array '" + name + "' (value_array)");
  if (it->second.components != 3 || static_cast<Eigen::Index>(it->second.tuples()) != mesh.points.rows())
    throw Error(what + ": point array '" + name + "' (value_array) must have 3 components per point, it has " +
                std::to_string(it->second.components));
  return it->second;
}

}  // namespace

Eigen::Vector3d rotation_displacement(const PrescribedRotation& r, const Eigen::Vector3d& X, double load) {
  const Eigen::Vector3d arm = X - r.centre;
  // R arm - arm rather than R arm + centre - X: no cancellation against the centre's size.
  return Eigen::AngleAxisd(load * r.angle, r.axis) * arm - arm + load * r.translation;
}

void dirichlet_data(const EnrichedMesh& em, const Problem& problem, std::vector<long>& fixed,
                    std::vector<double>& values, double load) {
  if (!(load > 0.0 && load <= 1.0))
    throw Error(problem.file + ": the load factor of the Dirichlet data must lie in (0, 1], got " + short_number(load));
  std::map<long, std::pair<double, std::size_t>> prescribed;  // dof -> (value, condition)
  static const char* axis = "xyz";
  std::vector<long> branch_of;  // built on first need
  const double diagonal = (em.mesh.points.colwise().maxCoeff() - em.mesh.points.colwise().minCoeff()).norm();
  for (std::size_t c = 0; c < problem.dirichlet.size(); ++c) {
    const DirichletCondition& d = problem.dirichlet[c];
    const std::string what = describe(problem, "dirichlet", c);
    auto prescribe = [&](long dof, double v) {
      const auto [it, inserted] = prescribed.emplace(dof, std::make_pair(v, c));
      if (!inserted && it->second.first != v) {
        const long vector = dof / 3;
        const std::string where = vector < em.np ? "node " + std::to_string(vector) : "DOF vector " + std::to_string(vector);
        throw Error(what + " and " + describe(problem, "dirichlet", it->second.second).substr(problem.file.size() + 2) +
                    " prescribe different values for " + where + " component " + axis[dof % 3]);
      }
    };
    const DataArray* array = d.value_array.empty() ? nullptr : &value_array(em.mesh, d.value_array, what);
    for (int k : select_nodes(d.selector, em.mesh, what)) {
      const Eigen::Vector3d x = em.mesh.points.row(k).transpose();
      if (d.rotation) {
        const Eigen::Vector3d u = rotation_displacement(*d.rotation, x, load);
        for (int i = 0; i < 3; ++i) prescribe(3L * k + i, u[i]);
        continue;
      }
      if (array) {
        for (int i = 0; i < 3; ++i) {
          const double v = (*array)(static_cast<std::size_t>(k), i);
          if (!std::isfinite(v))
            throw Error(what + ": point array '" + d.value_array + "' (value_array) holds a non-finite value at node " +
                        std::to_string(k) + " component " + axis[i]);
          prescribe(3L * k + i, v * load);
        }
        continue;
      }
      if (!d.exact) {
        for (int i = 0; i < 3; ++i)
          if (d.value[i]) prescribe(3L * k + i, *d.value[i] * load);
        continue;
      }
      // The exact field at the node, on the node's own side (decided once, by xfem-classify).
      const int side = em.side.empty() ? 1 : em.side[k];
      Eigen::Vector3d u = d.exact->displacement(x, side) * load;
      if (d.exact_enriched) {
        if (branch_of.empty()) branch_of = branch_dof_of_node(em);
        if (branch_of[k] >= 0) {
          // u_h(x_k) = U_k + sum_j F_j(x_k) A_kj (unshifted ACTFs, paper 3.4): A_kj = the field's
          // coefficients, U_k what the ACTFs leave of u(x_k) (0 when every node is enriched).
          const CrackTipFrame frame = em.front.frame(x);
          Eigen::Matrix<double, 3, 4> C;
          try {
            C = d.exact->williams.branch_coefficients(frame, 1e-8 * diagonal) * load;
          } catch (const Error& e) {
            throw Error(what + ", node " + std::to_string(k) + ": " + e.what());
          }
          u -= C * branch_functions(frame, x, side).F;
          for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 3; ++i) prescribe(3 * (branch_of[k] + j) + i, C(i, j));
        }
      }
      for (int i = 0; i < 3; ++i) prescribe(3L * k + i, u[i]);
    }
  }
  fixed.clear();
  values.clear();
  for (const auto& [dof, v] : prescribed) {
    fixed.push_back(dof);
    values.push_back(v.first);
  }
}

}  // namespace xfem
