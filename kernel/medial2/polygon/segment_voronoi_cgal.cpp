// segment_voronoi_cgal.cpp -- the interior segment Voronoi topology by CGAL's
// Segment_Delaunay_graph_2 (see segment_voronoi.h). CGAL is used in this file only.
// A Voronoi vertex is a finite face of the segment Delaunay graph (its three sites in
// counter-clockwise order), a Voronoi edge the dual of a Delaunay edge; the edge between
// a segment and its own endpoint is the one we drop. Faces of cocircular sites come out
// as several faces with one circle (zero-length Voronoi edges, contracted later).
// Speed (measured, notes fast2d2.md): on exact points of a smooth curve the interval
// filter of the incircle predicate fails often (consecutive segments are nearly tangent
// to one osculating circle) and every failure costs an exact evaluation in a square-root
// extension. The exact kernel is therefore CGAL's Mpzf (exact ring operations on binary
// floats, small ones without allocation; the default Gmpq normalises every product by a
// gcd), and the segments are inserted in a seeded random order after the spatially sorted
// points (CGAL inserts them in input order, i.e. along the boundary): together 5x faster
// at 10^4 segments, but still superlinear (the failures grow with the sampling density).
#include <CGAL/Mpzf.h>
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "medial2/polygon/segment_voronoi.h"

namespace grassfire {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Traits = CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<
    Kernel, CGAL::Field_with_sqrt_tag, CGAL::Simple_cartesian<CGAL::Mpzf>, CGAL::Integral_domain_without_division_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_2<Traits>;
using Face = Sdg::Face_handle;
using Key = std::pair<double, double>;

class SiteIndex {
 public:
  explicit SiteIndex(const PolygonSites& s) : s_(s) {
    for (std::uint32_t v = 0; v < s.vertex_count(); ++v) point_[{s.vertex[v].x, s.vertex[v].y}] = v;
  }
  std::uint32_t of(const Sdg::Site_2& site) const {
    if (site.is_point()) return point(site.point());
    const std::uint32_t a = point(site.segment().source()), b = point(site.segment().target());
    if (s_.next[a] == b) return s_.vertex_count() + a;
    if (s_.next[b] == a) return s_.vertex_count() + b;
    throw std::logic_error("cgal_segment_voronoi: a segment site that is no polygon edge");
  }

 private:
  std::uint32_t point(const Kernel::Point_2& p) const {
    auto it = point_.find({p.x(), p.y()});
    if (it == point_.end()) throw std::logic_error("cgal_segment_voronoi: a point site that is no polygon vertex");
    return it->second;
  }
  const PolygonSites& s_;
  std::map<Key, std::uint32_t> point_;
};

}  // namespace

VoronoiTopology cgal_segment_voronoi(const PolygonSites& sites) {
  std::vector<Kernel::Point_2> points;
  std::vector<std::pair<std::size_t, std::size_t>> segments;
  points.reserve(sites.vertex_count());
  segments.reserve(sites.vertex_count());
  for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
    points.emplace_back(sites.vertex[i].x, sites.vertex[i].y);
    segments.emplace_back(i, sites.next[i]);
  }
  std::mt19937 order(20261202);
  std::shuffle(segments.begin(), segments.end(), order);
  Sdg sdg;
  sdg.insert_segments(points, segments.begin(), segments.end());
  const SiteIndex index(sites);

  VoronoiTopology out;
  std::map<Face, std::uint32_t> id;
  std::vector<std::pair<Face, int>> stack;  // Delaunay edges (face, opposite vertex) to cross
  auto site_of = [&](Face f, int i) { return index.of(f->vertex(i)->site()); };
  auto secondary = [&](std::uint32_t a, std::uint32_t b) {
    return (sites.is_point(a) && !sites.is_point(b) && sites.is_endpoint(a, b)) ||
           (sites.is_point(b) && !sites.is_point(a) && sites.is_endpoint(b, a));
  };
  auto add = [&](Face f) {
    auto [it, fresh] = id.emplace(f, static_cast<std::uint32_t>(out.vertices.size()));
    if (fresh) {
      VoronoiTopology::Vertex v;
      v.sites = {site_of(f, 0), site_of(f, 1), site_of(f, 2)};
      out.vertices.push_back(v);
    }
    return std::make_pair(it->second, fresh);
  };
  for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
    const std::uint32_t s[3] = {site_of(f, 0), site_of(f, 1), site_of(f, 2)};
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t p = s[i];
      if (!sites.is_point(p) || !is_convex_vertex(sites, p)) continue;
      const std::uint32_t s1 = sites.vertex_count() + sites.prev[p], s2 = sites.vertex_count() + p;
      const std::uint32_t a = s[(i + 1) % 3], b = s[(i + 2) % 3];
      if (!((a == s1 && b == s2) || (a == s2 && b == s1))) continue;
      const std::uint32_t v = add(f).first;
      out.vertices[v].apex = true;
      out.vertices[v].sites = {p, s1, s2};
      stack.emplace_back(f, i);
    }
  }
  std::map<std::pair<Face, int>, bool> done;
  while (!stack.empty()) {
    auto [f, i] = stack.back();
    stack.pop_back();
    const Face g = f->neighbor(i);
    if (done.count({f, i})) continue;
    done[{f, i}] = true;
    done[{g, sdg.tds().mirror_index(f, i)}] = true;
    if (sdg.is_infinite(g)) throw std::logic_error("cgal_segment_voronoi: an interior search reached infinity");
    const std::uint32_t u = id.at(f);
    const auto [v, fresh] = add(g);
    out.edges.push_back({u, v, site_of(f, Sdg::ccw(i)), site_of(f, Sdg::cw(i))});
    if (!fresh || out.vertices[v].apex) continue;
    for (int j = 0; j < 3; ++j) {
      if (secondary(site_of(g, Sdg::ccw(j)), site_of(g, Sdg::cw(j)))) continue;
      if (!done.count({g, j})) stack.emplace_back(g, j);
    }
  }
  return out;
}

}  // namespace grassfire
