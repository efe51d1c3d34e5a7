// SPDX-License-Identifier: MIT
#pragma once
// VTK libraries loaded on first use. vtkIOGeometry (STL) and vtkIOImage (NRRD, MetaImage, NIfTI)
// bring ~24 and ~12 more shared libraries (filters, rendering core, JPEG/PNG/TIFF, ...): a few
// milliseconds of start-up per process, more than a small pipeline stage's own work, and only
// .stl surfaces and label maps need them. The tools do not link them; the readers are made here
// by their New(), found by name in the library opened on the first such file, and used through
// the virtual functions of their bases (docs/PERFORMANCE.md, "Organ S outside the integration").
#include <string>

namespace xfem {

/// The SONAMEs of vtkIOGeometry and vtkIOImage (from VTK's CMake targets; Debian 12's otherwise).
extern const char* const vtk_io_geometry_library;
extern const char* const vtk_io_image_library;

/// The address of `symbol` (a mangled C++ name) in the shared library `library` (a SONAME),
/// opened on the first call for it and kept for the life of the process. Throws Error
/// "<path>: cannot read <what>: ..." when the library or the symbol is missing.
void* vtk_symbol(const char* library, const char* symbol, const std::string& path, const char* what);

/// A new object of a VTK class whose New() is `new_symbol` in `library` (see vtk_symbol).
template <class T>
T* vtk_new_on_demand(const char* library, const char* new_symbol, const std::string& path, const char* what) {
  return reinterpret_cast<T* (*)()>(vtk_symbol(library, new_symbol, path, what))();
}

}  // namespace xfem

