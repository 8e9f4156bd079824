// curves3d.h -- medial curves of a 3D medial axis (5.1.2) and the planar / tubular split
// (5.3), with the JSON `grassfire curves3d --json` writes.
//
// Computes what `grassfire curves3d` computes and what the Python module's
// grassfire.curves3d returns (both call curves3d() below): the complex and burning field an
// input names (pipeline/burn3d_field.h), the refinement K at the field's resolution
// (curves3/axis_refinement.h), the medial curves (curves3/medial_curves.h), validated (a graph
// in the axis with the axis' b0 and b1, by simplicial homology), the shape analysis
// (curves3/shape_analysis.h) and the document (format grassfire-curves3d, io/curves_export.h)
// with its "analysis" member.
// Contract: arrive and depart cosines in [0, 1), min_et_fraction and planar_tubularity in
// [0, 1], time_margin >= 0 when given (std::invalid_argument otherwise, before any work);
// other errors are exceptions naming the input.
// Complexity: the field's, then O(K log K) for the K triangles of the refinement.
// Section: 5.1.2, 5.3.
#pragma once

#include <nlohmann/json.hpp>

#include <memory>

#include "curves3/axis_refinement.h"
#include "curves3/medial_curves.h"
#include "curves3/shape_analysis.h"
#include "pipeline/burn3d_field.h"

namespace grassfire {

struct Curves3dSetup {
  FieldSetup field;
  MedialCurveOptions curves;       // time_margin < 0: the field's resolution
  double planar_tubularity = 0.5;  // a part is planar where 1 - R / BT >= this (5.3)
};

struct Curves3dRun {
  FieldRun field;
  std::unique_ptr<AxisRefinement> refinement;
  MedialCurves curves;
  ShapeAnalysis analysis;
  nlohmann::json json;
};

Curves3dRun curves3d(const Curves3dSetup& setup);

}  // namespace grassfire
