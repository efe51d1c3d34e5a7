// SPDX-License-Identifier: MIT
#include "xfem/core/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/error.h"

namespace xfem {

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  if (path == "-") {
    write(path);
    return;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw Error(path + ": directory " + dir.string() + " does not exist");
  // The temporary keeps the target's extension: VTK writers choose their format by it.
  const std::string tmp = (dir / ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) +
                                  target.extension().string()))
                              .string();
  try {
    write(tmp);
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) throw Error(path + ": cannot rename temporary file: " + ec.message());
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

void require_readable(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw Error(path + ": is a directory, expected a file");
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open for reading (does it exist?)");
}

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace xfem
