// SPDX-License-Identifier: MIT
#pragma once
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace xfem {

/// Lowers the calling thread's CPU priority to the lowest (nice 19 on Linux; nothing elsewhere).
/// Threads it starts afterwards inherit it.
void lower_this_thread_priority();

/// Tasks run in the background by one worker thread at the lowest CPU priority, their results
/// taken by the caller in the order the tasks were pushed. At that priority the worker gets only
/// the CPU time the caller's own threads leave idle (on a 2-core machine, a second thread at the
/// same priority would halve every parallel section of the caller's work). The caller never
/// waits on the starved worker for more than the one task it is running: `take` runs a task the
/// worker has not started in the calling thread, and `run_oldest_waiting` lets the caller catch up
/// when the worker falls behind. An exception in a task is rethrown by the `take` of its result.
template <class T>
class BackgroundQueue {
 public:
  /// Without `background` (a run held to one thread: --threads 1) there is no worker: every task
  /// runs in the caller, by take or run_oldest_waiting.
  explicit BackgroundQueue(bool background = true) {
    if (background) worker_ = std::thread([this] { work(); });
  }
  BackgroundQueue(const BackgroundQueue&) = delete;
  BackgroundQueue& operator=(const BackgroundQueue&) = delete;
  /// Waits for the task the worker is running, if any; tasks not started are dropped.
  ~BackgroundQueue() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    if (worker_.joinable()) worker_.join();
  }

  void push(std::function<T()> task) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      tasks_.push_back(std::make_unique<Task>());
      tasks_.back()->run = std::move(task);
    }
    changed_.notify_all();
  }
  /// Tasks pushed and not taken.
  std::size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return tasks_.size();
  }
  /// Tasks pushed and not started.
  std::size_t waiting() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t n = 0;
    for (const auto& t : tasks_) n += t->state == State::Waiting;
    return n;
  }
  /// Whether the oldest task's result is there to take without waiting.
  bool ready() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return !tasks_.empty() && tasks_.front()->state == State::Done;
  }
  /// Runs the oldest task nobody has started, in the calling thread (none: returns at once).
  void run_oldest_waiting() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (auto& t : tasks_)
      if (t->state == State::Waiting) {
        run(*t, lock);
        return;
      }
  }
  /// The oldest task's result (precondition: size() > 0): run here if the worker has not started
  /// it, else waited for.
  T take() {
    std::unique_lock<std::mutex> lock(mutex_);
    Task& t = *tasks_.front();
    if (t.state == State::Waiting) run(t, lock);
    changed_.wait(lock, [&] { return t.state == State::Done; });
    std::unique_ptr<Task> done = std::move(tasks_.front());
    tasks_.pop_front();
    lock.unlock();
    if (done->failure) std::rethrow_exception(done->failure);
    return std::move(*done->result);
  }

 private:
  enum class State { Waiting, Running, Done };
  struct Task {
    std::function<T()> run;
    State state = State::Waiting;
    std::optional<T> result;
    std::exception_ptr failure;
  };
  // Runs t (state Waiting, lock held) with the lock released; returns with it held again.
  void run(Task& t, std::unique_lock<std::mutex>& lock) {
    t.state = State::Running;
    lock.unlock();
    std::optional<T> result;
    std::exception_ptr failure;
    try {
      result.emplace(t.run());
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    t.result = std::move(result);
    t.failure = failure;
    t.state = State::Done;
    changed_.notify_all();
  }
  void work() {
    lower_this_thread_priority();
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      Task* next = nullptr;
      changed_.wait(lock, [&] {
        if (stop_) return true;
        for (auto& t : tasks_)
          if (t->state == State::Waiting) {
            next = t.get();
            return true;
          }
        return false;
      });
      if (stop_) return;
      run(*next, lock);
    }
  }

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::unique_ptr<Task>> tasks_;  // pointers: a Task stays put while it runs
  bool stop_ = false;
  std::thread worker_;  // last: started once the members it uses exist
};

}  // namespace xfem
