// bench_burn3d_discrete -- the discrete burning baseline on complexes of 10^3 .. 10^5
// triangles at two Steiner spacings, against a plain multi-source Dijkstra on the same
// Steiner graph (no link rule: what the junction bookkeeping costs).
//
// Complexes: the board and fin refined (g cells per unit), books of 5 pages, and exact box
// medial axes subdivided n x n. Spacings: h = the typical edge length (about one Steiner
// point per edge) and h / 2. Each case runs in a forked child so that its peak resident
// memory (VmHWM from /proc/self/status) is its own. CSV on stdout:
// complex,triangles,complex_build_seconds,spacing,steiner_points,graph_points,pushes,seconds,
// plain_dijkstra_seconds,ratio,peak_memory_kb,load (seconds: the baseline; complex_build: the
// exact MedialComplex construction from the RawComplex; load: the 1-minute load average when
// the row was measured, machine_load.h).
// Usage: bench_burn3d_discrete [--quick]
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <queue>
#include <string>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/steiner_graph.h"
#include "complex3/synthetic_complexes.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

long peak_memory_kb() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// Multi-source Dijkstra from the ignited points over the same moves, without the link
// rule: every point burns at its first arrival (geodesic distance + f on manifolds).
double plain_dijkstra_seconds(const MedialComplex& mc, double h) {
  const auto start = std::chrono::steady_clock::now();
  const SteinerGraph g(mc, h, 500'000'000);
  std::vector<double> dist(g.node_count(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (std::isfinite(mc.ignition_at_vertex(v))) q.push({dist[v] = mc.ignition_at_vertex(v), v});
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Border)
      for (std::uint32_t i = 1; i <= g.steiner_count(e); ++i) {
        const double f = mc.ignition_on_edge(e, g.parameter(e, i));
        if (std::isfinite(f)) q.push({dist[g.steiner_node(e, i)] = f, g.steiner_node(e, i)});
      }
  while (!q.empty()) {
    const auto [d, u] = q.top();
    q.pop();
    if (d > dist[u]) continue;
    g.for_each_move(u, [&](std::uint32_t y, std::uint32_t, double len) {
      if (d + len < dist[y]) q.push({dist[y] = d + len, y});
    });
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Case {
  std::string name;
  std::function<RawComplex()> build;
  double edge;  // typical edge length
};

void run_case(const Case& c, double h) {
  int fd[2];
  if (pipe(fd) != 0) return;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const RawComplex raw = c.build();
    const auto t0 = std::chrono::steady_clock::now();
    const MedialComplex mc(raw);
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const DiscreteBurning d = burn_discrete(mc, {h, 500'000'000});
    const double plain = plain_dijkstra_seconds(mc, h);
    char buf[512];
    const int n = std::snprintf(buf, sizeof buf, "%s,%zu,%.4f,%.6g,%llu,%llu,%llu,%.4f,%.4f,%.2f,%ld,%.2f\n",
                                c.name.c_str(), mc.triangle_count(), build, h, static_cast<unsigned long long>(d.stats.steiner_points),
                                static_cast<unsigned long long>(d.stats.steiner_points + mc.vertex_count()),
                                static_cast<unsigned long long>(d.stats.pushes), d.stats.seconds, plain,
                                d.stats.seconds / plain, peak_memory_kb(), bench::machine_load());
    if (write(fd[1], buf, static_cast<std::size_t>(n)) != n) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  char buf[512];
  const ssize_t n = read(fd[0], buf, sizeof buf - 1);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (n > 0) {
    buf[n] = 0;
    std::fputs(buf, stdout);
    std::fflush(stdout);
  } else {
    std::printf("%s,failed,%.6g\n", c.name.c_str(), h);
  }
}

constexpr const char* kUsage =
    "usage: bench_burn3d_discrete [--quick]\nthe discrete burning baseline on complexes of 10^3 .. 10^5 triangles at two Steiner spacings, against a plain multi-source Dijkstra on the same Steiner graph (no link rule: what the junction bookkeeping costs).\n(CSV columns and details: the header of experiments/bench_burn3d_discrete.cpp)\n";

int run(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::vector<Case> cases;
  for (int g : quick ? std::vector<int>{1, 4} : std::vector<int>{1, 4, 13})
    cases.push_back({"board-fin g=" + std::to_string(g), [g] { return board_fin({10, g}); }, 1.0 / g});
  for (int g : quick ? std::vector<int>{2, 6} : std::vector<int>{2, 6, 18})
    cases.push_back({"book k=5 g=" + std::to_string(g), [g] { return book({5, {}, 0, g}); }, 1.0 / g});
  for (int n : quick ? std::vector<int>{6, 20} : std::vector<int>{6, 20, 60})
    cases.push_back({"box 7:4:3 n=" + std::to_string(n), [n] { return box_medial_axis(7, 4, 3, n); }, 4.0 / n});
  std::printf("complex,triangles,complex_build_seconds,spacing,steiner_points,graph_points,pushes,seconds,plain_dijkstra_seconds,ratio,"
              "peak_memory_kb,load\n");
  for (const Case& c : cases)
    for (double h : {c.edge, c.edge / 2}) run_case(c, h);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_burn3d_discrete", kUsage, run);
}
