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

namespace {

// The temporary of `path` (number `index` of several written together): a hidden name in the
// target's directory, keeping the target's extension (VTK writers choose their format by it).
std::string temporary_of(const std::string& path, std::size_t index) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw Error(path + ": directory " + dir.string() + " does not exist");
  return (dir / ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) +
                 (index > 0 ? "_" + std::to_string(index) : std::string()) + target.extension().string()))
      .string();
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw Error(path + ": cannot rename temporary file: " + ec.message());
}

}  // namespace

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  if (path == "-") {
    write(path);
    return;
  }
  const std::string tmp = temporary_of(path, 0);
  try {
    write(tmp);
    rename_into_place(tmp, path);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

void write_atomically_together(const std::vector<FileWriter>& files) {
  std::vector<std::string> temporaries;
  try {
    for (std::size_t k = 0; k < files.size(); ++k) {
      const std::string& path = files[k].first;
      temporaries.push_back(path == "-" ? path : temporary_of(path, k + 1));
      files[k].second(temporaries.back());
    }
    for (std::size_t k = 0; k < files.size(); ++k)
      if (files[k].first != "-") rename_into_place(temporaries[k], files[k].first);
  } catch (...) {
    for (std::size_t k = 0; k < temporaries.size(); ++k)
      if (files[k].first != "-") std::remove(temporaries[k].c_str());
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
