// cpu_clock.h -- process CPU seconds, for the stage times the builders report.
//
// The builders are single-threaded, so CPU time equals wall time on an idle machine and,
// unlike wall time, is not inflated when the machine is shared (the benchmarks compare
// stages and baselines measured this way). Linux/POSIX clock_gettime.
#pragma once

#include <time.h>

namespace grassfire {

inline double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace grassfire
