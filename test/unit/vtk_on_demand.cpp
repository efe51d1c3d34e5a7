// SPDX-License-Identifier: MIT
// VTK libraries loaded on first use (io/vtk_on_demand.h): found, and a missing library or symbol
// is one error naming the file being read.
#include "xfem/io/vtk_on_demand.h"

#include <catch2/catch.hpp>
#include <string>

#include "xfem/core/error.h"

namespace {
std::string error_of(const char* library, const char* symbol) {
  try {
    xfem::vtk_symbol(library, symbol, "in.stl", "triangle surface");
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("vtk_on_demand: the readers' New() are found in the libraries the tools do not link", "[vtk_on_demand]") {
  CHECK(xfem::vtk_symbol(xfem::vtk_io_geometry_library, "_ZN12vtkSTLReader3NewEv", "in.stl", "triangle surface"));
  for (const char* symbol : {"_ZN13vtkNrrdReader3NewEv", "_ZN18vtkMetaImageReader3NewEv",
                             "_ZN19vtkNIFTIImageReader3NewEv", "_ZN19vtkNIFTIImageReader14GetNIFTIHeaderEv"})
    CHECK(xfem::vtk_symbol(xfem::vtk_io_image_library, symbol, "in.nii", "label map"));
}

TEST_CASE("vtk_on_demand: a missing library or symbol is one error naming the file", "[vtk_on_demand]") {
  const std::string missing = error_of("libxfem-no-such-library.so.0", "_ZN12vtkSTLReader3NewEv");
  CHECK(missing.rfind("in.stl: cannot read triangle surface: VTK's library libxfem-no-such-library.so.0 cannot be "
                      "loaded (",
                      0) == 0);
  CHECK(missing.find('\n') == std::string::npos);
  // Asked again, the same error (the failed load is remembered, dlerror is empty then).
  CHECK(error_of("libxfem-no-such-library.so.0", "x").rfind("in.stl: cannot read triangle surface: VTK's library", 0) == 0);
  CHECK(error_of(xfem::vtk_io_geometry_library, "no_such_symbol") ==
        std::string("in.stl: cannot read triangle surface: VTK's library ") + xfem::vtk_io_geometry_library +
            " has no no_such_symbol");
}
