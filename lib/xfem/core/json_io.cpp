// SPDX-License-Identifier: MIT
#include "xfem/core/json_io.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"

namespace xfem {
namespace {

// nlohmann's parser recurses once per nesting level: 1e5 levels overflow the stack. No xfem
// input nests deeper than a few levels, so deeper documents are refused before parsing.
constexpr int kMaxDepth = 64;

void check_depth(const std::string& text, const std::string& path) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDepth)
        throw Error(path + ": JSON nested deeper than " + std::to_string(kMaxDepth) + " levels (byte " +
                    std::to_string(i + 1) + ")");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// The JSON path of the first non-finite number ("" if none): nlohmann would write it as null.
std::string non_finite_at(const Json& j, const std::string& where) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return where.empty() ? "(top level)" : where;
  if (j.is_object())
    for (const auto& [key, value] : j.items()) {
      const std::string found = non_finite_at(value, where.empty() ? key : where + "." + key);
      if (!found.empty()) return found;
    }
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string found = non_finite_at(j[i], where + "[" + std::to_string(i) + "]");
      if (!found.empty()) return found;
    }
  return "";
}

}  // namespace

void write_json(const Json& j, const std::string& path) {
  const std::string bad = non_finite_at(j, "");
  if (!bad.empty()) throw Error(path + ": refusing to write a non-finite value (NaN or Inf) in '" + bad + "'");
  const std::string text = j.dump(2) + "\n";
  write_atomically(path, [&](const std::string& tmp) {
    if (tmp == "-") {
      std::cout << text << std::flush;
      return;
    }
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw Error(path + ": cannot write");
  });
}

Json parse_json(const std::string& text, const std::string& path) {
  check_depth(text, path);
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(path + ": not valid JSON (byte " + std::to_string(e.byte) + ")");
  } catch (const nlohmann::json::out_of_range& e) {
    if (e.id == 406) throw Error(path + ": a number in the JSON is too large for a double (beyond 1.8e308)");
    throw Error(path + ": not valid JSON (value out of range)");
  } catch (const nlohmann::json::exception&) {
    throw Error(path + ": not valid JSON");
  }
}

Json read_json(const std::string& path) {
  require_readable(path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_json(ss.str(), path);
}

}  // namespace xfem
