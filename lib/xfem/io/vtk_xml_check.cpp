// SPDX-License-Identifier: MIT
#include "xfem/io/vtk_xml_check.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>

#include "xfem/core/error.h"

namespace xfem {

namespace {

using u64 = unsigned long long;

bool xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// One XML start tag as the parser (expat) reads it: name, then attributes `name = "value"` or
// `name = 'value'` with optional white space around '='. `end` is the index after its '>'.
struct StartTag {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::size_t end = 0;
};

// Reads the start tag at text[at] == '<'. False for what is not a well-formed start tag (the XML
// parser refuses the file then, so nothing further needs checking).
bool read_start_tag(const std::string& text, std::size_t at, StartTag& tag) {
  std::size_t p = at + 1;
  const std::size_t n = text.size();
  const auto name_char = [&](std::size_t i) {
    return i < n && !xml_space(text[i]) && text[i] != '>' && text[i] != '/' && text[i] != '=' && text[i] != '<';
  };
  while (name_char(p)) ++p;
  if (p == at + 1) return false;
  tag.name = text.substr(at + 1, p - at - 1);
  tag.attributes.clear();
  for (;;) {
    while (p < n && xml_space(text[p])) ++p;
    if (p >= n) return false;
    if (text[p] == '>' || (text[p] == '/' && p + 1 < n && text[p + 1] == '>')) {
      tag.end = p + (text[p] == '>' ? 1 : 2);
      return true;
    }
    const std::size_t name_start = p;
    while (name_char(p)) ++p;
    if (p == name_start) return false;
    const std::string name = text.substr(name_start, p - name_start);
    while (p < n && xml_space(text[p])) ++p;
    if (p >= n || text[p] != '=') return false;
    ++p;
    while (p < n && xml_space(text[p])) ++p;
    if (p >= n || (text[p] != '"' && text[p] != '\'')) return false;
    const std::size_t close = text.find(text[p], p + 1);
    if (close == std::string::npos) return false;
    tag.attributes.emplace(name, text.substr(p + 1, close - p - 1));
    p = close + 1;
  }
}

// Decodes base64 from text[from] on, skipping white space, until `bytes` bytes are decoded or the
// encoded run ends ('=', another character, the end of the text).
std::string base64_prefix(const std::string& text, std::size_t from, std::size_t bytes) {
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (std::size_t i = from; i < text.size() && out.size() < bytes; ++i) {
    const char c = text[i];
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else if (xml_space(c)) continue;
    else break;
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>((bits >> count) & 0xff);
    }
  }
  return out;
}

class Checker {
 public:
  Checker(const std::string& path, const std::string& text) : path_(path), text_(text), size_(text.size()) {}

  Error corrupt(const std::string& what) const { return Error(path_ + ": " + what + " (corrupt file?)"); }

  // An attribute the checks depend on: a character reference would be decoded by the XML parser
  // and not here, so none is accepted.
  const std::string* attribute(const StartTag& tag, const char* name) const {
    const auto it = tag.attributes.find(name);
    if (it == tag.attributes.end()) return nullptr;
    if (it->second.find('&') != std::string::npos)
      throw corrupt("attribute " + std::string(name) + " of <" + tag.name + "> holds a character reference");
    return &it->second;
  }

  // A count attribute: digits only (white space around them allowed), at most what the file can
  // hold (zlib expands at most ~1032:1, so no honest file holds more items than 1100 per byte).
  u64 count(const StartTag& tag, const char* name, u64 fallback) const {
    const std::string* value = attribute(tag, name);
    if (!value) return fallback;
    std::size_t b = 0, e = value->size();
    while (b < e && xml_space((*value)[b])) ++b;
    while (e > b && xml_space((*value)[e - 1])) --e;
    if (b == e || e - b > 19 || !std::all_of(value->begin() + static_cast<long>(b), value->begin() + static_cast<long>(e),
                                             [](char c) { return c >= '0' && c <= '9'; }))
      throw corrupt(std::string(name) + " = '" + value->substr(0, 20) + "' is not a count");
    const u64 n = std::stoull(value->substr(b, e - b));
    if (n > 1100 * size_)
      throw corrupt(std::string(name) + " = " + std::to_string(n) + " is more than " + std::to_string(size_) +
                    " bytes can hold");
    return n;
  }

  // The header words of a binary array whose encoded data starts at text[at]: raw bytes or base64.
  struct Header {
    const Checker& checker;
    std::size_t at;
    bool base64;
    bool big_endian;
    u64 h;
    mutable std::string decoded;
    // Word k, or false when the file ends before it.
    bool word(u64 k, u64& v) const {
      const u64 need = (k + 1) * h;
      const char* bytes;
      if (base64) {
        if (decoded.size() < need) decoded = base64_prefix(checker.text_, at, static_cast<std::size_t>(need));
        if (decoded.size() < need) return false;
        bytes = decoded.data() + k * h;
      } else {
        if (at > checker.size_ || checker.size_ - at < need) return false;
        bytes = checker.text_.data() + at + k * h;
      }
      v = 0;
      for (u64 b = 0; b < h; ++b) {
        const u64 byte = static_cast<unsigned char>(bytes[big_endian ? h - 1 - b : b]);
        v |= byte << (8 * b);
      }
      return true;
    }
  };

  // What VTK reads before allocating: the byte count of an uncompressed array, or the block
  // count, block size, last block size and compressed block sizes of a compressed one. `room`:
  // the encoded bytes the file holds from the array's start on.
  void check_array(const Header& header, u64 room, bool compressed) const {
    const u64 h = header.h;
    u64 first = 0;
    if (!header.word(0, first)) throw corrupt("an array's data lies beyond the end of the file");
    if (!compressed) {
      if (first > room) throw corrupt("an array claims more bytes than the file holds");
      return;
    }
    u64 block = 0, last = 0;
    if (!header.word(1, block) || !header.word(2, last)) throw corrupt("a compressed array's header is cut short");
    const u64 blocks = first;
    if (blocks > room / h) throw corrupt("a compressed array claims more blocks than the file holds");
    if ((blocks > 0 && block == 0) || block > (1ULL << 31) || last > block)  // VTK allocates `block` even for 0 blocks
      throw corrupt("a compressed array has an impossible block size");
    // No blocks but a partial last block: VTK takes the array's size as (blocks - 1) x block +
    // last, wraps around, and reads block sizes that are not there (a crash found by fuzzing).
    if (blocks == 0 && last != 0) throw corrupt("a compressed array has no blocks but a last block of " + std::to_string(last) + " bytes");
    u64 total = 0;
    for (u64 b = 0; b < blocks; ++b) {
      u64 s = 0;
      if (!header.word(3 + b, s)) throw corrupt("a compressed array's header is cut short");
      if (s > room) throw corrupt("a compressed array claims more bytes than the file holds");
      total += s;
    }
    if (total > room) throw corrupt("a compressed array claims more bytes than the file holds");
    if (block > 0 && blocks > 1100 * size_ / block) throw corrupt("a compressed array expands to more than its file can hold");
  }

  void run() {
    const std::size_t n = text_.size();
    bool little = true, compressed = false;
    u64 h = 4;
    u64 piece_items = 0;  // the largest count of the current <Piece>
    std::vector<u64> appended;  // the offsets of the appended arrays
    std::size_t p = 0;
    std::size_t appended_tag = std::string::npos;
    StartTag tag;
    while ((p = text_.find('<', p)) != std::string::npos) {
      if (text_.compare(p, 4, "<!--") == 0) {
        p = text_.find("-->", p + 4);
        if (p == std::string::npos) break;
        continue;
      }
      if (text_.compare(p, 9, "<![CDATA[") == 0) {
        p = text_.find("]]>", p + 9);
        if (p == std::string::npos) break;
        continue;
      }
      if (p + 1 < n && (text_[p + 1] == '!' || text_[p + 1] == '?' || text_[p + 1] == '/')) {
        ++p;
        continue;
      }
      if (!read_start_tag(text_, p, tag)) {  // not well-formed: the XML parser refuses the file
        ++p;
        continue;
      }
      for (const auto& [name, value] : tag.attributes)
        if (name.compare(0, 8, "NumberOf") == 0) count(tag, name.c_str(), 0);
      if (tag.name == "VTKFile") {
        if (const std::string* order = attribute(tag, "byte_order")) {
          if (*order != "LittleEndian" && *order != "BigEndian") throw corrupt("unknown byte_order '" + order->substr(0, 20) + "'");
          little = *order == "LittleEndian";
        }
        if (const std::string* type = attribute(tag, "header_type")) {
          if (*type != "UInt32" && *type != "UInt64") throw corrupt("unknown header_type '" + type->substr(0, 20) + "'");
          h = *type == "UInt64" ? 8 : 4;
        }
        if (const std::string* c = attribute(tag, "compressor")) {
          if (*c != "vtkZLibDataCompressor" && *c != "vtkLZ4DataCompressor" && *c != "vtkLZMADataCompressor")
            throw corrupt("unknown compressor '" + c->substr(0, 30) + "'");
          compressed = true;
        }
      } else if (tag.name == "Piece") {
        piece_items = 0;
        for (const char* key : {"NumberOfPoints", "NumberOfCells", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
          piece_items = std::max(piece_items, count(tag, key, 0));
      } else if (tag.name == "DataArray" || tag.name == "Array") {
        const u64 tuples = count(tag, "NumberOfTuples", piece_items), components = count(tag, "NumberOfComponents", 1);
        if (components > 0 && tuples > 1100 * size_ / components)
          throw corrupt("an array of " + std::to_string(tuples) + " tuples of " + std::to_string(components) +
                        " components is more than " + std::to_string(size_) + " bytes can hold");
        const std::string* format = attribute(tag, "format");
        const std::string f = format ? *format : "ascii";
        if (f == "appended") {
          const u64 offset = count(tag, "offset", ~0ULL);  // (offsets, like counts, cannot exceed 1100 per byte)
          if (offset == ~0ULL) throw corrupt("an appended array without an offset");
          appended.push_back(offset);
        } else if (f == "binary") {  // inline base64, up to the next tag
          const std::size_t stop = std::min(text_.find('<', tag.end), n);
          check_array(Header{*this, tag.end, true, !little, h, {}}, stop - tag.end, compressed);
        } else if (f != "ascii") {
          throw corrupt("unknown array format '" + f.substr(0, 20) + "'");
        }
      } else if (tag.name == "AppendedData") {
        appended_tag = p;
        break;  // raw bytes follow: no further tags to read
      }
      p = tag.end;
    }
    if (appended.empty()) return;
    if (appended_tag == std::string::npos) throw corrupt("appended arrays but no <AppendedData>");
    const std::string* encoding = attribute(tag, "encoding");
    const bool base64 = encoding && *encoding == "base64";
    if (encoding && !base64 && *encoding != "raw") throw corrupt("unknown AppendedData encoding '" + encoding->substr(0, 20) + "'");
    // As VTK: the data starts after the first non-space character past the tag, which must be '_'.
    std::size_t data = tag.end;
    while (data < n && xml_space(text_[data])) ++data;
    if (data >= n || text_[data] != '_') throw corrupt("the appended data does not start with '_'");
    ++data;
    for (const u64 offset : appended) {
      if (offset > size_ - data) throw corrupt("an array's data lies beyond the end of the file");
      const std::size_t at = data + static_cast<std::size_t>(offset);
      check_array(Header{*this, at, base64, !little, h, {}}, size_ - at, compressed);
    }
  }

 private:
  const std::string& path_;
  const std::string& text_;
  const u64 size_;
};

}  // namespace

void check_vtk_xml_sizes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Checker(path, text).run();
}

void check_vtk_xml_text(const std::string& name, const std::string& text) { Checker(name, text).run(); }

}  // namespace xfem
