// SPDX-License-Identifier: MIT
#include <dlfcn.h>
#include <sys/resource.h>

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "xfem/core/blas_threads.h"

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace {
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}
}  // namespace

TEST_CASE("after blas_threads_sleep_when_idle, BLAS still computes and its idle threads burn no CPU", "[blas]") {
  const bool user_set = std::getenv("OPENBLAS_THREAD_TIMEOUT") != nullptr;
  const bool changed = xfem::blas_threads_sleep_when_idle();
  if (user_set) CHECK_FALSE(changed);
  // A product large enough for OpenBLAS to use its threads, checked against Eigen's own.
  const int n = 600;
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n), b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  const double one = 1.0, zero = 0.0;
  dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
  const Eigen::MatrixXd expected = a * b;
  CHECK((c - expected).norm() <= 1e-12 * expected.norm());
  if (!changed) return;  // another BLAS, or the user's own timeout: nothing more to check
  // Spinning threads would burn ~0.1 s of CPU in the next 0.1 s of wall time; sleeping ones none.
  const double before = cpu_seconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  CHECK(cpu_seconds() - before < 0.02);
}

TEST_CASE("BlasThreads sets OpenBLAS's thread count for its lifetime, and leaves a right count alone", "[blas]") {
  using Get = int (*)();
  using Set = void (*)(int);
  const auto get = reinterpret_cast<Get>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set) return;  // another BLAS: nothing to set
  const int before = get();
  set(2);
  {
    const xfem::BlasThreads one(1);
    CHECK(get() == 1);
    {
      // Already 1: it changes nothing, now or at its end (xfem-sweep's frame thread may be in a BLAS
      // call meanwhile), so the outer object's count holds after it.
      const xfem::BlasThreads again(1);
      CHECK(get() == 1);
      set(2);  // as if someone else changed it meanwhile: `again` must not set it back
    }
    CHECK(get() == 2);
  }
  CHECK(get() == 2);
  set(before);
}
