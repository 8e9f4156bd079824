// curve_distance.cpp -- Hausdorff distance between curve graphs (see header).
#include "curves3/curve_distance.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "geometry3/vec3.h"

namespace grassfire {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SegmentList = std::vector<K::Segment_3>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, SegmentList::const_iterator>>>;

K::Point_3 point(const Vec3d& p) { return {p[0], p[1], p[2]}; }

// B's edges as segments (a graph without edges: its nodes, as segments of length 0) in an
// AABB tree: the nearest point in O(log |B|) per query, whatever the spread of the points
// (the uniform grid it replaces scanned up to 33^3 cells per query and all of B past them:
// the curve study's axis point sets took hours).
class SegmentIndex {
 public:
  explicit SegmentIndex(const MedialCurves& b) {
    for (const CurveEdge& e : b.edges) segments_.push_back({point(b.nodes[e.u].position), point(b.nodes[e.v].position)});
    if (b.edges.empty())
      for (const CurveNode& n : b.nodes) segments_.push_back({point(n.position), point(n.position)});
    tree_.emplace(segments_.begin(), segments_.end());
    tree_->accelerate_distance_queries();
  }

  double nearest(const Vec3d& p) const { return std::sqrt(CGAL::to_double(tree_->squared_distance(point(p)))); }

 private:
  SegmentList segments_;
  std::optional<SegmentTree> tree_;
};

}  // namespace

double directed_curve_distance(const MedialCurves& a, const MedialCurves& b, double step) {
  if (a.nodes.empty() || b.nodes.empty() || !(step > 0))
    throw std::invalid_argument("curve distance: both graphs need a node, and step > 0");
  const SegmentIndex index(b);
  double worst = 0;
  for (const CurveNode& n : a.nodes) worst = std::max(worst, index.nearest(n.position));
  for (const CurveEdge& e : a.edges) {
    const Vec3d p = a.nodes[e.u].position, q = a.nodes[e.v].position;
    const int n = static_cast<int>(std::ceil(e.length / step));
    for (int i = 1; i < n; ++i) worst = std::max(worst, index.nearest(v3::lerp(p, q, static_cast<double>(i) / n)));
  }
  return worst;
}

double curve_hausdorff(const MedialCurves& a, const MedialCurves& b, double step) {
  return std::max(directed_curve_distance(a, b, step), directed_curve_distance(b, a, step));
}

}  // namespace grassfire
