// SPDX-License-Identifier: MIT
#include "xfem/core/background_queue.h"

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace xfem {

void lower_this_thread_priority() {
#ifdef __linux__
  // On Linux the nice value belongs to the thread (its id as the "process"). A failure leaves the
  // priority as it was: the work is the same, only shared less politely.
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
}

}  // namespace xfem
