// cpu_clock.h -- CPU time of the calling thread, for stage timings.
//
// The machines this runs on are often shared: wall-clock stage times then count the
// time other processes held the CPU. Thread CPU time (CLOCK_THREAD_CPUTIME_ID) does not,
// so stage tables and same-run ratios stay comparable under load.
#pragma once

#include <ctime>

namespace grassfire {

inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace grassfire
