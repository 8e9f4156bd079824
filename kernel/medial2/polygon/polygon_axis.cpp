// polygon_axis.cpp -- see polygon_axis.h.
#include "medial2/polygon/polygon_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry2/predicates2.h"
#include "support/cpu_clock.h"
#include "medial2/polygon/polygon_axis_geometry.h"
#include "medial2/polygon/polygon_axis_symmetry.h"
#include "medial2/polygon/segment_voronoi.h"
#include "support/union_find.h"
#include "medial2/polygon/voronoi_circle.h"
#include "medial2/polygon/segment_voronoi_check.h"

namespace grassfire {

namespace {

// An enclosure is re-evaluated in Arb when it has fewer than this many relative bits.
constexpr int kTightBits = 40;


bool is_tight(const Interval& a) {
  const double m = std::fmax(std::fabs(a.lo), std::fabs(a.hi));
  return a.hi - a.lo <= std::ldexp(m, -kTightBits);
}

bool overlap(const Interval& a, const Interval& b) { return a.lo <= b.hi && b.lo <= a.hi; }

// The exact frame: Boost on decimal or binary integers when the policy allows, else CGAL on doubles.
struct Frame {
  AxisConstruction construction = AxisConstruction::CgalSdg;
  int digits = -1;
  int binary_digits = std::numeric_limits<int>::min();
  mpq_class to_input = 1;
  PolygonSites sites;
};

// The binary policy: every double is an integer times a power of two, so the polygon
// scaled by 2^K (K = minus the smallest exponent of a lowest set bit) has integer
// coordinates, exactly. Boost runs on them when they fit int32, Boost with the wide traits
// when they lie within 2^62 of their bounding box's centre (fits_wide_boost).
bool dyadic_frame(Frame& f, bool wide_only) {
  int low = std::numeric_limits<int>::max();
  double largest = 0;
  for (const Point2& p : f.sites.vertex)
    for (double x : {p.x, p.y}) {
      if (x == 0) continue;
      low = std::min(low, lowest_bit_exponent(x));
      largest = std::max(largest, std::fabs(x));
    }
  if (low == std::numeric_limits<int>::max()) low = 0;
  const double top = std::ldexp(largest, -low);
  if (!(top < 0x1p126)) return false;
  PolygonSites scaled = f.sites;
  for (Point2& p : scaled.vertex) p = {std::ldexp(p.x, -low), std::ldexp(p.y, -low)};
  if (top <= 2147483647.0 && !wide_only)
    f.construction = AxisConstruction::BoostPolygon;
  else if (fits_wide_boost(scaled))
    f.construction = AxisConstruction::BoostPolygonWide;
  else
    return false;
  f.sites = std::move(scaled);
  f.binary_digits = -low;
  f.to_input = low >= 0 ? mpq_class(mpz_class(mpz_class(1) << low)) : mpq_class(mpz_class(1), mpz_class(mpz_class(1) << -low));
  return true;
}

Frame choose_frame(const Shape2& shape, const PolygonAxisOptions& options) {
  Frame f;
  f.sites = make_sites(shape, 1.0);
  std::vector<long long> ints;
  int k_max = 0;
  if (options.construction == AxisConstruction::BoostPolygonMp) {
    f.construction = AxisConstruction::BoostPolygonMp;
    return f;
  }
  const bool wide_only = options.construction == AxisConstruction::BoostPolygonWide;
  bool decimal = options.construction != AxisConstruction::CgalSdg && !wide_only;
  std::vector<int> digits;
  for (const Point2& p : f.sites.vertex) {
    for (double x : {p.x, p.y}) {
      long long m = 0;
      const int k = decimal ? decimal_digits(x, options.max_decimal_digits, &m) : -1;
      decimal = decimal && k >= 0;
      ints.push_back(m);
      digits.push_back(k);
      k_max = std::max(k_max, k);
    }
  }
  if (decimal) {
    long long pow10[10] = {1};
    for (int i = 1; i < 10; ++i) pow10[i] = pow10[i - 1] * 10;
    std::vector<double> scaled;
    for (std::size_t i = 0; i < ints.size() && decimal; ++i) {
      const long double v = static_cast<long double>(ints[i]) * pow10[k_max - digits[i]];
      decimal = std::fabs(v) <= 2147483647.0L;
      scaled.push_back(static_cast<double>(v));
    }
    if (decimal) {
      for (std::size_t i = 0; i < f.sites.vertex.size(); ++i) f.sites.vertex[i] = {scaled[2 * i], scaled[2 * i + 1]};
      f.construction = AxisConstruction::BoostPolygon;
      f.digits = k_max;
      f.to_input = make_rational(1, mpz_class(std::to_string(pow10[k_max])));
      return f;
    }
  }
  if (options.construction != AxisConstruction::CgalSdg && dyadic_frame(f, wide_only)) return f;
  if (options.construction == AxisConstruction::BoostPolygon || wide_only)
    throw std::invalid_argument(shape.name + ": Boost.Polygon needs decimal or binary coordinates that fit int32, or 62 bits about their centre, once scaled");
  if (options.construction != AxisConstruction::CgalSdg) f.construction = AxisConstruction::BoostPolygonMp;
  return f;
}


// The frame's Voronoi topology by its construction; the wide traits' overflow of their
// 4096-bit exact integers (never observed) falls back to the mp traits on the same frame
// (exact integers of any size: its integer parts cannot overflow).
VoronoiTopology boost_voronoi_of(Frame& frame, MpTier* tier) {
  if (frame.construction == AxisConstruction::BoostPolygon) return boost_segment_voronoi(frame.sites);
  if (frame.construction == AxisConstruction::BoostPolygonWide) {
    try {
      return boost_segment_voronoi_wide(frame.sites);
    } catch (const std::overflow_error&) {
      frame.construction = AxisConstruction::BoostPolygonMp;
    }
  }
  return boost_segment_voronoi_mp(frame.sites, tier);
}

// A construction's topology and the first defect segment_voronoi_check.h finds in it (an
// extraction that stops on an impossible diagram is a defect too).
std::optional<std::string> checked_run(VoronoiTopology& topo, std::uint32_t holes, const PolygonSites& sites,
                                       const std::function<VoronoiTopology()>& build) {
  try {
    topo = build();
  } catch (const std::logic_error& e) {
    return std::string(e.what());
  }
  return voronoi_topology_defect(sites, topo, holes);
}

// The checked Voronoi topology of the frame: Boost's diagram when it passes the check,
// else CGAL's segment Delaunay graph (exact predicates on the same frame), counted as a
// fallback. A diagram no construction gets right is an error naming the shape.
VoronoiTopology voronoi_of(Frame& frame, MpTier* tier, const Shape2& shape, PolygonAxisReport& rep) {
  const std::uint32_t holes = static_cast<std::uint32_t>(shape.rings.size() - 1);
  VoronoiTopology topo;
  std::string tried;
  if (frame.construction != AxisConstruction::CgalSdg) {
    const auto defect = checked_run(topo, holes, frame.sites, [&] { return boost_voronoi_of(frame, tier); });
    if (!defect) return topo;
    ++rep.voronoi_fallbacks;
    rep.rejected_construction = frame.construction;
    rep.fallback_reason = *defect;
    tried = std::string(to_string(frame.construction)) + " gave a wrong diagram (" + *defect + "), and ";
    frame.construction = AxisConstruction::CgalSdg;
  }
  const auto defect = checked_run(topo, holes, frame.sites, [&] { return cgal_segment_voronoi(frame.sites); });
  if (!defect) return topo;
  throw std::runtime_error(shape.name + ": the exact polygon axis cannot be constructed: " + tried +
                           "CGAL's segment Delaunay graph gave a wrong diagram (" + *defect + ")");
}

class Builder {
 public:
  Builder(const Frame& frame, VoronoiTopology topo, PolygonAxisReport& report)
      : sites_(std::make_shared<PolygonSites>(frame.sites)), to_input_(frame.to_input), topo_(std::move(topo)),
        report_(report) {}

  MedialGraph run() {
    solve_circles();
    conditions_ = conditions_of_sites(*sites_);
    contract();
    return assemble();
  }

 private:
  void solve_circles() {
    const std::size_t n = topo_.vertices.size();
    circles_.resize(n);
    values_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      circles_[i] = classify_circle(*sites_, topo_.vertices[i]);
      ++report_.circles_by_kind[static_cast<int>(circles_[i].kind)];
      values_[i] = solve_interval(*sites_, circles_[i]);
      if (!tight(values_[i])) {
        ++report_.dd_refinements;
        const CircleValue<DDBall>& d = dd(i);
        values_[i] = {d.x.to_interval(), d.y.to_interval(), d.r.to_interval()};
      }
      if (!tight(values_[i])) {
        ++report_.ball_refinements;
        const CircleValue<Ball>& b = ball(i);
        values_[i] = {b.x.to_interval(), b.y.to_interval(), b.r.to_interval()};
      }
    }
  }

  // R to kTightBits relative bits; the centre's coordinates to kTightBits bits of the
  // circle's scale (the largest of |x|, |y| and R): a coordinate that is 0 (a centre on a
  // symmetry axis through the origin) is never relatively tight, and refining it in
  // double-double and Arb only narrowed an enclosure of 0.
  static bool tight(const CircleValue<Interval>& v) {
    const double scale = std::fmax(magnitude(v.r), std::fmax(magnitude(v.x), magnitude(v.y)));
    return is_tight(v.r) && within(v.x, scale) && within(v.y, scale);
  }
  static double magnitude(const Interval& a) { return std::fmax(std::fabs(a.lo), std::fabs(a.hi)); }
  static bool within(const Interval& a, double scale) { return a.hi - a.lo <= std::ldexp(scale, -kTightBits); }

  // The circle of vertex i in double-double, computed once.
  const CircleValue<DDBall>& dd(std::uint32_t i) {
    if (dds_.size() < circles_.size()) dds_.resize(circles_.size());
    if (!dds_[i]) dds_[i] = solve_dd(*sites_, circles_[i]);
    return *dds_[i];
  }

  // The circle of vertex i in Arb (default precision), computed once.
  const CircleValue<Ball>& ball(std::uint32_t i) {
    if (balls_.size() < circles_.size()) balls_.resize(circles_.size());
    if (!balls_[i]) balls_[i] = solve_ball(*sites_, circles_[i]);
    return *balls_[i];
  }

  // The conditions of a circle: its point sites and its segment sites' lines (straight
  // runs), sorted.
  std::array<std::uint32_t, 3> conditions(std::uint32_t i) const {
    std::array<std::uint32_t, 3> c = circles_[i].sites;
    for (std::uint32_t& site : c)
      site = conditions_[site];
    std::sort(c.begin(), c.end());
    return c;
  }

  enum class Same { No, Certified, Uncertified };

  // Exact test that two Voronoi vertices are the same point.
  Same same_point(std::uint32_t i, std::uint32_t j) {
    const CircleValue<Interval>& a = values_[i];
    const CircleValue<Interval>& b = values_[j];
    if (!overlap(a.x, b.x) || !overlap(a.y, b.y) || !overlap(a.r, b.r)) return Same::No;
    // Two circles of one kind with the same conditions (typically the two sides of a
    // collinear vertex: its two segments are one line), both with R > 0, are the same
    // circle when those conditions have at most one solution (voronoi_circle.h).
    const std::array<std::uint32_t, 3> ca = conditions(i);
    if (circles_[i].kind == circles_[j].kind && ca == conditions(j) && ca[0] != ca[1] && ca[1] != ca[2] &&
        a.r.lo > 0 && b.r.lo > 0 && at_most_one_circle(*sites_, circles_[i])) {
      ++report_.contracted_by_conditions;
      return Same::Certified;
    }
    const auto ea = solve_exact(*sites_, circles_[i]);
    const auto eb = solve_exact(*sites_, circles_[j]);
    if (ea && eb) return sign(ea->x - eb->x) == 0 && sign(ea->y - eb->y) == 0 ? Same::Certified : Same::No;
    for (long bits : {256L, 1024L}) {
      BallPrecision guard(bits);
      const CircleValue<Ball> ba = solve_ball(*sites_, circles_[i]), bb = solve_ball(*sites_, circles_[j]);
      if ((ba.x - bb.x).sign() != 0 && (ba.x - bb.x).sign() != kUndecided) return Same::No;
      if ((ba.y - bb.y).sign() != 0 && (ba.y - bb.y).sign() != kUndecided) return Same::No;
    }
    ++report_.uncertified_contractions;
    return Same::Uncertified;
  }

  bool has_site(std::uint32_t vertex, std::uint32_t site) const {
    const auto& s = circles_[vertex].sites;
    return std::find(s.begin(), s.end(), site) != s.end();
  }

  // A group's circles are aliases of its representative (same centre and R, exactly) when
  // every contraction in it is certified and each contracted edge's two sites are sites of
  // the circles at both of its ends: two circles with one centre X and a common segment
  // site have R = the signed distance from X to that site's line; with a common point
  // site, R = |X - P| for both, as both R are positive (their enclosures say so).
  void contract() {
    UnionFind uf(topo_.vertices.size());
    contracted_.assign(topo_.edges.size(), false);
    std::vector<std::size_t> contracted;
    std::vector<bool> uncertified(topo_.edges.size(), false);
    for (std::size_t e = 0; e < topo_.edges.size(); ++e) {
      const auto& ed = topo_.edges[e];
      if (topo_.vertices[ed.u].apex || topo_.vertices[ed.v].apex) continue;  // R = 0 against R > 0
      const Same same = same_point(ed.u, ed.v);
      if (same != Same::No) {
        contracted_[e] = true;
        uncertified[e] = same == Same::Uncertified;
        contracted.push_back(e);
        uf.unite(ed.u, ed.v);
        ++report_.contracted_edges;
      }
    }
    group_.resize(topo_.vertices.size());
    for (std::uint32_t i = 0; i < topo_.vertices.size(); ++i) group_[i] = uf.find(i);
    aliasable_.assign(topo_.vertices.size(), true);
    for (std::size_t e : contracted) {
      const auto& ed = topo_.edges[e];
      const bool shares = has_site(ed.u, ed.site_a) && has_site(ed.u, ed.site_b) && has_site(ed.v, ed.site_a) &&
                          has_site(ed.v, ed.site_b);
      const bool positive = values_[ed.u].r.lo > 0 && values_[ed.v].r.lo > 0;
      if (uncertified[e] || !shares || !positive) aliasable_[group_[ed.u]] = false;
    }
  }

  MedialGraph assemble() {
    std::vector<std::uint32_t> node_of(topo_.vertices.size(), kNone);
    std::vector<AxisNodeData> data;
    std::vector<MedialNode> nodes;
    const Interval scale = enclose(to_input_);
    const double scale_d = to_input_.get_d();
    for (std::uint32_t i = 0; i < topo_.vertices.size(); ++i) {
      const std::uint32_t root = group_[i];
      if (node_of[root] == kNone) {
        node_of[root] = static_cast<std::uint32_t>(nodes.size());
        data.push_back({circles_[root], {}, {}, true, {}});
        data.back().radius = topo_.vertices[root].apex ? Interval(0.0) : values_[root].r;
        const CircleValue<Interval>& v = values_[root];
        nodes.push_back({{v.x.mid() * scale_d, v.y.mid() * scale_d}, v.r * scale});
        if (topo_.vertices[root].apex) nodes.back().radius = 0.0;
      }
      node_of[i] = node_of[root];
      if (i != root) {
        if (aliasable_[root])
          data[node_of[i]].aliases.push_back(circles_[i]);
        else
          data[node_of[i]].all_aliased = false;
      }
      auto& s = data[node_of[i]].sites;
      s.insert(s.end(), topo_.vertices[i].sites.begin(), topo_.vertices[i].sites.end());
    }
    for (AxisNodeData& d : data) {
      std::sort(d.sites.begin(), d.sites.end());
      d.sites.erase(std::unique(d.sites.begin(), d.sites.end()), d.sites.end());
    }
    std::vector<AxisEdgeData> edata;
    std::vector<MedialEdge> edges;
    for (std::size_t e = 0; e < topo_.edges.size(); ++e) {
      if (contracted_[e]) continue;
      const auto& ed = topo_.edges[e];
      AxisEdgeData a{node_of[ed.u], node_of[ed.v], ed.site_a, ed.site_b, is_parabolic(ed.site_a, ed.site_b), {}};
      Interval len = edge_length(*sites_, a, values_[group_[ed.u]], values_[group_[ed.v]]);
      if (!is_tight(len)) {
        ++report_.dd_refinements;
        len = edge_length(*sites_, a, dd(group_[ed.u]), dd(group_[ed.v]));
      }
      if (!is_tight(len)) {
        ++report_.ball_refinements;
        len = edge_length(*sites_, a, ball(group_[ed.u]), ball(group_[ed.v])).to_interval();
      }
      a.length = len;
      report_.parabolic_arcs += a.parabolic;
      edges.push_back({a.u, a.v, a.parabolic ? EdgeKind::ParabolicArc : EdgeKind::Segment, len * scale});
      edata.push_back(a);
    }
    auto geometry = std::make_shared<PolygonAxisGeometry>(sites_, to_input_, std::move(data), std::move(edata));
    MedialGraph g(std::move(nodes), std::move(edges), std::move(geometry));
    report_.nodes = g.node_count();
    report_.edges = g.edge_count();
    for (std::uint32_t v = 0; v < g.node_count(); ++v) report_.leaves += g.is_leaf(v);
    return g;
  }

  // A point site and a segment site whose line misses the point bound a parabolic arc.
  bool is_parabolic(std::uint32_t a, std::uint32_t b) const {
    if (sites_->is_point(a) == sites_->is_point(b)) return false;
    const std::uint32_t p = sites_->is_point(a) ? a : b, l = sites_->is_point(a) ? b : a;
    return orientation(sites_->vertex[sites_->seg_start(l)], sites_->vertex[sites_->seg_end(l)], sites_->vertex[p]) != 0;
  }

  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::shared_ptr<const PolygonSites> sites_;
  mpq_class to_input_;
  VoronoiTopology topo_;
  PolygonAxisReport& report_;
  std::vector<VoronoiCircle> circles_;
  std::vector<CircleValue<Interval>> values_;
  std::vector<bool> contracted_;
  std::vector<std::uint32_t> group_;
  std::vector<bool> aliasable_;  // by group root
  std::vector<std::optional<CircleValue<Ball>>> balls_;
  std::vector<std::optional<CircleValue<DDBall>>> dds_;
  std::vector<std::uint32_t> conditions_;  // by site: conditions_of_sites
};

}  // namespace

const char* to_string(AxisConstruction c) {
  switch (c) {
    case AxisConstruction::Auto: return "auto";
    case AxisConstruction::BoostPolygon: return "boost-polygon";
    case AxisConstruction::BoostPolygonWide: return "boost-polygon-wide";
    case AxisConstruction::BoostPolygonMp: return "boost-polygon-mp";
    case AxisConstruction::CgalSdg: return "cgal-sdg";
  }
  return "unknown";
}

int decimal_digits(double x, int max_digits, long long* m) {
  double pow10 = 1;
  for (int k = 0; k <= max_digits; ++k, pow10 *= 10) {
    const double scaled = x * pow10;
    if (!(std::fabs(scaled) < 9.0e15)) return -1;
    const long long c = std::llround(scaled);
    for (long long cand : {c - 1, c, c + 1}) {
      // m / 10^k correctly rounded (both exact doubles, one IEEE division) is x?
      if (static_cast<double>(cand) / pow10 == x) {
        *m = cand;
        return k;
      }
    }
  }
  return -1;
}

int lowest_bit_exponent(double x) {
  int e = 0;
  const double f = std::frexp(std::fabs(x), &e);  // |x| = f 2^e, f in [1/2, 1)
  auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // exact: 53-bit integer
  int low = e - 53;
  while ((m & 1u) == 0) {
    m >>= 1;
    ++low;
  }
  return low;
}

MedialGraph exact_polygon_axis(const Shape2& shape, const PolygonAxisOptions& options, PolygonAxisReport* report) {
  const double t0 = thread_seconds();
  PolygonAxisReport local;
  PolygonAxisReport& rep = report ? *report : local;
  rep = PolygonAxisReport{};
  if (shape.rings.empty()) throw std::invalid_argument(shape.name + ": the shape has no ring");
  for (const Ring& r : shape.rings)
    if (r.points.size() < 3) throw std::invalid_argument(shape.name + ": a ring has fewer than 3 vertices");
  Frame frame = choose_frame(shape, options);
  MpTier tier;
  VoronoiTopology topo = voronoi_of(frame, &tier, shape, rep);
  rep.construction = frame.construction;
  rep.mp_input_bits = tier.input_bits;
  rep.mp_float_bits = tier.float_bits;
  rep.mp_filtered = tier.filtered;
  rep.mp_fallbacks = tier.fallbacks;
  rep.decimal_digits = frame.digits;
  rep.binary_digits = frame.binary_digits;
  rep.frame_scale = 1 / frame.to_input.get_d();
  rep.polygon_vertices = frame.sites.vertex_count();
  rep.voronoi_vertices = topo.vertices.size();
  rep.voronoi_seconds = thread_seconds_since(t0);
  const double t1 = thread_seconds();
  MedialGraph g = Builder(frame, std::move(topo), rep).run();
  rep.values_seconds = thread_seconds_since(t1);
  rep.total_seconds = thread_seconds_since(t0);
  return g;
}

}  // namespace grassfire
