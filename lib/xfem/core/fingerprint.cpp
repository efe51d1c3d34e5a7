// SPDX-License-Identifier: MIT
#include "xfem/core/fingerprint.h"

#include <cstdio>
#include <cstring>
#include <fstream>

#include "xfem/core/error.h"

namespace xfem {
namespace {

constexpr const char* kPrefix = "fnv1a64:";
constexpr const char* kComment = "% xfem-fingerprint ";

template <class T>
Fingerprint add(Fingerprint h, const T& value) {
  return fnv1a64(&value, sizeof value, h);
}

// Geometry in a fixed byte order: counts as int64, coordinates as their IEEE bits (so -0 and 0
// differ; a stage copies coordinates, it never recomputes them).
template <class Ids>
Fingerprint geometry(const Points& points, const Ids& ids) {
  Fingerprint h = fnv1a64(nullptr, 0);
  h = add(h, static_cast<std::int64_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    for (int c = 0; c < 3; ++c) h = add(h, points(i, c));
  h = add(h, static_cast<std::int64_t>(ids.rows()));
  h = add(h, static_cast<std::int64_t>(ids.cols()));
  for (Eigen::Index i = 0; i < ids.rows(); ++i)
    for (Eigen::Index c = 0; c < ids.cols(); ++c) h = add(h, static_cast<std::int32_t>(ids(i, c)));
  return h;
}

// A header line as it can be quoted in a one-line message: control and non-ASCII bytes as '?'.
std::string printable(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  return text;
}

}  // namespace

Fingerprint fnv1a64(const void* data, std::size_t bytes, Fingerprint seed) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    seed ^= p[i];
    seed *= 0x100000001b3ULL;
  }
  return seed;
}

std::string to_string(Fingerprint f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%s%016llx", kPrefix, static_cast<unsigned long long>(f));
  return buf;
}

bool parse_fingerprint(const std::string& text, Fingerprint* f) {
  const std::size_t n = std::strlen(kPrefix);
  if (text.size() != n + 16 || text.compare(0, n, kPrefix) != 0) return false;
  Fingerprint v = 0;
  for (std::size_t i = n; i < text.size(); ++i) {
    const char c = text[i];
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return false;
    v = v << 4 | static_cast<Fingerprint>(d);
  }
  *f = v;
  return true;
}

Fingerprint fingerprint(const TetMesh& mesh) { return geometry(mesh.points, mesh.tets); }
Fingerprint fingerprint(const TriangleMesh& mesh) { return geometry(mesh.points, mesh.triangles); }

Fingerprint fingerprint(const Json& j) {
  const std::string text = j.dump();
  return fnv1a64(text.data(), text.size());
}

Fingerprint fingerprint_json_file(const std::string& path) { return fingerprint(read_json(path)); }

void store_fingerprint(DataArrays& field_data, const std::string& name, Fingerprint f) {
  DataArray a = make_array(DataArray::Type::Int64, 1, 2);
  a.values[0] = static_cast<double>(f >> 32);
  a.values[1] = static_cast<double>(f & 0xffffffffULL);
  field_data[name] = a;
}

bool stored_fingerprint(const DataArrays& field_data, const std::string& name, Fingerprint* f) {
  const auto it = field_data.find(name);
  if (it == field_data.end()) return false;
  const DataArray& a = it->second;
  const auto word = [](double v) { return v >= 0 && v <= 4294967295.0 && v == static_cast<double>(static_cast<std::uint64_t>(v)); };
  if (a.values.size() != 2 || !word(a.values[0]) || !word(a.values[1])) return false;
  *f = static_cast<Fingerprint>(a.values[0]) << 32 | static_cast<Fingerprint>(a.values[1]);
  return true;
}

void check_cut_matches(const TetMesh& mesh, const std::string& mesh_path, const TriangleMesh& cut,
                       const std::string& cut_path) {
  Fingerprint recorded = 0;
  if (!stored_fingerprint(mesh.field_data, "cut_fingerprint", &recorded)) return;
  const Fingerprint actual = fingerprint(cut);
  if (actual != recorded)
    throw Error(cut_path + ": not the cut " + mesh_path + " was classified with (cut " + to_string(actual) +
                ", classified with " + to_string(recorded) + ")");
}

Json provenance_json(const Provenance& p) {
  Json j = Json::object();
  for (const auto& [name, f] : p) j[name] = to_string(f);
  return j;
}

Provenance provenance_from_json(const Json& j, const std::string& file) {
  Provenance p;
  if (!j.is_object() || !j.contains("fingerprints")) return p;
  const Json& f = j["fingerprints"];
  if (!f.is_object()) throw Error(file + ": key 'fingerprints' is not an object");
  for (const auto& [name, value] : f.items()) {
    Fingerprint v = 0;
    if (!value.is_string() || !parse_fingerprint(value.get<std::string>(), &v))
      throw Error(file + ": fingerprints." + name + " is not of the form fnv1a64:<16 hex digits>");
    p[name] = v;
  }
  return p;
}

std::vector<std::string> provenance_comments(const Provenance& p) {
  std::vector<std::string> lines;
  for (const auto& [name, f] : p) lines.push_back(kComment + name + " " + to_string(f));
  return lines;
}

Provenance read_mtx_provenance(const std::string& path) {
  Provenance p;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  // The header: the banner, then comment lines; fingerprints sit among the comments.
  for (int n = 0; n < 64 && std::getline(in, line); ++n) {
    if (line.empty() || line[0] != '%') break;
    if (line.compare(0, std::strlen(kComment), kComment) != 0) continue;
    const std::string rest = line.substr(std::strlen(kComment));
    const std::size_t space = rest.find(' ');
    Fingerprint v = 0;
    std::string value = space == std::string::npos ? "" : rest.substr(space + 1);
    while (!value.empty() && (value.back() == '\r' || value.back() == ' ')) value.pop_back();
    if (space == 0 || space == std::string::npos || !parse_fingerprint(value, &v))
      throw Error(path + ": malformed fingerprint line '" + printable(line.substr(0, 80)) +
                  "' (expected '% xfem-fingerprint <name> fnv1a64:<16 hex digits>')");
    const std::string name = rest.substr(0, space);
    // The same name twice with two values: one of them was edited, neither can be trusted.
    const auto [it, inserted] = p.emplace(name, v);
    if (!inserted && it->second != v)
      throw Error(path + ": conflicting fingerprint lines for '" + printable(name) + "' (" + to_string(it->second) +
                  " and " + to_string(v) + ")");
  }
  return p;
}

void check_provenance(const Provenance& recorded, const std::string& file, const std::string& name,
                      Fingerprint actual, const std::string& given_file) {
  const auto it = recorded.find(name);
  if (it == recorded.end() || it->second == actual) return;
  throw Error(file + ": does not belong to " + given_file + " (made for the " + name + " with fingerprint " +
              to_string(it->second) + ", " + given_file + " has " + to_string(actual) + ")");
}

}  // namespace xfem
