// alignment_overlap.cpp -- polygon_overlap of alignment.h: exact areas of intersection and
// union by CGAL's Boolean set operations (the only file of apps2d with CGAL headers).
// GCC 12 reports a false -Warray-bounds inside CGAL's Arr_polyline_traits_2, which the
// Boolean set operations instantiate; nothing of ours is involved.
#pragma GCC diagnostic ignored "-Warray-bounds"
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <iterator>
#include <list>
#include <stdexcept>

#include "apps2d/alignment.h"

namespace grassfire {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

// The ring translated by the shift, exactly (FT sums of the doubles' exact values).
Polygon exact_ring(const Ring& r, const FT& dx, const FT& dy) {
  Polygon p;
  for (const Point2& q : r.points) p.push_back(K::Point_2(FT(q.x) + dx, FT(q.y) + dy));
  return p;
}

PolygonWithHoles exact_shape(const Shape2& s, const Point2& shift) {
  if (s.rings.empty()) throw std::invalid_argument("polygon_overlap: the shape '" + s.name + "' is empty");
  const FT dx(shift.x), dy(shift.y);
  Polygon outer = exact_ring(s.rings[0], dx, dy);
  // Validated shapes are counter-clockwise outside and clockwise inside (shape2.h), the
  // orientation CGAL's Boolean operations expect.
  PolygonWithHoles p(outer);
  for (std::size_t i = 1; i < s.rings.size(); ++i) p.add_hole(exact_ring(s.rings[i], dx, dy));
  return p;
}

FT area(const PolygonWithHoles& p) {
  FT a = p.outer_boundary().area();
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += h->area();  // holes are clockwise: negative
  return a;
}

// The double nearest to the exact value: forcing the exact computation tightens the lazy
// number's interval approximation to the exact value, which to_double then rounds (the
// interval of a long lazy computation can otherwise be as wide as 1e-7).
double rounded(const FT& x) {
  CGAL::exact(x);
  return CGAL::to_double(x);
}

}  // namespace

Overlap polygon_overlap(const Shape2& a, const Shape2& b, const Point2& shift) {
  const PolygonWithHoles pa = exact_shape(a, {0, 0}), pb = exact_shape(b, shift);
  std::list<PolygonWithHoles> parts;
  CGAL::intersection(pa, pb, std::back_inserter(parts));
  FT inter(0);
  for (const PolygonWithHoles& p : parts) inter += area(p);
  const FT area_a = area(pa), area_b = area(pb), uni = area_a + area_b - inter;
  Overlap o;
  o.area_a = rounded(area_a);
  o.area_b = rounded(area_b);
  o.intersection = rounded(inter);
  o.union_area = rounded(uni);
  o.iou = rounded(inter / uni);
  return o;
}

}  // namespace grassfire
