// SPDX-License-Identifier: MIT
#include "xfem/io/paraview_collection.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"

namespace xfem {

void write_paraview_collection(const std::vector<CollectionEntry>& entries, const std::string& path) {
  for (const auto& e : entries)
    if (!std::isfinite(e.time)) throw Error(path + ": the time of " + e.file + " is not a finite number");
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& e : entries) {
      char time[40];
      std::snprintf(time, sizeof time, "%.17g", e.time);
      std::string file;  // XML-escape the few characters a file name may hold
      for (char c : e.file) file += c == '&' ? "&amp;" : c == '"' ? "&quot;" : c == '<' ? "&lt;" : std::string(1, c);
      out << "    <DataSet timestep=\"" << time << "\" part=\"" << e.part << "\" file=\"" << file << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    if (!out) throw Error(path + ": cannot write");
  });
}

}  // namespace xfem
