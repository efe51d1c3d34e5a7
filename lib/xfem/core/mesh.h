// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

namespace xfem {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;      ///< #V x 3, metres
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;           ///< #T x 4 point ids
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;      ///< #F x 3 point ids

/// A named VTK data array. Values are kept as double whatever the stored type: integer arrays
/// (ids, flags) are exact below 2^53. `type` is what is written back to VTK.
struct DataArray {
  enum class Type { Int32, Int64, Float64 };
  Type type = Type::Float64;
  int components = 1;
  std::vector<double> values;  ///< tuple-major: values[i * components + c]

  std::size_t tuples() const { return components > 0 ? values.size() / components : 0; }
  double operator()(std::size_t tuple, int c = 0) const { return values[tuple * components + c]; }
};

/// Arrays by name. Stages keep arrays they do not understand, so later stages still see them.
using DataArrays = std::map<std::string, DataArray>;

/// A tetrahedral volume mesh with its named arrays (the contract in docs/FORMATS.md).
/// Tets are positively oriented: det[p1-p0, p2-p0, p3-p0] > 0.
struct TetMesh {
  Points points;
  Tets tets;
  DataArrays point_data;  ///< one tuple per point
  DataArrays cell_data;   ///< one tuple per tet
  DataArrays field_data;  ///< any length (e.g. the extended connectivity, the DOF counts)
  /// Names of regions by id (may be empty, and may name regions no tet has). Each tet's region
  /// is the Int32 cell array "region" (core/regions.h): a cell array, so every stage that keeps,
  /// permutes or picks cell arrays carries it without code of its own. In a .vtu the names are the
  /// field arrays region_ids and region_names (docs/FORMATS.md "Regions").
  std::map<int, std::string> region_names;
};

/// The boundary faces of `mesh` (a face of exactly one tet; a cut is not part of the mesh, so its
/// faces are none) as sorted node triples, in increasing order.
std::vector<std::array<int, 3>> boundary_faces(const TetMesh& mesh);

/// A triangulated surface (a cut, or the boundary of a body to mesh).
struct TriangleMesh {
  Points points;
  Triangles triangles;
  DataArrays point_data;
  DataArrays cell_data;
};

/// Signed volume of the tet (p0, p1, p2, p3): det[p1-p0, p2-p0, p3-p0] / 6.
double signed_volume(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                     const Eigen::Vector3d& p3);
double signed_volume(const TetMesh& mesh, int tet);

/// Distance from x to the segment (p, q) (to p when the segment has no length).
double point_segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& q);
/// Distance between the segments p0p1 and q0q1 (either may be a point).
double segment_segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1);

/// The array `name` of `arrays`, checked to have `components` components and `tuples` tuples.
/// Throws xfem::Error "<file>: <where> array '<name>' missing (is this <stage> output?)" or a
/// message naming the wrong size. `where` is "point", "cell" or "field".
const DataArray& require_array(const DataArrays& arrays, const std::string& name, const char* where,
                               int components, std::size_t tuples, const std::string& file,
                               const std::string& stage);

/// Makes an array of `n` tuples of `components` components, all `fill`.
DataArray make_array(DataArray::Type type, int components, std::size_t n, double fill = 0.0);

}  // namespace xfem
