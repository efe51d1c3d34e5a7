// SPDX-License-Identifier: MIT
#include "xfem/io/gmsh_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "xfem/core/error.h"

namespace xfem {
namespace {

// The file's bytes and a position in them; every read is bounded by the end of the file.
class Cursor {
 public:
  Cursor(const std::string& text, std::size_t pos, const std::string& path)
      : text_(text), pos_(std::min(pos, text.size())), path_(path) {}

  // The rest of the line, without its '\r'.
  std::string line() {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string out = text_.substr(pos_, end - pos_);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    pos_ = std::min(end + 1, text_.size());
    return out;
  }

  // A whole number in ASCII, after any whitespace, as gmsh's fscanf("%d") or ("%lu") reads it.
  long long integer(const char* what) {
    while (pos_ < text_.size() && std::strchr(" \t\r\n", text_[pos_])) ++pos_;
    const std::size_t start = pos_;
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
    while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9' && pos_ - start < 18) ++pos_;
    const std::string word = text_.substr(start, pos_ - start);
    if (word.empty() || word == "-" || word == "+" || (pos_ < text_.size() && !std::strchr(" \t\r\n", text_[pos_])))
      throw Error(path_ + ": " + what + " in the $Elements section is not a whole number of at most 17 digits (or the file ends there)");
    return std::stoll(word);
  }

  // A binary value of this machine's byte order.
  template <class T>
  T binary(const char* what) {
    if (text_.size() - pos_ < sizeof(T))
      throw Error(path_ + ": the file ends inside its binary $Elements section (at " + what + ")");
    T value;
    std::memcpy(&value, text_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  // Skips `count` binary values of `bytes` bytes each.
  void skip(std::uint64_t count, std::uint64_t bytes, const char* what) {
    if (bytes != 0 && count > (text_.size() - pos_) / bytes)
      throw Error(path_ + ": the file ends inside its binary $Elements section (in " + what + ")");
    pos_ += static_cast<std::size_t>(count * bytes);
  }

 private:
  const std::string& text_;
  std::size_t pos_;
  const std::string& path_;
};

// The element types of each entity, by shape ("Tetrahedron", "Triangle", ...): one per shape.
class Entities {
 public:
  Entities(const std::string& path, const std::function<GmshElementType(int)>& element_type)
      : path_(path), element_type_(element_type) {}

  // gmsh's properties of a type number; the number is checked to be one.
  const GmshElementType& type(long long number) {
    if (number < 1 || number > 100000)
      throw Error(path_ + ": element type " + std::to_string(number) + " is not a gmsh element type");
    auto known = types_.find(static_cast<int>(number));
    if (known == types_.end()) known = types_.emplace(static_cast<int>(number), element_type_(static_cast<int>(number))).first;
    return known->second;
  }

  // An element of `type` in the entity of dimension `entity_dim` (-1: the type's own, MSH 2) and tag.
  void add(int entity_dim, long long tag, long long type_number) {
    const std::array<long long, 3> key{entity_dim, tag, type_number};
    if (key == last_) return;  // consecutive elements of one entity and type: checked with the first
    const GmshElementType& t = type(type_number);
    const int type = static_cast<int>(type_number);
    const int dim = entity_dim < 0 ? t.dim : entity_dim;
    if (t.dim != dim)
      throw Error(path_ + ": entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) + " holds " +
                  name(type) + " elements, of dimension " + std::to_string(t.dim));
    const std::string shape = t.name.substr(0, t.name.find(' '));
    const auto [first, fresh] = shapes_[{dim, tag}].emplace(shape, type);
    if (!fresh && first->second != type)
      throw Error(path_ + ": entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) + " mixes " +
                  name(first->second) + " and " + name(type) +
                  " elements, which gmsh's library cannot read (mesh the whole entity with one order, or give each "
                  "order its own entity)");
    last_ = key;
  }

 private:
  std::string name(int type) const {
    return types_.at(type).name + " (gmsh element type " + std::to_string(type) + ")";
  }
  const std::string& path_;
  const std::function<GmshElementType(int)>& element_type_;
  std::map<int, GmshElementType> types_;
  std::map<std::pair<int, long long>, std::map<std::string, int>> shapes_;
  std::array<long long, 3> last_{-2, 0, 0};
};

void check_msh2_ascii(Cursor& in, Entities& entities) {
  const long long count = in.integer("the element count");
  for (long long e = 0; e < count; ++e) {  // number type ntags tag_1 .. tag_ntags node_1 .. node_n
    in.integer("an element number");
    const long long type = in.integer("an element type");
    const long long tags = in.integer("an element's tag count");
    long long elementary = 0;  // gmsh's entity: the second tag
    for (long long k = 0; k < tags; ++k) {
      const long long tag = in.integer("an element tag");
      if (k == 1) elementary = tag;
    }
    entities.add(-1, elementary, type);
    for (int k = 0; k < entities.type(type).nodes; ++k) in.integer("an element's node");
  }
}

void check_msh2_binary(Cursor& in, Entities& entities, const std::string& path) {
  const long long count = in.integer("the element count");
  in.line();
  for (long long read = 0; read < count;) {  // blocks: type, count, ntags; then each: number, tags, nodes
    const std::int32_t type = in.binary<std::int32_t>("an element block's type");
    const std::int32_t block = in.binary<std::int32_t>("an element block's count");
    const std::int32_t tags = in.binary<std::int32_t>("an element block's tag count");
    if (block < 1 || tags < 0) throw Error(path + ": an element block of the binary $Elements section is malformed");
    const std::int64_t ints = 1 + std::int64_t{tags} + entities.type(type).nodes;
    for (std::int32_t e = 0; e < block; ++e) {
      std::int32_t elementary = 0;
      for (std::int64_t k = 0; k < ints; ++k) {
        const std::int32_t value = in.binary<std::int32_t>("an element");
        if (k == 2) elementary = value;  // number, then the tags: the second is the entity
      }
      entities.add(-1, tags > 1 ? elementary : 0, type);
    }
    read += block;
  }
}

void check_msh41(Cursor& in, Entities& entities, bool binary, const std::string& path) {
  const auto size = [&](const char* what) {
    return binary ? static_cast<long long>(in.binary<std::uint64_t>(what)) : in.integer(what);
  };
  const long long blocks = size("the entity block count");
  for (int k = 0; k < 3; ++k) size("the element count or tags");
  for (long long b = 0; b < blocks; ++b) {  // entityDim entityTag elementType count; then each: tag nodes
    const long long dim = binary ? in.binary<std::int32_t>("an entity's dimension") : in.integer("an entity's dimension");
    const long long tag = binary ? in.binary<std::int32_t>("an entity's tag") : in.integer("an entity's tag");
    const long long type = binary ? in.binary<std::int32_t>("an element type") : in.integer("an element type");
    const long long count = size("an element block's count");
    if (dim < 0 || dim > 3 || count < 0)
      throw Error(path + ": element block " + std::to_string(b) + " has entity dimension " + std::to_string(dim) +
                  " or element count " + std::to_string(count));
    entities.add(static_cast<int>(dim), tag, type);
    const int nodes = entities.type(type).nodes;
    if (binary) {
      in.skip(static_cast<std::uint64_t>(count), 8ull * (1 + static_cast<std::uint64_t>(nodes)), "an element block");
    } else {
      for (long long e = 0; e < count; ++e)
        for (int k = 0; k <= nodes; ++k) in.integer("an element's tag or node");
    }
  }
}

bool starts_with(const std::string& s, const char* prefix) { return s.compare(0, std::strlen(prefix), prefix) == 0; }

}  // namespace

void check_gmsh_elements(const std::string& path, const std::function<GmshElementType(int)>& element_type) {
  std::ifstream file(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  // Every line that starts a section; in a binary file such bytes inside the data would be checked
  // too (and most likely refused), which a real mesh does not hold.
  std::string version, file_type, data_size;
  std::size_t after_format = std::string::npos;  // where a binary file's byte order mark is
  std::vector<std::size_t> element_sections;       // positions after their "$Elements" line
  bool msh1 = false;
  for (std::size_t at = 0; at < text.size();) {
    Cursor in(text, at, path);
    const std::string line = in.line();
    at = std::min(text.find('\n', at), text.size()) + 1;
    if (line == "$MeshFormat" && version.empty()) {
      std::istringstream(in.line()) >> version >> file_type >> data_size;
      after_format = std::min(text.find('\n', at), text.size()) + 1;
    }
    if (line == "$Elements") element_sections.push_back(at);
    if (line == "$ELM") msh1 = true;
  }
  if (element_sections.empty() && !msh1) return;
  const bool msh2 = starts_with(version, "2.") || version == "2", msh41 = version == "4.1";
  if (msh1 || !(msh2 || msh41))
    throw Error(path + ": MSH version " + (msh1 ? std::string("1") : "'" + version.substr(0, 20) + "'") +
                " is not read (save as MSH 4.1 or 2.2: gmsh -format msh41)");
  const bool binary = file_type == "1";
  if (file_type != "0" && !binary) throw Error(path + ": the $MeshFormat file type must be 0 (ASCII) or 1 (binary)");
  if (binary) {
    if (data_size != "8") throw Error(path + ": a binary .msh file must have data size 8");
    Cursor one(text, std::min(after_format, text.size()), path);
    if (one.binary<std::int32_t>("the byte order mark") != 1)
      throw Error(path + ": a binary .msh file of another byte order is not read (save it as ASCII)");
  }
  Entities entities(path, element_type);
  for (std::size_t at : element_sections) {
    Cursor in(text, at, path);
    if (msh41)
      check_msh41(in, entities, binary, path);
    else if (binary)
      check_msh2_binary(in, entities, path);
    else
      check_msh2_ascii(in, entities);
  }
}

}  // namespace xfem
