// cpu_clock.h -- CPU seconds for stage timings: of the calling thread, or of the process.
//
// The machines this runs on are often shared: wall-clock stage times then count the time
// other processes held the CPU. CPU time does not, so stage tables and same-run ratios stay
// comparable under load. thread_seconds (CLOCK_THREAD_CPUTIME_ID) times one thread's
// stages; cpu_seconds (CLOCK_PROCESS_CPUTIME_ID) a single-threaded builder, where it equals
// wall time on an idle machine. wall_seconds_since measures wall time (std::chrono's steady
// clock) where a caller wants it (reports that include waiting, or several threads).
// The one home of stage timing: every "seconds" of a report comes from one of these three.
// POSIX clock_gettime; O(1).
#pragma once

#include <chrono>
#include <ctime>

namespace grassfire {

inline double clock_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
inline double thread_seconds() { return clock_seconds(CLOCK_THREAD_CPUTIME_ID); }
inline double cpu_seconds() { return clock_seconds(CLOCK_PROCESS_CPUTIME_ID); }

// Seconds elapsed since `start`, which was read from the same clock.
inline double thread_seconds_since(double start) { return thread_seconds() - start; }
inline double cpu_seconds_since(double start) { return cpu_seconds() - start; }
inline double wall_seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace grassfire
