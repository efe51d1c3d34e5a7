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
  Cursor(const std::string& text, std::size_t pos, const std::string& path, const char* section = "$Elements")
      : text_(text), pos_(std::min(pos, text.size())), path_(path), section_(section) {}

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
      throw Error(path_ + ": " + what + " in the " + section_ + " section is not a whole number of at most 17 digits (or the file ends there)");
    return std::stoll(word);
  }

  // A binary value of this machine's byte order.
  template <class T>
  T binary(const char* what) {
    if (text_.size() - pos_ < sizeof(T))
      throw Error(path_ + ": the file ends inside its binary " + section_ + " section (at " + what + ")");
    T value;
    std::memcpy(&value, text_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  // Skips one ASCII word (a coordinate): its value is gmsh's to judge, its presence ours.
  void word(const char* what) {
    while (pos_ < text_.size() && std::strchr(" \t\r\n", text_[pos_])) ++pos_;
    if (pos_ == text_.size()) throw Error(path_ + ": the file ends inside its " + section_ + " section (at " + what + ")");
    while (pos_ < text_.size() && !std::strchr(" \t\r\n", text_[pos_])) ++pos_;
  }

  // Bytes after the position.
  std::size_t left() const { return text_.size() - pos_; }

  // Checks that `count` binary values of `bytes` bytes each follow.
  void require(std::uint64_t count, std::uint64_t bytes, const char* what) const {
    if (bytes != 0 && count > (text_.size() - pos_) / bytes)
      throw Error(path_ + ": the file ends inside its binary " + section_ + " section (in " + what + ")");
  }

  // Skips `count` binary values of `bytes` bytes each.
  void skip(std::uint64_t count, std::uint64_t bytes, const char* what) {
    require(count, bytes, what);
    pos_ += static_cast<std::size_t>(count * bytes);
  }

 private:
 private:
  const std::string& text_;
  std::size_t pos_;
  const std::string& path_;
  const char* section_;
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

// libgmsh reads MSH 2 node tags as int: a tag above 2^31 - 1 wrapped (2^32 + 1 read as node 1,
// a silently wrong mesh). Tags are 1 to 2^31 - 1.
void check_msh2_tag(long long tag, const char* what, const std::string& path) {
  if (tag < 1 || tag > 2147483647)
    throw Error(path + ": " + what + " " + std::to_string(tag) + ", outside gmsh's node tags 1 to 2147483647");
}

void check_msh2_ascii(Cursor& in, Entities& entities, const std::string& path) {
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
    for (int k = 0; k < entities.type(type).nodes; ++k) check_msh2_tag(in.integer("an element's node"), "an element in the $Elements section has node", path);
  }
}

// MSH 2 ASCII $Nodes: the count, then "tag x y z" per node.
void check_msh2_nodes(Cursor& in, const std::string& path) {
  const long long count = in.integer("the node count");
  if (count < 0) throw Error(path + ": the node count in the $Nodes section is negative");
  for (long long k = 0; k < count; ++k) {
    check_msh2_tag(in.integer("a node tag"), "the $Nodes section has node tag", path);
    for (int c = 0; c < 3; ++c) in.word("a node's coordinate");
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

// The node tags of a MSH 4.1 $Nodes section: the range its header gives, every tag checked.
struct NodeTags {
  bool known = false;  // false: no $Nodes section (gmsh then refuses any element)
  unsigned long long min = 0, max = 0;
};

// libgmsh trusts the $Nodes header: it sizes its node table from the node count and the tag
// range and stores each node at its tag, so a tag outside the range, a block larger than the
// count or a tag given twice made it write out of bounds (SIGSEGV). Each is refused here.
NodeTags check_msh41_nodes(Cursor& in, bool binary, const std::string& path) {
  const auto size = [&](const char* what) -> unsigned long long {
    if (binary) return in.binary<std::uint64_t>(what);
    const long long v = in.integer(what);
    if (v < 0) throw Error(path + ": " + what + " in the $Nodes section is negative");
    return static_cast<unsigned long long>(v);
  };
  const auto int32 = [&](const char* what) -> long long {
    return binary ? in.binary<std::int32_t>(what) : in.integer(what);
  };
  const unsigned long long blocks = size("the node block count"), count = size("the node count");
  NodeTags tags{true, size("the smallest node tag"), size("the largest node tag")};
  if (binary) in.require(blocks, 20, "the node blocks");  // 3 int32 and a size_t each at least
  if (count > 0 && (tags.min > tags.max || tags.max - tags.min + 1 < count))
    throw Error(path + ": the $Nodes section's header gives " + std::to_string(count) + " nodes with tags " +
                std::to_string(tags.min) + " to " + std::to_string(tags.max));
  std::vector<unsigned long long> seen;
  for (unsigned long long b = 0; b < blocks; ++b) {  // entityDim entityTag parametric count; tags; coordinates
    const long long dim = int32("an entity's dimension");
    int32("an entity's tag");
    const long long parametric = int32("a node block's parametric flag");
    const unsigned long long n = size("a node block's count");
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
      throw Error(path + ": node block " + std::to_string(b) + " has entity dimension " + std::to_string(dim) +
                  " or parametric flag " + std::to_string(parametric));
    if (n > count - std::min<unsigned long long>(count, seen.size()))
      throw Error(path + ": the $Nodes section's header gives " + std::to_string(count) + " nodes, its blocks hold at least " +
                  (n <= ~0ull - seen.size() ? std::to_string(seen.size() + n) : std::string("2^64")));
    if (binary) in.require(n, 8, "a node block's tags");
    for (unsigned long long k = 0; k < n; ++k) {
      const unsigned long long tag = size("a node tag");
      if (tag < tags.min || tag > tags.max)
        throw Error(path + ": node tag " + std::to_string(tag) + " in the $Nodes section is outside the range " +
                    std::to_string(tags.min) + " to " + std::to_string(tags.max) + " its header gives");
      seen.push_back(tag);
    }
    const unsigned long long values = 3 + static_cast<unsigned long long>(parametric) * static_cast<unsigned long long>(dim);
    if (binary)
      in.skip(n, 8 * values, "a node block's coordinates");
    else
      for (unsigned long long k = 0; k < n * values; ++k) in.word("a node's coordinate");
  }
  if (seen.size() != count)
    throw Error(path + ": the $Nodes section's header gives " + std::to_string(count) + " nodes, its blocks hold " +
                std::to_string(seen.size()));
  std::sort(seen.begin(), seen.end());
  if (const auto twice = std::adjacent_find(seen.begin(), seen.end()); twice != seen.end())
    throw Error(path + ": node tag " + std::to_string(*twice) + " is given twice in the $Nodes section");
  return tags;
}

// MSH 4.1 $Entities: four counts (points, curves, surfaces, volumes), then each entity: its tag, a
// point (3 doubles) or a bounding box (6), its physical tags (a count and the tags) and, but for a
// point, its bounding entities (a count and the tags). libgmsh allocates by each count before it
// reads what the count announces: a count beyond the file's size asked for up to 2^63 bytes
// (std::bad_alloc out of the library, an abort under ASan) or looped for minutes. Every count is
// checked against the bytes left (ASCII: at least 2 per value), every value read.
void check_msh41_entities(Cursor& in, bool binary, const std::string& path) {
  const auto count = [&](const char* what, std::uint64_t bytes_each) -> unsigned long long {
    unsigned long long n = 0;
    if (binary) {
      n = in.binary<std::uint64_t>(what);
      in.require(n, bytes_each, what);
    } else {
      const long long v = in.integer(what);
      if (v < 0) throw Error(path + ": " + what + " in the $Entities section is negative");
      n = static_cast<unsigned long long>(v);
      if (n > in.left() / 2)  // a digit and a separator at least
        throw Error(path + ": " + what + " " + std::to_string(n) + " in the $Entities section is more than the file holds");
    }
    return n;
  };
  const auto tag = [&](const char* what) {
    if (binary)
      in.binary<std::int32_t>(what);
    else
      in.integer(what);
  };
  const auto real = [&](const char* what) {
    if (binary)
      in.binary<double>(what);
    else
      in.word(what);
  };
  unsigned long long counts[4];
  for (int d = 0; d < 4; ++d) counts[d] = count("an entity count", 4 + 3 * 8 + 8);
  for (int d = 0; d < 4; ++d)
    for (unsigned long long e = 0; e < counts[d]; ++e) {
      tag("an entity's tag");
      for (int k = 0; k < (d == 0 ? 3 : 6); ++k) real("an entity's coordinate");
      for (unsigned long long k = count("an entity's physical tag count", 4); k > 0; --k) tag("a physical tag");
      if (d > 0)
        for (unsigned long long k = count("an entity's bounding entity count", 4); k > 0; --k) tag("a bounding entity");
    }
}

void check_msh41(Cursor& in, Entities& entities, bool binary, const std::string& path, const NodeTags& nodes) {
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
    const int per_element = entities.type(type).nodes;
    if (binary) in.require(static_cast<std::uint64_t>(count), 8ull * (1 + static_cast<std::uint64_t>(per_element)), "an element block");
    for (long long e = 0; e < count; ++e) {
      size("an element's tag");
      for (int k = 0; k < per_element; ++k) {
        const long long node = binary ? static_cast<long long>(in.binary<std::uint64_t>("an element's node"))
                                      : in.integer("an element's node");
        // libgmsh looks a node up by its tag without a bound on every path: a tag it has no node
        // for is refused here (negative: a size_t above 2^63)
        if (nodes.known && (node < 0 || static_cast<unsigned long long>(node) < nodes.min ||
                            static_cast<unsigned long long>(node) > nodes.max))
          throw Error(path + ": an element in the $Elements section has node " +
                      (binary ? std::to_string(static_cast<unsigned long long>(node)) : std::to_string(node)) + ", outside the node tags " +
                      std::to_string(nodes.min) + " to " + std::to_string(nodes.max));
      }
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
  std::vector<std::size_t> node_sections;          // positions after their "$Nodes" line
  std::vector<std::size_t> entity_sections;        // positions after their "$Entities" line
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
    if (line == "$Nodes") node_sections.push_back(at);
    if (line == "$Entities") entity_sections.push_back(at);
    if (line == "$ELM") msh1 = true;
  }
  if (element_sections.empty() && node_sections.empty() && entity_sections.empty() && !msh1) return;
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
  if (node_sections.size() > 1) throw Error(path + ": the file has " + std::to_string(node_sections.size()) + " $Nodes sections");
  if (msh41)
    for (std::size_t at : entity_sections) {
      Cursor in(text, at, path, "$Entities");
      check_msh41_entities(in, binary, path);
    }
  NodeTags nodes;
  if (msh41 && !node_sections.empty()) {
    Cursor in(text, node_sections[0], path, "$Nodes");
    nodes = check_msh41_nodes(in, binary, path);
  } else if (msh2 && !binary && !node_sections.empty()) {
    Cursor in(text, node_sections[0], path, "$Nodes");
    check_msh2_nodes(in, path);
  }
  Entities entities(path, element_type);
  for (std::size_t at : element_sections) {
    Cursor in(text, at, path);
    if (msh41)
      check_msh41(in, entities, binary, path, nodes);
    else if (binary)
      check_msh2_binary(in, entities, path);
    else
      check_msh2_ascii(in, entities, path);
  }
}

}  // namespace xfem
