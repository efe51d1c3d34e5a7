// SPDX-License-Identifier: MIT
#include "xfem/core/mesh.h"

#include <algorithm>


#include "xfem/core/error.h"

namespace xfem {

std::vector<std::array<int, 3>> boundary_faces(const TetMesh& mesh) {
  // Every tet's 4 faces as sorted node triples, sorted: a triple that appears once is on the boundary.
  std::vector<std::array<int, 3>> faces;
  faces.reserve(4 * static_cast<std::size_t>(mesh.tets.rows()));
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int c = 0, i = 0; c < 4; ++c)
        if (c != skip) f[i++] = mesh.tets(t, c);
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<int, 3>> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) boundary.push_back(faces[i]);
    i = j;
  }
  return boundary;
}

double signed_volume(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                     const Eigen::Vector3d& p3) {
  return (p1 - p0).cross(p2 - p0).dot(p3 - p0) / 6.0;
}

double signed_volume(const TetMesh& mesh, int tet) {
  const auto& t = mesh.tets.row(tet);
  return signed_volume(mesh.points.row(t[0]), mesh.points.row(t[1]), mesh.points.row(t[2]),
                       mesh.points.row(t[3]));
}

double point_segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - p;
  const double dd = d.squaredNorm();
  const double t = dd > 0 ? std::clamp((x - p).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - p - t * d).norm();
}

double segment_segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1) {
  double best = std::min({point_segment_distance(p0, q0, q1), point_segment_distance(p1, q0, q1),
                          point_segment_distance(q0, p0, p1), point_segment_distance(q1, p0, p1)});
  // The interior minimum, when both closest points fall inside their segments.
  const Eigen::Vector3d u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = a * c - b * b;
  if (den > 1e-14 * a * c) {
    const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, (w + s * u - t * v).norm());
  }
  return best;
}

const DataArray& require_array(const DataArrays& arrays, const std::string& name, const char* where,
                               int components, std::size_t tuples, const std::string& file,
                               const std::string& stage) {
  const auto it = arrays.find(name);
  if (it == arrays.end())
    throw Error(file + ": " + where + " array '" + name + "' missing (is this " + stage + " output?)");
  const DataArray& a = it->second;
  if (a.components != components)
    throw Error(file + ": " + where + " array '" + name + "' has " + std::to_string(a.components) +
                " components, expected " + std::to_string(components));
  if (tuples != static_cast<std::size_t>(-1) && a.tuples() != tuples)
    throw Error(file + ": " + where + " array '" + name + "' has " + std::to_string(a.tuples()) +
                " tuples, expected " + std::to_string(tuples));
  return a;
}

DataArray make_array(DataArray::Type type, int components, std::size_t n, double fill) {
  DataArray a;
  a.type = type;
  a.components = components;
  a.values.assign(n * components, fill);
  return a;
}

}  // namespace xfem
