// targets.h -- what fuzz_readers runs on each mutated input: one target per reader, the
// reader followed by the checks its result feeds (validation, not the axis builders).
//
//  mesh readers (off, ply, obj, stl): parse_triangle_mesh, then require_closed_manifold
//    and mesh_orientation (what medial3d runs before any builder);
//  balls, halfspaces, disks: the readers;
//  ma, complex_json: parse_ma / parse_complex_json, then MedialComplex (strata, links, the
//    embedding check) and validate();
//  shape_json, shape_wkt: the readers, then validate_shape;
//  with deep = true also the builders fed by the reader: union_of_balls_axis,
//  convex_polyhedron_axis, disk_union_axis, convex_polyhedron_from_mesh (slower; for
//  longer hunts, not for the documented counts).
// A target returns normally when the input is accepted and throws otherwise.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace grassfire::fuzz {

struct Target {
  std::string name;                        // e.g. "off"
  std::string extension;                   // of the source name handed to the reader
  std::vector<std::string> corpus;         // file contents, from the test data
  std::vector<std::string> corpus_files;   // their paths
  std::function<void(const std::string& bytes, const std::string& source)> run;
};

// The targets, with their corpora read from the project's tests/data and data folders.
std::vector<Target> fuzz_targets(const std::string& test_data, const std::string& project_data, bool deep);

}  // namespace grassfire::fuzz
