// SPDX-License-Identifier: MIT
#include "xfem/post/deformed_mesh.h"

#include <array>
#include <cmath>
#include <map>
#include <string>

#include "xfem/integrate/element_stiffness.h"
#include "xfem/post/cell_stress.h"
#include "xfem/enrich/enriched_basis.h"
#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"

namespace xfem {
namespace {
// Wound offset along its outward normal, as a fraction of the body's bounding-box diagonal: far
// below what a picture resolves (0.02 mm on the 0.2 m beam), far above depth-buffer resolution.
}  // namespace

DisplacementField xfem_displacement(const EnrichedMesh& em, const Eigen::VectorXd& u) {
  DisplacementField f;
  f.value = [&em, &u](int t, const Eigen::Vector3d& x, int side) { return displacement_at(em, t, x, side, u); };
  f.gradient = [&em, &u](int t, const Eigen::Vector3d& x, int side) {
    return displacement_gradient_at(em, t, x, side, u);
  };
  return f;
}

double von_mises(const Eigen::Matrix3d& s) {
  const double d = (s(0, 0) - s(1, 1)) * (s(0, 0) - s(1, 1)) + (s(1, 1) - s(2, 2)) * (s(1, 1) - s(2, 2)) +
                   (s(2, 2) - s(0, 0)) * (s(2, 2) - s(0, 0));
  const double shear = s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2);
  return std::sqrt(0.5 * d + 3.0 * shear);
}

DeformedBody deformed_body(const SplitMesh& split, const std::vector<int>& cut_class, const DisplacementField& u,
                           double E, double nu, const std::function<void(double)>& progress, double wound_offset,
                           MaterialModel model) {
  if (!(E > 0)) throw Error("deformed_body: Young's modulus E must be positive, got " + std::to_string(E));
  if (!(nu > -1 && nu < 0.5)) throw Error("deformed_body: Poisson's ratio nu must be in (-1, 0.5), got " + std::to_string(nu));
  return deformed_body(split, cut_class, u, TetMaterials(model, E, nu), progress, wound_offset);
}

DeformedBody deformed_body(const SplitMesh& split, const std::vector<int>& cut_class, const DisplacementField& u,
                           const TetMaterials& materials, const std::function<void(double)>& progress,
                           double wound_offset) {
  const Eigen::Index np = split.points.rows(), nt = split.tets.rows();

  DeformedBody out;
  TetMesh& v = out.volume;
  v.points = split.points;
  v.tets = split.tets;
  DataArray disp = make_array(DataArray::Type::Float64, 3, np);
  DataArray point_side = make_array(DataArray::Type::Int32, 1, np);
  const double work = static_cast<double>(np + nt);
  // Every point and every cell on its own: in a few threads (parallel_for.h), the same values.
  parallel_for(np, [&](long begin, long end) {
    for (Eigen::Index k = begin; k < end; ++k) {
      const Eigen::Vector3d x = split.points.row(k).transpose();
      const Eigen::Vector3d d = u.value(split.point_tet[k], x, split.point_side[k]);
      for (int c = 0; c < 3; ++c) disp.values[3 * k + c] = d[c];
      point_side.values[k] = split.point_side[k];
    }
  }, progress ? std::function<void(double)>([&](double f) { progress(f * np / work); }) : std::function<void(double)>());
  for (Eigen::Index k = 0; k < np; ++k)
    if (!std::isfinite(disp.values[3 * k]) || !std::isfinite(disp.values[3 * k + 1]) ||
        !std::isfinite(disp.values[3 * k + 2]))
      throw Error("deformed_body: displacement at point " + std::to_string(k) + " (in tet " +
                  std::to_string(split.point_tet[k]) + ") is not finite");

  out.det_F.assign(static_cast<std::size_t>(nt), 1.0);
  DataArray cls = make_array(DataArray::Type::Int32, 1, nt), side = make_array(DataArray::Type::Int32, 1, nt),
            parent = make_array(DataArray::Type::Int64, 1, nt), strain = make_array(DataArray::Type::Float64, 6, nt),
            stress = make_array(DataArray::Type::Float64, 6, nt), vm = make_array(DataArray::Type::Float64, 1, nt);
  parallel_for(nt, [&](long begin, long end) {
    for (Eigen::Index t = begin; t < end; ++t) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int c = 0; c < 4; ++c) centroid += split.points.row(split.tets(t, c)).transpose() / 4;
      const int p = split.parent[t];
      const CellStress cs = cell_stress(materials.law(p), u.gradient(p, centroid, split.tet_side[t]));
      // VTK's order of a symmetric tensor's 6 components (as ParaView reads them).
      static const int kI[6] = {0, 1, 2, 0, 1, 0}, kJ[6] = {0, 1, 2, 1, 2, 2};
      for (int c = 0; c < 6; ++c) {
        strain.values[6 * t + c] = cs.strain(kI[c], kJ[c]);
        stress.values[6 * t + c] = cs.stress(kI[c], kJ[c]);
      }
      vm.values[t] = von_mises(cs.stress);
      out.det_F[t] = cs.det_F;
      cls.values[t] = cut_class[p];
      side.values[t] = split.tet_side[t];
      parent.values[t] = p;
    }
  }, progress ? std::function<void(double)>([&](double f) { progress((np + f * nt) / work); })
              : std::function<void(double)>());
  v.point_data["displacement"] = disp;
  v.point_data["side"] = point_side;
  v.cell_data["cut_class"] = cls;
  v.cell_data["piece_side"] = side;  // not "side": ParaView lists point and cell arrays by name
  v.cell_data["parent"] = parent;
  v.cell_data["strain"] = strain;
  v.cell_data["stress"] = stress;
  v.cell_data["von_mises"] = vm;

  // The wound keeps only the points its triangles use, renumbered in order of first use.
  std::vector<int> renumber(np, -1);
  std::vector<int> used;
  TriangleMesh& w = out.wound;
  w.triangles.resize(split.wound.rows(), 3);
  for (Eigen::Index f = 0; f < split.wound.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      int& id = renumber[split.wound(f, c)];
      if (id < 0) {
        id = static_cast<int>(used.size());
        used.push_back(split.wound(f, c));
      }
      w.triangles(f, c) = id;
    }
  w.points.resize(static_cast<Eigen::Index>(used.size()), 3);
  DataArray wdisp = make_array(DataArray::Type::Float64, 3, used.size());
  for (std::size_t i = 0; i < used.size(); ++i) {
    w.points.row(static_cast<Eigen::Index>(i)) = split.points.row(used[i]);
    for (int c = 0; c < 3; ++c) wdisp.values[3 * i + c] = disp.values[3 * used[i] + c];
  }
  // Shown together with deformed.vtu, whose outer surface holds the same faces, the wound would
  // z-fight; moved by wound_offset x the body's diagonal along its faces' outward normal (into the
  // opening) it is drawn just in front of them. The area-weighted normals of a front point's two
  // faces cancel: it stays where it is, on the front.
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(w.points.rows(), 3);
  Eigen::VectorXd magnitude = Eigen::VectorXd::Zero(w.points.rows());
  for (Eigen::Index f = 0; f < w.triangles.rows(); ++f) {
    const Eigen::Vector3d a = w.points.row(w.triangles(f, 0)), b = w.points.row(w.triangles(f, 1)),
                          c = w.points.row(w.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) {
      normal.row(w.triangles(f, k)) += n.transpose();
      magnitude[w.triangles(f, k)] += n.norm();
    }
  }
  const double offset =
      np > 0 ? wound_offset * (split.points.colwise().maxCoeff() - split.points.colwise().minCoeff()).norm() : 0;
  for (Eigen::Index i = 0; i < w.points.rows(); ++i) {
    const double length = normal.row(i).norm();
    if (length > 0.5 * magnitude[i]) w.points.row(i) += offset / length * normal.row(i);
  }
  DataArray wside = make_array(DataArray::Type::Int32, 1, split.wound_side.size());
  for (std::size_t f = 0; f < split.wound_side.size(); ++f) wside.values[f] = split.wound_side[f];
  w.point_data["displacement"] = wdisp;
  w.cell_data["side"] = wside;
  if (progress) progress(1.0);
  return out;
}

CutOpening cut_opening(const SplitMesh& split, const DataArray& displacement,
                       const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& normal) {
  // The two copies of a point are made from the same coordinates, so they compare equal exactly.
  std::map<std::array<double, 3>, std::array<int, 2>> copies;
  for (Eigen::Index k = 0; k < split.points.rows(); ++k) {
    if (split.point_side[k] == 0) continue;
    auto& c = copies.try_emplace({split.points(k, 0), split.points(k, 1), split.points(k, 2)}, std::array<int, 2>{-1, -1})
                  .first->second;
    c[split.point_side[k] > 0 ? 0 : 1] = static_cast<int>(k);
  }
  CutOpening o;
  double sum = 0;
  for (const auto& [x, c] : copies) {
    if (c[0] < 0 || c[1] < 0) continue;
    Eigen::Vector3d d;
    for (int i = 0; i < 3; ++i) d[i] = displacement(c[0], i) - displacement(c[1], i);
    const double dn = d.dot(normal(Eigen::Vector3d(x[0], x[1], x[2])));
    o.min_normal = o.pairs == 0 ? dn : std::min(o.min_normal, dn);
    o.max_normal = o.pairs == 0 ? dn : std::max(o.max_normal, dn);
    o.max_jump = std::max(o.max_jump, d.norm());
    sum += dn;
    ++o.pairs;
  }
  if (o.pairs > 0) o.mean_normal = sum / o.pairs;
  return o;
}

}  // namespace xfem
