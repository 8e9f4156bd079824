// alignment.cpp -- see alignment.h. The exact overlap is in alignment_overlap.cpp (CGAL).
#include "apps2d/alignment.h"

#include <algorithm>
#include <stdexcept>

#include "apps2d/axis_correspondence.h"
#include "burn2/potential_residue.h"

namespace grassfire {

const char* to_string(AlignmentMethod m) {
  switch (m) {
    case AlignmentMethod::Centroid: return "centroid";
    case AlignmentMethod::BoundingBox: return "bounding-box";
    case AlignmentMethod::Ema: return "ema";
    case AlignmentMethod::PrMaximum: return "pr-maximum";
  }
  return "unknown";
}

const std::vector<AlignmentMethod>& all_alignment_methods() {
  static const std::vector<AlignmentMethod> k{AlignmentMethod::Centroid, AlignmentMethod::BoundingBox,
                                              AlignmentMethod::Ema, AlignmentMethod::PrMaximum};
  return k;
}

std::optional<Point2> ShapeCentres::get(AlignmentMethod m) const {
  switch (m) {
    case AlignmentMethod::Centroid: return centroid;
    case AlignmentMethod::BoundingBox: return bounding_box;
    case AlignmentMethod::Ema: return ema;
    case AlignmentMethod::PrMaximum: return pr_maximum;
  }
  return std::nullopt;
}

Point2 area_centroid(const Shape2& shape) {
  // Signed shoelace sums: holes are clockwise, so they subtract themselves.
  double a = 0, cx = 0, cy = 0;
  for (const Ring& r : shape.rings) {
    const std::size_t n = r.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& p = r.points[i];
      const Point2& q = r.points[(i + 1) % n];
      const double c = p.x * q.y - q.x * p.y;
      a += c;
      cx += (p.x + q.x) * c;
      cy += (p.y + q.y) * c;
    }
  }
  if (a == 0) throw std::invalid_argument("area_centroid: the shape '" + shape.name + "' has zero area");
  return {cx / (3 * a), cy / (3 * a)};
}

Point2 bounding_box_centre(const Shape2& shape) {
  if (shape.rings.empty() || shape.rings[0].points.empty())
    throw std::invalid_argument("bounding_box_centre: the shape '" + shape.name + "' is empty");
  const auto& p = shape.rings[0].points;
  auto [xmin, xmax] = std::minmax_element(p.begin(), p.end(), [](const Point2& u, const Point2& v) { return u.x < v.x; });
  auto [ymin, ymax] = std::minmax_element(p.begin(), p.end(), [](const Point2& u, const Point2& v) { return u.y < v.y; });
  return {0.5 * (xmin->x + xmax->x), 0.5 * (ymin->y + ymax->y)};
}

ShapeCentres shape_centres(const Shape2& shape, const MedialGraph& axis, const GrassfireResult& burning,
                           const BoundarySamples* samples) {
  ShapeCentres c;
  c.centroid = area_centroid(shape);
  c.bounding_box = bounding_box_centre(shape);
  Point2 e;
  if (ema_position(axis, burning, &e)) c.ema = e;
  const PotentialResidue pr = potential_residue(axis, closest_points(axis, &shape, samples));
  if (!pr.maximum.value.value.is_infinite()) c.pr_maximum = pr.maximum.position;
  return c;
}

std::optional<Point2> alignment_shift(const ShapeCentres& a, const ShapeCentres& b, AlignmentMethod m) {
  const std::optional<Point2> ca = a.get(m), cb = b.get(m);
  if (!ca || !cb) return std::nullopt;
  return Point2{ca->x - cb->x, ca->y - cb->y};
}

}  // namespace grassfire
