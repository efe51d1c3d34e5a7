// SPDX-License-Identifier: MIT
#pragma once
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace xfem::cli {

/// Prints "<tool>: <what>: 12 s so far" on stderr every few seconds while a long library call runs
/// (from 3 s on: 3, 6, 9, then every 10 s), so a user sees that a factorization of a minute is
/// alive. Ticks from construction to destruction, in a thread of its own; nothing when not
/// `enabled` (e.g. under -q).
class ProgressTicker {
 public:
  ProgressTicker(std::string what, bool enabled);
  ~ProgressTicker();
  ProgressTicker(const ProgressTicker&) = delete;
  ProgressTicker& operator=(const ProgressTicker&) = delete;

 private:
  void run();
  std::string what_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace xfem::cli
