// test_mesh_axis_support.h -- what the mesh axis tests share: Betti numbers printed by
// Catch, and the project's meshes (data/meshes) by name.
#pragma once

#include <catch2/catch.hpp>

#include <string>

#include "complex3/simplicial_homology.h"
#include "geometry3/triangle_mesh.h"
#include "io/mesh_io.h"

namespace Catch {
template <>
struct StringMaker<grassfire::BettiNumbers> {
  static std::string convert(const grassfire::BettiNumbers& b) { return grassfire::betti_text(b); }
};
}  // namespace Catch

namespace grassfire::testing {

inline TriangleMesh3 project_mesh(const std::string& name) {
  return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name);
}

}  // namespace grassfire::testing
