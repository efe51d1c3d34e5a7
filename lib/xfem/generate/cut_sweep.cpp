// SPDX-License-Identifier: MIT
#include "xfem/generate/cut_sweep.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "xfem/core/error.h"

namespace xfem {

std::vector<double> cut_times(const TriangleMesh& cut, const std::string& file) {
  const auto it = cut.cell_data.find("time");
  if (it == cut.cell_data.end())
    throw Error(file + ": no cell array 'time' (when the blade makes each triangle, in seconds): not a sweep "
                "(xfem-mesh cut-sweep writes one; docs/FORMATS.md)");
  const DataArray& a = it->second;
  if (a.components != 1)
    throw Error(file + ": cell array 'time' has " + std::to_string(a.components) + " components, expected 1");
  if (a.tuples() != static_cast<std::size_t>(cut.triangles.rows()))
    throw Error(file + ": cell array 'time' has " + std::to_string(a.tuples()) + " values for " +
                std::to_string(cut.triangles.rows()) + " triangles");
  for (std::size_t k = 0; k < a.values.size(); ++k)
    if (!std::isfinite(a.values[k]))
      throw Error(file + ": cell array 'time' of triangle " + std::to_string(k) + " is not a finite number");
  if (a.values.empty()) throw Error(file + ": the sweep has no triangle");
  return a.values;
}

std::vector<int> cut_until_ids(const std::vector<double>& times, double t) {
  std::vector<int> keep;
  for (int k = 0; k < static_cast<int>(times.size()); ++k)
    if (times[k] <= t) keep.push_back(k);
  return keep;
}

TriangleMesh cut_until(const TriangleMesh& sweep, const std::vector<double>& times, double t) {
  const std::vector<int> keep = cut_until_ids(times, t);
  std::vector<int> new_id(sweep.points.rows(), -1);
  for (int k : keep)
    for (int c = 0; c < 3; ++c) new_id[sweep.triangles(k, c)] = 0;
  std::vector<int> old_id;
  for (int p = 0; p < sweep.points.rows(); ++p)
    if (new_id[p] == 0) {
      new_id[p] = static_cast<int>(old_id.size());
      old_id.push_back(p);
    }
  TriangleMesh out;
  out.points.resize(static_cast<long>(old_id.size()), 3);
  for (std::size_t p = 0; p < old_id.size(); ++p) out.points.row(static_cast<long>(p)) = sweep.points.row(old_id[p]);
  out.triangles.resize(static_cast<long>(keep.size()), 3);
  for (std::size_t k = 0; k < keep.size(); ++k)
    for (int c = 0; c < 3; ++c) out.triangles(static_cast<long>(k), c) = new_id[sweep.triangles(keep[k], c)];
  auto subset = [](const DataArray& a, const std::vector<int>& ids) {
    DataArray b = a;
    b.values.clear();
    for (int i : ids)
      for (int c = 0; c < a.components; ++c) b.values.push_back(a(static_cast<std::size_t>(i), c));
    return b;
  };
  for (const auto& [name, a] : sweep.point_data) out.point_data[name] = subset(a, old_id);
  for (const auto& [name, a] : sweep.cell_data) out.cell_data[name] = subset(a, keep);
  return out;
}

std::vector<double> step_times(const std::vector<double>& times, int steps) {
  if (steps < 1) throw Error("the number of steps must be at least 1, got " + std::to_string(steps));
  const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
  std::vector<double> t;
  for (int k = 1; k <= steps; ++k) t.push_back(k == steps ? *hi : *lo + (*hi - *lo) * k / steps);
  return t;
}

TriangleMesh cut_sweep(const BladePath& path, double depth, const Eigen::Vector3d& down_in, double tilt,
                       double resolution, double duration) {
  if (!(depth > 0)) throw Error("the blade's depth must be positive");
  if (!(resolution > 0)) throw Error("the resolution must be positive");
  if (!(duration > 0)) throw Error("the duration must be positive");
  if (!(down_in.norm() > 0)) throw Error("the blade direction must not be zero");
  const Eigen::Vector3d down = down_in.normalized();
  // Samples of the path (points, unit tangents, arc length).
  std::vector<Eigen::Vector3d> p, tangent;
  std::vector<double> s;
  if (!path.polyline.empty()) {
    if (path.polyline.size() < 2) throw Error("a blade path needs at least 2 points");
    p.push_back(path.polyline[0]);
    s.push_back(0);
    std::vector<Eigen::Vector3d> seg_t;
    for (std::size_t k = 0; k + 1 < path.polyline.size(); ++k) {
      const Eigen::Vector3d a = path.polyline[k], b = path.polyline[k + 1];
      const double len = (b - a).norm();
      if (!(len > 0)) throw Error("the blade path has two equal consecutive points (point " + std::to_string(k + 1) + ")");
      const int n = std::max(1, static_cast<int>(std::ceil(len / resolution - 1e-9)));
      if (n > 1000000) throw Error("the resolution is too fine for the path's length (over 1e6 samples)");
      for (int i = 1; i <= n; ++i) {
        p.push_back(a + (b - a) * (double(i) / n));
        s.push_back(s.back() + len / n);
        seg_t.push_back((b - a) / len);
      }
    }
    // Tangent at a sample: its segment's, the mean of both at a corner of the polyline.
    tangent.push_back(seg_t.front());
    for (std::size_t i = 1; i < p.size(); ++i) {
      Eigen::Vector3d t = seg_t[i - 1];
      if (i < seg_t.size() && seg_t[i] != seg_t[i - 1]) t = (seg_t[i - 1] + seg_t[i]).normalized();
      tangent.push_back(t);
    }
  } else {
    if (!(path.radius > 0)) throw Error("the arc's radius must be positive");
    if (!(path.axis.norm() > 0)) throw Error("the arc's axis must not be zero");
    if (!(path.a1 != path.a0)) throw Error("the arc's start and end angles are equal");
    const Eigen::Vector3d axis = path.axis.normalized();
    // e1: the plane direction closest to x (y when the axis is x).
    Eigen::Vector3d e1 = Eigen::Vector3d::UnitX() - axis * axis.x();
    if (e1.norm() < 1e-6) e1 = Eigen::Vector3d::UnitY() - axis * axis.y();
    e1.normalize();
    const Eigen::Vector3d e2 = axis.cross(e1);
    const double a0 = path.a0 * M_PI / 180, a1 = path.a1 * M_PI / 180;
    const double len = std::fabs(a1 - a0) * path.radius;
    const int n = std::max(2, static_cast<int>(std::ceil(len / resolution - 1e-9)));
    if (n > 1000000) throw Error("the resolution is too fine for the path's length (over 1e6 samples)");
    const double sign = a1 > a0 ? 1 : -1;
    for (int i = 0; i <= n; ++i) {
      const double a = a0 + (a1 - a0) * i / n;
      p.push_back(path.centre + path.radius * (std::cos(a) * e1 + std::sin(a) * e2));
      tangent.push_back(sign * (-std::sin(a) * e1 + std::cos(a) * e2));
      s.push_back(len * i / n);
    }
  }
  const double length = s.back();
  if (!(length > 0)) throw Error("the blade path has zero length");
  const int m = std::max(1, static_cast<int>(std::ceil(depth / resolution - 1e-9)));
  const long columns = static_cast<long>(p.size());
  if (2.0 * (columns - 1) * m > 1e6) throw Error("the resolution is too fine: over 1e6 triangles");
  TriangleMesh out;
  out.points.resize(columns * (m + 1), 3);
  for (long i = 0; i < columns; ++i) {
    const Eigen::Vector3d blade = Eigen::AngleAxisd(tilt * M_PI / 180, tangent[i]) * down;
    if (blade.cross(tangent[i]).norm() < 1e-6)
      throw Error("the blade points along the path at sample " + std::to_string(i) + ": no surface is swept");
    for (int j = 0; j <= m; ++j) out.points.row(i * (m + 1) + j) = (p[i] + blade * (depth * j / m)).transpose();
  }
  out.triangles.resize(2 * (columns - 1) * m, 3);
  DataArray time;
  time.type = DataArray::Type::Float64;
  long f = 0;
  for (long i = 0; i + 1 < columns; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = static_cast<int>(i * (m + 1) + j), b = static_cast<int>((i + 1) * (m + 1) + j);
      out.triangles.row(f++) << a, b, b + 1;
      out.triangles.row(f++) << a, b + 1, a + 1;
      time.values.push_back(duration * s[i + 1] / length);
      time.values.push_back(duration * s[i + 1] / length);
    }
  out.cell_data["time"] = time;
  return out;
}

}  // namespace xfem
