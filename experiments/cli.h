// experiments/cli.h -- what every benchmark and study's main shares.
//
// guarded_main(argc, argv, name, usage, run): --help or -h anywhere on the command line
// prints `usage` on stdout and exits 0 before anything runs (no benchmark starts, no file
// is written); otherwise run(argc, argv) runs, and an exception that escapes it (a bad
// argument, an unreadable file, a mesh the builders refuse) is printed as "name: message"
// on stderr with exit status 1, never std::terminate's abort; a command line the study does
// not accept (UsageError, experiments/run_options.h) prints "name: message" and the usage on
// stderr with exit status 2. Constant time.
#pragma once

#include <cstdio>
#include <cstring>
#include <exception>

#include "run_options.h"

namespace grassfire::experiments {

inline int guarded_main(int argc, char** argv, const char* name, const char* usage, int (*run)(int, char**)) {
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::fputs(usage, stdout);
      return 0;
    }
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: %s\n%s", name, e.what(), usage);
    return 2;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace grassfire::experiments
