// Helpers shared by the test files.
#include "support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

namespace grassfire::testing {

MedialGraph integer_graph(const std::vector<long>& radii,
                          const std::vector<std::tuple<std::uint32_t, std::uint32_t, long>>& edges) {
  std::vector<Point2> positions;
  std::vector<ExactSum> r, lengths;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  for (std::size_t v = 0; v < radii.size(); ++v) {
    positions.push_back({static_cast<double>(v), 0.0});
    r.push_back(ExactSum::rational(radii[v]));
  }
  for (const auto& [u, v, w] : edges) {
    ends.emplace_back(u, v);
    lengths.push_back(ExactSum::rational(w));
  }
  MedialGraph g = MedialGraph::from_exact(positions, r, ends, lengths);
  g.validate();
  return g;
}

namespace {
mpq_class rational_of(ExactSum x) {
  x.simplify();
  REQUIRE(x.sqrt_terms().empty());
  REQUIRE(x.constant_terms().empty());
  return x.rational_part();
}
}  // namespace

mpq_class exact_value(const GrassfireResult& r, std::uint32_t node) {
  REQUIRE_FALSE(r.is_infinite(node));
  return rational_of(r.times.exact(r.burn[node]));
}

GraphSum ema_offset_sum(const GrassfireResult& r, const ExtendedMedialAxis& ema) {
  GraphSum s = GraphSum().add_length(ema.point.edge) + r.times.as_graph_sum(ema.sent_other) -
               r.times.as_graph_sum(ema.sent_from);
  return s.divide(2);
}

GraphSum ema_edf_sum(const GrassfireResult& r, const ExtendedMedialAxis& ema) {
  if (ema.point.at_node) return r.times.as_graph_sum(r.burn[ema.point.node]);
  GraphSum s = GraphSum().add_length(ema.point.edge) + r.times.as_graph_sum(ema.sent_other) +
               r.times.as_graph_sum(ema.sent_from);
  return s.divide(2);
}

mpq_class exact_ema_offset(const GrassfireResult& r, const ExtendedMedialAxis& ema) {
  return rational_of(ema_offset_sum(r, ema).exact(r.times.graph()));
}

mpq_class exact_ema_edf(const GrassfireResult& r, const ExtendedMedialAxis& ema) {
  return rational_of(ema_edf_sum(r, ema).exact(r.times.graph()));
}

void require_equal_to_definition(const MedialGraph& g, const GrassfireResult& r, const DefinitionalEdf& d) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    INFO("node " << v);
    if (!d.edf[v]) {
      REQUIRE(r.is_infinite(v));
      continue;
    }
    REQUIRE_FALSE(r.is_infinite(v));
    REQUIRE(compare(r.times.as_graph_sum(r.burn[v]), *d.edf[v], g) == 0);
  }
  REQUIRE(r.ema.size() == d.ema.size());
  for (std::size_t c = 0; c < r.ema.size(); ++c) {
    INFO("component " << c);
    const ExtendedMedialAxis& e = r.ema[c];
    const DefinitionalEma& o = d.ema[c];
    REQUIRE((e.kind == ExtendedMedialAxis::Kind::Cycles) == o.cycles);
    if (o.cycles) {
      REQUIRE(e.nodes == o.core_nodes);
      continue;
    }
    REQUIRE(o.maxima == 1);
    REQUIRE(e.point.at_node == o.at_node);
    REQUIRE(compare(ema_edf_sum(r, e), o.edf, g) == 0);
    if (o.at_node) {
      REQUIRE(e.point.node == o.node);
      continue;
    }
    REQUIRE(e.point.edge == o.edge);
    GraphSum offset = ema_offset_sum(r, e);
    if (e.point.from != o.from) offset = GraphSum().add_length(e.point.edge) - offset;
    REQUIRE(compare(offset, o.offset, g) == 0);
  }
}

CliRun run_cli(const std::string& args) {
  const std::string command = std::string(GF_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  CliRun run;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string temp_path(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("grassfire_tests_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace grassfire::testing
