// SPDX-License-Identifier: MIT
#include "xfem/io/vtk_on_demand.h"

#include <dlfcn.h>

#include <map>
#include <mutex>

#include "xfem/core/error.h"

#ifndef XFEM_VTK_IO_GEOMETRY_LIBRARY
#define XFEM_VTK_IO_GEOMETRY_LIBRARY "libvtkIOGeometry-9.1.so.1"
#endif
#ifndef XFEM_VTK_IO_IMAGE_LIBRARY
#define XFEM_VTK_IO_IMAGE_LIBRARY "libvtkIOImage-9.1.so.1"
#endif

namespace xfem {

const char* const vtk_io_geometry_library = XFEM_VTK_IO_GEOMETRY_LIBRARY;
const char* const vtk_io_image_library = XFEM_VTK_IO_IMAGE_LIBRARY;

void* vtk_symbol(const char* library, const char* symbol, const std::string& path, const char* what) {
  static std::mutex mutex;
  static std::map<std::string, void*> handles;  // library -> dlopen handle (null: failed)
  std::lock_guard<std::mutex> lock(mutex);
  auto it = handles.find(library);
  if (it == handles.end()) it = handles.emplace(library, ::dlopen(library, RTLD_NOW | RTLD_LOCAL)).first;
  if (!it->second) {
    const char* why = ::dlerror();
    throw Error(path + ": cannot read " + what + ": VTK's library " + library + " cannot be loaded (" +
                (why ? why : "loading failed before") + "; install libvtk9-dev, scripts/install-deps.sh)");
  }
  void* address = ::dlsym(it->second, symbol);
  if (!address)
    throw Error(path + ": cannot read " + what + ": VTK's library " + library + " has no " + symbol);
  return address;
}

}  // namespace xfem
