// SPDX-License-Identifier: MIT
#include "xfem/linear_system.h"

#include <charconv>
#include <cstdio>
#include <filesystem>

#include "xfem/atomic_file.h"
#include "xfem/error.h"

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
  return j[key].get<long>();
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

void write_linear_system(const LinearSystem& s, const std::string& dir, const std::string& generator) {
  check_linear_system(s, dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw Error(dir + ": cannot create directory");
  write_symmetric_matrix(s.K, join(dir, "K.mtx"));
  write_vector(s.f, join(dir, "f.mtx"));
  write_dirichlet(s, join(dir, "dirichlet.mtx"));
  const bool with_coordinates = s.coordinates.size() != 0;
  if (with_coordinates) {
    Eigen::VectorXd c(3 * s.np);
    for (long k = 0; k < s.np; ++k) c.segment<3>(3 * k) = s.coordinates.row(k).transpose();
    write_vector(c, join(dir, "coordinates.mtx"));
  } else {
    std::filesystem::remove(join(dir, "coordinates.mtx"), ec);  // a stale one would lie
  }
  Json j;
  j["generator"] = generator;
  j["np"] = s.np;
  j["ns"] = s.ns;
  j["nb"] = s.nb;
  j["n"] = s.n;
  j["dofs"] = 3 * s.n;
  j["nonzeros"] = lower_nonzeros(s.K);
  j["fixed"] = static_cast<long>(s.fixed.size());
  j["coordinates"] = with_coordinates;
  j["pieces"] = Json::array();
  for (const Piece& p : s.pieces) j["pieces"].push_back(Json{{"tets", p.tets}, {"constrained", p.constrained}});
  // system.json last: its presence says the directory is complete.
  write_json(j, join(dir, "system.json"));
}

LinearSystem read_linear_system(const std::string& dir) {
  if (!std::filesystem::exists(dir)) throw Error(dir + ": no such directory" + kHint);
  if (!std::filesystem::is_directory(dir))
    throw Error(dir + ": not a directory (expected the system directory written by xfem-assemble)");
  const std::string json_path = join(dir, "system.json");
  const Json j = read_with_hint([&] { return read_json(json_path); });
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

  const std::string k_path = join(dir, "K.mtx");
  s.K = read_with_hint([&] { return read_matrix(k_path); });
  if (s.K.rows() != dofs || s.K.cols() != dofs)
    throw Error(k_path + ": " + std::to_string(s.K.rows()) + " x " + std::to_string(s.K.cols()) +
                ", expected 3N x 3N = " + std::to_string(dofs) + " x " + std::to_string(dofs) + kHint);

  const std::string f_path = join(dir, "f.mtx");
  s.f = read_with_hint([&] { return read_vector(f_path); });
  if (s.f.size() != dofs)
    throw Error(f_path + ": " + std::to_string(s.f.size()) + " rows, expected 3N = " + std::to_string(dofs) + kHint);

  const std::string d_path = join(dir, "dirichlet.mtx");
  const SparseMatrix d = read_with_hint([&] { return read_matrix(d_path); });
  if (d.rows() != dofs || d.cols() != 1)
    throw Error(d_path + ": " + std::to_string(d.rows()) + " x " + std::to_string(d.cols()) +
                ", expected 3N x 1 = " + std::to_string(dofs) + " x 1" + kHint);
  for (SparseMatrix::InnerIterator it(d, 0); it; ++it) {  // sorted by row
    s.fixed.push_back(it.row());
    s.fixed_values.push_back(it.value());
  }

  const std::string c_path = join(dir, "coordinates.mtx");
  const bool with_coordinates = j.value("coordinates", false);
  if (with_coordinates) {
    const Eigen::VectorXd c = read_with_hint([&] { return read_vector(c_path); });
    if (c.size() != 3 * s.np)
      throw Error(c_path + ": " + std::to_string(c.size()) + " rows, expected 3 NP = " + std::to_string(3 * s.np) + kHint);
    s.coordinates.resize(s.np, 3);
    for (long k = 0; k < s.np; ++k) s.coordinates.row(k) = c.segment<3>(3 * k).transpose();
  }
  check_linear_system(s, dir);
  return s;
}

}  // namespace xfem
