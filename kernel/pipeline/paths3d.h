// paths3d.h -- burning paths on a 3D medial axis (5.1.2, Fig. 5.2), with the JSON
// `grassfire paths3d --json` writes.
//
// Computes what `grassfire paths3d` computes and what the Python module's grassfire.paths3d
// returns (both call paths3d() below): the complex and burning field an input names
// (pipeline/burn3d_field.h), then the burning paths (curves3/burning_paths.h) of every vertex
// ("vertices"), of every node of the medial curves ("curves"; the curves are validated
// first), the paths that end on the curves ("ends": at a node on an edge of the axis, one per
// arriving side), or of given points ("points"), each located exactly at its nearest point of
// the complex (complex3/point_location.h); and the document (format grassfire-paths3d,
// io/curves_export.h).
// Contract: `from` is one of the four; points are given exactly when from = "points" and
// are not empty (std::invalid_argument otherwise, before any work).
// Complexity: the field's, plus O(points) located points and the paths' lengths.
// Section: 5.1.2.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "curves3/burning_paths.h"
#include "io/point_csv.h"
#include "pipeline/burn3d_field.h"

namespace grassfire {

struct Paths3dSetup {
  FieldSetup field;
  std::string from = "ends";
  std::vector<CsvPoint> points;  // from = "points"
  std::string points_name;       // names them in messages
};

struct Paths3dRun {
  FieldRun field;
  std::vector<BurningPath> paths;
  double farthest = 0;  // from = "points": the largest distance from a point to the complex
  nlohmann::json json;
};

Paths3dRun paths3d(const Paths3dSetup& setup);

}  // namespace grassfire
