// SPDX-License-Identifier: MIT
// libFuzzer harness for one reader, chosen by the executable's name fuzz_<reader> (one executable
// per reader, fuzz/CMakeLists.txt). The input bytes are written to a file of the reader's extension and
// read: a reader may reject them with xfem::Error (its one-line message) and nothing else. Any
// other exception, a crash, a hang or a sanitizer report is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/system/linear_system.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/problem.h"
#include "xfem/io/vtk_io.h"
#include "xfem/io/label_image.h"

namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("xfem-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void write_file(const fs::path& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

std::string file_with(const char* name, const std::uint8_t* data, std::size_t size) {
  const fs::path path = scratch() / name;
  write_file(path, data, size);
  return path.string();
}

// A system directory from one input: its files separated by the line "=====", in the order
// system.json, K.mtx, f.mtx, dirichlet.mtx, coordinates.mtx (missing parts: no file).
std::string system_dir(const std::uint8_t* data, std::size_t size) {
  const fs::path dir = scratch() / "system";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string text(reinterpret_cast<const char*>(data), size);
  const char* names[] = {"system.json", "K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx"};
  std::size_t start = 0;
  for (const char* name : names) {
    if (start > text.size()) break;
    std::size_t stop = text.find("\n=====\n", start);
    const std::string part = text.substr(start, stop == std::string::npos ? std::string::npos : stop - start);
    write_file(dir / name, reinterpret_cast<const std::uint8_t*>(part.data()), part.size());
    if (stop == std::string::npos) break;
    start = stop + 7;
  }
  return dir.string();
}

using Reader = void (*)(const std::uint8_t*, std::size_t);

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> all = {
      {"vtu", [](const std::uint8_t* d, std::size_t n) { xfem::read_tet_mesh(file_with("mesh.vtu", d, n)); }},
      {"vtk_mesh", [](const std::uint8_t* d, std::size_t n) { xfem::read_tet_mesh(file_with("mesh.vtk", d, n)); }},
      {"vtk_surface", [](const std::uint8_t* d, std::size_t n) { xfem::read_triangle_mesh(file_with("s.vtk", d, n)); }},
      {"vtp", [](const std::uint8_t* d, std::size_t n) { xfem::read_triangle_mesh(file_with("s.vtp", d, n)); }},
      {"stl", [](const std::uint8_t* d, std::size_t n) { xfem::read_triangle_mesh(file_with("s.stl", d, n)); }},
      {"obj", [](const std::uint8_t* d, std::size_t n) { xfem::read_triangle_mesh(file_with("s.obj", d, n)); }},
      {"off", [](const std::uint8_t* d, std::size_t n) { xfem::read_triangle_mesh(file_with("s.off", d, n)); }},
      {"mtx_matrix", [](const std::uint8_t* d, std::size_t n) { xfem::read_matrix(file_with("K.mtx", d, n)); }},
      {"mtx_vector",
       [](const std::uint8_t* d, std::size_t n) {
         const std::string path = file_with("u.mtx", d, n);
         xfem::read_mtx_provenance(path);
         xfem::read_vector(path);
       }},
      {"system", [](const std::uint8_t* d, std::size_t n) { xfem::read_linear_system(system_dir(d, n)); }},
      {"problem", [](const std::uint8_t* d, std::size_t n) { xfem::read_problem(file_with("problem.json", d, n)); }},
      {"exact", [](const std::uint8_t* d, std::size_t n) { xfem::read_exact_field(file_with("exact.json", d, n)); }},
      {"msh",  // gmsh's .msh, read as a body and as a cut
       [](const std::uint8_t* d, std::size_t n) {
         const std::string path = file_with("mesh.msh", d, n);
         try {
           xfem::read_tet_mesh(path);
         } catch (const xfem::Error&) {
         }
         xfem::read_triangle_mesh(path);
       }},
      // Label maps (label_image.h): the header checks, then VTK's or CGAL's reader.
      {"nrrd", [](const std::uint8_t* d, std::size_t n) { xfem::read_label_image(file_with("labels.nrrd", d, n)); }},
      {"nii", [](const std::uint8_t* d, std::size_t n) { xfem::read_label_image(file_with("labels.nii", d, n)); }},
      {"mha", [](const std::uint8_t* d, std::size_t n) { xfem::read_label_image(file_with("labels.mha", d, n)); }},
      {"inr", [](const std::uint8_t* d, std::size_t n) { xfem::read_label_image(file_with("labels.inr", d, n)); }},
      {"vti", [](const std::uint8_t* d, std::size_t n) { xfem::read_label_image(file_with("labels.vti", d, n)); }},
  };
  return all;
}

Reader chosen = nullptr;

}  // namespace

// The reader is named by the executable: fuzz_<reader> (one object file, linked once per reader).
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  (void)argc;
  const std::string name = fs::path((*argv)[0]).filename().string();
  const auto it = readers().find(name.substr(name.find('_') + 1));
  if (name.rfind("fuzz_", 0) != 0 || it == readers().end()) {
    std::fprintf(stderr, "fuzz: run as fuzz_<reader>, not %s\n", name.c_str());
    std::exit(2);
  }
  chosen = it->second;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    chosen(data, size);
  } catch (const xfem::Error&) {
    // The expected rejection of a bad input.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: a reader threw %s instead of xfem::Error\n", e.what());
    std::abort();
  }
  return 0;
}
