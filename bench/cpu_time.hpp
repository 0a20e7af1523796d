#pragma once
// This thread's CPU time, for rates per core: other processes on a shared machine slow a
// loop's wall time, not its CPU time (they still share caches and clock speed with it).

#include <time.h>

namespace esc::bench {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace esc::bench
