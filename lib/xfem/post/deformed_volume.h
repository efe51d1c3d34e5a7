// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/integrate/material_law.h"

namespace xfem {

/// The volume of a deformed body (xfem-visualize's report, docs/FORMATS.md "deformed.vtu"): before
/// (the undeformed cells) and after (the cells with their corners moved by `displacement`),
/// summed over the whole body and per piece side.
struct DeformedVolume {
  struct Part {
    int side = 0;         ///< piece_side: +1 above the cut, -1 below, 0 kept whole
    long cells = 0;
    double before = 0.0;  ///< m^3
    double after = 0.0;   ///< m^3, signed: an inverted cell counts negative
  };
  Part body;                ///< every cell
  std::vector<Part> sides;  ///< per piece_side present, in the order +1, -1, 0; empty without a cut
  long inverted = 0;        ///< cells with det F <= 0 at the centroid or a deformed volume <= 0
  long undefined_stress = 0;  ///< of these, cells with det F <= 0 (their Cauchy stress is undefined)
};

/// The volumes of `deformed` (an output of deformed_body: point array `displacement`, cell
/// array `piece_side`), `det_F` per cell (DeformedBody::det_F). Throws xfem::Error when an
/// array is missing or has the wrong size.
DeformedVolume deformed_volume(const TetMesh& deformed, const std::vector<double>& det_F);

/// One line for the report: "volume 0.00036 m^3 -> 0.00036 m^3 (relative change +1.2e-16); above
/// the cut (piece_side +1) ... ; 0 inverted cells (0 with det F <= 0 at the centroid, 0 slivers
/// flipped by their moved corners only)".
std::string describe(const DeformedVolume& v);

/// The warning for the cells with det F <= 0 (empty when there are none): how many and what it
/// means for `model`'s stress arrays. Slivers of a split element flipped by their moved corners
/// (det F > 0 at the centroid: a thin piece whose corners' displacement differs by more than its
/// thickness) are counted in describe() only: their stress is defined.
std::string inverted_warning(const DeformedVolume& v, MaterialModel model);

}  // namespace xfem
