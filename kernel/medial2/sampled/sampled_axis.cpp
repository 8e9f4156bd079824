// sampled_axis.cpp -- see sampled_axis.h. The only 2D translation unit with CGAL headers.
#include "medial2/sampled/sampled_axis.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry2/shape_locator.h"
#include "support/cpu_clock.h"
#include "medial2/sampled/sampled_geometry.h"
#include "support/union_find.h"

namespace grassfire {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
constexpr std::uint32_t kNone = 0xffffffffu;       // a face whose circumcentre is not inside
constexpr std::uint32_t kUnvisited = 0xfffffffeu;  // a face the pass has not reached yet

// Face info: the candidate id of a face, born unvisited (CGAL constructs every face).
struct FaceTag {
  std::uint32_t id = kUnvisited;
};
using Fb = CGAL::Triangulation_face_base_with_info_2<FaceTag, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;

// Two adjacent candidates a < b, and whether their shared Delaunay edge joins
// consecutive samples of one ring (rule (a) of the header).
struct Adjacency {
  std::uint32_t a, b;
  bool boundary_dual;
};

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
    report.samples = points_.size();  // before assemble() moves the points into the geometry
    const double t0 = thread_seconds();
    triangulate();
    const double t1 = thread_seconds();
    locate_circumcentres(report);
    dt_.clear();
    const double t2 = thread_seconds();
    merge_cocircular(report);
    collect_edges(report);
    const double t3 = thread_seconds();
    MedialGraph g = assemble(report);
    const double t4 = thread_seconds();
    report.delaunay_seconds = t1 - t0;
    report.locate_seconds = t2 - t1;
    report.edges_seconds = t3 - t2;
    report.graph_seconds = t4 - t3;
    report.axis_seconds = t4 - t1;
    return g;
  }

 private:
  // Insertion order: a biased randomised insertion order (BRIO, Amenta, Choi and Rote
  // 2003) with the rounds in boundary order. Each sample draws a round from a fixed hash
  // of its id (round k >= 1 with probability 3 / 4^(k+1), as in CGAL's multiscale spatial
  // sort; the round-0 samples, about 3/4, go last); the rounds are inserted from the
  // smallest, each in the samples' order along their rings, each insertion hinted by the
  // previous vertex. The randomness of the rounds is what bounds the expected work; inside
  // a round, the boundary order already keeps consecutive insertions close, which is what
  // CGAL's spatial sort (a Hilbert sort of every round) buys at the cost of sorting.
  void triangulate() {
    const std::uint32_t n = static_cast<std::uint32_t>(points_.size());
    constexpr int kRounds = 24;
    std::vector<std::uint8_t> round(n);
    std::array<std::uint32_t, kRounds + 1> start{};
    for (std::uint32_t i = 0; i < n; ++i) {
      std::uint64_t h = (i + 1) * 0x9e3779b97f4a7c15ull;  // splitmix64 finaliser
      h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
      h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
      h ^= h >> 31;
      const int r = std::min(kRounds - 1, h == 0 ? kRounds : __builtin_ctzll(h) / 2);
      round[i] = static_cast<std::uint8_t>(r);
      ++start[kRounds - 1 - r + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[start[kRounds - 1 - round[i]]++] = i;
    Delaunay::Face_handle hint;
    for (const std::uint32_t i : order) {
      const Delaunay::Vertex_handle v = dt_.insert(K::Point_2(points_[i].x, points_[i].y), hint);
      v->info() = i;
      hint = v->face();
    }
    if (dt_.number_of_vertices() != points_.size())
      throw std::invalid_argument(shape_.name + ": boundary samples are not pairwise distinct (" +
                                  std::to_string(points_.size() - dt_.number_of_vertices()) + " duplicates)");
    if (dt_.dimension() < 2) throw std::invalid_argument(shape_.name + ": boundary samples are collinear");
  }

  // One pass over the finite triangles, in the triangulation's own storage (no copy):
  // the circumcircle's enclosure, then the centre's side of the shape boundary, from the
  // locator's empty cells where possible (no exact arithmetic), exactly otherwise.
  // Triangles with the centre strictly inside become candidates, numbered in storage
  // order (face info); the others get kNone. A candidate's neighbours that the pass has
  // already numbered are its adjacent candidates with smaller ids: every adjacent pair is
  // found once, with the neighbour's info read once (the memory traffic of this stage),
  // and pairs with overlapping centres get CGAL's exact in-circle test for cocircularity.
  void locate_circumcentres(SampledAxisReport& report) {
    locator_ = std::make_unique<ShapeLocator>(shape_, dt_.number_of_faces());
    const ShapeLocator& locator = *locator_;
    const auto in_circle = K().side_of_oriented_circle_2_object();
    auto infinite = dt_.incident_faces(dt_.infinite_vertex()), done = infinite;
    do {
      infinite->info().id = kNone;
    } while (++infinite != done);
    triangles_.reserve(dt_.number_of_faces());
    circles_.reserve(dt_.number_of_faces());
    adjacent_.reserve(dt_.number_of_faces());
    // The faces are visited in storage order; their vertices and neighbours are scattered
    // in memory. So the vertices' data and the neighbours' infos of the face kAhead places
    // further are prefetched (the addresses of the members themselves: a 56-byte face or a
    // 32-byte vertex often straddles two cache lines), and the circles of the already
    // numbered neighbours of the face kAhead / 2 places further (their infos are in cache
    // by then).
    constexpr int kAhead = 16;
    auto ahead = dt_.all_faces_begin(), half = ahead;
    for (int k = 0; k < kAhead && ahead != dt_.all_faces_end(); ++k) {
      ++ahead;
      if (k < kAhead / 2) ++half;
    }
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
      if (ahead != dt_.all_faces_end()) {
        for (int i = 0; i < 3; ++i) {
          __builtin_prefetch(&ahead->vertex(i)->point());
          __builtin_prefetch(&ahead->vertex(i)->info());
          __builtin_prefetch(&ahead->neighbor(i)->info());
        }
        ++ahead;
      }
      if (half != dt_.all_faces_end()) {
        for (int i = 0; i < 3; ++i) {
          const std::uint32_t a = half->neighbor(i)->info().id;
          if (a < circles_.size()) {
            __builtin_prefetch(&circles_[a].center.x);
            __builtin_prefetch(&circles_[a].center.y.hi);
          }
        }
        ++half;
      }
      if (dt_.is_infinite(f)) continue;
      ++report.delaunay_triangles;
      const std::array<std::uint32_t, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      const std::array<Point2, 3> x{point_of(f->vertex(0)), point_of(f->vertex(1)), point_of(f->vertex(2))};
      const Circle circle = interval_circle(x[0], x[1], x[2]);
      std::optional<BoundedSide> side = locator.locate_in_empty_cell(circle.center);
      if (!side) {
        side = locator.locate(LazyPoint::circumcenter(x[0], x[1], x[2], circle.center));
        ++report.exact_locations;
      }
      if (*side != BoundedSide::Inside) {
        f->info().id = kNone;
        continue;
      }
      const std::uint32_t b = static_cast<std::uint32_t>(triangles_.size());
      f->info().id = b;
      triangles_.push_back(t);
      circles_.push_back(circle);
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = f->neighbor(i)->info().id;
        if (a >= kUnvisited) continue;
        adjacent_.push_back({a, b, consecutive_samples(t[Delaunay::ccw(i)], t[Delaunay::cw(i)])});
        if (overlaps(circles_[a].center, circle.center) &&
            in_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                      dt_.mirror_vertex(f, i)->point()) == CGAL::ON_ORIENTED_BOUNDARY)
          cocircular_.emplace_back(a, b);
      }
    }
  }

  // Adjacent triangles with cocircular vertices share their circumcentre: one node.
  void merge_cocircular(SampledAxisReport& report) {
    groups_ = UnionFind(triangles_.size());
    for (const auto& [a, b] : cocircular_) groups_.unite(a, b);
    report.merged_triangles = cocircular_.size();
  }

  static Point2 point_of(Delaunay::Vertex_handle v) { return {v->point().x(), v->point().y()}; }

  bool consecutive_samples(std::uint32_t a, std::uint32_t b) const {
    if (ring_of_[a] != ring_of_[b]) return false;
    const std::uint32_t r = ring_of_[a], n = ring_start_[r + 1] - ring_start_[r];
    const std::uint32_t i = a - ring_start_[r], j = b - ring_start_[r];
    return (i + 1) % n == j || (j + 1) % n == i;
  }

  LazyPoint center_of(std::uint32_t candidate) const {
    const auto& t = triangles_[candidate];
    return LazyPoint::circumcenter(points_[t[0]], points_[t[1]], points_[t[2]], circles_[candidate].center);
  }

  // The Voronoi edges between candidates of different groups, by the rules of the header.
  void collect_edges(SampledAxisReport& report) {
    // The circles are read at random: those of the pair kAhead places further are
    // prefetched (at the candidates themselves, which are almost always their groups').
    constexpr std::size_t kAhead = 8;
    for (std::size_t k = 0; k < adjacent_.size(); ++k) {
      if (k + kAhead < adjacent_.size()) {
        __builtin_prefetch(&circles_[adjacent_[k + kAhead].a]);
        __builtin_prefetch(&circles_[adjacent_[k + kAhead].b]);
      }
      const Adjacency& p = adjacent_[k];
      const std::uint32_t ra = groups_.find(p.a), rb = groups_.find(p.b);
      if (ra == rb) continue;
      if (p.boundary_dual) {
        ++report.boundary_dual_edges;
        continue;
      }
      std::optional<bool> meets = locator_->segment_meets_boundary_in_empty_cells(circles_[ra].center, circles_[rb].center);
      if (!meets) meets = locator_->segment_meets_boundary(center_of(ra), center_of(rb));
      if (*meets) {
        ++report.crossing_edges;
        continue;
      }
      ends_.emplace_back(ra, rb);
    }
    adjacent_ = {};
    report.predicates = locator_->counters();
  }

  // Nodes are the group representatives (the smallest candidate of each group), ordered
  // by the smallest sample id of their triangle, ties in candidate order; edges by their
  // smaller end, ties in the order of collect_edges (two stable counting sorts). Samples
  // are numbered along the boundary, so consecutive nodes of a chain of the axis mostly
  // get consecutive numbers and the walks along the graph downstream (chains, fronts,
  // components) read memory in order; in candidate order (the triangulation's storage
  // order) they read it at random. Then the largest component (keep_largest_component).
  MedialGraph assemble(SampledAxisReport& report) {
    auto key = [&](std::uint32_t a) { return std::min({triangles_[a][0], triangles_[a][1], triangles_[a][2]}); };
    std::vector<std::uint32_t> start(points_.size() + 1, 0);
    for (std::uint32_t a = 0; a < triangles_.size(); ++a)
      if (groups_.find(a) == a) ++start[key(a) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    const std::size_t n = start.back();
    std::vector<std::uint32_t> node_of(triangles_.size(), kNone);
    std::vector<std::uint32_t> candidate(n);
    std::vector<MedialNode> nodes(n);
    std::vector<std::array<std::uint32_t, 3>> node_triangle(n);
    for (std::uint32_t a = 0; a < triangles_.size(); ++a) {
      if (groups_.find(a) != a) continue;
      const std::uint32_t v = start[key(a)]++;
      node_of[a] = v;
      candidate[v] = a;
      const IntervalPoint2& c = circles_[a].center;
      nodes[v] = {Point2{c.x.mid(), c.y.mid()}, circles_[a].radius, std::max(c.x.radius(), c.y.radius())};
      node_triangle[v] = triangles_[a];
    }
    start.assign(n + 1, 0);
    for (auto& [a, b] : ends_) ++start[std::min(node_of[a], node_of[b]) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<MedialEdge> edges(ends_.size());
    for (std::size_t k = 0; k < ends_.size(); ++k) {
      if (k + 8 < ends_.size()) {  // random reads, as in collect_edges
        __builtin_prefetch(&circles_[ends_[k + 8].first]);
        __builtin_prefetch(&circles_[ends_[k + 8].second]);
      }
      const auto [a, b] = ends_[k];
      edges[start[std::min(node_of[a], node_of[b])]++] = {
          node_of[a], node_of[b], EdgeKind::Segment, interval_distance(circles_[a].center, circles_[b].center)};
    }
    for (std::size_t k = 0; k < edges.size(); ++k) ends_[k] = {edges[k].u, edges[k].v};
    report.inside_nodes = nodes.size();
    keep_largest_component(nodes, node_triangle, candidate, edges, ends_, report);
    report.edges = edges.size();
    auto geometry = std::make_shared<SampledVoronoiGeometry>(std::move(points_), std::move(node_triangle), std::move(ends_));
    return MedialGraph(std::move(nodes), std::move(edges), std::move(geometry));
  }

  // The shape is connected, so its medial axis is; smaller components of the Voronoi
  // graph are fragments left by undersampled sharp features. Keep the largest one; of
  // equally large ones, the one with the smallest candidate (`candidate`: per node).
  static void keep_largest_component(std::vector<MedialNode>& nodes, std::vector<std::array<std::uint32_t, 3>>& triangles,
                                     const std::vector<std::uint32_t>& candidate, std::vector<MedialEdge>& edges,
                                     std::vector<std::pair<std::uint32_t, std::uint32_t>>& ends,
                                     SampledAxisReport& report) {
    UnionFind components(nodes.size());
    for (const MedialEdge& e : edges) components.unite(e.u, e.v);
    std::vector<std::uint32_t> size(nodes.size(), 0), smallest(nodes.size(), kNone);
    for (std::uint32_t v = 0; v < nodes.size(); ++v) {
      const std::uint32_t r = components.find(v);
      ++size[r];
      smallest[r] = std::min(smallest[r], candidate[v]);
    }
    std::uint32_t largest = 0;
    for (std::uint32_t v = 0; v < nodes.size(); ++v) {
      if (size[v] > size[largest] || (size[v] == size[largest] && smallest[v] < smallest[largest])) largest = v;
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
  std::unique_ptr<ShapeLocator> locator_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;  // per candidate: its sample ids
  std::vector<Circle> circles_;                          // per candidate: its circumcircle
  std::vector<Adjacency> adjacent_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cocircular_, ends_;
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
