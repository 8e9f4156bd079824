// study_exact_axis_throughput -- the exact polygon axis plus the extended grassfire on
// every shape of a folder (e.g. the 979 shapes of the 2D Shape Structure dataset).
//
// For each *.json / *.wkt file: load and validate the shape (io/load_shape.h), build
// the exact axis (medial2/polygon/polygon_axis.h), run the extended grassfire; with --validate
// also the definition-level check (medial2/polygon/polygon_axis_validate.h).
// Output (stdout): one CSV row per shape, sorted: file,construction,vertices,nodes,edges,
// parabolic_arcs,contracted,uncertified_contractions,uncertified_ties,ball_refinements,
// axis_s,edf_s,valid,error (uncertified_ties: comparisons of the burning that no stage
// could prove, docs/design.md 3); then a summary line on stderr: shapes, failures, total
// seconds, the uncertified counts and how many shapes have any.
// --shard I/N runs every N-th shape (experiments/shard.h); --progress / --quiet as the program.
// Usage: study_exact_axis_throughput FOLDER [--validate] [--shard I/N] [--progress|--quiet]
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "support/progress.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/polygon_axis_validate.h"
#include "io/load_shape.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {

struct Totals {
  int failures = 0;
  double seconds = 0;
  std::uint64_t contractions = 0, ties = 0, shapes_with_any = 0;  // uncertified
};

std::string run_shape(const std::filesystem::path& f, bool validate, Totals& totals) {
  char row[1024];
  try {
    const Shape2 s = load_shape(f.string());
    auto t0 = std::chrono::steady_clock::now();
    PolygonAxisReport rep;
    const MedialGraph g = exact_polygon_axis(s, {}, &rep);
    auto t1 = std::chrono::steady_clock::now();
    const GrassfireResult r = extended_grassfire(g);
    auto t2 = std::chrono::steady_clock::now();
    const double axis_s = std::chrono::duration<double>(t1 - t0).count();
    const double edf_s = std::chrono::duration<double>(t2 - t1).count();
    totals.seconds += axis_s + edf_s;
    std::string valid = "not-run";
    if (validate) {
      const AxisValidation v = validate_polygon_axis(g);
      valid = v.ok() ? "yes" : "no: " + v.failures.front();
      totals.failures += !v.ok();
    }
    const std::uint64_t ties = r.stats().uncertified_zero;
    totals.contractions += rep.uncertified_contractions;
    totals.ties += ties;
    totals.shapes_with_any += rep.uncertified_contractions + ties > 0;
    std::snprintf(row, sizeof row, "%s,%s,%llu,%u,%u,%llu,%llu,%llu,%llu,%llu,%.5f,%.5f,\"%s\",",
                  f.filename().c_str(), to_string(rep.construction), (unsigned long long)rep.polygon_vertices,
                  g.node_count(), g.edge_count(), (unsigned long long)rep.parabolic_arcs,
                  (unsigned long long)rep.contracted_edges, (unsigned long long)rep.uncertified_contractions,
                  (unsigned long long)ties, (unsigned long long)rep.ball_refinements, axis_s, edf_s, valid.c_str());
  } catch (const std::exception& e) {
    ++totals.failures;
    std::snprintf(row, sizeof row, "%s,,,,,,,,,,,,,\"%s\"", f.filename().c_str(), e.what());
  }
  return row;
}

constexpr const char* kUsage =
    "usage: study_exact_axis_throughput FOLDER [--validate] [--shard I/N] [--progress|--quiet]\nthe exact polygon axis plus the extended grassfire on every shape of a folder (e.g. the 979 shapes of the 2D Shape Structure dataset).\n(CSV columns and details: the header of experiments/study_exact_axis_throughput.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{"--validate"}, {}, 1, 1});
  const experiments::Shard shard = cmd.shard;
  const bool validate = cmd.flag("--validate");
  const std::vector<std::filesystem::path> files =
      experiments::shard_of(experiments::folder_files(cmd.positional[0], {".json", ".wkt"}), shard);
  Totals totals;
  std::vector<std::string> rows;
  Progress progress("study_exact_axis_throughput " + shard.label(), files.size());
  for (const auto& f : files) {
    progress.item(f.filename().string());
    rows.push_back(run_shape(f, validate, totals));
    progress.advance();
  }
  progress.done();
  experiments::write_sorted_csv(std::cout,
                                "file,construction,vertices,nodes,edges,parabolic_arcs,contracted,"
                                "uncertified_contractions,uncertified_ties,ball_refinements,axis_s,edf_s,valid,error",
                                rows);
  if (notes_enabled())
    std::fprintf(stderr,
                 "shapes %zu, failures %d, total axis+edf seconds %.3f, uncertified contractions %llu and ties %llu "
                 "in %llu shapes\n",
                 files.size(), totals.failures, totals.seconds, (unsigned long long)totals.contractions,
                 (unsigned long long)totals.ties, (unsigned long long)totals.shapes_with_any);
  return totals.failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_exact_axis_throughput", kUsage, run);
}
