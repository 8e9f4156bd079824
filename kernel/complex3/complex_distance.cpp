// complex_distance.cpp -- see complex_distance.h.
#include "complex3/complex_distance.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "geometry3/exact_predicates3.h"

namespace grassfire {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using TriangleList = std::vector<K::Triangle_3>;
using SegmentList = std::vector<K::Segment_3>;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriangleList::const_iterator>>>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, SegmentList::const_iterator>>>;

// |B| for nearest-point queries: its triangles, its segments and its vertices (as
// segments of length 0, so that isolated vertices count).
class ComplexDistance {
 public:
  explicit ComplexDistance(const RawComplex& b) {
    if (b.vertices.empty()) throw std::invalid_argument("complex distance: " + b.source + " has no vertex");
    for (const ExactPoint3& v : b.vertices) points_.push_back(point(v));
    for (const auto& t : b.triangles) {
      const K::Triangle_3 tri(points_[t[0]], points_[t[1]], points_[t[2]]);
      if (!tri.is_degenerate()) triangles_.push_back(tri);
    }
    for (const auto& s : b.segments) segments_.push_back({points_[s[0]], points_[s[1]]});
    for (const K::Point_3& p : points_) segments_.push_back({p, p});
    triangle_tree_.emplace(triangles_.begin(), triangles_.end());
    triangle_tree_->accelerate_distance_queries();
    segment_tree_.emplace(segments_.begin(), segments_.end());
    segment_tree_->accelerate_distance_queries();
  }

  double operator()(const K::Point_3& p) const {
    double d2 = CGAL::to_double(segment_tree_->squared_distance(p));
    if (!triangles_.empty()) d2 = std::min(d2, CGAL::to_double(triangle_tree_->squared_distance(p)));
    return std::sqrt(d2);
  }

  static K::Point_3 point(const ExactPoint3& v) {
    const auto d = to_double(v);
    return {d[0], d[1], d[2]};
  }

 private:
  std::vector<K::Point_3> points_;
  TriangleList triangles_;
  SegmentList segments_;
  std::optional<TriangleTree> triangle_tree_;
  std::optional<SegmentTree> segment_tree_;
};

// Calls visit(point, value) for the samples of A (values interpolated from vertex_value,
// or 1 when it is empty).
void sample_complex(const RawComplex& a, const std::vector<double>& vertex_value, double step,
                    const std::function<void(const K::Point_3&, double)>& visit) {
  if (!(step > 0)) throw std::invalid_argument("complex distance: the step must be positive");
  std::vector<K::Point_3> p;
  for (const ExactPoint3& v : a.vertices) p.push_back(ComplexDistance::point(v));
  auto value = [&](std::uint32_t i) { return vertex_value.empty() ? 1.0 : vertex_value[i]; };
  for (std::uint32_t i = 0; i < p.size(); ++i) visit(p[i], value(i));
  for (const auto& s : a.segments) {
    const int n = static_cast<int>(std::ceil(std::sqrt(CGAL::squared_distance(p[s[0]], p[s[1]])) / step));
    for (int k = 1; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      visit(p[s[0]] + t * (p[s[1]] - p[s[0]]), (1 - t) * value(s[0]) + t * value(s[1]));
    }
  }
  for (const auto& t : a.triangles) {
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, std::sqrt(CGAL::squared_distance(p[t[k]], p[t[(k + 1) % 3]])));
    const int n = std::max(1, static_cast<int>(std::ceil(longest / step)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        if (i == n || j == n || i + j == 0) continue;  // the corners are visited as vertices
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n, w = 1 - u - v;
        const K::Point_3 x(w * p[t[0]].x() + u * p[t[1]].x() + v * p[t[2]].x(), w * p[t[0]].y() + u * p[t[1]].y() + v * p[t[2]].y(),
                           w * p[t[0]].z() + u * p[t[1]].z() + v * p[t[2]].z());
        visit(x, w * value(t[0]) + u * value(t[1]) + v * value(t[2]));
      }
  }
}

}  // namespace

double directed_complex_distance(const RawComplex& a, const std::vector<double>& vertex_value, double at_least,
                                 const RawComplex& b, double step) {
  if (!vertex_value.empty() && vertex_value.size() != a.vertices.size())
    throw std::invalid_argument("complex distance: one value per vertex of " + a.source + " expected");
  const ComplexDistance to_b(b);
  double worst = 0;
  sample_complex(a, vertex_value, step, [&](const K::Point_3& x, double w) {
    if (w >= at_least) worst = std::max(worst, to_b(x));
  });
  return worst;
}

double directed_complex_distance(const RawComplex& a, const RawComplex& b, double step) {
  return directed_complex_distance(a, {}, 0, b, step);
}

double complex_hausdorff(const RawComplex& a, const RawComplex& b, double step) {
  return std::max(directed_complex_distance(a, b, step), directed_complex_distance(b, a, step));
}

}  // namespace grassfire
