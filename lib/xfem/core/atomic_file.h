// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <string>

namespace xfem {

/// Writes `path` so that no half-written file ever carries its name: `write` is called with a
/// temporary path in the same directory, which is renamed over `path` once `write` returns.
/// On any exception the temporary file is removed and the exception rethrown.
/// `path` == "-" calls `write("-")` directly (the writer streams to stdout).
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp)>& write);

/// Throws xfem::Error naming `path` unless the file exists and can be opened for reading.
void require_readable(const std::string& path);

/// Lower-case extension of `path` including the dot (".vtu"), "" if none.
std::string extension_of(const std::string& path);

}  // namespace xfem
