// SPDX-License-Identifier: MIT
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace xfem {

using Json = nlohmann::ordered_json;  ///< keys keep their insertion order: stable, readable reports

/// Writes `j` (2-space indent, trailing newline), atomically; "-" is stdout. Refuses a document
/// holding NaN or Inf (JSON has no such numbers) with an error naming the key.
void write_json(const Json& j, const std::string& path);

/// Reads a JSON file; throws xfem::Error naming the file and the parse error's position, a number
/// beyond the double range, or nesting deeper than 64 levels (refused before parsing: the parser
/// recurses per level).
Json read_json(const std::string& path);

/// Parses `text` as read_json does; `path` names it in messages.
Json parse_json(const std::string& text, const std::string& path);

}  // namespace xfem
