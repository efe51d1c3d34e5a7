// SPDX-License-Identifier: MIT
#pragma once
#include <string>

namespace xfem {

/// The most threads a run may use (--threads; then OMP_NUM_THREADS; else every core there is,
/// at most 8): parallel_for's team, and the BLAS, OpenMP and writer threads the tools start, so
/// that users can pin runs and share a machine. Results do not depend on it (every parallel loop
/// computes each index on its own).
constexpr int kMaxThreads = 1024;

/// The number of threads parallel work uses: the one set_thread_limit gave, else OMP_NUM_THREADS
/// when it is valid (its first number, as OpenMP reads "4,2"), else the cores, 1 to 8.
int thread_limit();

/// Sets the thread count for the rest of the run (1..kMaxThreads; 0 = back to the default) and
/// passes it on to the libraries' own threads (OpenBLAS, OpenMP: set_library_threads).
void set_thread_limit(int threads);

/// OMP_NUM_THREADS read as thread_limit does: 0 when it is unset or empty, the count when valid,
/// -1 when it is set but not a whole number from 1 to kMaxThreads (then `problem`, if given, says
/// why, one line naming the variable).
int threads_from_environment(std::string* problem = nullptr);

/// Test hook (XFEM_COUNT_THREADS set in the environment): the most threads this process was seen
/// to have at once, counted in /proc/self/task while parallel_for's team runs and whenever
/// note_thread_count is called; 0 when the hook is off.
void note_thread_count();
int thread_count_peak();

}  // namespace xfem
