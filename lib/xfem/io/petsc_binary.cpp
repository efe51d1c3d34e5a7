// SPDX-License-Identifier: MIT
#include "xfem/io/petsc_binary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "xfem/core/error.h"

namespace xfem {
namespace {

// PETSc files are big-endian; this machine (x86, ARM) is little-endian.
inline std::uint32_t swap(std::uint32_t v) { return __builtin_bswap32(v); }
inline std::uint64_t swap(std::uint64_t v) { return __builtin_bswap64(v); }

const char* const kHint = " (is this a PETSc binary file written by xfem-assemble?)";

struct File {
  std::FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

// Big-endian int32 / double arrays, converted in blocks so no second copy of the data is held.
class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path) {
    file_.f = std::fopen(path.c_str(), "wb");
    if (!file_.f) throw Error(path + ": cannot open for writing");
  }
  void ints(const int* v, std::size_t n) { put<std::uint32_t>(v, n); }
  void doubles(const double* v, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(v[k])) throw Error(path_ + ": value " + std::to_string(k) + " is not finite; nothing written");
    put<std::uint64_t>(v, n);
  }
  void close() {
    std::FILE* f = file_.f;
    file_.f = nullptr;
    if (std::fclose(f) != 0) throw Error(path_ + ": cannot write (disk full?)");
  }

 private:
  template <class U, class T>
  void put(const T* v, std::size_t n) {
    static_assert(sizeof(U) == sizeof(T));
    constexpr std::size_t kBlock = 1 << 16;
    U buf[kBlock];
    for (std::size_t done = 0; done < n;) {
      const std::size_t m = std::min(kBlock, n - done);
      std::memcpy(buf, v + done, m * sizeof(U));
      for (std::size_t k = 0; k < m; ++k) buf[k] = swap(buf[k]);
      if (std::fwrite(buf, sizeof(U), m, file_.f) != m) throw Error(path_ + ": cannot write (disk full?)");
      done += m;
    }
  }
  std::string path_;
  File file_;
};

// The whole file in memory, read with bounds checks against what the header promises.
class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {
    File file;
    file.f = std::fopen(path.c_str(), "rb");
    if (!file.f) throw Error(path + ": cannot open for reading (does it exist?)");
    if (std::fseek(file.f, 0, SEEK_END) != 0) throw Error(path + ": cannot read (not a regular file?)");
    const long size = std::ftell(file.f);
    if (size < 0) throw Error(path + ": cannot read (not a regular file?)");
    std::rewind(file.f);
    bytes_.resize(static_cast<std::size_t>(size));
    if (size > 0 && std::fread(bytes_.data(), 1, bytes_.size(), file.f) != bytes_.size())
      throw Error(path + ": cannot read");
  }
  std::size_t size() const { return bytes_.size(); }
  // The header's int32 at position `k` (the file must hold it).
  long header(std::size_t k) const {
    std::uint32_t v;
    std::memcpy(&v, bytes_.data() + 4 * k, 4);
    return static_cast<std::int32_t>(swap(v));
  }
  void ints(std::size_t offset, int* out, std::size_t n) const { get<std::uint32_t>(offset, out, n); }
  void doubles(std::size_t offset, double* out, std::size_t n) const {
    get<std::uint64_t>(offset, out, n);
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(out[k]))
        throw Error(path_ + ": value " + std::to_string(k) + " is not finite (" + std::to_string(out[k]) + ")");
  }

 private:
  template <class U, class T>
  void get(std::size_t offset, T* out, std::size_t n) const {
    if (n == 0) return;  // `out` may be null then (an empty vector's data()): memcpy must not see it
    std::memcpy(out, bytes_.data() + offset, n * sizeof(U));
    U* u = reinterpret_cast<U*>(out);
    for (std::size_t k = 0; k < n; ++k) u[k] = swap(u[k]);
  }
  std::string path_;
  std::vector<char> bytes_;
};

void require_size(const Reader& r, const std::string& path, std::size_t expected, const std::string& layout) {
  if (r.size() != expected)
    throw Error(path + ": " + std::to_string(r.size()) + " bytes, but its header (" + layout + ") needs " +
                std::to_string(expected) + (r.size() < expected ? " (truncated?)" : " (trailing bytes)") + kHint);
}

void require_class(const Reader& r, const std::string& path, int expected, const char* what) {
  if (r.size() < 8) throw Error(path + ": " + std::to_string(r.size()) + " bytes, too short for a PETSc " + what + kHint);
  if (r.header(0) != expected)
    throw Error(path + ": class id " + std::to_string(r.header(0)) + ", expected " + std::to_string(expected) +
                " (a PETSc " + what + ")" + kHint);
}

}  // namespace

void write_petsc_symmetric_matrix(const SparseMatrix& K, const std::string& path) {
  if (K.rows() != K.cols()) throw Error(path + ": the matrix is not square");
  const SparseMatrix full = K.selfadjointView<Eigen::Lower>();  // both triangles, columns sorted
  const long nnz = full.nonZeros();
  if (nnz > std::numeric_limits<int>::max())
    throw Error(path + ": " + std::to_string(nnz) + " non-zeros do not fit PETSc's 32-bit indices");
  // K is symmetric, so its column j (CSC) is its row j (CSR): the arrays are PETSc's as they are.
  std::vector<int> lengths(full.rows());
  for (long j = 0; j < full.cols(); ++j) lengths[j] = full.outerIndexPtr()[j + 1] - full.outerIndexPtr()[j];
  const int header[4] = {kPetscMatClassId, static_cast<int>(full.rows()), static_cast<int>(full.cols()),
                         static_cast<int>(nnz)};
  Writer w(path);
  w.ints(header, 4);
  w.ints(lengths.data(), lengths.size());
  w.ints(full.innerIndexPtr(), nnz);
  w.doubles(full.valuePtr(), nnz);
  w.close();
}

SparseMatrix read_petsc_matrix(const std::string& path) {
  const Reader r(path);
  require_class(r, path, kPetscMatClassId, "matrix");
  if (r.size() < 16) throw Error(path + ": " + std::to_string(r.size()) + " bytes, too short for a PETSc matrix header" + kHint);
  const long rows = r.header(1), cols = r.header(2), nnz = r.header(3);
  if (rows < 0 || cols < 0 || nnz < 0)
    throw Error(path + ": negative size in the header (" + std::to_string(rows) + " x " + std::to_string(cols) +
                ", " + std::to_string(nnz) + " non-zeros)" + kHint);
  require_size(r, path, 16 + 4 * static_cast<std::size_t>(rows) + 12 * static_cast<std::size_t>(nnz),
               std::to_string(rows) + " x " + std::to_string(cols) + ", " + std::to_string(nnz) + " non-zeros");
  // The file's rows become the columns of T (CSC), so T is the transpose of the stored matrix.
  SparseMatrix T(cols, rows);
  T.resizeNonZeros(nnz);
  std::vector<int> lengths(rows);
  r.ints(16, lengths.data(), rows);
  int* outer = T.outerIndexPtr();
  outer[0] = 0;
  for (long i = 0; i < rows; ++i) {
    if (lengths[i] < 0 || lengths[i] > nnz - outer[i])
      throw Error(path + ": row " + std::to_string(i) + " claims " + std::to_string(lengths[i]) +
                  " entries, more than the header's " + std::to_string(nnz) + " non-zeros left" + kHint);
    outer[i + 1] = outer[i] + lengths[i];
  }
  if (outer[rows] != nnz)
    throw Error(path + ": the row lengths add up to " + std::to_string(outer[rows]) + ", the header says " +
                std::to_string(nnz) + " non-zeros" + kHint);
  int* inner = T.innerIndexPtr();
  r.ints(16 + 4 * static_cast<std::size_t>(rows), inner, nnz);
  for (long i = 0; i < rows; ++i)
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (inner[k] < 0 || inner[k] >= cols || (k > outer[i] && inner[k] <= inner[k - 1]))
        throw Error(path + ": row " + std::to_string(i) + ": column index " + std::to_string(inner[k]) +
                    (inner[k] < 0 || inner[k] >= cols ? " out of range 0.." + std::to_string(cols - 1)
                                                      : " not increasing (duplicate or unsorted)") + kHint);
  r.doubles(16 + 4 * static_cast<std::size_t>(rows) + 4 * static_cast<std::size_t>(nnz), T.valuePtr(), nnz);
  return T.transpose();
}

PetscMatrixHeader read_petsc_matrix_header(const std::string& path) {
  File file;
  file.f = std::fopen(path.c_str(), "rb");
  if (!file.f) throw Error(path + ": cannot open for reading (does it exist?)");
  std::uint32_t h[4] = {0, 0, 0, 0};
  const std::size_t got = std::fread(h, 4, 4, file.f);
  if (std::fseek(file.f, 0, SEEK_END) != 0) throw Error(path + ": cannot read (not a regular file?)");
  const long size = std::ftell(file.f);
  const auto value = [&](int k) { return static_cast<long>(static_cast<std::int32_t>(swap(h[k]))); };
  if (got >= 1 && value(0) != kPetscMatClassId)
    throw Error(path + ": class id " + std::to_string(value(0)) + ", expected " + std::to_string(kPetscMatClassId) +
                " (a PETSc matrix)" + kHint);
  if (got < 4) throw Error(path + ": " + std::to_string(size) + " bytes, too short for a PETSc matrix header" + kHint);
  PetscMatrixHeader m{value(1), value(2), value(3)};
  if (m.rows < 0 || m.cols < 0 || m.nonzeros < 0)
    throw Error(path + ": negative size in the header" + kHint);
  const long expected = 16 + 4 * m.rows + 12 * m.nonzeros;
  if (size != expected)
    throw Error(path + ": " + std::to_string(size) + " bytes, but its header (" + std::to_string(m.rows) + " x " +
                std::to_string(m.cols) + ", " + std::to_string(m.nonzeros) + " non-zeros) needs " +
                std::to_string(expected) + (size < expected ? " (truncated?)" : " (trailing bytes)") + kHint);
  return m;
}

SparseMatrix read_petsc_symmetric_matrix_rows(const std::string& path, const std::vector<long>& wanted) {
  const PetscMatrixHeader h = read_petsc_matrix_header(path);  // size checked against the file
  File file;
  file.f = std::fopen(path.c_str(), "rb");
  if (!file.f) throw Error(path + ": cannot open for reading (does it exist?)");
  const auto read_at = [&](long offset, void* out, std::size_t bytes) {
    if (std::fseek(file.f, offset, SEEK_SET) != 0 || std::fread(out, 1, bytes, file.f) != bytes)
      throw Error(path + ": cannot read");
  };
  std::vector<std::uint32_t> lengths(static_cast<std::size_t>(h.rows));
  read_at(16, lengths.data(), 4 * lengths.size());
  std::vector<long> first(static_cast<std::size_t>(h.rows) + 1, 0);  // offset of each row's entries
  for (long i = 0; i < h.rows; ++i) {
    const long n = static_cast<std::int32_t>(swap(lengths[i]));
    if (n < 0 || n > h.nonzeros - first[i])
      throw Error(path + ": row " + std::to_string(i) + " claims " + std::to_string(n) +
                  " entries, more than the header's " + std::to_string(h.nonzeros) + " non-zeros left" + kHint);
    first[i + 1] = first[i] + n;
  }
  SparseMatrix K(h.cols, h.rows);  // column d = the file's row d
  std::vector<long> rows = wanted;
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  long total = 0;
  for (long d : rows) {
    if (d < 0 || d >= h.rows)
      throw Error(path + ": row " + std::to_string(d) + " asked for, the matrix has " + std::to_string(h.rows));
    total += first[d + 1] - first[d];
  }
  K.resizeNonZeros(total);
  int* outer = K.outerIndexPtr();
  std::fill(outer, outer + h.rows + 1, 0);
  for (long d : rows) outer[d + 1] = static_cast<int>(first[d + 1] - first[d]);
  for (long i = 0; i < h.rows; ++i) outer[i + 1] += outer[i];
  const long values = 16 + 4 * h.rows + 4 * h.nonzeros;
  std::vector<std::uint32_t> index;
  std::vector<std::uint64_t> value;
  for (long d : rows) {
    const std::size_t n = static_cast<std::size_t>(first[d + 1] - first[d]);
    index.resize(n), value.resize(n);
    read_at(16 + 4 * h.rows + 4 * first[d], index.data(), 4 * n);
    read_at(values + 8 * first[d], value.data(), 8 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const long j = static_cast<std::int32_t>(swap(index[k]));
      const std::uint64_t bits = swap(value[k]);
      double v;
      std::memcpy(&v, &bits, 8);
      if (j < 0 || j >= h.cols || (k > 0 && j <= K.innerIndexPtr()[outer[d] + k - 1]))
        throw Error(path + ": row " + std::to_string(d) + ": column index " + std::to_string(j) +
                    (j < 0 || j >= h.cols ? " out of range" : " not increasing (duplicate or unsorted)") + kHint);
      if (!std::isfinite(v)) throw Error(path + ": row " + std::to_string(d) + " holds a non-finite value" + kHint);
      K.innerIndexPtr()[outer[d] + k] = static_cast<int>(j);
      K.valuePtr()[outer[d] + k] = v;
    }
  }
  return K;
}

void write_petsc_vector(const Eigen::VectorXd& v, const std::string& path) {
  if (v.size() > std::numeric_limits<int>::max()) throw Error(path + ": vector too long for PETSc's 32-bit sizes");
  const int header[2] = {kPetscVecClassId, static_cast<int>(v.size())};
  Writer w(path);
  w.ints(header, 2);
  w.doubles(v.data(), v.size());
  w.close();
}

Eigen::VectorXd read_petsc_vector(const std::string& path) {
  const Reader r(path);
  require_class(r, path, kPetscVecClassId, "vector");
  const long n = r.header(1);
  if (n < 0) throw Error(path + ": negative length " + std::to_string(n) + " in the header" + kHint);
  require_size(r, path, 8 + 8 * static_cast<std::size_t>(n), "length " + std::to_string(n));
  Eigen::VectorXd v(n);
  r.doubles(8, v.data(), n);
  return v;
}

}  // namespace xfem
