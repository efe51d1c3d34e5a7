// SPDX-License-Identifier: MIT
#pragma once

namespace xfem {

/// OpenBLAS's thread count for the lifetime of the object, when the BLAS behind CHOLMOD and LAPACK
/// is OpenBLAS (found by name at run time: another BLAS is left alone). The count is process-wide:
/// an object that finds it already right changes nothing, then or at its end, so it may be made
/// while another thread calls BLAS.
class BlasThreads {
 public:
  explicit BlasThreads(int threads);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

 private:
  using Set = void (*)(int);
  Set set_ = nullptr;
  int before_ = 0;
};

/// After each call OpenBLAS's idle worker threads spin on sched_yield for 2^28 cycles (~0.1 s)
/// before they sleep, taking a core from whatever the program does next. A program that alternates
/// short BLAS calls with its own threads (xfem-sweep: every step's Schur update, then the next
/// step's threaded element matrices and frame) loses ~0.03 s a step to them on 2 cores
/// (docs/PERFORMANCE.md). This makes them sleep at once (OPENBLAS_THREAD_TIMEOUT=4, OpenBLAS's
/// minimum), by re-reading the environment and restarting the thread pool, which OpenBLAS starts
/// anew on the next call. Does nothing when the user set OPENBLAS_THREAD_TIMEOUT or the BLAS is not
/// OpenBLAS. Returns whether it changed the setting. Call it before any other thread is started.
bool blas_threads_sleep_when_idle();

/// The libraries' own thread teams for the rest of the run, for --threads (thread_limit.h): OpenBLAS
/// (behind CHOLMOD and LAPACK; its idle pool, started when the library was loaded, is stopped, and
/// the next threaded call starts `threads` - 1 helpers) and OpenMP (CHOLMOD's, through libgomp's
/// omp_set_num_threads, and no active parallel region: CHOLMOD's fixed team of 4 would exceed the
/// limit) and VTK's SMP tools (TBB, at most one per core).
/// Each found by name at run time: a library that is not there is left alone. Call it before any
/// other thread of ours uses them.
void set_library_threads(int threads);

}  // namespace xfem
