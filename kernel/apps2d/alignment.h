// alignment.h -- translational alignment of planar shapes by a centre point (3.5.2,
// Fig. 3.8), and the overlap that judges it.
//
// Computes:
//  - the candidate centres of a shape: the area centroid (the usual first step of
//    alignment), the centre of its bounding box (what a [0,1]^2 normalisation aligns), the
//    EMA point of the exact polygon axis (3.5.2: stable under isometric deformations), and
//    the maximum of the potential residue PR (3.4.2, Fig. 3.8 blue dots; burn2/potential_
//    residue.h on the same axis);
//  - the shift that moves a shape's centre onto another's;
//  - polygon_overlap: areas of intersection and union of two shapes, the second translated
//    by a shift, and their ratio IoU. This is exact: CGAL's Boolean set operations on
//    polygons with holes over exact constructions (Epeck), the shift applied exactly to the
//    double coordinates; only the final areas and ratio are rounded to double.
// Exactness: the overlap is exact (above). The centroid is the shoelace formula in double
// precision; the EMA point and the PR maximum are the double positions of certified
// points (inside a parabolic arc placed by MedialGeometry::point_along, a double drawing
// routine): centres are measurements, not decisions.
// Contract: validated shapes (geometry2/shape2.h); the burning was computed on the exact
// polygon axis of the same shape. A shape with holes has an EMA made of cycles and no EMA
// point, and PR is infinite between rings: those centres are then absent.
// Complexity: centres O(n) after the axis; overlap O((n + k) log n) for n vertices and k
// intersections (CGAL sweep).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "shapes/resample.h"
#include "geometry2/shape2.h"

namespace grassfire {

enum class AlignmentMethod { Centroid, BoundingBox, Ema, PrMaximum };
const char* to_string(AlignmentMethod m);
const std::vector<AlignmentMethod>& all_alignment_methods();

struct ShapeCentres {
  Point2 centroid;
  Point2 bounding_box;
  std::optional<Point2> ema;          // absent when the EMA is a set of cycles
  std::optional<Point2> pr_maximum;   // absent when PR is infinite (holes)
  std::optional<Point2> get(AlignmentMethod m) const;
};

// Area centroid of the shape (outer ring minus holes).
Point2 area_centroid(const Shape2& shape);
Point2 bounding_box_centre(const Shape2& shape);

// Centroid, bounding box, EMA point (the EMA of the largest component of the axis) and PR
// maximum. The axis is an exact polygon axis or a sampled axis (then `samples` are its
// boundary samples, needed for the closest points).
ShapeCentres shape_centres(const Shape2& shape, const MedialGraph& axis, const GrassfireResult& burning,
                           const BoundarySamples* samples = nullptr);

struct Overlap {
  double area_a = 0, area_b = 0;
  double intersection = 0, union_area = 0;
  double iou = 0;  // intersection / union, rounded once from the exact ratio
};

// Overlap of a and (b translated by shift), exactly (see the header comment).
Overlap polygon_overlap(const Shape2& a, const Shape2& b, const Point2& shift);

// The shift that moves b's centre onto a's centre for the method; nullopt when either
// shape lacks that centre.
std::optional<Point2> alignment_shift(const ShapeCentres& a, const ShapeCentres& b, AlignmentMethod m);

}  // namespace grassfire
