// SPDX-License-Identifier: MIT
#include "xfem/core/progress_ticker.h"

#include <chrono>

#include "xfem/core/cli.h"

namespace xfem::cli {

ProgressTicker::ProgressTicker(std::string what, bool enabled) : what_(std::move(what)) {
  if (enabled) thread_ = std::thread([this] { run(); });
}

ProgressTicker::~ProgressTicker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ProgressTicker::run() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  for (int seconds = 3;; seconds += seconds < 10 ? 3 : 10) {
    if (wake_.wait_until(lock, start + std::chrono::seconds(seconds), [this] { return done_; })) return;
    info(what_ + ": " + std::to_string(seconds) + " s so far");
  }
}

}  // namespace xfem::cli
