// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "xfem/core/thread_limit.h"

namespace xfem {

/// Runs body(begin, end) over [0, n) in chunks of `chunk` indices, in up to thread_limit() threads
/// (--threads, OMP_NUM_THREADS, else the cores there are, at most 8). Every index must be computed independently, so the result does not depend on the
/// thread count. `progress` (optional) gets the fraction done from the calling thread. An exception
/// in a thread (bad_alloc, a CGAL precondition) would call std::terminate: the first one is kept,
/// the work stops, and it is rethrown on the calling thread after the join.
inline void parallel_for(long n, const std::function<void(long, long)>& body,
                         const std::function<void(double)>& progress = {}, long chunk = 4096) {
  const int threads = thread_limit();
  std::atomic<long> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&](bool report) {
    try {
      for (long b; (b = next.fetch_add(chunk)) < n;) {
        body(b, std::min(n, b + chunk));
        if (report && progress) progress(static_cast<double>(std::min(n, b + chunk)) / n);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = n;
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads && n > chunk; ++i) pool.emplace_back(work, false);
  if (!pool.empty()) note_thread_count();  // the test hook (thread_limit.h): the team is there
  work(true);
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace xfem
