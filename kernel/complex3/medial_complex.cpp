// medial_complex.cpp -- construction of the MedialComplex from a RawComplex (see header).
#include "complex3/medial_complex.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "complex3/complex_checks.h"
#include "complex3/complex_intersections.h"
#include "complex3/medial_complex_detail.h"

namespace grassfire {

const char* to_string(EdgeStratum s) {
  switch (s) {
    case EdgeStratum::Dangling: return "dangling";
    case EdgeStratum::Border: return "border";
    case EdgeStratum::Manifold: return "manifold";
    case EdgeStratum::Singular: return "singular";
  }
  return "?";
}

const char* to_string(VertexKind k) {
  switch (k) {
    case VertexKind::Isolated: return "isolated";
    case VertexKind::Interior: return "interior";
    case VertexKind::Border: return "border";
    case VertexKind::SegmentEnd: return "segment-end";
    case VertexKind::SegmentInterior: return "segment-interior";
    case VertexKind::SingularCurve: return "singular-curve";
    case VertexKind::SingularPoint: return "singular-point";
  }
  return "?";
}

MedialComplex::MedialComplex(const RawComplex& raw, bool check_embedding) : source_(raw.source) {
  const FilteredPoints points(raw.vertices);
  check_raw(raw, points);
  vertices_.resize(raw.vertices.size());
  for (std::size_t i = 0; i < raw.vertices.size(); ++i) {
    ComplexVertex& v = vertices_[i];
    v.exact = raw.vertices[i];
    v.approx = to_double(v.exact);
    v.radius_squared = raw.radius_squared[i];
    v.radius = std::sqrt(v.radius_squared.get_d());
  }
  build_edges(raw, points);
  build_incidences();
  order_edge_triangles(points);
  if (check_embedding)
    if (auto problem = first_improper_intersection(raw, points)) fail(*problem);
  build_sheets(points);
  build_sectors();
  classify_vertices();
  apply_ignition(raw);
  filter_counts_ = points.counts();
}

void MedialComplex::fail(const std::string& what) const {
  throw std::invalid_argument((source_.empty() ? std::string("complex") : source_) + ": " + what);
}

void MedialComplex::check_raw(const RawComplex& raw, const FilteredPoints& points) const {
  const auto radius = [&](std::size_t v) -> const mpq_class& { return raw.radius_squared[v]; };
  if (auto problem = first_raw_violation(points, radius, raw.radius_squared.size(), raw.triangles, raw.segments))
    fail(*problem);
}

// The occurrences of the edges in the cells, bucketed by their lower vertex and sorted
// within a bucket by (higher vertex, is segment, cell, corner): edges come out numbered in
// (lower, higher) order and each edge's triangles in increasing id, in linear time plus
// the sorts of the small buckets.
void MedialComplex::build_edges(const RawComplex& raw, const FilteredPoints& points) {
  struct Occurrence {
    std::uint32_t high, cell;
    std::uint8_t is_segment, corner;
    bool operator<(const Occurrence& o) const {
      return std::tie(high, is_segment, cell, corner) < std::tie(o.high, o.is_segment, o.cell, o.corner);
    }
  };
  const std::size_t n = raw.vertices.size();
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const auto& tv : raw.triangles)
    for (int i = 0; i < 3; ++i) ++start[std::min(tv[(i + 1) % 3], tv[(i + 2) % 3]) + 1];
  for (const auto& sv : raw.segments) ++start[std::min(sv[0], sv[1]) + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<Occurrence> occ(start[n]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < raw.triangles.size(); ++t) {
    const auto& tv = raw.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = tv[(i + 1) % 3], b = tv[(i + 2) % 3];
      occ[fill[std::min(a, b)]++] = {std::max(a, b), t, 0, static_cast<std::uint8_t>(i)};
    }
  }
  for (std::uint32_t s = 0; s < raw.segments.size(); ++s) {
    const auto& sv = raw.segments[s];
    occ[fill[std::min(sv[0], sv[1])]++] = {std::max(sv[0], sv[1]), s, 1, 0};
  }
  triangles_.resize(raw.triangles.size());
  for (std::uint32_t t = 0; t < raw.triangles.size(); ++t) triangles_[t].v = raw.triangles[t];
  edges_.reserve(occ.size() / 2 + 1);
  edge_triangles_.reserve(occ.size() / 2 + 1);
  for (std::uint32_t a = 0; a < n; ++a) {
    std::sort(occ.begin() + start[a], occ.begin() + start[a + 1]);
    for (std::size_t i = start[a]; i < start[a + 1];) {
      const std::uint32_t b = occ[i].high;
      std::vector<std::uint32_t> tris;
      int segments = 0;
      std::uint32_t segment_id = 0;
      for (; i < start[a + 1] && occ[i].high == b; ++i) {
        if (occ[i].is_segment) {
          ++segments;
          segment_id = occ[i].cell;
        } else {
          tris.push_back(occ[i].cell);
          triangles_[occ[i].cell].e[occ[i].corner] = static_cast<std::uint32_t>(edges_.size());
        }
      }
      add_edge(a, b, std::move(tris), segments, segment_id, points);
    }
  }
}

void MedialComplex::add_edge(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t> tris, int segments,
                             std::uint32_t segment_id, const FilteredPoints& points) {
  const auto where = [&] { return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")"; };
  if (segments > 1) fail("segment " + std::to_string(segment_id) + " repeats " + where());
  if (segments == 1 && !tris.empty())
    fail("segment " + std::to_string(segment_id) + " is also an edge of triangle " + std::to_string(tris[0]));
  const std::size_t k = tris.size();
  ComplexEdge e;
  e.v = {a, b};
  e.stratum = k == 0 ? EdgeStratum::Dangling : k == 1 ? EdgeStratum::Border : k == 2 ? EdgeStratum::Manifold : EdgeStratum::Singular;
  e.length = points.distance(a, b);
  edges_.push_back(e);
  edge_triangles_.push_back(std::move(tris));
}

// vertex_edges (by edge id) and vertex_triangles (by triangle id), each list allocated once.
void MedialComplex::build_incidences() {
  std::vector<std::uint32_t> edge_degree(vertices_.size(), 0), triangle_degree(vertices_.size(), 0);
  for (const ComplexEdge& e : edges_)
    for (std::uint32_t v : e.v) ++edge_degree[v];
  for (const ComplexTriangle& t : triangles_)
    for (std::uint32_t v : t.v) ++triangle_degree[v];
  vertex_edges_.assign(vertices_.size(), {});
  vertex_triangles_.assign(vertices_.size(), {});
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    vertex_edges_[v].reserve(edge_degree[v]);
    vertex_triangles_[v].reserve(triangle_degree[v]);
  }
  for (std::uint32_t e = 0; e < edges_.size(); ++e)
    for (std::uint32_t v : edges_[e].v) vertex_edges_[v].push_back(e);
  for (std::uint32_t t = 0; t < triangles_.size(); ++t)
    for (std::uint32_t v : triangles_[t].v) vertex_triangles_[v].push_back(t);
}

std::uint32_t MedialComplex::find_edge(std::uint32_t a, std::uint32_t b) const {
  if (a >= vertices_.size() || b >= vertices_.size()) return kNoIndex;
  for (std::uint32_t e : vertex_edges_[a])
    if (edges_[e].v[0] == std::min(a, b) && edges_[e].v[1] == std::max(a, b)) return e;
  return kNoIndex;
}

void MedialComplex::order_edge_triangles(const FilteredPoints& points) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;  // (third vertex, triangle)
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    auto& tris = edge_triangles_[e];
    if (tris.size() < 2) continue;
    const FilteredEdgeOrder order(points, edges_[e].v[0], edges_[e].v[1]);
    if (tris.size() == 2) {
      // The sort below never moves the reference (angle 0 is the least), so two triangles
      // keep their order, and they overlap iff the second has angle 0 too: det = 0 and the
      // same direction (EdgeAngularOrder::compare(ref, ref, w) == 0).
      const std::uint32_t ref = third_vertex(triangles_[tris[0]], edges_[e].v);
      const std::uint32_t w = third_vertex(triangles_[tris[1]], edges_[e].v);
      if (order.compare(ref, ref, w) == 0) fail_overlap(tris[0], tris[1], e);
      continue;
    }
    keyed.clear();
    for (std::uint32_t t : tris) keyed.emplace_back(third_vertex(triangles_[t], edges_[e].v), t);
    const std::uint32_t ref = keyed.front().first;
    std::sort(keyed.begin(), keyed.end(),
              [&](const auto& p, const auto& q) { return order.compare(ref, p.first, q.first) < 0; });
    for (std::size_t i = 0; i + 1 < keyed.size(); ++i)
      if (order.compare(ref, keyed[i].first, keyed[i + 1].first) == 0) fail_overlap(keyed[i].second, keyed[i + 1].second, e);
    for (std::size_t i = 0; i < keyed.size(); ++i) tris[i] = keyed[i].second;
  }
}

void MedialComplex::fail_overlap(std::uint32_t t0, std::uint32_t t1, std::uint32_t e) const {
  fail("triangles " + std::to_string(t0) + " and " + std::to_string(t1) + " overlap along edge (" +
       std::to_string(edges_[e].v[0]) + ", " + std::to_string(edges_[e].v[1]) + ")");
}

void MedialComplex::build_sheets(const FilteredPoints& points) {
  std::vector<std::uint32_t> parent(triangles_.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::uint32_t e = 0; e < edges_.size(); ++e)
    if (edges_[e].stratum == EdgeStratum::Manifold) {
      const std::uint32_t r0 = find(edge_triangles_[e][0]), r1 = find(edge_triangles_[e][1]);
      if (r0 != r1) parent[std::max(r0, r1)] = std::min(r0, r1);
    }
  std::vector<std::uint32_t> sheet_of_root(triangles_.size(), kNoIndex);
  for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
    const std::uint32_t r = find(t);
    if (sheet_of_root[r] == kNoIndex) {
      sheet_of_root[r] = static_cast<std::uint32_t>(sheets_.size());
      sheets_.emplace_back();
    }
    triangles_[t].sheet = sheet_of_root[r];
    sheets_[sheet_of_root[r]].triangles.push_back(t);
  }
  // Frames in the order the sheets come: one per planar sheet, one per triangle otherwise.
  triangle_frame_.assign(triangles_.size(), kNoIndex);
  SheetPlanarity planarity(points, triangles_);
  for (Sheet& s : sheets_) {
    s.planar = planarity.planar(s);
    if (s.planar) {
      s.frame = static_cast<std::uint32_t>(frame_triangle_.size());
      frame_triangle_.push_back(s.triangles.front());
      for (std::uint32_t t : s.triangles) triangle_frame_[t] = s.frame;
      continue;
    }
    for (std::uint32_t t : s.triangles) {
      triangle_frame_[t] = static_cast<std::uint32_t>(frame_triangle_.size());
      frame_triangle_.push_back(t);
    }
  }
  frame_store_ = make_frame_store(frame_triangle_.size());
}

bool MedialComplex::is_pole(std::uint32_t e) const {
  return edges_[e].stratum == EdgeStratum::Singular || edges_[e].stratum == EdgeStratum::Dangling;
}

void MedialComplex::build_sectors() {
  link_elements_.assign(vertices_.size(), {});
  corner_element_.assign(3 * triangles_.size(), kNoIndex);
  edge_end_element_.assign(2 * edges_.size(), kNoIndex);
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    auto& elements = link_elements_[v];
    for (std::uint32_t e : vertex_edges_[v])
      if (is_pole(e)) {
        edge_end_element_[2 * e + (edges_[e].v[0] == v ? 0 : 1)] = static_cast<std::uint32_t>(elements.size());
        elements.push_back({true, e});
      }
    for (std::uint32_t t : vertex_triangles_[v]) {
      if (corner_element_[3 * t + corner_of(triangles_[t], v)] != kNoIndex) continue;
      Sector s = trace_fan(v, t);
      const auto local = static_cast<std::uint32_t>(elements.size());
      for (std::uint32_t ft : s.triangles) corner_element_[3 * ft + corner_of(triangles_[ft], v)] = local;
      for (std::uint32_t ft : s.triangles)
        for (std::uint32_t e : edges_at(triangles_[ft], v))
          if (!is_pole(e)) edge_end_element_[2 * e + (edges_[e].v[0] == v ? 0 : 1)] = local;
      elements.push_back({false, static_cast<std::uint32_t>(sectors_.size())});
      sectors_.push_back(std::move(s));
    }
  }
}

// The fan of triangles around v that contains t, joined across non-pole edges at v: walk
// back from t to an end (or all the way round), then forward collecting the fan in order.
Sector MedialComplex::trace_fan(std::uint32_t v, std::uint32_t t) const {
  auto across = [&](std::uint32_t tri, std::uint32_t e) {  // the other triangle on manifold edge e
    const auto& et = edge_triangles_[e];
    return et[0] == tri ? et[1] : et[0];
  };
  auto other_edge = [&](std::uint32_t tri, std::uint32_t e) {
    const auto es = edges_at(triangles_[tri], v);
    return es[0] == e ? es[1] : es[0];
  };
  // Walk backwards through edges_at(t)[0] until a non-manifold edge or back at t.
  std::uint32_t start = t, entry = edges_at(triangles_[t], v)[0];
  bool closed = false;
  for (std::size_t guard = 0; edges_[entry].stratum == EdgeStratum::Manifold; ++guard) {
    if (guard > vertex_triangles_[v].size()) throw std::logic_error("fan walk does not terminate");
    const std::uint32_t prev = across(start, entry);
    if (prev == t) {
      closed = true;
      break;
    }
    entry = other_edge(prev, entry);
    start = prev;
  }
  Sector s;
  s.apex = v;
  s.sheet = triangles_[t].sheet;
  s.closed = closed;
  std::uint32_t cur = start, e = entry;
  if (!closed) s.ends[0] = entry;
  for (std::size_t guard = 0;; ++guard) {
    if (guard > vertex_triangles_[v].size()) throw std::logic_error("fan walk does not terminate");
    s.triangles.push_back(cur);
    e = other_edge(cur, e);
    if (edges_[e].stratum != EdgeStratum::Manifold) {
      s.ends[1] = e;
      break;
    }
    const std::uint32_t next = across(cur, e);
    if (closed && next == start) break;
    cur = next;
  }
  return s;
}

void MedialComplex::classify_vertices() {
  border_point_.assign(vertices_.size(), false);
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    vertices_[v].kind = classify_link(v);
    border_point_[v] = link_burns(v, std::vector<bool>(link_elements_[v].size(), false));
  }
}

VertexKind MedialComplex::classify_link(std::uint32_t v) const {
  std::vector<std::uint32_t> poles, sectors;
  for (const LinkElement& el : link_elements_[v]) (el.is_pole ? poles : sectors).push_back(el.id);
  auto dangling = [&](std::uint32_t e) { return edges_[e].stratum == EdgeStratum::Dangling; };
  if (poles.empty() && sectors.empty()) return VertexKind::Isolated;
  if (poles.empty() && sectors.size() == 1) return sectors_[sectors[0]].closed ? VertexKind::Interior : VertexKind::Border;
  if (sectors.empty() && poles.size() == 1 && dangling(poles[0])) return VertexKind::SegmentEnd;
  if (sectors.empty() && poles.size() == 2 && dangling(poles[0]) && dangling(poles[1]))
    return VertexKind::SegmentInterior;
  if (poles.size() == 2 && sectors.size() >= 3 && !dangling(poles[0]) && !dangling(poles[1])) {
    const bool theta = std::all_of(sectors.begin(), sectors.end(), [&](std::uint32_t s) {
      const auto& ends = sectors_[s].ends;
      return (ends[0] == poles[0] && ends[1] == poles[1]) || (ends[0] == poles[1] && ends[1] == poles[0]);
    });
    if (theta) return VertexKind::SingularCurve;
  }
  return VertexKind::SingularPoint;
}

bool MedialComplex::link_burns(std::uint32_t v, const std::vector<bool>& arrived) const {
  const auto& elements = link_elements_[v];
  // Union-find over the surviving poles (local indices); a surviving sector whose two ends
  // are surviving poles joins them, and closes a cycle when they are already joined.
  std::vector<std::uint32_t> parent(elements.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t segment_directions = 0;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (arrived[i]) continue;
    if (elements[i].is_pole) {
      segment_directions += edges_[elements[i].id].stratum == EdgeStratum::Dangling ? 1 : 0;
      continue;
    }
    const Sector& s = sectors_[elements[i].id];
    if (s.closed) return false;  // a whole circle survives
    std::array<std::uint32_t, 2> alive{kNoIndex, kNoIndex};
    int n_alive = 0;
    for (std::uint32_t e : s.ends) {
      if (!is_pole(e)) continue;  // a free end (border edge)
      const std::uint32_t local = edge_end_element_[2 * e + (edges_[e].v[0] == v ? 0 : 1)];
      if (!arrived[local]) alive[n_alive++] = local;
    }
    if (n_alive < 2) continue;  // a pendant or free arc closes no cycle
    const std::uint32_t r0 = find(alive[0]), r1 = find(alive[1]);
    if (r0 == r1) return false;  // a cycle (a loop when both ends are one pole)
    parent[r0] = r1;
  }
  return segment_directions <= 1;
}

bool MedialComplex::edge_link_burns(std::size_t triangle_count, bool pole0, bool pole1, std::size_t arrived_triangles) {
  const std::size_t alive_arcs = triangle_count - arrived_triangles;
  if (triangle_count == 0) return pole0 || pole1;   // a segment: like a 2D edge point
  return pole0 || pole1 || alive_arcs <= 1;         // a cycle needs both poles and two arcs
}

void MedialComplex::apply_ignition(const RawComplex& raw) {
  for (const BorderIgnition& rule : raw.border_rules) {
    const std::uint32_t e = find_edge(rule.edge[0], rule.edge[1]);
    if (e == kNoIndex || edges_[e].stratum != EdgeStratum::Border)
      fail("border rule names (" + std::to_string(rule.edge[0]) + ", " + std::to_string(rule.edge[1]) +
           "), which is not a border edge");
    edges_[e].rule = rule.rule;
    edges_[e].rule_point = rule.point;
    edges_[e].rule_point_approx = to_double(rule.point);
  }
  const double inf = std::numeric_limits<double>::infinity();
  vertex_ignition_.assign(vertices_.size(), inf);
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    if (!border_point_[v]) continue;
    bool has_border_edge = false;
    double f = inf;
    for (std::uint32_t e : vertex_edges_[v]) {
      if (edges_[e].stratum != EdgeStratum::Border) continue;
      has_border_edge = true;
      f = std::min(f, ignition_on_edge(e, edges_[e].v[0] == v ? 0.0 : 1.0));
    }
    vertex_ignition_[v] = has_border_edge ? f : vertices_[v].radius;
  }
}

double MedialComplex::ignition_on_edge(std::uint32_t e, double s) const {
  const ComplexEdge& ed = edges_[e];
  const Vec3d& a = vertices_[ed.v[0]].approx;
  const Vec3d& b = vertices_[ed.v[1]].approx;
  switch (ed.rule) {
    case IgnitionRule::Never: return std::numeric_limits<double>::infinity();
    case IgnitionRule::Linear: return (1.0 - s) * vertices_[ed.v[0]].radius + s * vertices_[ed.v[1]].radius;
    case IgnitionRule::DistanceToPoint: {
      double d2 = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double c = (1.0 - s) * a[i] + s * b[i] - ed.rule_point_approx[i];
        d2 += c * c;
      }
      return std::sqrt(d2);
    }
  }
  return std::numeric_limits<double>::infinity();
}

std::size_t MedialComplex::count(EdgeStratum s) const {
  return static_cast<std::size_t>(
      std::count_if(edges_.begin(), edges_.end(), [&](const ComplexEdge& e) { return e.stratum == s; }));
}

std::size_t MedialComplex::count(VertexKind k) const {
  return static_cast<std::size_t>(
      std::count_if(vertices_.begin(), vertices_.end(), [&](const ComplexVertex& v) { return v.kind == k; }));
}

}  // namespace grassfire
