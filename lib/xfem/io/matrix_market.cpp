// SPDX-License-Identifier: MIT
#include "xfem/io/matrix_market.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/core/thread_limit.h"

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

// Rejects a size line that promises more entries than the file can hold (each entry takes at
// least `min_bytes` characters), before anything is allocated: a corrupt header claiming 1e12
// rows must be an error naming the file, not "out of memory".
void check_claim(const Scanner& s, long count, long min_bytes, const char* what) {
  const long left = static_cast<long>(s.end - s.p);
  if (count > left / min_bytes + 1)
    throw Error(s.path + ": the size line claims " + std::to_string(count) + " " + what + " but only " +
                std::to_string(left) + " bytes follow (truncated file or corrupt header)");
}

// Nothing but white space may follow the last entry: extra values mean a wrong header.
void expect_end(Scanner& s, long count) {
  s.skip_space();
  if (s.p != s.end)
    throw Error(s.path + ": line " + std::to_string(s.line) + ": more values than the " + std::to_string(count) +
                " entries the size line announces");
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
  // Large matrices (the beam's K has ~6 million entries) spend most of their time here. The
  // entries are formatted in blocks of consecutive columns (about 2^18 entries each) by worker
  // threads into uninitialized buffers sized for the longest line (two 10-digit ints, a 24-char
  // double, separators), while this thread writes the finished blocks in order and frees them:
  // formatting overlaps the kernel's copy into the page cache, and no buffer is zero-filled. The
  // bytes are those of a single-threaded writer (docs/PERFORMANCE.md, "Speed-up"; about 2.5x
  // faster than formatting everything first, then writing).
  constexpr std::size_t line_max = 11 + 1 + 11 + 1 + 25 + 1;
  constexpr long block_entries = 1L << 18;
  const int columns = static_cast<int>(K.outerSize());
  const long stored = K.outerIndexPtr()[columns];
  const int blocks = static_cast<int>(std::max(1L, stored / block_entries));
  std::vector<int> first(blocks + 1);  // block b: columns first[b] .. first[b+1]-1
  for (int b = 0; b <= blocks; ++b)
    first[b] = b == blocks ? columns
                           : static_cast<int>(std::lower_bound(K.outerIndexPtr(), K.outerIndexPtr() + columns,
                                                               stored * b / blocks) - K.outerIndexPtr());
  std::vector<std::unique_ptr<char[]>> text(blocks);
  std::vector<std::size_t> length(blocks, 0);
  std::vector<char> done(blocks, 0);
  std::mutex mutex;
  std::condition_variable finished;
  std::atomic<int> next{0};
  std::exception_ptr failure;  // a worker's bad_alloc, rethrown by the writing thread
  const auto format = [&] {
    for (int b; (b = next++) < blocks;) {
      const auto capacity = static_cast<std::size_t>(K.outerIndexPtr()[first[b + 1]] - K.outerIndexPtr()[first[b]]) * line_max;
      std::unique_ptr<char[]> out;
      try {
        out.reset(new char[std::max<std::size_t>(capacity, 1)]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        done[b] = 1;
        finished.notify_all();
        continue;
      }
      char* p = out.get();
      char* const stop = p + capacity;
      for (int j = first[b]; j < first[b + 1]; ++j)
        for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
          if (it.row() < j) continue;
          p = std::to_chars(p, stop, static_cast<long>(it.row() + 1)).ptr;
          *p++ = ' ';
          p = std::to_chars(p, stop, static_cast<long>(j + 1)).ptr;
          *p++ = ' ';
          p = std::to_chars(p, stop, it.value()).ptr;
          *p++ = '\n';
        }
      std::lock_guard<std::mutex> lock(mutex);
      length[b] = static_cast<std::size_t>(p - out.get());
      text[b] = std::move(out);
      done[b] = 1;
      finished.notify_all();
    }
  };
  const int workers = blocks == 1 ? 0 : std::clamp(thread_limit(), 1, 4);
  std::vector<std::thread> threads;
  struct Join {  // the workers must end before the buffers go, also when writing throws
    std::vector<std::thread>& threads;
    std::atomic<int>& next;
    int blocks;
    ~Join() {
      next = blocks;  // no further blocks
      for (auto& t : threads) t.join();
    }
  } join{threads, next, blocks};
  for (int w = 0; w < workers; ++w) threads.emplace_back(format);
  if (workers == 0) format();
  // Hands block b (in order) to `sink` once it is formatted, then frees it.
  const auto each_block = [&](const std::function<void(const char*, std::size_t)>& sink) {
    for (int b = 0; b < blocks; ++b) {
      std::unique_ptr<char[]> block;
      {
        std::unique_lock<std::mutex> lock(mutex);
        finished.wait(lock, [&] { return done[b] != 0; });
        if (failure) std::rethrow_exception(failure);
        block = std::move(text[b]);
      }
      sink(block.get(), length[b]);
    }
  };
  write_atomically(path, [&](const std::string& tmp) {
    if (tmp == "-") {
      std::cout.write(head.data(), static_cast<std::streamsize>(head.size()));
      each_block([](const char* p, std::size_t n) { std::cout.write(p, static_cast<std::streamsize>(n)); });
      std::cout.flush();
      return;
    }
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(path + ": cannot open for writing");
    bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
    each_block([&](const char* p, std::size_t n) { ok = ok && std::fwrite(p, 1, n, f) == n; });
    if (std::fclose(f) != 0 || !ok) throw Error(path + ": cannot write (disk full?)");
  });
}

SparseMatrix read_matrix(const std::string& path, bool rows_increasing) {
  const std::string text = read_text(path);
  Scanner s{path, text.data(), text.data() + text.size()};
  const Header h = parse_header(s);
  if (!h.coordinate) throw Error(path + ": expected a sparse (coordinate) Matrix Market matrix");
  const long rows = s.number<long>("the row count"), cols = s.number<long>("the column count"),
             nnz = s.number<long>("the entry count");
  if (rows < 0 || cols < 0 || nnz < 0) throw Error(path + ": negative size in the size line");
  if (rows > std::numeric_limits<int>::max() || cols > std::numeric_limits<int>::max())
    throw Error(path + ": " + std::to_string(rows) + " x " + std::to_string(cols) + " is larger than supported (2^31 - 1)");
  if (h.symmetric && rows != cols) throw Error(path + ": a symmetric matrix must be square");
  check_claim(s, nnz, 6, "entries");
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(h.symmetric ? 2 * nnz : nnz));
  long previous_row = -1;
  for (long k = 0; k < nnz; ++k) {
    const long i = s.number<long>("a row index") - 1, j = s.number<long>("a column index") - 1;
    const double v = s.real();
    if (i < 0 || i >= rows || j < 0 || j >= cols)
      throw Error(path + ": line " + std::to_string(s.line) + ": index out of range");
    if (rows_increasing && i <= previous_row)
      throw Error(path + ": line " + std::to_string(s.line) + ": row " + std::to_string(i + 1) + " after row " +
                  std::to_string(previous_row + 1) + " (the rows must be strictly increasing)");
    previous_row = i;
    if (h.symmetric && i < j)
      throw Error(path + ": line " + std::to_string(s.line) + ": entry (" + std::to_string(i + 1) + ", " +
                  std::to_string(j + 1) + ") above the diagonal in a symmetric file (only the lower triangle is stored)");
    entries.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
    if (h.symmetric && i != j) entries.emplace_back(static_cast<int>(j), static_cast<int>(i), v);
  }
  expect_end(s, nnz);
  SparseMatrix K(static_cast<int>(rows), static_cast<int>(cols));
  // A duplicated entry would be summed silently: refuse it.
  K.setFromTriplets(entries.begin(), entries.end(), [&](double, double) -> double {
    throw Error(path + ": an entry appears twice (duplicated (row, column) pair)");
  });
  return K;
}

void write_vector(const Eigen::VectorXd& v, const std::string& path, const std::vector<std::string>& comments) {
  std::string text = "%%MatrixMarket matrix array real general\n";
  for (const std::string& c : comments) text += c + "\n";
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
  if (h.coordinate)
    throw Error(path + ": a sparse (coordinate) Matrix Market file, expected a dense (array) vector of all values");
  check_claim(s, rows, 2, "values");
  Eigen::VectorXd v = Eigen::VectorXd::Zero(rows);
  for (long i = 0; i < rows; ++i) v[i] = s.real();
  expect_end(s, rows);
  return v;
}

}  // namespace xfem
