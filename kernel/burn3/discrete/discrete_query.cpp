// discrete_query.cpp -- see discrete_query.h.
#include "burn3/discrete/discrete_query.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grassfire {
namespace {

double distance(const Vec3d& a, const Vec3d& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

bool holds(const MedialComplex& mc, std::uint32_t t, const ComplexPoint& s) {
  const ComplexTriangle& tr = mc.triangle(t);
  switch (s.kind) {
    case ComplexPoint::Kind::Vertex: return corner_of(tr, s.id) >= 0;
    case ComplexPoint::Kind::Edge: return tr.e[0] == s.id || tr.e[1] == s.id || tr.e[2] == s.id;
    case ComplexPoint::Kind::Triangle: return s.id == t;
  }
  return false;
}

bool same_point(const ComplexPoint& a, const ComplexPoint& b) {
  return a.kind == b.kind && a.id == b.id && a.point == b.point;
}

// min over the graph points of edge e (indices first..last) of BT + distance to p.
double from_edge_points(const MedialComplex& mc, const DiscreteBurning& d, std::uint32_t e, std::uint32_t first,
                        std::uint32_t last, const Vec3d& p) {
  double best = DiscreteBurning::kInfinity;
  const double n1 = d.steiner_count(e) + 1.0;
  for (std::uint32_t i = first; i <= last; ++i) {
    const double bt = d.bt_on_edge(mc, e, i);
    if (std::isfinite(bt)) best = std::min(best, bt + distance(p, DiscreteBurning::point_on_edge(mc, e, i / n1)));
  }
  return best;
}

// The first arrival at p (inside or on the boundary of t) across t, from the graph points
// of t's boundary other than those of edge `skip` (kNoIndex: none skipped) and from the
// sources in closed t that are not on `skip`.
double across_triangle(const MedialComplex& mc, const DiscreteBurning& d, const std::vector<PointSource>& sources,
                       std::uint32_t t, std::uint32_t skip, const Vec3d& p) {
  const ComplexTriangle& tr = mc.triangle(t);
  double best = DiscreteBurning::kInfinity;
  for (int c = 0; c < 3; ++c) {
    if (tr.e[c] == skip) continue;
    best = std::min(best, from_edge_points(mc, d, tr.e[c], 0, d.steiner_count(tr.e[c]) + 1, p));
  }
  for (const PointSource& s : sources) {
    if (!holds(mc, t, s.location)) continue;
    if (skip != kNoIndex && s.location.kind == ComplexPoint::Kind::Edge && s.location.id == skip) continue;
    best = std::min(best, s.t0.get_d() + distance(p, s.location.approx()));
  }
  return best;
}

double inside_edge(const MedialComplex& mc, const DiscreteBurning& d, const std::vector<PointSource>& sources,
                   const ComplexPoint& x) {
  const std::uint32_t e = x.id, n = d.steiner_count(e);
  const mpq_class scaled = x.parameter * (n + 1);
  const mpz_class lower_z = scaled.get_num() / scaled.get_den();
  const auto lower = static_cast<std::uint32_t>(lower_z.get_ui());
  if (scaled == lower_z) return d.bt_on_edge(mc, e, lower);  // exactly a Steiner point
  const Vec3d p = x.approx();
  // Arrivals per link element: along e from the v[0] side, from the v[1] side, then one per triangle.
  std::vector<double> arrival = {from_edge_points(mc, d, e, lower, lower, p),
                                 from_edge_points(mc, d, e, lower + 1, lower + 1, p)};
  for (const PointSource& s : sources)
    if (s.location.kind == ComplexPoint::Kind::Edge && s.location.id == e) {
      const double t = s.t0.get_d() + distance(p, s.location.approx());
      double& side = arrival[s.location.parameter < x.parameter ? 0 : 1];
      side = std::min(side, t);
    }
  for (std::uint32_t t : mc.edge_triangles(e)) arrival.push_back(across_triangle(mc, d, sources, t, e, p));
  const std::size_t k = mc.edge_triangles(e).size();
  if (MedialComplex::edge_link_burns(k, false, false, 0)) {  // a border point: min(f, first arrival)
    const double f = mc.ignition_on_edge(e, x.parameter.get_d());
    return std::min(f, *std::min_element(arrival.begin(), arrival.end()));
  }
  std::vector<std::size_t> order(arrival.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return arrival[a] < arrival[b]; });
  bool pole0 = false, pole1 = false;
  std::size_t arcs = 0;
  for (std::size_t i : order) {
    if (!std::isfinite(arrival[i])) break;
    if (i == 0) pole0 = true;
    else if (i == 1) pole1 = true;
    else ++arcs;
    if (MedialComplex::edge_link_burns(k, pole0, pole1, arcs)) return arrival[i];
  }
  return DiscreteBurning::kInfinity;
}

}  // namespace

double discrete_burning_time_at(const MedialComplex& mc, const DiscreteBurning& d,
                                const std::vector<PointSource>& sources, const ComplexPoint& x) {
  double bt = DiscreteBurning::kInfinity;
  switch (x.kind) {
    case ComplexPoint::Kind::Vertex: bt = d.vertex_bt[x.id]; break;
    case ComplexPoint::Kind::Triangle: bt = across_triangle(mc, d, sources, x.id, kNoIndex, x.approx()); break;
    case ComplexPoint::Kind::Edge: bt = inside_edge(mc, d, sources, x); break;
  }
  for (const PointSource& s : sources)
    if (same_point(s.location, x)) bt = std::min(bt, s.t0.get_d());
  return bt;
}

}  // namespace grassfire
