// validate_shape.cpp -- see validate_shape.h.
#include "shapes/validate_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>

#include "shapes/edge_grid.h"

namespace grassfire {

namespace {

std::string message(const std::string& source, long ring, const std::string& problem) {
  return source + ": " + (ring >= 0 ? ring_label(static_cast<std::size_t>(ring)) + ": " : std::string()) + problem;
}

std::string format_point(const Point2& p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g)", p.x, p.y);
  return buf;
}

// The rings with their repeated vertices dropped; input[r][k] is the given position of
// vertex k of ring r.
struct WorkingShape {
  std::vector<Ring> rings;
  std::vector<std::vector<std::size_t>> input;
};

void add_without_repeated_vertices(const Ring& ring, WorkingShape& w) {
  std::vector<Point2> points;
  std::vector<std::size_t> input;
  for (std::size_t i = 0; i < ring.points.size(); ++i) {
    if (!points.empty() && ring.points[i] == points.back()) continue;
    points.push_back(ring.points[i]);
    input.push_back(i);
  }
  while (points.size() > 1 && points.back() == points.front()) {
    points.pop_back();
    input.pop_back();
  }
  w.rings.push_back({std::move(points)});
  w.input.push_back(std::move(input));
}

// Stages 1 and 2 of the header.
WorkingShape prepare_rings(const Shape2& shape, const std::string& source) {
  if (shape.rings.empty()) throw InvalidShapeError(source, -1, -1, "the shape has no rings (empty input)");
  for (std::size_t r = 0; r < shape.rings.size(); ++r)
    for (std::size_t i = 0; i < shape.rings[r].points.size(); ++i) {
      const Point2& p = shape.rings[r].points[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InvalidShapeError(source, static_cast<long>(r), static_cast<long>(i),
                                "vertex " + std::to_string(i) + " has a non-finite coordinate " + format_point(p));
    }
  WorkingShape w;
  for (std::size_t r = 0; r < shape.rings.size(); ++r) {
    add_without_repeated_vertices(shape.rings[r], w);
    const std::size_t n = w.rings.back().points.size();
    if (n < 3)
      throw InvalidShapeError(source, static_cast<long>(r), n == 0 ? -1 : 0,
                              "only " + std::to_string(n) + " distinct vertices (a ring needs at least 3)");
  }
  return w;
}

// An edge named by its ring and the given positions of its endpoints: (ring, lo, hi).
using EdgeKey = std::tuple<std::uint32_t, std::size_t, std::size_t>;

struct PairProblem {
  EdgeKey first, second;  // first < second
  std::uint32_t ring1, edge1, ring2, edge2;
  SegmentIntersection kind;
  bool adjacent;  // consecutive edges of one ring
};

// Stage 3: judges candidate pairs and keeps the first offence.
class PairJudge {
 public:
  PairJudge(const WorkingShape& shape, OrientationStats* stats) : shape_(shape), stats_(stats) {}

  void judge(std::uint32_t r1, std::uint32_t e1, std::uint32_t r2, std::uint32_t e2) {
    ++pairs_;
    const Point2 &p0 = point(r1, e1), &p1 = point(r1, e1 + 1), &q0 = point(r2, e2), &q1 = point(r2, e2 + 1);
    const SegmentIntersection kind = classify_segments(p0, p1, q0, q1, stats_);
    const bool adjacent = r1 == r2 && (next(r1, e1) == e2 || next(r2, e2) == e1);
    if (kind == SegmentIntersection::Disjoint || (adjacent && kind != SegmentIntersection::Overlap)) return;
    PairProblem p{key(r1, e1), key(r2, e2), r1, e1, r2, e2, kind, adjacent};
    if (p.second < p.first) {
      std::swap(p.first, p.second);
      std::swap(p.ring1, p.ring2);
      std::swap(p.edge1, p.edge2);
    }
    if (!worst_ || std::tie(p.first, p.second) < std::tie(worst_->first, worst_->second)) worst_ = p;
  }

  std::uint64_t pairs() const { return pairs_; }
  void throw_if_any(const std::string& source) const;

 private:
  const Point2& point(std::uint32_t r, std::uint32_t k) const {
    const std::vector<Point2>& p = shape_.rings[r].points;
    return p[k % p.size()];
  }
  std::uint32_t next(std::uint32_t r, std::uint32_t e) const {
    return static_cast<std::uint32_t>((e + 1) % shape_.rings[r].points.size());
  }
  std::size_t input_index(std::uint32_t r, std::uint32_t k) const {
    return shape_.input[r][k % shape_.input[r].size()];
  }
  EdgeKey key(std::uint32_t r, std::uint32_t e) const {
    const std::size_t a = input_index(r, e), b = input_index(r, e + 1);
    return {r, std::min(a, b), std::max(a, b)};
  }
  std::string edge_name(std::uint32_t r, std::uint32_t e) const {
    return std::to_string(input_index(r, e)) + "-" + std::to_string(input_index(r, e + 1));
  }
  Point2 meeting_point(const PairProblem& p) const;

  const WorkingShape& shape_;
  OrientationStats* stats_;
  std::uint64_t pairs_ = 0;
  std::optional<PairProblem> worst_;
};

// A common point of the two edges, rounded, for the message only.
Point2 PairJudge::meeting_point(const PairProblem& p) const {
  const Point2 &p0 = point(p.ring1, p.edge1), &p1 = point(p.ring1, p.edge1 + 1);
  const Point2 &q0 = point(p.ring2, p.edge2), &q1 = point(p.ring2, p.edge2 + 1);
  if (p.kind == SegmentIntersection::Crossing) {
    const double dx = p1.x - p0.x, dy = p1.y - p0.y, ex = q1.x - q0.x, ey = q1.y - q0.y;
    const double t = ((q0.x - p0.x) * ey - (q0.y - p0.y) * ex) / (dx * ey - dy * ex);
    return {p0.x + t * dx, p0.y + t * dy};
  }
  for (const Point2* c : {&q0, &q1})
    if (on_segment(*c, p0, p1)) return *c;
  return on_segment(p0, q0, q1) ? p0 : p1;
}

void PairJudge::throw_if_any(const std::string& source) const {
  if (!worst_) return;
  const PairProblem& p = *worst_;
  const long ring = static_cast<long>(p.ring1);
  const long vertex = static_cast<long>(std::get<1>(p.first));
  if (p.adjacent) {
    const std::uint32_t before = next(p.ring1, p.edge1) == p.edge2 ? p.edge1 : p.edge2;
    const std::uint32_t after = before == p.edge1 ? p.edge2 : p.edge1;
    throw InvalidShapeError(source, ring, vertex,
                            "spike at vertex " + std::to_string(input_index(p.ring1, after)) + ": edges " +
                                edge_name(p.ring1, before) + " and " + edge_name(p.ring1, after) +
                                " overlap (the boundary doubles back on itself)");
  }
  const char* verb = p.kind == SegmentIntersection::Crossing ? "crosses"
                     : p.kind == SegmentIntersection::Touching ? "touches"
                                                               : "overlaps";
  const std::string other = p.ring1 == p.ring2 ? "edge " + edge_name(p.ring2, p.edge2)
                                               : "edge " + edge_name(p.ring2, p.edge2) + " of " + ring_label(p.ring2);
  throw InvalidShapeError(source, ring, vertex,
                          "edge " + edge_name(p.ring1, p.edge1) + " " + verb + " " + other + " at about " +
                              format_point(meeting_point(p)));
}

// Stage 4. `inside(j)` gives, for hole j's vertex 0, whether it lies inside each ring.
template <class InsideOf>
void check_nesting(const WorkingShape& w, const std::string& source, InsideOf inside) {
  for (std::size_t j = 1; j < w.rings.size(); ++j) {
    const std::vector<bool> in = inside(j);
    const long v = static_cast<long>(w.input[j][0]);
    const std::string vertex = "vertex " + std::to_string(v);
    if (!in[0])
      throw InvalidShapeError(source, static_cast<long>(j), v,
                              "lies outside the outer ring (" + vertex + " is outside ring 0)");
    for (std::size_t k = 1; k < w.rings.size(); ++k)
      if (k != j && in[k])
        throw InvalidShapeError(source, static_cast<long>(j), v,
                                "lies inside " + ring_label(k) + "; holes must not nest (" + vertex +
                                    " is inside ring " + std::to_string(k) + ")");
  }
}

void check_pairs_and_nesting(const WorkingShape& w, const std::string& source, PairSearch search,
                             ShapeValidation& report) {
  OrientationStats* stats = &report.predicates;
  const std::vector<Ring>& rings = w.rings;
  PairJudge judge(w, stats);
  if (search == PairSearch::Grid) {
    const EdgeGrid grid(rings, stats);
    grid.for_each_candidate_pair([&](std::uint32_t g1, std::uint32_t g2) {
      const EdgeGrid::EdgeId a = grid.edge(g1), b = grid.edge(g2);
      judge.judge(a.ring, a.index, b.ring, b.index);
    });
    judge.throw_if_any(source);
    check_nesting(w, source, [&](std::size_t j) {
      std::vector<long> winding(rings.size(), 0);
      grid.add_ray_windings(rings[j].points[0], static_cast<std::uint32_t>(j), winding, stats);
      std::vector<bool> in(rings.size());
      for (std::size_t k = 0; k < rings.size(); ++k) in[k] = winding[k] != 0;
      return in;
    });
  } else {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t r = 0; r < rings.size(); ++r)
      for (std::uint32_t e = 0; e < rings[r].points.size(); ++e) edges.emplace_back(r, e);
    for (std::size_t a = 0; a < edges.size(); ++a)
      for (std::size_t b = a + 1; b < edges.size(); ++b)
        judge.judge(edges[a].first, edges[a].second, edges[b].first, edges[b].second);
    judge.throw_if_any(source);
    check_nesting(w, source, [&](std::size_t j) {
      std::vector<bool> in(rings.size(), false);
      for (std::size_t k = 0; k < rings.size(); ++k)
        if (k != j) in[k] = locate_in_ring(rings[j].points[0], rings[k].points, stats) == BoundedSide::Inside;
      return in;
    });
  }
  report.candidate_pairs = judge.pairs();
}

// Orientation of a simple ring: the turn at its lexicographically smallest vertex, which is
// convex and (no spikes) not collinear with its neighbours.
int ring_orientation(const std::vector<Point2>& p, OrientationStats* stats) {
  const std::size_t n = p.size();
  const std::size_t m = static_cast<std::size_t>(
      std::min_element(p.begin(), p.end(),
                       [](const Point2& a, const Point2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }) -
      p.begin());
  return orientation(p[(m + n - 1) % n], p[m], p[(m + 1) % n], stats);
}

}  // namespace

InvalidShapeError::InvalidShapeError(const std::string& source, long ring, long vertex, const std::string& problem)
    : std::runtime_error(message(source, ring, problem)), source_(source), ring_(ring), vertex_(vertex),
      problem_(problem) {}

std::string ring_label(std::size_t ring) {
  return "ring " + std::to_string(ring) + (ring == 0 ? " (outer)" : " (hole)");
}

ShapeValidation validate_shape(Shape2& shape, const std::string& source, PairSearch search) {
  ShapeValidation report;
  WorkingShape w = prepare_rings(shape, source);
  check_pairs_and_nesting(w, source, search, report);
  for (std::size_t r = 0; r < w.rings.size(); ++r) {
    std::vector<Point2>& p = w.rings[r].points;
    const int wanted = r == 0 ? 1 : -1;
    const bool reverse = ring_orientation(p, &report.predicates) != wanted;
    if (reverse) std::reverse(p.begin() + 1, p.end());
    report.rings.push_back({shape.rings[r].points.size(), p.size(), reverse});
  }
  shape.rings = std::move(w.rings);
  return report;
}

Interval signed_area(const Ring& ring) {
  const std::vector<Point2>& p = ring.points;
  if (p.size() < 3) return Interval(0.0);
  // Shoelace about vertex 0, which keeps the products small for shapes far from the origin.
  Interval twice(0.0);
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Interval ax = Interval(p[i].x) - p[0].x, ay = Interval(p[i].y) - p[0].y;
    const Interval bx = Interval(p[i + 1].x) - p[0].x, by = Interval(p[i + 1].y) - p[0].y;
    twice += ax * by - ay * bx;
  }
  return half(twice);
}

}  // namespace grassfire
