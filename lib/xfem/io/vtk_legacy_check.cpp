// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io_detail.h"

namespace xfem::vtk_io_detail {

// VTK 9.1's legacy reader fills a POINTS section that ends early with invented points, reads a
// huge count as an allocation, and crashes (null stream) on a cell section shorter than its
// header says. So each section header is checked against what the file holds before VTK sees it:
// POINTS n (3n numbers), CELLS / POLYGONS / LINES / VERTICES / TRIANGLE_STRIPS n size (size
// numbers, size >= 2n... at least one id per cell), CELL_TYPES n (n numbers).
void check_legacy_sections(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t binary_at = text.find("\nBINARY");
  const char* end = text.data() + text.size();
  // Point ids are checked against the POINTS count: VTK's legacy reader, which is not built with
  // the sanitizers, writes out of bounds for an id beyond the points (found by fuzzing).
  long long point_count = -1;
  const auto check_id = [&](double id, long long cell) {  // cell: 1-based count of the section's cells
    if (!(id >= 0 && id == std::floor(id) && (point_count < 0 || id < static_cast<double>(point_count))))
      throw Error(path + ": cell " + std::to_string(cell - 1) + " uses point " + short_number(id) + ", out of range [0, " +
                  std::to_string(std::max(point_count, 0LL)) + ")");
  };
  // VTK's legacy reader trusts what it parses (it is not built with the sanitizers, and it wrote
  // past its arrays or followed null pointers on the files fuzzing made of ours): an ASCII file
  // must be text, and a line starting with a keyword's letters must be that keyword.
  if (text.compare(0, 14, "# vtk DataFile") != 0) return;  // not legacy VTK: VTK's reader says so
  if (binary_at == std::string::npos)
    for (std::size_t i = 0; i < text.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      // Lines are what this check reads and whitespace what VTK reads: a vertical tab, a form feed
      // or a lone carriage return would let a keyword hide inside a line.
      const bool lone_cr = c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n');
      if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c >= 0x7f || lone_cr)
        throw Error(path + ": byte " + std::to_string(i) + " is not text, in an ASCII legacy VTK file");
    }
  static const char* const kKeywords[] = {"points", "cells", "cell_types", "polygons", "lines", "vertices",
                                          "triangle_strips", "point_data", "cell_data", "field", "scalars",
                                          "vectors", "normals", "tensors", "lookup_table", "color_scalars",
                                          "texture_coordinates", "global_ids", "pedigree_ids", "metadata", "dataset",
                                          "offsets", "connectivity"};
  std::size_t line_start = 0;
  for (int line = 0; line_start < text.size(); ++line) {
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    // Data lines start with a digit or a sign; line 1 is the title (free text).
    if (line == 1 || !std::isalpha(static_cast<unsigned char>(text[line_start]))) {
      line_start = line_end + 1;
      continue;
    }
    const std::string head = text.substr(line_start, std::min<std::size_t>(line_end - line_start, 200));
    std::istringstream header(head);
    std::string keyword;
    header >> keyword;
    std::string lower = keyword;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // VTK compares only a keyword's first letters: "CELLS2 10" is CELLS, and "10" and the next
    // line's count became its counts.
    for (const char* k : kKeywords)
      if (lower.compare(0, std::strlen(k), k) == 0 && lower != k)
        throw Error(path + ": unknown keyword '" + keyword.substr(0, 40) + "' in the legacy VTK file (did you mean '" +
                    std::string(k) + "'?)");
    const bool points = lower == "points", types = lower == "cell_types";
    const bool cells = lower == "cells" || lower == "polygons" || lower == "lines" || lower == "vertices" ||
                       lower == "triangle_strips";
    std::vector<std::string> words;
    for (std::string w; header >> w;) words.push_back(w);
    for (std::string w : words) {  // one keyword per line: VTK would take one that follows
      for (char& c : w) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      for (const char* k : {"points", "cells", "cell_types", "polygons", "lines", "vertices", "triangle_strips",
                            "point_data", "cell_data"})
        if (w.compare(0, std::strlen(k), k) == 0)
          throw Error(path + ": a second keyword in the line of " + keyword + " in the legacy VTK file");
    }
    if (points && words.size() == 2) {
      static const char* const kTypes[] = {"bit", "unsigned_char", "char", "unsigned_short", "short", "unsigned_int",
                                           "int", "unsigned_long", "long", "float", "double", "vtkidtype",
                                           "vtktypeint64", "vtktypeuint64"};
      std::string t = words[1];
      for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; }))
        throw Error(path + ": POINTS of unknown type '" + words[1].substr(0, 20) + "' in the legacy VTK file");
    }
    if (points || types || cells) {
      // The counts as whole numbers, nothing after them but the points' type.
      const std::size_t counts = cells ? 2 : 1;
      bool ok = words.size() == counts + (points ? 1 : 0);
      for (std::size_t i = 0; ok && i < counts; ++i)
        ok = !words[i].empty() && words[i].size() <= 18 &&
             std::all_of(words[i].begin(), words[i].end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!ok) throw Error(path + ": malformed " + keyword + " line in the legacy VTK file");
      const long long n = std::stoll(words[0]), size = cells ? std::stoll(words[1]) : -1;
      const std::string type = points ? words[1] : std::string();
      if (n > static_cast<long long>(text.size()) || size > static_cast<long long>(text.size()))
        throw Error(path + ": " + keyword + " claims " + std::to_string(n) + " items, more than the file can hold");
      const std::size_t data = std::min(line_end + 1, text.size());
      const bool new_cells = cells && text.compare(data, 7, "OFFSETS") == 0 &&  // VTK 5.1 layout
                             text.compare(0, 24, "# vtk DataFile Version 5") == 0;
      if (cells && !new_cells && size < 2 * n)
        throw Error(path + ": " + keyword + " " + std::to_string(n) + " " + std::to_string(size) +
                    ": too few values for that many cells");
      const long long want = points ? 3 * n : cells ? size : n;
      const long long left = static_cast<long long>(text.size() - data);
      if (points) point_count = n;
      if (binary_at != std::string::npos && binary_at < line_start) {
        const long long bytes = points ? (type == "double" ? 8 : 4) : 4;
        if (!new_cells && want > left / bytes)
          throw Error(path + ": " + keyword + " claims " + std::to_string(n) + " items but the file holds fewer");
        if (cells && !new_cells) {  // big-endian int32: each cell "k id_1 .. id_k"
          const auto value = [&](long long i) {
            const unsigned char* b = reinterpret_cast<const unsigned char*>(text.data() + data + 4 * i);
            return static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                             (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
          };
          long long i = 0, cell = 0;
          while (i < want) {
            const std::int32_t k = value(i);
            if (k < 1 || k > 1000 || ++cell > n || i + 1 + k > want)
              throw Error(path + ": " + keyword + " section: cell " + std::to_string(cell) +
                          " has an impossible point count or there are more cells than " + std::to_string(n));
            for (std::int32_t j = 1; j <= k; ++j) check_id(value(i + j), cell);
            i += 1 + k;
          }
        }
      } else if (!new_cells) {
        long long numbers = 0;  // ASCII: count the numbers up to the next keyword
        long long next_cell = 0, cells_seen = 0;  // cell sections: each cell is "k id_1 .. id_k"
        const char* p = text.data() + data;
        while (p < end && numbers < want) {
          while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
          if (p == end || std::isalpha(static_cast<unsigned char>(*p))) break;
          const char* token = p;
          while (p < end && !std::isspace(static_cast<unsigned char>(*p))) ++p;
          const std::string word(token, std::min<std::size_t>(p - token, 40));
          char* stop = nullptr;
          std::strtod(word.c_str(), &stop);
          if (stop != word.c_str() + word.size()) {
            std::string shown(token, std::min<std::size_t>(p - token, 20));
            for (char& c : shown)  // one printable line
              if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
            throw Error(path + ": " + keyword + " section: '" + shown + "' is not a number");
          }
          if ((cells || types) && !std::all_of(word.begin(), word.end(), [](char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+'; })) {
            std::string shown = word.substr(0, 20);
            throw Error(path + ": " + keyword + " section: '" + shown + "' is not a whole number");
          }
          if (cells && numbers == next_cell) {  // a cell's point count
            const double k = std::strtod(word.c_str(), nullptr);
            if (!(k >= 1 && k <= 1000) || ++cells_seen > n)
              throw Error(path + ": " + keyword + " section: cell " + std::to_string(cells_seen) +
                          " has an impossible point count or there are more cells than " + std::to_string(n));
            next_cell = numbers + 1 + static_cast<long long>(k);
          } else if (cells) {
            check_id(std::strtod(word.c_str(), nullptr), cells_seen);
          }
          ++numbers;
        }
        if (cells && numbers == want && (next_cell != want || cells_seen != n))
          throw Error(path + ": " + keyword + " " + std::to_string(n) + " " + std::to_string(size) +
                      ": the cells' point counts do not add up to the section's size");
        if (numbers < want)
          throw Error(path + ": " + keyword + " claims " + std::to_string(n) +
                      (points ? " points but only " : " items but only ") + std::to_string(numbers) +
                      (points ? " coordinates" : " values") + " follow (" + std::to_string(want) + " expected)");
      }
    }
    line_start = line_end + 1;
  }
}

}  // namespace xfem::vtk_io_detail
