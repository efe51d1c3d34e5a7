// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

namespace xfem {

/// One file of a ParaView collection: its time (s), its part (0, 1, ...: datasets shown together
/// at one time, e.g. the body and the wound) and its path relative to the .pvd.
struct CollectionEntry {
  double time = 0;
  int part = 0;
  std::string file;
};

/// Writes a ParaView data collection (.pvd: VTKFile type "Collection", one DataSet per entry;
/// ParaView plays it as a time series, docs/FORMATS.md "sweep.pvd"), atomically. Throws
/// xfem::Error for a time that is not finite (nothing written).
void write_paraview_collection(const std::vector<CollectionEntry>& entries, const std::string& path);

}  // namespace xfem
