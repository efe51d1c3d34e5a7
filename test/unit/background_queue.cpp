// SPDX-License-Identifier: MIT
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "xfem/core/background_queue.h"

namespace {
int my_thread_id() { return static_cast<int>(syscall(SYS_gettid)); }
int my_nice() { return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid))); }
struct Ran {
  int value, thread, nice;
};
}  // namespace

TEST_CASE("BackgroundQueue: results in push order, from the worker at the lowest priority", "[background]") {
  xfem::BackgroundQueue<Ran> queue;
  const int caller = my_thread_id(), caller_nice = my_nice();
  for (int i = 0; i < 20; ++i) queue.push([i] { return Ran{i, my_thread_id(), my_nice()}; });
  for (int i = 0; i < 20; ++i) {
    while (!queue.ready()) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // all by the worker
    const Ran r = queue.take();
    CHECK(r.value == i);
    CHECK(r.thread != caller);
    CHECK(r.nice == 19);
  }
  CHECK(queue.size() == 0);
  CHECK(my_nice() == caller_nice);  // the caller's own priority untouched
}

TEST_CASE("BackgroundQueue: the caller runs what the busy worker has not started; errors at their take",
          "[background]") {
  xfem::BackgroundQueue<Ran> queue;
  const int caller = my_thread_id();
  std::atomic<bool> started{false}, release{false};
  queue.push([&] {  // keeps the worker busy until released
    started = true;
    while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return Ran{0, my_thread_id(), my_nice()};
  });
  queue.push([] { return Ran{1, my_thread_id(), my_nice()}; });
  queue.push([]() -> Ran { throw std::runtime_error("frame 2 failed"); });
  queue.push([] { return Ran{3, my_thread_id(), my_nice()}; });
  while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  CHECK(queue.waiting() == 3);
  queue.run_oldest_waiting();  // task 1, here
  CHECK(queue.waiting() == 2);
  CHECK_FALSE(queue.ready());  // task 0 still running in the worker
  release = true;
  const Ran first = queue.take();
  CHECK(first.value == 0);
  CHECK(first.thread != caller);
  const Ran second = queue.take();
  CHECK(second.value == 1);
  CHECK(second.thread == caller);
  CHECK_THROWS_WITH(queue.take(), "frame 2 failed");
  CHECK(queue.take().value == 3);  // an error does not stop the queue
  CHECK(queue.size() == 0);
}

TEST_CASE("BackgroundQueue: destroyed with tasks not started, it waits for the running one only", "[background]") {
  std::atomic<int> runs{0};
  {
    xfem::BackgroundQueue<int> queue;
    std::atomic<bool> started{false};
    queue.push([&] {
      started = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      return ++runs;
    });
    while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    for (int i = 0; i < 5; ++i) queue.push([&] { return ++runs; });
  }
  CHECK(runs == 1);
}
