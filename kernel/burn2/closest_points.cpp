// closest_points.cpp -- see closest_points.h.
#include "burn2/closest_points.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <stdexcept>

#include "medial2/disks/disk_union_geometry.h"
#include "medial2/polygon/polygon_axis_geometry.h"
#include "medial2/sampled/sampled_geometry.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using RPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using RValue = std::pair<RPoint, std::uint32_t>;

mpq_class squared_length(const Point2& a, const Point2& b) {
  const mpq_class dx = mpq_class(b.x) - mpq_class(a.x), dy = mpq_class(b.y) - mpq_class(a.y);
  return dx * dx + dy * dy;
}

Interval interval_sum_of_roots(const std::vector<mpq_class>& squares, std::size_t begin, std::size_t end) {
  Interval s(0.0);
  for (std::size_t i = begin; i < end; ++i) s += sqrt(enclose(squares[i]));
  return s;
}

IntervalPoint2 point_enclosure(const Point2& p) { return {Interval(p.x), Interval(p.y)}; }

// ---- sampled axis ---------------------------------------------------------------------

class SampledClosest {
 public:
  SampledClosest(const MedialGraph& g, const SampledVoronoiGeometry& geo, const Shape2& shape,
                 const BoundarySamples& samples)
      : g_(g), geo_(geo) {
    for (std::uint32_t r = 0; r < samples.size(); ++r) {
      for (std::uint32_t k = 0; k < samples[r].size(); ++k) where_.push_back({r, k});
      out_.ring_samples.push_back(static_cast<std::uint32_t>(samples[r].size()));
      const std::vector<Point2>& p = shape.rings.at(r).points;
      std::vector<mpq_class> edges;
      for (std::size_t i = 0; i < p.size(); ++i) edges.push_back(squared_length(p[i], p[(i + 1) % p.size()]));
      out_.ring_length.push_back(interval_sum_of_roots(edges, 0, edges.size()));
      out_.ring_edges.push_back(std::move(edges));
    }
    if (where_.size() != geo.samples().size())
      throw std::invalid_argument("closest points: the samples are not those the axis was built from");
    std::vector<RValue> values;
    for (std::uint32_t i = 0; i < geo.samples().size(); ++i)
      values.emplace_back(RPoint(geo.samples()[i].x, geo.samples()[i].y), i);
    tree_ = Tree(values.begin(), values.end());
    out_.node.assign(g.node_count(), {});
    out_.edge.assign(g.edge_count(), {});
  }

  ClosestPoints run() {
    std::vector<std::vector<std::uint32_t>> group(g_.node_count());
    for (std::uint32_t n = 0; n < g_.node_count(); ++n) {
      group[n] = cocircular_samples(n);
      for (std::uint32_t s : group[n]) out_.node[n].push_back(point(s));
    }
    for (std::uint32_t e = 0; e < g_.edge_count(); ++e) {
      std::vector<std::uint32_t> common;
      const auto &a = group[g_.edge(e).u], &b = group[g_.edge(e).v];
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
      if (common.size() != 2)
        throw std::logic_error("closest points: edge " + std::to_string(e) + " has " + std::to_string(common.size()) +
                               " common samples at its ends, not 2");
      out_.edge[e] = {point(common[0]), point(common[1]), point(common[0]), point(common[1])};
    }
    return std::move(out_);
  }

 private:
  using Tree = bgi::rtree<RValue, bgi::quadratic<16>>;

  BoundaryPoint point(std::uint32_t global) const {
    const auto [r, k] = where_[global];
    BoundaryPoint p;
    p.ring = r;
    p.sample = k;
    p.arc = Interval(static_cast<double>(k)) * out_.ring_length[r] / Interval(static_cast<double>(out_.ring_samples[r]));
    p.position = point_enclosure(geo_.samples()[global]);
    return p;
  }

  // The samples on the node's empty circle: the nearest samples to its centre at exactly
  // distance R. The query grows until a sample certainly farther than R is returned.
  std::vector<std::uint32_t> cocircular_samples(std::uint32_t n) const {
    const std::array<std::uint32_t, 3>& t = geo_.node_triangle(n);
    const std::vector<Point2>& s = geo_.samples();
    const ExactPoint2 o = exact_circumcenter(s[t[0]], s[t[1]], s[t[2]]);
    auto squared = [&](std::uint32_t i) -> mpq_class {
      const mpq_class dx = mpq_class(s[i].x) - o.x, dy = mpq_class(s[i].y) - o.y;
      return dx * dx + dy * dy;
    };
    const mpq_class r2 = squared(t[0]);
    const RPoint centre(g_.node(n).position.x, g_.node(n).position.y);
    const double margin = g_.node(n).radius.hi * (1 + 1e-9) + 4 * g_.node(n).position_error;
    for (unsigned k = 8;; k *= 2) {
      std::vector<RValue> near;
      tree_.query(bgi::nearest(centre, k), std::back_inserter(near));
      std::vector<std::uint32_t> on;
      double farthest = 0;
      for (const RValue& v : near) {
        farthest = std::max(farthest, bg::distance(centre, v.first));
        if (squared(v.second) == r2) on.push_back(v.second);
      }
      if (farthest > margin || near.size() < k) {
        std::sort(on.begin(), on.end());
        if (on.size() < 3) throw std::logic_error("closest points: node " + std::to_string(n) + " has < 3 samples");
        return on;
      }
    }
  }

  const MedialGraph& g_;
  const SampledVoronoiGeometry& geo_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> where_;  // global sample -> (ring, index)
  Tree tree_;
  ClosestPoints out_;
};

// ---- exact polygon axis ------------------------------------------------------------------

class PolygonClosest {
 public:
  PolygonClosest(const MedialGraph& g, const PolygonAxisGeometry& geo) : g_(g), geo_(geo), s_(geo.sites()) {
    const mpq_class scale2 = geo.to_input() * geo.to_input();
    ring_of_.assign(s_.vertex_count(), 0);
    local_.assign(s_.vertex_count(), 0);
    for (std::uint32_t first = 0; first < s_.vertex_count();) {
      const std::uint32_t r = static_cast<std::uint32_t>(out_.ring_edges.size());
      std::vector<mpq_class> edges;
      std::uint32_t v = first, k = 0;
      do {
        ring_of_[v] = r;
        local_[v] = k++;
        edges.push_back(squared_length(s_.vertex[v], s_.vertex[s_.next[v]]) * scale2);
        v = s_.next[v];
      } while (v != first);
      std::vector<Interval> prefix{Interval(0.0)};
      for (const mpq_class& e : edges) prefix.push_back(prefix.back() + sqrt(enclose(e)));
      out_.ring_length.push_back(prefix.back());
      prefix_.push_back(std::move(prefix));
      out_.ring_edges.push_back(std::move(edges));
      first += k;
    }
    out_.node.assign(g.node_count(), {});
    out_.edge.assign(g.edge_count(), {});
  }

  ClosestPoints run() {
    for (std::uint32_t n = 0; n < g_.node_count(); ++n)
      for (std::uint32_t site : geo_.node_data(n).sites) out_.node[n].push_back(foot(site, n));
    for (std::uint32_t e = 0; e < g_.edge_count(); ++e) {
      const AxisEdgeData& d = geo_.edge_data(e);
      out_.edge[e] = {foot(d.site_a, g_.edge(e).u), foot(d.site_b, g_.edge(e).u), foot(d.site_a, g_.edge(e).v),
                      foot(d.site_b, g_.edge(e).v)};
    }
    return std::move(out_);
  }

 private:
  // The closest point of site `site` to node n: the vertex of a point site, the
  // perpendicular foot on a segment site (t = (X - a).(b - a) / |b - a|^2 in the frame).
  BoundaryPoint foot(std::uint32_t site, std::uint32_t n) const {
    const mpq_class& to_input = geo_.to_input();
    const Interval scale = enclose(to_input);
    const std::uint32_t a = s_.is_point(site) ? site : s_.seg_start(site);
    BoundaryPoint p;
    p.ring = ring_of_[a];
    p.vertex = local_[a];
    const Point2 pa = s_.vertex[a];
    if (s_.is_point(site)) {
      p.offset = ExactSum();
      p.arc = prefix_[p.ring][p.vertex];
      p.position = {Interval(pa.x) * scale, Interval(pa.y) * scale};
      return p;
    }
    const Point2 pb = s_.vertex[s_.seg_end(site)];
    const CircleValue<Interval> c = solve_interval(s_, geo_.node_data(n).circle);
    const Interval ex(pb.x - pa.x), ey(pb.y - pa.y);  // exact: frame coordinates are exact doubles
    const mpq_class len2 = squared_length(pa, pb);
    const Interval t = ((c.x - Interval(pa.x)) * ex + (c.y - Interval(pa.y)) * ey) / enclose(len2);
    p.arc = prefix_[p.ring][p.vertex] + t * sqrt(enclose(len2)) * scale;
    p.position = {(Interval(pa.x) + t * ex) * scale, (Interval(pa.y) + t * ey) * scale};
    if (const auto& exact = geo_.exact_circle(n)) {
      // offset = (X - a).(b - a) / |b - a| = (X - a).(b - a) sqrt(len2) / len2.
      ExactSum dx = exact->x - ExactSum::rational(pa.x), dy = exact->y - ExactSum::rational(pa.y);
      const ExactSum dot = dx.scale(mpq_class(pb.x) - mpq_class(pa.x)) + dy.scale(mpq_class(pb.y) - mpq_class(pa.y));
      ExactSum offset = multiply(dot, ExactSum::sqrt_of(len2));
      p.offset = offset.scale(to_input / len2);
    }
    return p;
  }

  const MedialGraph& g_;
  const PolygonAxisGeometry& geo_;
  const PolygonSites& s_;
  std::vector<std::uint32_t> ring_of_, local_;
  std::vector<std::vector<Interval>> prefix_;
  ClosestPoints out_;
};

// ---- union of disks: corners only ----------------------------------------------------------

ClosestPoints disk_union_closest(const MedialGraph& g, const DiskUnionGeometry& geo) {
  ClosestPoints out;
  out.has_arc_length = false;
  auto corner = [&](std::uint32_t c) {
    BoundaryPoint p;
    p.position = geo.corners()[c].approx;
    return p;
  };
  out.node.resize(g.node_count());
  for (std::uint32_t n = 0; n < g.node_count(); ++n)
    for (std::uint32_t c : geo.node_data(n).corners) out.node[n].push_back(corner(c));
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const UnionEdgeData& d = geo.edge_data(e);
    out.edge.push_back({corner(d.a), corner(d.b), corner(d.a), corner(d.b)});
  }
  return out;
}

}  // namespace

ExactSum ClosestPoints::exact_ring_length(std::uint32_t ring) const {
  ExactSum l;
  for (const mpq_class& e : ring_edges[ring]) l += ExactSum::sqrt_of(e);
  return l;
}

std::optional<ExactSum> ClosestPoints::exact_arc_difference(const BoundaryPoint& p, const BoundaryPoint& q) const {
  if (p.sample != kNoSample) {
    ExactSum d = exact_ring_length(p.ring);
    return d.scale(make_rational(mpz_class(p.sample) - mpz_class(q.sample), ring_samples[p.ring]));
  }
  if (!p.offset || !q.offset) return std::nullopt;
  ExactSum d = *p.offset - *q.offset;
  const std::uint32_t lo = std::min(p.vertex, q.vertex), hi = std::max(p.vertex, q.vertex);
  ExactSum between;
  for (std::uint32_t i = lo; i < hi; ++i) between += ExactSum::sqrt_of(ring_edges[p.ring][i]);
  if (p.vertex >= q.vertex)
    d += between;
  else
    d -= between;
  return d;
}

ClosestPoints closest_points(const MedialGraph& g, const Shape2* shape, const BoundarySamples* samples) {
  if (const auto* s = dynamic_cast<const SampledVoronoiGeometry*>(&g.geometry())) {
    if (!shape || !samples) throw std::invalid_argument("closest points of a sampled axis need its shape and samples");
    return SampledClosest(g, *s, *shape, *samples).run();
  }
  if (const auto* p = dynamic_cast<const PolygonAxisGeometry*>(&g.geometry())) return PolygonClosest(g, *p).run();
  if (const auto* d = dynamic_cast<const DiskUnionGeometry*>(&g.geometry())) return disk_union_closest(g, *d);
  throw std::invalid_argument("closest points: the graph's geometry (" + g.geometry().description() +
                              ") knows no boundary");
}

}  // namespace grassfire
