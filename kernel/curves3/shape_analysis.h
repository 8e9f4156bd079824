// shape_analysis.h -- tubular and planar parts of a 3D medial axis, a signature, and the
// burning mapped onto the shape's surface (5.3, Figs. 5.4-5.5).
//
// Computes, on the refinement K of the medial curves (axis_refinement.h, medial_curves.h):
//  - the split (our threshold rule for 5.3's "large burning time: planar, small: tubular",
//    measured against the thickness R): a triangle of K is PLANAR when its shape
//    tubularity ST = 1 - R / BT (the 2D measure of 3.5.1 carried to 3D, with BT in place of
//    the EDF) at its centroid is at least `planar_tubularity` (default 1/2: ET = BT - R >=
//    R, the sheet reaches at least one ball radius beyond the ball in its widest direction),
//    else TUBULAR (such a sheet is a ribbon no wider than its balls: the part is a tube, and
//    the medial curves represent it); BT = infinity counts as planar; R = BT = 0 as
//    planar (zero-radius complexes are all sheet);
//  - the signature: the areas of the planar parts (connected sets of planar triangles of
//    K sharing edges; the medial sheets of the mixed-dimensional axis) and the lengths of
//    the tubular branches of the medial curves (chains of curve edges whose midpoints have
//    ST below the threshold, or that lie on a dangling segment of M -- a 1-dimensional part
//    of the axis is a tube's own axis --, cut at nodes of degree other than 2), each sorted
//    descending,
//    and their totals;
//  - the surface values (Fig. 5.5): each surface point p takes BT, ET and R of the axis
//    sample x (a vertex of K with finite BT) minimising |p - x| - R(x): the medial ball
//    that touches p (0 on an exact axis), `gap` the minimum itself.
// Contract: `k` is the refinement the curves were built on (medial_curves with a given K).
// Complexity: O(|K|) for the split and signature; O(surface points x axis samples) for
// the surface values (a brute-force search, with a bound on R to skip far samples).
#pragma once

#include <vector>

#include "curves3/axis_refinement.h"
#include "curves3/medial_curves.h"

namespace grassfire {

struct ShapeAnalysisOptions {
  double planar_tubularity = 0.5;
};

struct ShapeSignature {
  double planar_area = 0, tubular_area = 0;
  double tubular_curve_length = 0, planar_curve_length = 0;
  std::vector<double> sheet_areas;    // planar parts, descending
  std::vector<double> curve_lengths;  // tubular branches of the curves, descending
};

struct ShapeAnalysis {
  std::vector<bool> planar;           // per triangle of K
  std::vector<double> tubularity;     // ST per triangle of K
  std::vector<bool> tubular_edge;     // per edge of the curve graph
  ShapeSignature signature;
};

ShapeAnalysis analyze_shape(const AxisRefinement& k, const MedialCurves& curves, const ShapeAnalysisOptions& options = {});

struct SurfaceValues {
  std::vector<double> bt, et, radius, gap;  // per surface point
};
SurfaceValues map_to_surface(const AxisRefinement& k, const std::vector<Vec3d>& surface_points);

}  // namespace grassfire
