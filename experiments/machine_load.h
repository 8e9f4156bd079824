// machine_load.h -- the machine's load average, for the benchmarks' CSV rows.
//
// Computes: the 1-minute load average of /proc/loadavg at the time of the call (Linux), or
// -1 when it cannot be read. Benchmarks print it beside both sides' times, so that a row
// says how busy the shared machine was when it was measured (CPU seconds on a loaded
// machine still vary with cache and memory contention).
// Complexity: one small file read.
#pragma once

#include <fstream>

namespace grassfire::bench {

inline double machine_load() {
  std::ifstream in("/proc/loadavg");
  double load = -1;
  if (!(in >> load)) return -1;
  return load;
}

}  // namespace grassfire::bench
