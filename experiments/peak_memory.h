// peak_memory.h -- run a measurement in a child process and read its peak memory.
//
// Benchmarks fork one child per configuration so that VmHWM (the peak resident set of
// the child alone) is the memory of that configuration, not of earlier, larger ones.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace grassfire::bench {

// Peak resident set size of this process in MiB (Linux /proc/self/status, VmHWM).
inline double peak_resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0;
      status >> kib;
      return kib / 1024.0;
    }
  }
  return -1;
}

// Runs `measure` in a child process; it returns numbers, which come back through a pipe.
// cpu_limit_s > 0: the child is killed past that many processor seconds (RLIMIT_CPU), and
// in_child throws as for any failed child.
inline std::vector<double> in_child(const std::function<std::vector<double>()>& measure, long cpu_limit_s = 0) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fd[0]);
    if (cpu_limit_s > 0) {
      const rlimit lim{static_cast<rlim_t>(cpu_limit_s), static_cast<rlim_t>(cpu_limit_s)};
      setrlimit(RLIMIT_CPU, &lim);
    }
    std::vector<double> values;
    try {
      values = measure();
      values.push_back(peak_resident_mib());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "measurement failed: %s\n", e.what());
      _exit(1);
    }
    const ssize_t n = static_cast<ssize_t>(values.size() * sizeof(double));
    if (write(fd[1], values.data(), static_cast<size_t>(n)) != n) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  std::vector<double> values;
  double buf[64];
  ssize_t got;
  std::string bytes;
  while ((got = read(fd[0], buf, sizeof buf)) > 0) bytes.append(reinterpret_cast<char*>(buf), static_cast<size_t>(got));
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error("child measurement failed");
  values.resize(bytes.size() / sizeof(double));
  std::copy(bytes.data(), bytes.data() + values.size() * sizeof(double), reinterpret_cast<char*>(values.data()));
  return values;
}

}  // namespace grassfire::bench
