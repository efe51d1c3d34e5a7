// SPDX-License-Identifier: MIT
#include "xfem/enrich/cut_files.h"

#include <cmath>
#include <set>

#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

std::vector<TriangleMesh> read_cuts(const std::vector<std::string>& paths, std::vector<std::string>& names,
                                    std::vector<std::string>* warnings) {
  std::vector<TriangleMesh> out;
  names.clear();
  for (const std::string& path : paths) {
    TriangleMesh m = read_triangle_mesh(path, warnings);
    const auto id = m.cell_data.find("cut_id");
    if (id == m.cell_data.end()) {
      out.push_back(std::move(m));
      names.push_back(path);
      continue;
    }
    const DataArray& a = id->second;
    if (a.components != 1) throw Error(path + ": cell array 'cut_id' has " + std::to_string(a.components) + " components, expected 1");
    std::set<long> values;
    for (std::size_t t = 0; t < a.values.size(); ++t) {
      if (!std::isfinite(a.values[t]) || a.values[t] != std::floor(a.values[t]))
        throw Error(path + ": cell array 'cut_id' of triangle " + std::to_string(t) + " is not a whole number");
      values.insert(static_cast<long>(a.values[t]));
    }
    for (const long v : values) {
      std::vector<int> keep, map(m.points.rows(), -1);
      for (int t = 0; t < m.triangles.rows(); ++t)
        if (static_cast<long>(a.values[t]) == v) keep.push_back(t);
      TriangleMesh piece;
      int np = 0;
      for (int t : keep)
        for (int c = 0; c < 3; ++c)
          if (map[m.triangles(t, c)] < 0) map[m.triangles(t, c)] = np++;
      piece.points.resize(np, 3);
      for (int i = 0; i < m.points.rows(); ++i)
        if (map[i] >= 0) piece.points.row(map[i]) = m.points.row(i);
      piece.triangles.resize(static_cast<int>(keep.size()), 3);
      for (std::size_t r = 0; r < keep.size(); ++r)
        for (int c = 0; c < 3; ++c) piece.triangles(static_cast<int>(r), c) = map[m.triangles(keep[r], c)];
      out.push_back(std::move(piece));
      names.push_back(path + "#" + std::to_string(v));
    }
  }
  if (out.size() > static_cast<std::size_t>(kMaxCuts))
    throw Error(std::to_string(out.size()) + " cuts given, at most " + std::to_string(kMaxCuts) + " are handled");
  return out;
}

void store_cut_fingerprints(const std::vector<TriangleMesh>& cuts, TetMesh& mesh) {
  for (std::size_t k = 0; k < cuts.size(); ++k)
    store_fingerprint(mesh.field_data, "cut_fingerprint" + cut_suffix(static_cast<int>(k)), fingerprint(cuts[k]));
}

}  // namespace xfem
