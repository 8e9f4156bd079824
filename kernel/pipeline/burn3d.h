// burn3d.h -- the 3D burning pipeline: input -> medial complex -> burning time BT, ET = BT - R,
// at the complex's vertices and at query points, with optional point sources.
//
// Computes what `grassfire burn3d` computes and what the Python module's grassfire.burn3d
// returns (both call burn3d() below, so the two agree): the complex an input names
// (pipeline/complex_input.h), optionally without border ignition; the point sources
// (x,y,z,t0), each located exactly on the complex (complex3/point_location.h; a source
// off the complex by at most the rounding of its coordinates to doubles, sqrt(3) 2^-52 times
// the largest magnitude among them and its nearest point's, is moved to that nearest point
// with a note giving the distance, counted in "sources_within_rounding"; one farther off is
// an error); the queries (x,y,z), each located at its nearest point of
// the complex; the burning time by a method of the table (pipeline/burn3d_methods.h) at
// the spacing `grassfire burn3d` chooses; and the report `burn3d --json` writes:
//   {"input", "method", "spacing" (discrete only), "complex": {vertices, edges, triangles,
//    segments, border_edges, singular_edges, singular_points, sheets}, "sources",
//    "sources_within_rounding", "queries" (counts), "stats": {the method's counters}, "summary": {burned_vertices,
//    unburned_vertices, max_bt, max_et}, "vertex_values": {"x", "y", "z", "R", "BT", "ET",
//    "BT_error" (methods with a certified two-sided bound: exact)}}
// with null for BT, ET and BT_error where nothing burns.
// Order of the checks (the program's messages depend on it): the method name, the
// complex, the spacing, the sources, the queries. Progress on stderr follows support/progress.h.
// Contract: errors are exceptions whose message names the input and the problem
// (std::invalid_argument for a bad method or spacing); nothing is returned then.
// Complexity: that of the builder (for shapes), O(cells) per located point plus exact
// evaluations (point_location.h), and the method's.
// Section: ch. 4 (Definitions 9-10), docs/design.md 5.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "medial3/mesh/mesh_repair.h"
#include "complex3/medial_complex.h"
#include "io/point_csv.h"
#include "pipeline/burn3d_methods.h"

namespace grassfire {

// Points given as rows, or read from a CSV file (io/point_csv.h) when `file` is set.
// `name` names the rows in messages ("<name>:<line>: ..."); for a file, its path.
struct BurnPoints {
  std::optional<std::string> file;
  std::string name;
  std::vector<CsvPoint> rows;
};

struct Burn3dSetup {
  std::string input;                // load_complex's INPUT
  std::string method = "discrete";  // burn_method's name
  bool mesh_is_complex = false;     // burn a mesh itself (R = 0)
  MeshRepairOptions repair;         // a defective mesh's repair before its axis (load_complex)
  bool no_border_ignition = false;  // every border rule Never: only the sources burn
  bool singular_walls = false;      // exact: singular edges as walls (BurnRequest)
  std::optional<double> spacing;    // discrete: Steiner spacing h; none: default_burn_spacing
  std::uint64_t max_points = 50'000'000;
  BurnPoints sources;               // x,y,z,t0
  BurnPoints queries;               // x,y,z
};

struct Burn3dRun {
  std::unique_ptr<MedialComplex> mc;  // validated
  std::vector<PointSource> sources;
  std::size_t rounded_sources = 0;    // sources off the complex by no more than their rounding, moved onto it
  std::vector<CsvPoint> query_rows;   // as given or read (the program echoes their text)
  std::vector<ComplexPoint> queries;  // located, in query order
  double spacing = 0.0;
  BurnOutcome outcome;
  std::vector<double> et;             // per vertex: BT - R (+inf where nothing burns)
  nlohmann::json report;              // the --json report
};

// 1/100 of the diagonal of the complex's bounding box (1 for a single point).
double default_burn_spacing(const MedialComplex& mc);

Burn3dRun burn3d(const Burn3dSetup& setup);

}  // namespace grassfire
