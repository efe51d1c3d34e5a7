// SPDX-License-Identifier: MIT
#include "xfem/core/thread_limit.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "xfem/core/blas_threads.h"

namespace xfem {
namespace {

std::atomic<int> chosen{0};
std::atomic<int> peak{0};

bool counting() {
  static const bool on = std::getenv("XFEM_COUNT_THREADS") != nullptr;
  return on;
}

}  // namespace

int threads_from_environment(std::string* problem) {
  const char* text = std::getenv("OMP_NUM_THREADS");
  if (!text || !*text) return 0;
  // OpenMP's syntax: a list "4,2" of nested teams' sizes; the first is ours. Spaces around it pass.
  const std::string value(text);
  std::size_t begin = value.find_first_not_of(" \t");
  std::size_t end = value.find(',');
  if (end == std::string::npos) end = value.size();
  std::string first = begin == std::string::npos || begin >= end ? std::string() : value.substr(begin, end - begin);
  first.erase(first.find_last_not_of(" \t") + 1);
  long n = -1;
  if (!first.empty() && first.find_first_not_of("0123456789") == std::string::npos && first.size() <= 9)
    n = std::strtol(first.c_str(), nullptr, 10);
  if (n >= 1 && n <= kMaxThreads) return static_cast<int>(n);
  if (problem)
    *problem = "OMP_NUM_THREADS=" + value + ": not a whole number of threads from 1 to " + std::to_string(kMaxThreads);
  return -1;
}

int thread_limit() {
  if (const int n = chosen.load()) return n;
  static const int from_environment = [] {
    const int n = threads_from_environment();
    return n > 0 ? n : static_cast<int>(std::clamp<unsigned>(std::thread::hardware_concurrency(), 1u, 8u));
  }();
  return from_environment;
}

void set_thread_limit(int threads) {
  chosen = std::clamp(threads, 0, kMaxThreads);
  if (threads > 0) set_library_threads(threads);
}

void note_thread_count() {
  if (!counting()) return;
  std::error_code error;
  int n = 0;
  for (std::filesystem::directory_iterator it("/proc/self/task", error), end; !error && it != end; it.increment(error))
    ++n;
  int seen = peak.load();
  while (n > seen && !peak.compare_exchange_weak(seen, n)) {
  }
}

int thread_count_peak() {
  note_thread_count();
  return peak.load();
}

}  // namespace xfem
