// Progress of the exact engine's sweep (burn3/exact/window_propagation.h on_event,
// pipeline/burn3d_methods.h exact_sweep_reporter, support/progress.h): `burn3d --method
// exact --progress` shows the event time against the largest ignition time and the
// estimate of the final time, the events and the windows during the sweep. The test lowers
// the interval between lines to 0 (GRASSFIRE_PROGRESS_SECONDS) instead of waiting: no
// assertion on time.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support.h"

using grassfire::testing::run_cli;

namespace {

// The sweep's lines: "burn3d: 37%, 2 s, t = ... events, ... windows -- exact propagation".
std::vector<std::smatch> sweep_lines(const std::string& output, std::vector<std::string>& storage) {
  static const std::regex line(R"(^burn3d: (\d+)%, \d+ s, t = (\S+) \(largest ignition (\S+), final ~(\S+)\), (\d+) events, (\d+) windows -- exact propagation$)");
  std::istringstream in(output);
  for (std::string l; std::getline(in, l);) storage.push_back(l);
  std::vector<std::smatch> out;
  for (const std::string& l : storage) {
    std::smatch m;
    if (std::regex_match(l, m, line)) out.push_back(m);
  }
  return out;
}

struct IntervalZero {
  IntervalZero() { setenv("GRASSFIRE_PROGRESS_SECONDS", "0", 1); }
  ~IntervalZero() { unsetenv("GRASSFIRE_PROGRESS_SECONDS"); }
};

}  // namespace

TEST_CASE("burn3d --method exact --progress: the sweep's time, events and windows during the run", "[cli][progress]") {
  IntervalZero zero;
  const auto run = run_cli("burn3d board-fin --method exact --progress");
  REQUIRE(run.code == 0);
  std::vector<std::string> storage;
  const auto lines = sweep_lines(run.output, storage);
  INFO(run.output);
  REQUIRE(lines.size() >= 2);
  unsigned long long previous_events = 0;
  for (const std::smatch& m : lines) {
    const double percent = std::stod(m[1]), t = std::stod(m[2]), ignition = std::stod(m[3]), final_t = std::stod(m[4]);
    const unsigned long long events = std::stoull(m[5]), windows = std::stoull(m[6]);
    CHECK(percent <= 99);
    CHECK(final_t >= ignition);
    CHECK(events > previous_events);  // one line per 256 events, in order
    CHECK(events % 256 == 0);
    CHECK(windows > 0);
    CHECK(t >= 0);
    previous_events = events;
  }
}

TEST_CASE("burn3d --method exact: no sweep lines without --progress, none with --quiet", "[cli][progress]") {
  IntervalZero zero;
  for (const char* flags : {"", " --quiet"}) {
    const auto run = run_cli(std::string("burn3d board-fin --method exact") + flags);
    REQUIRE(run.code == 0);
    std::vector<std::string> storage;
    CHECK(sweep_lines(run.output, storage).empty());
  }
}
