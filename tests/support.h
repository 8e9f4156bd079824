// Helpers shared by the test files: hand-built graphs and exact read-outs.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <exception>
#include <string>
#include <tuple>
#include <vector>

#include "burn2/edf_definition.h"
#include "burn2/extended_grassfire.h"

namespace grassfire::testing {

// A graph with integer R per node and integer-length edges {u, v, w}; positions on a line.
MedialGraph integer_graph(const std::vector<long>& radii,
                          const std::vector<std::tuple<std::uint32_t, std::uint32_t, long>>& edges);

// The exact EDF at a node, which must be rational (fails the test otherwise).
mpq_class exact_value(const GrassfireResult& r, std::uint32_t node);
// Exact offset and EDF of an EMA point inside an edge.
mpq_class exact_ema_offset(const GrassfireResult& r, const ExtendedMedialAxis& ema);
mpq_class exact_ema_edf(const GrassfireResult& r, const ExtendedMedialAxis& ema);
GraphSum ema_offset_sum(const GrassfireResult& r, const ExtendedMedialAxis& ema);
GraphSum ema_edf_sum(const GrassfireResult& r, const ExtendedMedialAxis& ema);

// REQUIREs that the engine's EDF at every node and its EMA equal the oracle's exactly.
void require_equal_to_definition(const MedialGraph& g, const GrassfireResult& r, const DefinitionalEdf& d);

// Runs `grassfire ARGS` (the program under test); its exit code and stdout + stderr.
struct CliRun {
  int code = -1;
  std::string output;
};
CliRun run_cli(const std::string& args);

// The message of the exception f() throws, or "no error".
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

// A path in this process's own temporary folder, which no other test process uses (CTest
// runs test cases in parallel): <tmp>/grassfire_tests_<pid>/<name>, the folder created.
// Tests write nowhere else: not into the source tree, the working directory or a fixed
// temporary name.
std::string temp_path(const std::string& name);

}  // namespace grassfire::testing
