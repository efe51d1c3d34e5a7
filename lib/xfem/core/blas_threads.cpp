// SPDX-License-Identifier: MIT
#include "xfem/core/blas_threads.h"

#include <dlfcn.h>

#include <cstdlib>

namespace xfem {

BlasThreads::BlasThreads(int threads) {
  using Get = int (*)();
  const auto get = reinterpret_cast<Get>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  set_ = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set_) {
    set_ = nullptr;
    return;
  }
  before_ = get();
  if (before_ == threads) {
    set_ = nullptr;  // nothing to restore: another thread's BLAS call is not disturbed
    return;
  }
  set_(threads);
}

BlasThreads::~BlasThreads() {
  if (set_ && before_ > 0) set_(before_);
}

bool blas_threads_sleep_when_idle() {
  if (std::getenv("OPENBLAS_THREAD_TIMEOUT")) return false;
  // Both are exported by OpenBLAS: openblas_read_env sets what its thread pool reads when it starts
  // (it read the environment once, when the library was loaded); blas_thread_shutdown_ (its
  // after-fork handler) stops the pool, and the next threaded call starts it with the new timeout.
  using Call = void (*)();
  using Shutdown = int (*)();
  const auto read_env = reinterpret_cast<Call>(::dlsym(RTLD_DEFAULT, "openblas_read_env"));
  const auto shutdown = reinterpret_cast<Shutdown>(::dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (!read_env || !shutdown) return false;
  ::setenv("OPENBLAS_THREAD_TIMEOUT", "4", 0);
  read_env();
  shutdown();
  return true;
}

}  // namespace xfem
