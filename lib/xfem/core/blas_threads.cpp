// SPDX-License-Identifier: MIT
#include "xfem/core/blas_threads.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

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

void set_library_threads(int threads) {
  using Get = int (*)();
  using Set = void (*)(int);
  using Shutdown = int (*)();
  const auto get = reinterpret_cast<Get>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  const auto shutdown = reinterpret_cast<Shutdown>(::dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (get && set) {
    const int before = get();
    set(threads);
    // The pool OpenBLAS started at load time holds one thread per core (or per OMP_NUM_THREADS),
    // and set_num_threads only lowers how many of them work: the pool is stopped, after the count
    // is lowered, so that it restarts (at its old size) only for a call that wants threads.
    if (threads < before && shutdown) shutdown();
  }
  const auto omp_set = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "omp_set_num_threads"));
  if (omp_set) omp_set(threads);
  // CHOLMOD (5.12) is the only user of OpenMP here, and its supernodal factorization asks for a
  // team of 4 by a num_threads clause that omp_set_num_threads does not bound (nor
  // OMP_NUM_THREADS): with a limit set, no parallel region is made active at all (max-active-levels
  // 0, global in libgomp). Its loop copies entries into a supernode; the BLAS that does the work
  // keeps its `threads`.
  const auto omp_levels = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (omp_levels) omp_levels(0);
  // VTK's SMP tools (TBB in Debian's VTK: the XML writers' cell-type scans) start one worker per
  // core and read neither variable. vtkSMPTools::Initialize(int), by its C++ name: core/ needs no
  // VTK header for it, and a program without VTK skips it. At most the cores (TBB warns beyond).
  const auto vtk_set = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "_ZN11vtkSMPTools10InitializeEi"));
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (vtk_set) vtk_set(std::min(threads, cores));
}

}  // namespace xfem
