// SPDX-License-Identifier: MIT
#include "xfem/post/deformed_volume.h"

#include <cstdio>

#include "xfem/core/error.h"

namespace xfem {
namespace {

std::string format(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string volumes(const DeformedVolume::Part& p) {
  const double change = p.before > 0 ? (p.after - p.before) / p.before : 0.0;
  return format("%.6g", p.before) + " m^3 -> " + format("%.6g", p.after) + " m^3 (relative change " +
         format("%+.3g", change) + ")";
}

}  // namespace

DeformedVolume deformed_volume(const TetMesh& deformed, const std::vector<double>& det_F) {
  const Eigen::Index nt = deformed.tets.rows(), np = deformed.points.rows();
  const auto u = deformed.point_data.find("displacement");
  const auto side = deformed.cell_data.find("piece_side");
  if (u == deformed.point_data.end() || u->second.components != 3 || u->second.tuples() != static_cast<std::size_t>(np) ||
      side == deformed.cell_data.end() || side->second.tuples() != static_cast<std::size_t>(nt) ||
      static_cast<Eigen::Index>(det_F.size()) != nt)
    throw Error("deformed_volume: the deformed mesh lacks its displacement, piece_side or det F per cell");
  DeformedVolume v;
  DeformedVolume::Part parts[3];  // piece_side +1, -1, 0
  parts[0].side = 1;
  parts[1].side = -1;
  for (Eigen::Index t = 0; t < nt; ++t) {
    Eigen::Vector3d x[4], y[4];
    for (int c = 0; c < 4; ++c) {
      const auto k = static_cast<std::size_t>(deformed.tets(t, c));
      x[c] = deformed.points.row(static_cast<Eigen::Index>(k)).transpose();
      y[c] = x[c] + Eigen::Vector3d(u->second(k, 0), u->second(k, 1), u->second(k, 2));
    }
    const double before = signed_volume(x[0], x[1], x[2], x[3]), after = signed_volume(y[0], y[1], y[2], y[3]);
    const int s = static_cast<int>(side->second(static_cast<std::size_t>(t), 0));
    DeformedVolume::Part& p = parts[s > 0 ? 0 : s < 0 ? 1 : 2];
    for (DeformedVolume::Part* q : {&p, &v.body}) {
      ++q->cells;
      q->before += before;
      q->after += after;
    }
    const bool undefined = !(det_F[t] > 0);
    v.undefined_stress += undefined;
    v.inverted += undefined || !(after > 0);
  }
  if (parts[0].cells + parts[1].cells > 0)
    for (const auto& p : parts)
      if (p.cells > 0) v.sides.push_back(p);
  return v;
}

std::string describe(const DeformedVolume& v) {
  std::string s = "volume " + volumes(v.body);
  for (const auto& p : v.sides)
    s += std::string(p.side > 0 ? "; above the cut (piece_side +1) " : p.side < 0 ? "; below (-1) " : "; whole (0) ") +
         volumes(p);
  return s + "; " + std::to_string(v.inverted) + " inverted cells (" + std::to_string(v.undefined_stress) +
         " with det F <= 0 at the centroid, " + std::to_string(v.inverted - v.undefined_stress) +
         " slivers flipped by their moved corners only)";
}

std::string inverted_warning(const DeformedVolume& v, MaterialModel model) {
  if (v.undefined_stress == 0) return {};  // slivers flipped by their corners only: in the volume line
  const std::string n = std::to_string(v.undefined_stress) + " of " + std::to_string(v.body.cells) +
                        " cells are inverted (det F <= 0 at the centroid): the displacement turns them inside out; ";
  if (model == MaterialModel::Linear)
    return n + "the small-strain model does not hold there (its Hooke stress is shown unchanged); for large motions "
               "solve with xfem-newton and material.model \"corotational\" or \"neo-hookean\"";
  return n + "not a physical state; the Cauchy stress P F^T / det F is undefined there: their stress and "
             "von_mises hold 0";
}

}  // namespace xfem
