// mesh_pole_axis.h -- the medial axis of an in-memory closed mesh through its inner polar
// balls, as `grassfire medial3d` builds it for a mesh file (medial_axis_input.h): the
// exact axis of the union of the inner polar balls (mesh_poles.h, union_of_balls_axis.h).
// For perturbed copies of meshes (studies, figures), which exist only in memory.
// Contract and complexity: those of inner_polar_balls and union_of_balls_axis.
#pragma once

#include "complex3/raw_complex.h"
#include "complex3/triangle_mesh.h"

namespace grassfire {

RawComplex mesh_pole_axis(const TriangleMesh3& mesh, int subdivision = 1);

}  // namespace grassfire
