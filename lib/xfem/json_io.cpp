// SPDX-License-Identifier: MIT
#include "xfem/json_io.h"

#include <fstream>
#include <iostream>

#include "xfem/atomic_file.h"
#include "xfem/error.h"

namespace xfem {

void write_json(const Json& j, const std::string& path) {
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

Json read_json(const std::string& path) {
  require_readable(path);
  std::ifstream in(path);
  try {
    return Json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(path + ": not valid JSON (byte " + std::to_string(e.byte) + ")");
  }
}

}  // namespace xfem
