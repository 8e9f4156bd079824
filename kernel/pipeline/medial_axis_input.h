// medial_axis_input.h -- from an input file to the medial axis of the 3D shape it describes.
//
// Computes: the RawComplex of the medial axis of
//  - a convex polyhedron: a convex mesh (.off, .ply, .obj) or a half-space list (.hs,
//    .halfspaces; convex_polyhedron_axis.h) -- exact, or certified approximate mode;
//  - a union of balls: a ball list (.cin, .balls; union_of_balls_axis.h) -- exact
//    combinatorics, rational or certified approximate vertices;
//  - a closed mesh: the inner Voronoi axis of surface samples, refined until its Betti
//    numbers are the solid's (mesh_axis.h) -- an approximation with exact vertices;
// and a JSON report of what was computed (counts, exactness and error bounds, timings,
// Betti numbers of the shape and of the axis where known; for meshes "mesh_input": what the
// reader welded and dropped, geometry3/mesh_weld.h, "repairs" its one-line summary; with
// repair.enabled, "repair": what mesh_repair.h found and did, "summary" its one line, and
// the axis is that of the repaired solid). Kind Auto
// picks by extension; for a mesh it takes the convex builder when the mesh is convex, else the mesh axis builder.
// Contract: errors are exceptions whose message names the file and the problem (readers:
// ComplexFormatError; geometry: std::invalid_argument); nothing is written here.
// Complexity: that of the builder used.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_repair.h"
#include "complex3/raw_complex.h"

namespace grassfire {

enum class MedialInputKind { Auto, Convex, Balls, Mesh };

// "auto", "convex", "balls", "mesh" (std::invalid_argument otherwise).
MedialInputKind parse_medial_input_kind(const std::string& name);

struct MedialAxisBuild {
  RawComplex complex;
  std::string kind;  // the builder used: "convex", "balls" or "mesh"
  nlohmann::json report;
};

// `mesh_options`: for closed meshes (mesh_axis.h); `repair`: for defective meshes
// (mesh_repair.h; without it a defective mesh is refused with the --repair hint).
MedialAxisBuild build_medial_axis(const std::string& path, MedialInputKind kind, const MeshAxisOptions& mesh_options = {},
                                  const MeshRepairOptions& repair = {});
// The mesh builder's options as `medial3d --samples S --angle DEG --refinements N
// --max-samples M` give them (the Python module's medial3d too): h = mean edge length / S,
// S in (0, 1024]; DEG in [0, 180); N in [0, 12]; M in [1000, 10^9] samples a round;
// std::invalid_argument with the program's message otherwise.
MeshAxisOptions medial3d_mesh_options(double samples, double angle_degrees, long refinements,
                                      long max_samples = 2000000);

}  // namespace grassfire
