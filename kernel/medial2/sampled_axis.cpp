// sampled_axis.cpp -- see sampled_axis.h. The only 2D translation unit with CGAL headers.
#include "medial2/sampled_axis.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <chrono>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geometry2/shape_locator.h"
#include "medial2/sampled_geometry.h"
#include "medial2/union_find.h"

namespace grassfire {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
constexpr std::uint32_t kNone = 0xffffffffu;


bool overlaps(const IntervalPoint2& a, const IntervalPoint2& b) {
  return !(a.x.hi < b.x.lo || b.x.hi < a.x.lo || a.y.hi < b.y.lo || b.y.hi < a.y.lo);
}

Interval interval_distance(const IntervalPoint2& a, const IntervalPoint2& b) {
  return sqrt(square(a.x - b.x) + square(a.y - b.y));
}

class SampledAxisBuilder {
 public:
  SampledAxisBuilder(const Shape2& shape, const std::vector<std::vector<Point2>>& samples) : shape_(shape) {
    for (std::uint32_t r = 0; r < samples.size(); ++r) {
      ring_start_.push_back(static_cast<std::uint32_t>(points_.size()));
      for (const Point2& p : samples[r]) {
        points_.push_back(p);
        ring_of_.push_back(r);
      }
    }
    ring_start_.push_back(static_cast<std::uint32_t>(points_.size()));
  }

  MedialGraph build(SampledAxisReport& report) {
    const auto t0 = std::chrono::steady_clock::now();
    triangulate();
    const auto t1 = std::chrono::steady_clock::now();
    number_faces();
    merge_cocircular(report);
    MedialGraph g = assemble(report);

    const auto t2 = std::chrono::steady_clock::now();
    report.samples = points_.size();
    report.delaunay_triangles = faces_.size();
    report.delaunay_seconds = std::chrono::duration<double>(t1 - t0).count();
    report.axis_seconds = std::chrono::duration<double>(t2 - t1).count();
    return g;
  }

 private:
  void triangulate() {
    std::vector<std::pair<K::Point_2, std::uint32_t>> input;
    input.reserve(points_.size());
    for (std::uint32_t i = 0; i < points_.size(); ++i) input.emplace_back(K::Point_2(points_[i].x, points_[i].y), i);
    dt_.insert(input.begin(), input.end());
    if (dt_.number_of_vertices() != points_.size())
      throw std::invalid_argument(shape_.name + ": boundary samples are not pairwise distinct (" +
                                  std::to_string(points_.size() - dt_.number_of_vertices()) + " duplicates)");
    if (dt_.dimension() < 2) throw std::invalid_argument(shape_.name + ": boundary samples are collinear");
  }

  // Copies the triangulation into flat arrays (triangles, neighbours, circumcircles) and
  // releases it: everything after this reads only the arrays.
  void number_faces() {
    std::uint32_t count = 0;
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f)
      f->info() = dt_.is_infinite(f) ? kNone : count++;
    faces_.reserve(count);
    neighbours_.reserve(count);
    centers_.reserve(count);
    radii_.reserve(count);
    for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
      const std::array<std::uint32_t, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      faces_.push_back(t);
      neighbours_.push_back({f->neighbor(0)->info(), f->neighbor(1)->info(), f->neighbor(2)->info()});
      const Circle circle = interval_circle(points_[t[0]], points_[t[1]], points_[t[2]]);
      centers_.push_back(circle.center);
      radii_.push_back(circle.radius);
    }
    dt_.clear();
  }

  // Calls f(face, neighbour, i) once for every pair of adjacent finite triangles; i is the
  // index in `face` of the vertex opposite the shared edge.
  template <class F>
  void for_each_adjacent_pair(F&& f) const {
    for (std::uint32_t a = 0; a < faces_.size(); ++a)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t b = neighbours_[a][i];
        if (b != kNone && a < b) f(a, b, i);
      }
  }

  // Adjacent triangles with cocircular vertices share their circumcentre: one node.
  void merge_cocircular(SampledAxisReport& report) {
    groups_ = UnionFind(faces_.size());
    const auto in_circle = K().side_of_oriented_circle_2_object();
    const auto point = [&](std::uint32_t sample) { return K::Point_2(points_[sample].x, points_[sample].y); };
    for_each_adjacent_pair([&](std::uint32_t a, std::uint32_t b, int) {
      if (!overlaps(centers_[a], centers_[b])) return;
      int j = 0;
      while (neighbours_[b][j] != a) ++j;
      const auto& t = faces_[a];
      if (in_circle(point(t[0]), point(t[1]), point(t[2]), point(faces_[b][j])) == CGAL::ON_ORIENTED_BOUNDARY) {
        groups_.unite(a, b);
        ++report.merged_triangles;
      }
    });
  }

  bool consecutive_samples(std::uint32_t a, std::uint32_t b) const {
    if (ring_of_[a] != ring_of_[b]) return false;
    const std::uint32_t r = ring_of_[a], n = ring_start_[r + 1] - ring_start_[r];
    const std::uint32_t i = a - ring_start_[r], j = b - ring_start_[r];
    return (i + 1) % n == j || (j + 1) % n == i;
  }

  LazyPoint center_of(std::uint32_t face) const {
    const auto& t = faces_[face];
    return LazyPoint::circumcenter(points_[t[0]], points_[t[1]], points_[t[2]], centers_[face]);
  }

  MedialGraph assemble(SampledAxisReport& report) {
    ShapeLocator locator(shape_, faces_.size());
    std::vector<std::uint32_t> node_of(faces_.size(), kNone);
    std::vector<MedialNode> nodes;
    std::vector<std::array<std::uint32_t, 3>> node_triangle;
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (groups_.find(f) != f) continue;
      if (locator.locate(center_of(f)) != BoundedSide::Inside) continue;
      node_of[f] = static_cast<std::uint32_t>(nodes.size());
      const IntervalPoint2& c = centers_[f];
      nodes.push_back({Point2{c.x.mid(), c.y.mid()}, radii_[f], std::max(c.x.radius(), c.y.radius())});
      node_triangle.push_back(faces_[f]);
    }
    std::vector<MedialEdge> edges;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
    for_each_adjacent_pair([&](std::uint32_t a, std::uint32_t b, int i) {
      const std::uint32_t ra = groups_.find(a), rb = groups_.find(b);
      if (ra == rb || node_of[ra] == kNone || node_of[rb] == kNone) return;
      if (consecutive_samples(faces_[a][(i + 1) % 3], faces_[a][(i + 2) % 3])) {
        ++report.boundary_dual_edges;
        return;
      }
      if (locator.segment_meets_boundary(center_of(ra), center_of(rb))) {
        ++report.crossing_edges;
        return;
      }
      ends.emplace_back(node_of[ra], node_of[rb]);
      edges.push_back({node_of[ra], node_of[rb], EdgeKind::Segment, interval_distance(centers_[ra], centers_[rb])});
    });
    report.inside_nodes = nodes.size();
    report.predicates = locator.counters();
    keep_largest_component(nodes, node_triangle, edges, ends, report);
    report.edges = edges.size();
    auto geometry = std::make_shared<SampledVoronoiGeometry>(points_, std::move(node_triangle), std::move(ends));
    return MedialGraph(std::move(nodes), std::move(edges), std::move(geometry));
  }

  // The shape is connected, so its medial axis is; smaller components of the Voronoi
  // graph are fragments left by undersampled sharp features. Keep the largest one.
  static void keep_largest_component(std::vector<MedialNode>& nodes, std::vector<std::array<std::uint32_t, 3>>& triangles,
                                     std::vector<MedialEdge>& edges,
                                     std::vector<std::pair<std::uint32_t, std::uint32_t>>& ends,
                                     SampledAxisReport& report) {
    UnionFind components(nodes.size());
    for (const MedialEdge& e : edges) components.unite(e.u, e.v);
    std::vector<std::uint32_t> size(nodes.size(), 0);
    for (std::uint32_t v = 0; v < nodes.size(); ++v) ++size[components.find(v)];
    std::uint32_t largest = 0;
    for (std::uint32_t v = 0; v < nodes.size(); ++v) {
      if (size[v] > size[largest]) largest = v;
      report.components += size[v] > 0 && components.find(v) == v;
    }
    if (nodes.empty() || report.components <= 1) return;
    std::vector<std::uint32_t> renumber(nodes.size(), kNone);
    std::uint32_t kept = 0;
    for (std::uint32_t v = 0; v < nodes.size(); ++v) {
      if (components.find(v) != largest) continue;
      renumber[v] = kept;
      nodes[kept] = nodes[v];
      triangles[kept] = triangles[v];
      ++kept;
    }
    report.fragment_nodes = nodes.size() - kept;
    nodes.resize(kept);
    triangles.resize(kept);
    std::size_t k = 0;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (renumber[edges[e].u] == kNone) continue;
      edges[k] = edges[e];
      edges[k].u = renumber[edges[e].u];
      edges[k].v = renumber[edges[e].v];
      ends[k] = {edges[k].u, edges[k].v};
      ++k;
    }
    edges.resize(k);
    ends.resize(k);
  }

  const Shape2& shape_;
  std::vector<Point2> points_;
  std::vector<std::uint32_t> ring_of_, ring_start_;
  Delaunay dt_;
  std::vector<std::array<std::uint32_t, 3>> faces_;       // sample ids per finite triangle
  std::vector<std::array<std::uint32_t, 3>> neighbours_;  // triangle across the edge opposite vertex i
  std::vector<IntervalPoint2> centers_;
  std::vector<Interval> radii_;
  UnionFind groups_;
};

}  // namespace

MedialGraph sampled_medial_axis(const Shape2& shape, const std::vector<std::vector<Point2>>& samples,
                                SampledAxisReport* report) {
  SampledAxisReport local;
  std::size_t total = 0;
  for (const auto& ring : samples) total += ring.size();
  if (samples.size() != shape.rings.size())
    throw std::invalid_argument(shape.name + ": one list of samples per ring is required");
  if (total < 3) throw std::invalid_argument(shape.name + ": at least 3 boundary samples are required");
  SampledAxisBuilder builder(shape, samples);
  return builder.build(report ? *report : local);
}

std::uint64_t plain_delaunay_triangle_count(const std::vector<Point2>& points) {
  std::vector<K::Point_2> input;
  input.reserve(points.size());
  for (const Point2& p : points) input.emplace_back(p.x, p.y);
  CGAL::Delaunay_triangulation_2<K> dt(input.begin(), input.end());
  return dt.number_of_faces();
}

}  // namespace grassfire
