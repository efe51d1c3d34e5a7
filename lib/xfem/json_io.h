// SPDX-License-Identifier: MIT
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace xfem {

using Json = nlohmann::ordered_json;  ///< keys keep their insertion order: stable, readable reports

/// Writes `j` (2-space indent, trailing newline), atomically; "-" is stdout.
void write_json(const Json& j, const std::string& path);

/// Reads a JSON file; throws xfem::Error naming the file and the parse error's position.
Json read_json(const std::string& path);

}  // namespace xfem
