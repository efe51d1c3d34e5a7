// SPDX-License-Identifier: MIT
#include "xfem/system/linear_system.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/io/petsc_binary.h"

namespace xfem {
namespace {

const char* const kHint = " (is this xfem-assemble output?)";

std::string join(const std::string& dir, const char* name) { return (std::filesystem::path(dir) / name).string(); }

// dirichlet.mtx: a sparse 3N x 1 vector, one entry per constrained DOF, so that a DOF fixed to 0
// is still listed (a dense vector could not tell it from a free one).
void write_dirichlet(const LinearSystem& s, const std::string& path) {
  std::string text = "%%MatrixMarket matrix coordinate real general\n";
  text += "% constrained scalar DOFs (row 3k + i + 1) and their prescribed values in metres\n";
  text += std::to_string(3 * s.n) + " 1 " + std::to_string(s.fixed.size()) + "\n";
  char buf[40];
  for (std::size_t k = 0; k < s.fixed.size(); ++k) {
    text += std::to_string(s.fixed[k] + 1) + " 1 ";
    const auto r = std::to_chars(buf, buf + sizeof buf, s.fixed_values[k]);
    text.append(buf, r.ptr);
    text += '\n';
  }
  write_atomically(path, [&](const std::string& tmp) {
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(path + ": cannot open for writing");
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) throw Error(path + ": cannot write (disk full?)");
  });
}

long lower_nonzeros(const SparseMatrix& K) {
  long nnz = 0;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() >= j) ++nnz;
  return nnz;
}

// A reader's own error ("not a Matrix Market file") plus the hint that names the expected producer.
template <class Read>
auto read_with_hint(Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const Error& e) {
    const std::string what = e.what();
    if (what.find(kHint) != std::string::npos) throw;
    throw Error(what + kHint);
  }
}

long get_count(const Json& j, const char* key, const std::string& path) {
  if (!j.contains(key) || !j[key].is_number_integer() || j[key].get<long>() < 0)
    throw Error(path + ": key '" + key + "' missing or not a non-negative integer" + kHint);
  // Matrices are indexed by int: 3 (np + ns + 4 nb) must stay below 2^31 (and not overflow here).
  if (j[key].get<long>() > 200000000)
    throw Error(path + ": key '" + key + "' = " + j[key].dump() + " is larger than supported (2e8)" + kHint);
  return j[key].get<long>();
}

// system.json must be an object whose optional `format` is a string and `coordinates` a boolean
// (otherwise the JSON library's type error would surface instead of a plain message).
Json read_system_json(const std::string& json_path) {
  Json j = read_with_hint([&] { return read_json(json_path); });
  if (!j.is_object()) throw Error(json_path + ": not a JSON object" + kHint);
  if (j.contains("format") && !j["format"].is_string()) throw Error(json_path + ": key 'format' is not a string" + kHint);
  if (j.contains("coordinates") && !j["coordinates"].is_boolean())
    throw Error(json_path + ": key 'coordinates' is not true or false" + kHint);
  return j;
}

}  // namespace

void check_linear_system(const LinearSystem& s, const std::string& where) {
  if (s.np < 0 || s.ns < 0 || s.nb < 0 || s.n != s.np + s.ns + 4 * s.nb)
    throw Error(where + ": N = " + std::to_string(s.n) + " but NP + NS + 4 NB = " +
                std::to_string(s.np + s.ns + 4 * s.nb));
  const long dofs = 3 * s.n;
  if (s.K.rows() != dofs || s.K.cols() != dofs)
    throw Error(where + ": K is " + std::to_string(s.K.rows()) + " x " + std::to_string(s.K.cols()) +
                ", expected 3N x 3N = " + std::to_string(dofs) + " x " + std::to_string(dofs));
  if (s.f.size() != dofs)
    throw Error(where + ": f has " + std::to_string(s.f.size()) + " rows, expected 3N = " + std::to_string(dofs));
  if (s.fixed.size() != s.fixed_values.size())
    throw Error(where + ": " + std::to_string(s.fixed.size()) + " fixed DOFs but " +
                std::to_string(s.fixed_values.size()) + " prescribed values");
  for (std::size_t k = 0; k < s.fixed.size(); ++k) {
    if (s.fixed[k] < 0 || s.fixed[k] >= dofs)
      throw Error(where + ": fixed DOF " + std::to_string(s.fixed[k]) + " out of range 0.." + std::to_string(dofs - 1));
    if (k > 0 && s.fixed[k] <= s.fixed[k - 1])
      throw Error(where + ": fixed DOF " + std::to_string(s.fixed[k]) + " listed twice or out of order");
  }
  if (s.coordinates.size() != 0 && (s.coordinates.rows() != s.np || s.coordinates.cols() != 3))
    throw Error(where + ": coordinates are " + std::to_string(s.coordinates.rows()) + " x " +
                std::to_string(s.coordinates.cols()) + ", expected NP x 3 = " + std::to_string(s.np) + " x 3");
}

namespace {

namespace fs = std::filesystem;

// Every name a system directory may hold: an existing directory with anything else in it is not
// replaced (it is someone's data, not an older system).
bool is_system_file(const std::string& name) {
  for (const char* known : {"K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx", "K.petsc", "f.petsc", "dirichlet_conditions.json", "provenance.json",
                            "coordinates.petsc", "system.json", "contact_gap.mtx", "contact_points.mtx", "contact_slip.mtx",
                            "contact_friction.mtx"})
    if (name == known) return true;
  return false;
}

// Puts the finished directory `tmp` in the place of `target`. An existing target is swapped
// out atomically (renameat2 RENAME_EXCHANGE), else moved aside first; removed only afterwards.
void move_into_place(const fs::path& tmp, const fs::path& target) {
  std::error_code ec;
  if (!fs::exists(target)) {
    fs::rename(tmp, target, ec);
    if (ec) throw Error(target.string() + ": cannot rename the temporary directory into place: " + ec.message());
    return;
  }
  if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(tmp, ec);  // now the old system
    return;
  }
  const fs::path old = tmp.string() + ".old";
  fs::rename(target, old, ec);
  if (ec) throw Error(target.string() + ": cannot move the old directory aside: " + ec.message());
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::rename(old, target, ignored);
    throw Error(target.string() + ": cannot rename the temporary directory into place: " + ec.message());
  }
  fs::remove_all(old, ec);
}

// fnv1a64 of a file's bytes, read in blocks (K can be gigabytes).
Fingerprint file_fingerprint(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open for reading");
  std::vector<char> block(1 << 20);
  Fingerprint h = fnv1a64(nullptr, 0);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    h = fnv1a64(block.data(), static_cast<std::size_t>(in.gcount()), h);
  }
  if (in.bad()) throw Error(path.string() + ": cannot read");
  return h;
}

// The manifest of the files in `dir` but system.json: name -> size and content hash. It ties
// the files to each other: a file truncated, edited or taken from another assembly no longer
// matches the system.json written with it.
Json file_manifest(const fs::path& dir) {
  Json files = Json::object();
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == "system.json") continue;
    files[name] = Json{{"bytes", static_cast<long>(entry.file_size())}, {"content", to_string(file_fingerprint(entry.path()))}};
  }
  return files;
}

// Checks the files of `dir` against the manifest of its system.json (`j`, read from `json_path`).
void check_files(const std::string& dir, const Json& j, const std::string& json_path) {
  if (!j.contains("files"))
    throw Error(json_path + ": no manifest of the system's files (written by an older xfem-assemble, or not by "
                "xfem-assemble): nothing ties its files together; assemble again");
  const Json& files = j["files"];
  if (!files.is_object()) throw Error(json_path + ": key 'files' (the manifest) is not an object" + kHint);
  for (const auto& [name, entry] : files.items()) {
    Fingerprint recorded = 0;
    if (!is_system_file(name) || name == "system.json" || !entry.is_object() || !entry.contains("bytes") ||
        !entry["bytes"].is_number_integer() || !entry.contains("content") || !entry["content"].is_string() ||
        !parse_fingerprint(entry["content"].get<std::string>(), &recorded))
      throw Error(json_path + ": manifest entry '" + name + "' is not a system file with integer 'bytes' and "
                  "'content' fnv1a64:<16 hex digits>" + kHint);
    const fs::path path = fs::path(dir) / name;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
      throw Error(path.string() + ": missing, but listed in system.json's manifest (the directory is incomplete: "
                  "assemble again)");
    const auto bytes = fs::file_size(path, ec);
    if (ec || static_cast<long>(bytes) != entry["bytes"].get<long>())
      throw Error(path.string() + ": " + std::to_string(bytes) + " bytes, but system.json's manifest says " +
                  entry["bytes"].dump() + " (truncated or replaced since xfem-assemble wrote it: assemble again)");
    if (file_fingerprint(path) != recorded)
      throw Error(path.string() + ": content differs from system.json's manifest (changed or replaced since "
                  "xfem-assemble wrote it: assemble again)");
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (is_system_file(name) && name != "system.json" && !files.contains(name))
      throw Error(entry.path().string() + ": not in system.json's manifest (not written with this system: remove "
                  "it or assemble again)");
  }
}

void write_system_files(const LinearSystem& s, const std::string& tmp, const std::string& dir,
                        const std::string& generator, SystemFormat format,
                        const std::function<void(const std::string&)>& write_more) {
  const bool binary = format == SystemFormat::Petsc;
  if (binary) {
    write_petsc_symmetric_matrix(s.K, join(tmp, "K.petsc"));
    write_petsc_vector(s.f, join(tmp, "f.petsc"));
  } else {
    write_symmetric_matrix(s.K, join(tmp, "K.mtx"));
    write_vector(s.f, join(tmp, "f.mtx"));
  }
  write_dirichlet(s, join(tmp, "dirichlet.mtx"));
  const bool with_coordinates = s.coordinates.size() != 0;
  if (with_coordinates) {
    Eigen::VectorXd c(3 * s.np);
    for (long k = 0; k < s.np; ++k) c.segment<3>(3 * k) = s.coordinates.row(k).transpose();
    if (binary)
      write_petsc_vector(c, join(tmp, "coordinates.petsc"));
    else
      write_vector(c, join(tmp, "coordinates.mtx"));
  }
  Json j;
  j["generator"] = generator;
  j["format"] = binary ? "petsc" : "matrix-market";
  j["np"] = s.np;
  j["ns"] = s.ns;
  j["nb"] = s.nb;
  j["n"] = s.n;
  j["dofs"] = 3 * s.n;
  j["nonzeros"] = lower_nonzeros(s.K);
  j["fixed"] = static_cast<long>(s.fixed.size());
  j["coordinates"] = with_coordinates;
  j["enriched"] = s.n > s.np;
  j["pieces"] = Json::array();
  for (const Piece& p : s.pieces) j["pieces"].push_back(Json{{"tets", p.tets}, {"constrained", p.constrained}});
  (void)dir;
  if (write_more) write_more(tmp);
  j["files"] = file_manifest(tmp);
  // system.json last: its presence says the directory is complete, its manifest what it holds.
  write_json(j, join(tmp, "system.json"));
}

}  // namespace

void write_linear_system(const LinearSystem& s, const std::string& dir, const std::string& generator,
                         SystemFormat format, const std::function<void(const std::string&)>& write_more) {
  check_linear_system(s, dir);
  for (long k = 0; k < s.K.nonZeros(); ++k)
    if (!std::isfinite(s.K.valuePtr()[k])) throw Error(dir + ": K holds a non-finite value; nothing written");
  if (!s.f.allFinite()) throw Error(dir + ": f holds a non-finite value; nothing written");
  fs::path target = fs::path(dir).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/system/"
  if (target.empty() || target.filename() == "." || target.filename() == "..")
    throw Error(dir + ": name the system directory itself (e.g. out/system)");
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (!fs::is_directory(parent)) throw Error(dir + ": cannot create the parent directory " + parent.string());
  if (fs::exists(target)) {
    if (!fs::is_directory(target)) throw Error(dir + ": exists and is not a directory");
    for (const auto& entry : fs::directory_iterator(target))
      if (!is_system_file(entry.path().filename().string()))
        throw Error(dir + ": exists and holds " + entry.path().filename().string() +
                    ", which is not part of a system directory; not replacing it (choose another -o)");
  }
  const fs::path tmp = parent / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
  fs::remove_all(tmp, ec);
  if (!fs::create_directory(tmp, ec)) throw Error(dir + ": cannot create " + tmp.string() + ": " + ec.message());
  try {
    write_system_files(s, tmp.string(), dir, generator, format, write_more);
    move_into_place(tmp, target);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

SystemFormat system_format(const std::string& dir) {
  const std::string json_path = join(dir, "system.json");
  const Json j = read_system_json(json_path);
  const std::string format = j.value("format", std::string("matrix-market"));
  if (format == "petsc") return SystemFormat::Petsc;
  if (format == "matrix-market") return SystemFormat::MatrixMarket;
  throw Error(json_path + ": unknown format '" + format + "' (petsc or matrix-market)" + kHint);
}

std::string system_matrix_file(const std::string& dir, SystemFormat format) {
  return join(dir, format == SystemFormat::Petsc ? "K.petsc" : "K.mtx");
}

LinearSystem read_linear_system(const std::string& dir, bool with_matrix, bool check_manifest) {
  if (!std::filesystem::exists(dir)) throw Error(dir + ": no such directory" + kHint);
  if (!std::filesystem::is_directory(dir))
    throw Error(dir + ": not a directory (expected the system directory written by xfem-assemble)");
  const std::string json_path = join(dir, "system.json");
  if (!std::filesystem::exists(json_path))
    throw Error(dir + ": no system.json, the marker xfem-assemble writes last: the directory is incomplete or not "
                "a system (rerun xfem-assemble)");
  const Json j = read_system_json(json_path);
  const SystemFormat format = system_format(dir);
  const bool binary = format == SystemFormat::Petsc;
  LinearSystem s;
  s.np = get_count(j, "np", json_path);
  s.ns = get_count(j, "ns", json_path);
  s.nb = get_count(j, "nb", json_path);
  s.n = get_count(j, "n", json_path);
  if (s.n != s.np + s.ns + 4 * s.nb)
    throw Error(json_path + ": n = " + std::to_string(s.n) + " but np + ns + 4 nb = " +
                std::to_string(s.np + s.ns + 4 * s.nb));
  const long dofs = 3 * s.n;
  if (j.contains("dofs") && j["dofs"] != dofs)
    throw Error(json_path + ": dofs = " + j["dofs"].dump() + ", expected 3N = " + std::to_string(dofs));
  if (j.contains("pieces")) {
    if (!j["pieces"].is_array()) throw Error(json_path + ": key 'pieces' is not an array" + kHint);
    for (const auto& p : j["pieces"]) {
      if (!p.is_object() || !p.contains("tets") || !p["tets"].is_number_integer() || !p.contains("constrained") ||
          !p["constrained"].is_boolean())
        throw Error(json_path + ": a piece needs integer 'tets' and boolean 'constrained'" + kHint);
      s.pieces.push_back(Piece{p["tets"].get<long>(), p["constrained"].get<bool>()});
    }
  }

  const std::string k_path = system_matrix_file(dir, format);
  if (with_matrix) {
    s.K = read_with_hint([&] { return binary ? read_petsc_matrix(k_path) : read_matrix(k_path); });
    if (s.K.rows() != dofs || s.K.cols() != dofs)
      throw Error(k_path + ": " + std::to_string(s.K.rows()) + " x " + std::to_string(s.K.cols()) +
                  ", expected 3N x 3N = " + std::to_string(dofs) + " x " + std::to_string(dofs) + kHint);
    if (binary) {  // a Matrix Market file says `symmetric` and stores one triangle; a binary one stores both
      const SparseMatrix Kt = s.K.transpose();
      const bool same_pattern = std::equal(Kt.outerIndexPtr(), Kt.outerIndexPtr() + dofs + 1, s.K.outerIndexPtr()) &&
                                std::equal(Kt.innerIndexPtr(), Kt.innerIndexPtr() + Kt.nonZeros(), s.K.innerIndexPtr());
      if (!same_pattern || !std::equal(Kt.valuePtr(), Kt.valuePtr() + Kt.nonZeros(), s.K.valuePtr()))
        throw Error(k_path + ": K is not symmetric (the stiffness matrix must be)" + kHint);
    }
  } else if (!std::filesystem::exists(k_path)) {
    throw Error(k_path + ": cannot open for reading (does it exist?)" + kHint);
  } else if (binary) {
    read_petsc_matrix_header(k_path);  // its own message for a truncated or wrong file, before the manifest's
  }

  const std::string f_path = join(dir, binary ? "f.petsc" : "f.mtx");
  s.f = read_with_hint([&] { return binary ? read_petsc_vector(f_path) : read_vector(f_path); });
  if (s.f.size() != dofs)
    throw Error(f_path + ": " + std::to_string(s.f.size()) + " rows, expected 3N = " + std::to_string(dofs) + kHint);

  const std::string d_path = join(dir, "dirichlet.mtx");
  const SparseMatrix d = read_with_hint([&] { return read_matrix(d_path, true); });
  if (d.rows() != dofs || d.cols() != 1)
    throw Error(d_path + ": " + std::to_string(d.rows()) + " x " + std::to_string(d.cols()) +
                ", expected 3N x 1 = " + std::to_string(dofs) + " x 1" + kHint);
  for (SparseMatrix::InnerIterator it(d, 0); it; ++it) {  // sorted by row
    s.fixed.push_back(it.row());
    s.fixed_values.push_back(it.value());
  }

  const std::string c_path = join(dir, binary ? "coordinates.petsc" : "coordinates.mtx");
  const bool with_coordinates = j.value("coordinates", false);
  if (with_coordinates) {
    const Eigen::VectorXd c = read_with_hint([&] { return binary ? read_petsc_vector(c_path) : read_vector(c_path); });
    if (c.size() != 3 * s.np)
      throw Error(c_path + ": " + std::to_string(c.size()) + " rows, expected 3 NP = " + std::to_string(3 * s.np) + kHint);
    s.coordinates.resize(s.np, 3);
    for (long k = 0; k < s.np; ++k) s.coordinates.row(k) = c.segment<3>(3 * k).transpose();
  }
  if (with_matrix) check_linear_system(s, dir);
  // Last, after each file parsed on its own: do they belong together? (Checked after the reads,
  // so that a directory swapped in while they ran differs from the manifest read before them.)
  if (check_manifest) check_files(dir, j, json_path);
  return s;
}

}  // namespace xfem
