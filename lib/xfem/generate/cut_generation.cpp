// SPDX-License-Identifier: MIT
#include "xfem/generate/cut_generation.h"

#include <cmath>
#include <string>

#include "xfem/core/error.h"

namespace xfem {
namespace {

constexpr double pi = 3.14159265358979323846;

void check_divisions(const Eigen::Vector2i& divisions, const char* what) {
  if ((divisions.array() < 1).any())
    throw Error(std::string(what) + ": divisions must be at least 1 (got " + std::to_string(divisions(0)) + " x " +
                std::to_string(divisions(1)) + ")");
}

// Two triangles per grid quad (i, j)-(i+1, j+1) of an (n0+1) x (n1+1) point grid numbered i
// fastest: (00, 10, 11) and (00, 11, 01), both turning from the first grid direction to the second.
Triangles grid_triangles(int n0, int n1) {
  Triangles t(2 * static_cast<Eigen::Index>(n0) * n1, 3);
  Eigen::Index f = 0;
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const int a = i + (n0 + 1) * j, b = a + 1, c = b + (n0 + 1), d = a + (n0 + 1);
      t.row(f++) << a, b, c;
      t.row(f++) << a, c, d;
    }
  return t;
}

}  // namespace

TriangleMesh cut_parallelogram(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                               const Eigen::Vector2i& divisions) {
  check_divisions(divisions, "rectangular cut");
  const Eigen::Vector3d e1 = p10 - p00, e2 = p01 - p00;
  if (!(e1.cross(e2).norm() > 1e-12 * e1.norm() * e2.norm()))
    throw Error("rectangular cut: its two edges are parallel or zero (the corners span no area)");
  const int n0 = divisions(0), n1 = divisions(1);
  TriangleMesh m;
  m.points.resize(static_cast<Eigen::Index>(n0 + 1) * (n1 + 1), 3);
  for (int j = 0; j <= n1; ++j)
    for (int i = 0; i <= n0; ++i) {
      const double t = double(j) / n1;
      // The last column starts from p10 itself so that this edge keeps the given coordinates.
      const Eigen::Vector3d base = i == n0 ? p10 : Eigen::Vector3d(p00 + (double(i) / n0) * e1);
      const Eigen::Vector3d p = j == 0 ? base : i == 0 && j == n1 ? p01 : Eigen::Vector3d(base + t * e2);
      m.points.row(i + (n0 + 1) * j) = p.transpose();
    }
  m.triangles = grid_triangles(n0, n1);
  return m;
}

TriangleMesh beam_cut(const Eigen::Vector2i& divisions) {
  return cut_parallelogram({-0.01, -0.01, 0.1}, {0.015, -0.01, 0.1}, {-0.01, 0.07, 0.1}, divisions);
}

TriangleMesh cut_sine(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double z0, double amplitude,
                      double wavelength, const Eigen::Vector2i& divisions) {
  check_divisions(divisions, "sinusoidal cut");
  if (!((hi.array() > lo.array()).all()))
    throw Error("sinusoidal cut: empty rectangle (hi must exceed lo in x and y)");
  if (!(wavelength > 0)) throw Error("sinusoidal cut: wavelength must be positive (got " + short_number(wavelength) + ")");
  if (!std::isfinite(wavelength) || !std::isfinite(z0) || !std::isfinite(amplitude) || !lo.allFinite() || !hi.allFinite())
    throw Error("sinusoidal cut: z0, amplitude, wavelength and the rectangle must be finite");
  const int n0 = divisions(0), n1 = divisions(1);
  TriangleMesh m;
  m.points.resize(static_cast<Eigen::Index>(n0 + 1) * (n1 + 1), 3);
  for (int j = 0; j <= n1; ++j)
    for (int i = 0; i <= n0; ++i) {
      const double x = i == n0 ? hi(0) : lo(0) + (hi(0) - lo(0)) * i / n0;
      const double y = j == n1 ? hi(1) : lo(1) + (hi(1) - lo(1)) * j / n1;
      m.points.row(i + (n0 + 1) * j) << x, y, z0 + amplitude * std::sin(2 * pi * x / wavelength);
    }
  // A graph over (x, y): triangles positive in the xy plane have normals with positive z.
  m.triangles = grid_triangles(n0, n1);
  return m;
}

TriangleMesh cut_disc(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double radius, int rings) {
  if (rings < 1) throw Error("disc cut: rings must be at least 1 (got " + std::to_string(rings) + ")");
  if (!(radius > 0)) throw Error("disc cut: radius must be positive (got " + short_number(radius) + ")");
  if (!(normal.norm() > 0)) throw Error("disc cut: the normal is zero");
  // In-plane frame (u, v, n) right-handed, u from the axis least aligned with n (deterministic).
  const Eigen::Vector3d n = normal.normalized();
  Eigen::Index axis;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d u = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  const Eigen::Vector3d v = n.cross(u);

  const auto ring_start = [](int k) { return k == 0 ? 0 : 1 + 3 * k * (k - 1); };  // first id of ring k
  TriangleMesh m;
  m.points.resize(1 + 3 * static_cast<Eigen::Index>(rings) * (rings + 1), 3);
  m.points.row(0) = centre.transpose();
  for (int k = 1; k <= rings; ++k)
    for (int i = 0; i < 6 * k; ++i) {
      const double a = 2 * pi * i / (6 * k), r = radius * k / rings;
      m.points.row(ring_start(k) + i) = (centre + r * (std::cos(a) * u + std::sin(a) * v)).transpose();
    }
  m.triangles.resize(6 * static_cast<Eigen::Index>(rings) * rings, 3);
  Eigen::Index f = 0;
  const auto add = [&](int a, int b, int c) {
    const Eigen::Vector3d pa = m.points.row(a), pb = m.points.row(b), pc = m.points.row(c);
    if ((pb - pa).cross(pc - pa).dot(n) < 0) std::swap(b, c);
    m.triangles.row(f++) << a, b, c;
  };
  for (int i = 0; i < 6; ++i) add(0, ring_start(1) + i, ring_start(1) + (i + 1) % 6);
  // Between rings k (A = 6k points) and k+1 (B = 6k+6): walk both rings by angle, always advancing
  // the one whose next point comes first (exact integer comparison of (i+1)/A and (j+1)/B).
  for (int k = 1; k < rings; ++k) {
    const int A = 6 * k, B = 6 * (k + 1), s = ring_start(k), t = ring_start(k + 1);
    int i = 0, j = 0;
    while (i < A || j < B) {
      const bool inner = j == B || (i < A && static_cast<long>(i + 1) * B < static_cast<long>(j + 1) * A);
      if (inner) {
        add(s + i % A, s + (i + 1) % A, t + j % B);
        ++i;
      } else {
        add(s + i % A, t + j % B, t + (j + 1) % B);
        ++j;
      }
    }
  }
  return m;
}

TriangleMesh cut_zigzag(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double z0, double amplitude, int folds,
                        int divisions) {
  if (folds < 0) throw Error("zig-zag cut: folds must be 0 or more (got " + std::to_string(folds) + ")");
  check_divisions({folds + 1, divisions}, "zig-zag cut");
  if (!((hi.array() > lo.array()).all())) throw Error("zig-zag cut: empty rectangle (hi must exceed lo in x and y)");
  const int n0 = folds + 1, n1 = divisions;
  TriangleMesh m;
  m.points.resize(static_cast<Eigen::Index>(n0 + 1) * (n1 + 1), 3);
  for (int j = 0; j <= n1; ++j)
    for (int i = 0; i <= n0; ++i) {
      // x and z depend on i only, so the points of one fold line agree bit for bit.
      const double x = i == n0 ? hi(0) : lo(0) + (hi(0) - lo(0)) * i / n0;
      const double y = j == n1 ? hi(1) : lo(1) + (hi(1) - lo(1)) * j / n1;
      m.points.row(i + (n0 + 1) * j) << x, y, i % 2 == 0 ? z0 - amplitude : z0 + amplitude;
    }
  m.triangles = grid_triangles(n0, n1);  // a graph over (x, y): normals with positive z
  return m;
}

TriangleMesh merge_surfaces(const std::vector<TriangleMesh>& pieces) {
  Eigen::Index np = 0, nt = 0;
  for (const auto& p : pieces) np += p.points.rows(), nt += p.triangles.rows();
  TriangleMesh m;
  m.points.resize(np, 3);
  m.triangles.resize(nt, 3);
  np = nt = 0;
  for (const auto& p : pieces) {
    m.points.middleRows(np, p.points.rows()) = p.points;
    m.triangles.middleRows(nt, p.triangles.rows()) = p.triangles.array() + static_cast<int>(np);
    np += p.points.rows(), nt += p.triangles.rows();
  }
  return m;
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = mesh.points.row(mesh.triangles(f, 0)), b = mesh.points.row(mesh.triangles(f, 1)),
                          c = mesh.points.row(mesh.triangles(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace xfem
