// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "xfem/core/parallel_for.h"
#include "xfem/core/thread_limit.h"

namespace {

// OMP_NUM_THREADS set to `value` (nullptr: unset) for the scope, then restored.
struct Environment {
  std::string before;
  bool had = false;
  explicit Environment(const char* value) {
    if (const char* b = std::getenv("OMP_NUM_THREADS")) {
      before = b;
      had = true;
    }
    if (value)
      ::setenv("OMP_NUM_THREADS", value, 1);
    else
      ::unsetenv("OMP_NUM_THREADS");
  }
  ~Environment() {
    if (had)
      ::setenv("OMP_NUM_THREADS", before.c_str(), 1);
    else
      ::unsetenv("OMP_NUM_THREADS");
  }
};

// The distinct threads parallel_for runs `n` one-index chunks on, each chunk waiting (up to 5 s)
// until `n` threads are in at once: a team of n threads passes at once, a smaller one times out
// and shows how many it had.
std::size_t team_size(long n) {
  std::mutex m;
  std::condition_variable all_in;
  std::set<std::thread::id> ids;
  xfem::parallel_for(n, [&](long, long) {
    std::unique_lock<std::mutex> lock(m);
    ids.insert(std::this_thread::get_id());
    all_in.notify_all();
    all_in.wait_for(lock, std::chrono::seconds(5), [&] { return static_cast<long>(ids.size()) >= n; });
  }, {}, 1);
  return ids.size();
}

}  // namespace

TEST_CASE("OMP_NUM_THREADS is read as OpenMP reads it, and refused when it is not a count", "[threads]") {
  std::string problem;
  {
    const Environment e(nullptr);
    CHECK(xfem::threads_from_environment(&problem) == 0);
  }
  for (const auto& [value, count] : std::vector<std::pair<const char*, int>>{
           {"", 0}, {"1", 1}, {"3", 3}, {" 2 ", 2}, {"4,2", 4}, {"1024", 1024}}) {
    const Environment e(value);
    CHECK(xfem::threads_from_environment(&problem) == count);
  }
  for (const char* value : {"0", "-1", "1e9", "x", "1025", "2.5", "9999999999", ",2", "+3"}) {
    const Environment e(value);
    problem.clear();
    CHECK(xfem::threads_from_environment(&problem) == -1);
    CHECK(problem == std::string("OMP_NUM_THREADS=") + value + ": not a whole number of threads from 1 to 1024");
  }
}

TEST_CASE("parallel_for runs in as many threads as set_thread_limit says, with the same result", "[threads]") {
  for (int n : {1, 2, 3}) {
    xfem::set_thread_limit(n);
    CHECK(xfem::thread_limit() == n);
    CHECK(team_size(n) == static_cast<std::size_t>(n));
  }
  // One thread: every chunk on the calling thread.
  xfem::set_thread_limit(1);
  CHECK(team_size(3) == 1);
  // The same sums whatever the team (each index computed on its own).
  std::vector<double> one(10000), three(10000);
  const auto fill = [](std::vector<double>& v) {
    xfem::parallel_for(static_cast<long>(v.size()), [&](long b, long e) {
      for (long i = b; i < e; ++i) v[i] = std::sin(0.001 * i) / (1.0 + i);
    }, {}, 64);
  };
  fill(one);
  xfem::set_thread_limit(3);
  fill(three);
  CHECK(one == three);
  xfem::set_thread_limit(0);  // back to the default
  CHECK(xfem::thread_limit() >= 1);
}
