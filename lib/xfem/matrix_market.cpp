// SPDX-License-Identifier: MIT
#include "xfem/matrix_market.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

#include "xfem/atomic_file.h"
#include "xfem/error.h"

namespace xfem {
namespace {

// Text is built in memory and written in one go: ~10x faster than iostream formatting.
void append(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
void append(std::string& out, long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void write_text(const std::string& text, const std::string& path) {
  write_atomically(path, [&](const std::string& tmp) {
    if (tmp == "-") {
      std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
      std::cout.flush();
      return;
    }
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(path + ": cannot open for writing");
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) throw Error(path + ": cannot write (disk full?)");
  });
}

std::string read_text(const std::string& path) {
  require_readable(path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A cursor over the file's text that parses numbers with from_chars and knows its line.
struct Scanner {
  const std::string& path;
  const char* p;
  const char* end;
  long line = 1;

  void skip_space() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) {
      if (*p == '\n') ++line;
      ++p;
    }
  }
  template <class T>
  T number(const char* what) {
    skip_space();
    if (p == end) throw Error(path + ": unexpected end of file (expected " + what + ")");
    T v{};
    const auto r = std::from_chars(p, end, v);
    if (r.ec != std::errc())
      throw Error(path + ": line " + std::to_string(line) + ": expected " + what);
    p = r.ptr;
    return v;
  }
  double real() {
    const double v = number<double>("a number");
    if (!std::isfinite(v)) throw Error(path + ": line " + std::to_string(line) + ": non-finite value");
    return v;
  }
};

struct Header {
  bool coordinate = false, symmetric = false;
};

Header parse_header(Scanner& s) {
  const char* eol = std::find(s.p, s.end, '\n');
  std::string banner(s.p, eol);
  std::transform(banner.begin(), banner.end(), banner.begin(), ::tolower);
  std::istringstream words(banner);
  std::string tag, object, format, field, symmetry;
  words >> tag >> object >> format >> field >> symmetry;
  if (tag != "%%matrixmarket" || object != "matrix")
    throw Error(s.path + ": not a Matrix Market file (first line must start with %%MatrixMarket matrix)");
  if (field != "real" && field != "integer" && field != "double")
    throw Error(s.path + ": Matrix Market field '" + field + "' not supported (expected real)");
  if (symmetry != "general" && symmetry != "symmetric")
    throw Error(s.path + ": Matrix Market symmetry '" + symmetry + "' not supported (general or symmetric)");
  Header h;
  h.coordinate = format == "coordinate";
  if (!h.coordinate && format != "array") throw Error(s.path + ": Matrix Market format '" + format + "' unknown");
  h.symmetric = symmetry == "symmetric";
  s.p = eol;
  // Skip comment lines.
  for (;;) {
    s.skip_space();
    if (s.p < s.end && *s.p == '%') {
      s.p = std::find(s.p, s.end, '\n');
    } else {
      break;
    }
  }
  return h;
}

}  // namespace

void write_symmetric_matrix(const SparseMatrix& K, const std::string& path) {
  if (K.rows() != K.cols()) throw Error(path + ": a symmetric matrix must be square");
  long nnz = 0;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() >= j) ++nnz;
  std::string head = "%%MatrixMarket matrix coordinate real symmetric\n";
  append(head, static_cast<long>(K.rows()));
  head += ' ';
  append(head, static_cast<long>(K.cols()));
  head += ' ';
  append(head, nnz);
  head += '\n';
  // Large matrices (the beam's K has ~6 million entries) spend most of their time here: format
  // straight into a buffer sized for the longest line (two 10-digit ints, a 24-char double,
  // separators), in column blocks on up to 4 threads, concatenated in order (same bytes).
  constexpr std::size_t line_max = 11 + 1 + 11 + 1 + 25 + 1;
  const int columns = static_cast<int>(K.outerSize());
  const int blocks = nnz > 200000 ? static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u)) : 1;
  std::vector<std::string> parts(blocks);
  const auto format = [&](int block) {
    // Block boundaries by entry count, so that threads get similar work.
    const auto first_column = [&](int b) {
      if (b == blocks) return columns;
      const long target = static_cast<long>(K.outerIndexPtr()[columns]) * b / blocks;
      return static_cast<int>(std::lower_bound(K.outerIndexPtr(), K.outerIndexPtr() + columns, target) -
                              K.outerIndexPtr());
    };
    const int begin = first_column(block), end = first_column(block + 1);
    std::string& out = parts[block];
    out.resize(static_cast<std::size_t>(K.outerIndexPtr()[end] - K.outerIndexPtr()[begin]) * line_max);
    char* p = out.data();
    char* const stop = out.data() + out.size();
    for (int j = begin; j < end; ++j)
      for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
        if (it.row() < j) continue;
        p = std::to_chars(p, stop, static_cast<long>(it.row() + 1)).ptr;
        *p++ = ' ';
        p = std::to_chars(p, stop, static_cast<long>(j + 1)).ptr;
        *p++ = ' ';
        p = std::to_chars(p, stop, it.value()).ptr;
        *p++ = '\n';
      }
    out.resize(static_cast<std::size_t>(p - out.data()));
  };
  if (blocks == 1) {
    format(0);
  } else {
    std::vector<std::thread> threads;
    for (int b = 0; b < blocks; ++b) threads.emplace_back(format, b);
    for (auto& t : threads) t.join();
  }
  write_atomically(path, [&](const std::string& tmp) {
    if (tmp == "-") {
      std::cout.write(head.data(), static_cast<std::streamsize>(head.size()));
      for (const auto& part : parts) std::cout.write(part.data(), static_cast<std::streamsize>(part.size()));
      std::cout.flush();
      return;
    }
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(path + ": cannot open for writing");
    bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
    for (const auto& part : parts) ok = ok && std::fwrite(part.data(), 1, part.size(), f) == part.size();
    if (std::fclose(f) != 0 || !ok) throw Error(path + ": cannot write (disk full?)");
  });
}

SparseMatrix read_matrix(const std::string& path) {
  const std::string text = read_text(path);
  Scanner s{path, text.data(), text.data() + text.size()};
  const Header h = parse_header(s);
  if (!h.coordinate) throw Error(path + ": expected a sparse (coordinate) Matrix Market matrix");
  const long rows = s.number<long>("the row count"), cols = s.number<long>("the column count"),
             nnz = s.number<long>("the entry count");
  if (rows < 0 || cols < 0 || nnz < 0) throw Error(path + ": negative size in the size line");
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(h.symmetric ? 2 * nnz : nnz));
  for (long k = 0; k < nnz; ++k) {
    const long i = s.number<long>("a row index") - 1, j = s.number<long>("a column index") - 1;
    const double v = s.real();
    if (i < 0 || i >= rows || j < 0 || j >= cols)
      throw Error(path + ": line " + std::to_string(s.line) + ": index out of range");
    entries.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
    if (h.symmetric && i != j) entries.emplace_back(static_cast<int>(j), static_cast<int>(i), v);
  }
  SparseMatrix K(static_cast<int>(rows), static_cast<int>(cols));
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

void write_vector(const Eigen::VectorXd& v, const std::string& path) {
  std::string text = "%%MatrixMarket matrix array real general\n";
  text.reserve(static_cast<std::size_t>(v.size()) * 25 + 64);
  append(text, static_cast<long>(v.size()));
  text += " 1\n";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) throw Error(path + ": refusing to write a non-finite value at row " + std::to_string(i + 1));
    append(text, v[i]);
    text += '\n';
  }
  write_text(text, path);
}

Eigen::VectorXd read_vector(const std::string& path) {
  const std::string text = read_text(path);
  Scanner s{path, text.data(), text.data() + text.size()};
  const Header h = parse_header(s);
  const long rows = s.number<long>("the row count"), cols = s.number<long>("the column count");
  if (cols != 1) throw Error(path + ": expected an n x 1 vector, got " + std::to_string(cols) + " columns");
  if (rows < 0) throw Error(path + ": negative size in the size line");
  Eigen::VectorXd v = Eigen::VectorXd::Zero(rows);
  if (h.coordinate) {
    const long nnz = s.number<long>("the entry count");
    for (long k = 0; k < nnz; ++k) {
      const long i = s.number<long>("a row index") - 1;
      s.number<long>("a column index");
      const double x = s.real();
      if (i < 0 || i >= rows) throw Error(path + ": line " + std::to_string(s.line) + ": index out of range");
      v[i] = x;
    }
  } else {
    for (long i = 0; i < rows; ++i) v[i] = s.real();
  }
  return v;
}

}  // namespace xfem
