// mesh_pole_axis.cpp -- see header.
#include "complex3/builders/mesh_pole_axis.h"

#include "complex3/builders/mesh_poles.h"
#include "complex3/builders/union_of_balls_axis.h"

namespace grassfire {

RawComplex mesh_pole_axis(const TriangleMesh3& mesh, int subdivision) {
  MeshPolesOptions o;
  o.subdivision = subdivision;
  RawComplex axis = union_of_balls_axis(inner_polar_balls(mesh, o).balls).complex;
  axis.source = mesh.source;
  return axis;
}

}  // namespace grassfire
