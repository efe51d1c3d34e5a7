// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace xfem {

/// Writes `path` so that no half-written file ever carries its name: `write` is called with a
/// temporary path in the same directory, which is renamed over `path` once `write` returns.
/// On any exception the temporary file is removed and the exception rethrown.
/// `path` == "-" calls `write("-")` directly (the writer streams to stdout).
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp)>& write);

/// Writes several files so that they appear together: each is written to a temporary of its own (in
/// its target's directory, as write_atomically), and only once every one is written are they
/// renamed into place, one after the other. A kill while writing leaves every target as it was; the
/// only window that can pair a new file with an old one is between two renames. On any exception
/// every temporary is removed (targets already renamed stay). A path "-" is written directly.
using FileWriter = std::pair<std::string, std::function<void(const std::string& tmp)>>;
void write_atomically_together(const std::vector<FileWriter>& files);

/// Throws xfem::Error naming `path` unless the file exists and can be opened for reading.
void require_readable(const std::string& path);

/// Lower-case extension of `path` including the dot (".vtu"), "" if none.
std::string extension_of(const std::string& path);

}  // namespace xfem
