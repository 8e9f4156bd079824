// check_exact_chapter4.cpp -- Props 5, 6 and 7 of chapter 4 (4.3) on the EXACT burning time
// (burn3/exact, docs/exact-engine.md), by limits along sequences into the points where BT may
// jump: vertices (singular points among them) and one point of every edge (the midpoint;
// on the baseline the middle graph point of the edge), points of singular curves among them.
//
// Probe points x and their sectors: at a vertex, every triangle at it and every segment
// leaving it (the triangles of one sector share the sector's limit, which checks it once
// per triangle; a segment's sequence is its point at 2^-16 of its length); at an edge
// point, every triangle on the edge (one half-disk each). For each sector triangle t the
// sequence x_n = x + 2^-n (c_t - x), n = 4, 8, 12, 16 (c_t the centroid: exact rational
// points inside t) with d_n = |x_n - x|; the engine's certified
// enclosures BT(x) (ExactBurning::burn_time at the located point: the link rule applied)
// and BT(x_n) (burn_time in t). Inside t BT is 1-Lipschitz (Prop 4), so each sequence has
// a limit L_t(x) with |BT(x_n) - L_t| <= d_n; the rows judge the propositions on these
// enclosures with d_n as the only allowance (a bound derived from Prop 4, shrinking to 0):
//  - Prop 5.1 (BT upper semicontinuous): BT(x_n) <= BT(x) + d_n for every sequence, and
//    some sequence reaches BT(x): |BT(x_16) - BT(x)| <= d_16 on at least one sector.
//  - Prop 5.2 (min CT lower semicontinuous): min CT(x) = min(BT(x), min_t L_t) (BT is a
//    char time); BT(x_n) >= min CT(x) - d_n for every sequence (inside a sheet CT = {BT}),
//    and some sequence reaches min CT(x).
//  - Prop 6 (a disk on which BT is continuous at x), for x not on the border: at least
//    min(2, number of sectors) sectors' limits equal BT(x) (|BT(x_16) - BT(x)| <= d_16);
//    two half-disks (or sectors) glued at x make the disk.
//  - Prop 7 (BT = infinity exactly on the maximal closed subcomplex): at every probe and
//    every sequence point, against the combinatorial peeling (closed_subcomplex.h). Exact.
// Corpora: those of the baseline's rows (corpora3d.h). An instance runs on the exact engine
// when exact_engine_unsupported says the engine burns it as Definition 9 (today: no
// singular edges, no singular points without segments); the others are counted as refused
// with the engine's reason, and a corpus with none run gives "not checked" rows. So these
// rows cover singular complexes as soon as the engine applies the junction rule.
// The same rows on the discrete baseline (DiscreteBurningField: BT_h at the probe, the
// t-side samples at the sequence points) with the allowance d_n + h: a second, independent
// computation whose error the baseline's spacing bounds only empirically (its paths are
// O(h) longer than the exact ones), so those rows are evidence on all complexes, also where
// the exact engine refuses.
//  - Prop 4 (BT 1-Lipschitz in a sheet and along singular curves, no allowance): between
//    the points of one sequence (a segment inside one triangle), and between the points 1/4,
//    1/2, 3/4 of every singular edge (distance along the edge); the rows the baseline's family
//    leaves "not checked" (there Prop 4 holds by construction), here on the exact BT.
// Mutants: bt-bump, bt-dip, bt-infinite (mutants3d.h) on BT at the probe points (the point of
// median BT inside a sheet), closed-burns on a probe in the closed subcomplex; for the Prop 4
// rows the same mutants act on a copy of the sequence values (or of the curve points).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "burn3/discrete/discrete_burning_field.h"
#include "burn3/exact/exact_burning.h"
#include "check_registry.h"
#include "complex3/closed_subcomplex.h"
#include "geometry3/exact_predicates3.h"
#include "geometry3/vec3.h"
#include "corpora3d.h"
#include "mutants3d.h"

namespace grassfire::checks {
namespace {

constexpr int kSteps[] = {4, 8, 12, 16};

struct Sequence {
  std::vector<Interval> bt;  // at x_n, n in kSteps
  std::vector<double> d;     // upper bounds of |x_n - x|
  bool in_closed = false;    // the sector's triangle is in the closed subcomplex
};

struct Probe {
  ComplexPoint x;
  Interval bt;
  bool border = false, in_sheet = false, closed = false;
  std::vector<Sequence> sectors;
};

// The values a row reads: from the exact engine or the baseline.
class Values {
 public:
  virtual ~Values() = default;
  virtual Interval at(const ComplexPoint& x) = 0;
  virtual Interval side(std::uint32_t t, const ExactPoint3& x) = 0;
  virtual Interval segment_start(std::uint32_t e, std::uint32_t v) = 0;
  // The parameter of edge e's probe point (0: none on this edge).
  virtual mpq_class edge_parameter(std::uint32_t) { return mpq_class(1, 2); }
};

class ExactValues final : public Values {
 public:
  explicit ExactValues(ExactBurning& eb) : eb_(eb) {}
  Interval at(const ComplexPoint& x) override { return eb_.burn_time(x); }
  Interval side(std::uint32_t t, const ExactPoint3& x) override { return eb_.burn_time(t, x); }
  Interval segment_start(std::uint32_t e, std::uint32_t v) override {
    return eb_.segment_burn_time(e, eb_.complex().edge(e).v[0] == v ? mpq_class(1, 1 << 16) : mpq_class(65535, 65536));
  }

 private:
  ExactBurning& eb_;
};

class DiscreteValues final : public Values {
 public:
  explicit DiscreteValues(const DiscreteBurningField& f) : f_(f) {}
  Interval at(const ComplexPoint& x) override {
    if (x.kind == ComplexPoint::Kind::Vertex) return point(f_.vertex_burn_time(x.id));
    const mpq_class i = x.parameter * (f_.edge_points(x.id) + 1);
    return point(f_.edge_point_burn_time(x.id, static_cast<std::uint32_t>(i.get_d())));
  }
  // The edge's middle graph point (BT_h of the point itself, by the baseline's link rule).
  mpq_class edge_parameter(std::uint32_t e) override {
    const std::uint32_t n = f_.edge_points(e);
    if (n == 0) return 0;
    mpq_class s((n + 1) / 2, n + 1);
    s.canonicalize();
    return s;
  }
  Interval side(std::uint32_t t, const ExactPoint3& x) override {
    return point(f_.sample_in_triangle(t, to_vec(x)).bt);
  }
  Interval segment_start(std::uint32_t e, std::uint32_t v) override {
    return point(f_.sample_on_segment(e, f_.complex().edge(e).v[0] == v ? 0x1p-16 : 1 - 0x1p-16).bt);
  }

 private:
  static Interval point(double v) { return std::isinf(v) ? Interval::infinity() : Interval(v); }
  static Vec3d to_vec(const ExactPoint3& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }
  const DiscreteBurningField& f_;
};

ExactPoint3 centroid(const MedialComplex& mc, std::uint32_t t) {
  const auto& v = mc.triangle(t).v;
  return mpq_class(1, 3) * (mc.vertex(v[0]).exact + mc.vertex(v[1]).exact + mc.vertex(v[2]).exact);
}

Sequence sequence_into(Values& values, const MedialComplex& mc, std::uint32_t t, const ExactPoint3& x, bool closed) {
  Sequence s;
  s.in_closed = closed;
  const ExactPoint3 c = centroid(mc, t), dc = c - x;
  const double len = std::sqrt(squared_distance(c, x).get_d()) * (1 + 0x1p-40);
  for (int n : kSteps) {
    mpq_class step(1);
    step /= mpq_class(mpz_class(1) << n);
    s.bt.push_back(values.side(t, x + step * dc));
    s.d.push_back(std::ldexp(len, -n));
  }
  return s;
}

std::vector<Probe> probes(const CheckContext& ctx, Values& values, const MedialComplex& mc, const ClosedSubcomplex& k) {
  std::vector<Probe> r;
  // Small complexes whole; larger ones thinned on the quick and tiny corpora.
  const bool small = mc.vertex_count() + mc.edge_count() <= 200;
  const std::uint32_t stride = small ? 1 : ctx.tiny() ? 4 : ctx.quick() ? 2 : 1;
  for (std::uint32_t v = 0; v < mc.vertex_count(); v += stride) {
    if (mc.vertex(v).kind == VertexKind::Isolated) continue;
    Probe p;
    p.x.kind = ComplexPoint::Kind::Vertex, p.x.id = v, p.x.point = mc.vertex(v).exact;
    p.bt = values.at(p.x);
    p.border = mc.is_border_point(v);
    p.in_sheet = mc.vertex(v).kind == VertexKind::Interior;
    p.closed = k.vertex[v];
    for (std::uint32_t t : mc.vertex_triangles(v)) p.sectors.push_back(sequence_into(values, mc, t, p.x.point, k.triangle[t]));
    for (std::uint32_t e : mc.vertex_edges(v)) {
      if (mc.edge(e).stratum != EdgeStratum::Dangling) continue;
      // A segment is a sector of x too: its sequence is one point at 2^-16 of its length.
      Sequence s;
      s.in_closed = k.edge[e];
      s.bt = {values.segment_start(e, v)};
      s.d = {mc.edge(e).length * 0x1p-16 * (1 + 0x1p-40)};
      p.sectors.push_back(std::move(s));
    }
    r.push_back(std::move(p));
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); e += stride) {
    if (mc.edge(e).stratum == EdgeStratum::Dangling) continue;
    Probe p;
    p.x.kind = ComplexPoint::Kind::Edge, p.x.id = e, p.x.parameter = values.edge_parameter(e);
    if (sgn(p.x.parameter) == 0) continue;
    const ExactPoint3& a = mc.vertex(mc.edge(e).v[0]).exact;
    p.x.point = a + p.x.parameter * (mc.vertex(mc.edge(e).v[1]).exact - a);
    p.bt = values.at(p.x);
    p.border = mc.edge(e).stratum == EdgeStratum::Border;
    p.in_sheet = mc.edge(e).stratum == EdgeStratum::Manifold;
    p.closed = k.edge[e];
    for (std::uint32_t t : mc.edge_triangles(e)) p.sectors.push_back(sequence_into(values, mc, t, p.x.point, k.triangle[t]));
    r.push_back(std::move(p));
  }
  return r;
}

// The output mutants on BT at the probes (shifting the enclosure).
void mutate(const CheckContext& ctx, std::vector<Probe>& ps) {
  std::vector<double> mid(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) mid[i] = ps[i].bt.mid();
  std::vector<double> m = mid;
  mutate_burning_times(ctx, m, [&](std::size_t i) { return ps[i].in_sheet; }, [&](std::size_t i) { return ps[i].closed; });
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (m[i] == mid[i]) continue;
    ps[i].bt = std::isinf(m[i]) ? Interval::infinity() : Interval(ps[i].bt.lo + m[i] - mid[i], ps[i].bt.hi + m[i] - mid[i]);
  }
}

struct Tallies {
  Tally usc, lsc, prop6, prop7, prop4_sheet, prop4_curve, def10;
};

// |a - b| <= slack on enclosures (both infinite: equal).
bool meets(const Interval& a, const Interval& b, double slack) {
  if (a.is_infinite() || b.is_infinite()) return a.is_infinite() && b.is_infinite();
  return a.lo <= b.hi + slack && b.lo <= a.hi + slack;
}

void violation(Tally& t, double amount) {
  ++t.violations;
  t.worst = std::max(t.worst, amount);
}

void judge(const Probe& p, double allowance, Tallies& t) {
  const Interval& bt = p.bt;
  // Prop 7: BT = inf at x and along every sequence exactly where the peeling keeps it.
  ++t.prop7.points;
  if (bt.is_infinite() != p.closed) violation(t.prop7, 1);
  for (const Sequence& s : p.sectors)
    for (const Interval& v : s.bt) {
      ++t.prop7.points;
      if (v.is_infinite() != s.in_closed) violation(t.prop7, 1);
    }
  // Prop 5.1 and 5.2.
  Interval min_ct = bt;
  for (const Sequence& s : p.sectors)
    if (!s.bt.back().is_infinite()) min_ct = Interval(std::min(min_ct.lo, s.bt.back().lo - s.d.back()), std::min(min_ct.hi, s.bt.back().hi + s.d.back()));
  ++t.usc.points, ++t.lsc.points;  // the probe itself (graphs have no sector sequences)
  bool reaches_bt = p.sectors.empty() || bt.is_infinite(), reaches_ct = reaches_bt;
  std::size_t equal = 0;
  for (const Sequence& s : p.sectors)
    for (std::size_t n = 0; n < s.bt.size(); ++n) {
      const Interval& v = s.bt[n];
      ++t.usc.points, ++t.lsc.points;
      if (v.is_infinite()) continue;  // inf only in the closed subcomplex (Prop 7's row)
      const double slack = s.d[n] + allowance;
      if (!bt.is_infinite() && v.lo > bt.hi + slack) violation(t.usc, v.lo - bt.hi - slack);
      if (!min_ct.is_infinite() && v.hi < min_ct.lo - slack) violation(t.lsc, min_ct.lo - slack - v.hi);
      if (n + 1 == s.bt.size()) {
        reaches_bt = reaches_bt || meets(v, bt, slack);
        reaches_ct = reaches_ct || meets(v, min_ct, slack);
        equal += meets(v, bt, slack) ? 1 : 0;
      }
    }
  if (!reaches_bt) violation(t.usc, 1);
  if (!reaches_ct) violation(t.lsc, 1);
  if (p.border || bt.is_infinite()) return;
  ++t.prop6.points;
  const std::size_t sectors = p.sectors.size();
  if (equal < std::min<std::size_t>(2, sectors)) violation(t.prop6, 1);
}

// |BT(a) - BT(b)| <= d_hi on enclosures: a violation is a certified excess.
void lipschitz(const Interval& a, const Interval& b, double d_hi, Tally& t) {
  ++t.points;
  if (a.is_infinite() || b.is_infinite()) {
    if (a.is_infinite() != b.is_infinite()) violation(t, INFINITY);
    return;
  }
  const double lower = std::max({0.0, a.lo - b.hi, b.lo - a.hi});
  if (lower > d_hi) violation(t, lower - d_hi);
}

// Prop 4 in a sheet: the points of one sequence lie on a segment inside one triangle, so
// d_M2(x_n, x_m) <= |x_n - x_m| = d_n - d_m. The output mutants act on a copy of these
// values (the point of median BT), apart from the probes' mutation.
void check_prop4_sheet(const CheckContext& ctx, const std::vector<Probe>& ps, Tally& t) {
  std::vector<Interval> values;
  std::vector<double> mid;
  for (const Probe& p : ps)
    for (const Sequence& s : p.sectors)
      if (s.bt.size() > 1)
        for (const Interval& v : s.bt) values.push_back(v), mid.push_back(v.mid());
  std::vector<double> m = mid;
  mutate_burning_times(ctx, m, [](std::size_t) { return true; }, [](std::size_t) { return false; });
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i] != mid[i])
      values[i] = std::isinf(m[i]) ? Interval::infinity() : Interval(values[i].lo + m[i] - mid[i], values[i].hi + m[i] - mid[i]);
  ++t.instances;
  std::size_t i = 0;
  for (const Probe& p : ps)
    for (const Sequence& s : p.sectors) {
      if (s.bt.size() < 2) continue;
      for (std::size_t a = 0; a < s.bt.size(); ++a)
        for (std::size_t b = a + 1; b < s.bt.size(); ++b) lipschitz(values[i + a], values[i + b], (s.d[a] - s.d[b]) * (1 + 0x1p-30), t);
      i += s.bt.size();
    }
}

// Prop 4 on singular curves: BT at the points 1/4, 1/2, 3/4 of every singular edge, against
// their distance along the (straight) edge.
void check_prop4_curves(const CheckContext& ctx, Values& values, const MedialComplex& mc, Tally& t) {
  std::vector<Interval> bt;
  std::vector<std::pair<std::uint32_t, int>> where;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular) continue;
    const ExactPoint3& a = mc.vertex(mc.edge(e).v[0]).exact;
    for (int q = 1; q <= 3; ++q) {
      ComplexPoint x;
      x.kind = ComplexPoint::Kind::Edge, x.id = e, x.parameter = mpq_class(q, 4);
      x.parameter.canonicalize();
      x.point = a + x.parameter * (mc.vertex(mc.edge(e).v[1]).exact - a);
      bt.push_back(values.at(x));
      where.emplace_back(e, q);
    }
  }
  std::vector<double> mid(bt.size());
  for (std::size_t i = 0; i < bt.size(); ++i) mid[i] = bt[i].mid();
  std::vector<double> m = mid;
  mutate_burning_times(ctx, m, [](std::size_t) { return false; }, [](std::size_t) { return false; });
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i] != mid[i]) bt[i] = std::isinf(m[i]) ? Interval::infinity() : Interval(bt[i].lo + m[i] - mid[i], bt[i].hi + m[i] - mid[i]);
  ++t.instances;
  for (std::size_t i = 0; i + 1 < bt.size(); ++i) {
    if (where[i].first != where[i + 1].first) continue;
    lipschitz(bt[i], bt[i + 1], mc.edge(where[i].first).length * 0.25 * (1 + 0x1p-30), t);
  }
}

// Def. 10 on the exact BT against the definition, at every vertex and edge probe: BT(x) is
// the infimum of the times at which burning paths of Definition 9 reach x, and the discrete
// baseline's value at a vertex is the time of one such path along its Steiner graph, so
// BT(v) <= BT_h(v) (the upper side, at vertices of every instance; BT infinite only where
// BT_h is; an edge probe need not be a graph point of the baseline, so it is not judged
// against the baseline); where the
// corpus has an independent value (the closed forms of books, the Y, box axes, the cube and
// the octahedron; corpora3d.h), BT(x) equals it to rounding (both sides), R interpolated
// linearly along an edge as the references expect.
void check_definition10(const Instance3& in, const std::vector<Probe>& ep, Values& baseline, Tally& t) {
  ++t.instances;
  const MedialComplex& mc = in.mc;
  for (const Probe& p : ep) {
    if (p.x.kind != ComplexPoint::Kind::Vertex && p.x.kind != ComplexPoint::Kind::Edge) continue;
    ++t.points;
    if (p.x.kind == ComplexPoint::Kind::Vertex) {
      const Interval h = baseline.at(p.x);
      if (p.bt.is_infinite() != h.is_infinite()) violation(t, DiscreteBurning::kInfinity);
      if (p.bt.is_infinite() || h.is_infinite()) continue;
      if (p.bt.lo > h.hi + 1e-9 * (1 + std::abs(h.hi))) violation(t, p.bt.lo - h.hi);
    }
    if (p.bt.is_infinite() && !in.reference) continue;
    if (!in.reference || in.planar_convex_sheet) continue;
    double radius = 0;
    if (p.x.kind == ComplexPoint::Kind::Vertex) {
      radius = mc.vertex(p.x.id).radius;
    } else {
      const double s = p.x.parameter.get_d();
      radius = (1 - s) * mc.vertex(mc.edge(p.x.id).v[0]).radius + s * mc.vertex(mc.edge(p.x.id).v[1]).radius;
    }
    const double ref = in.reference(mc, {p.x.point.x.get_d(), p.x.point.y.get_d(), p.x.point.z.get_d()}, radius);
    if (std::isnan(ref)) continue;  // outside the reference's domain
    if (!meets(p.bt, std::isinf(ref) ? Interval::infinity() : Interval(ref), 1e-9 * (1 + std::abs(ref))))
      violation(t, std::isinf(ref) ? DiscreteBurning::kInfinity : std::max(p.bt.lo - ref, ref - p.bt.hi));
  }
}

struct CorpusRun {
  Tallies exact, discrete;
  std::size_t refused = 0;
  std::string reason;
  std::uint64_t uncertified = 0;
};

constexpr std::size_t kMaxSingularEdges = 450;

void run_instance(const CheckContext& ctx, const Instance3& in, CorpusRun& c) {
  const ClosedSubcomplex k = maximal_closed_subcomplex(in.mc);
  const DiscreteBurning d = burn_discrete(in.mc, {in.spacing});
  const DiscreteBurningField field(in.mc, d);
  DiscreteValues dv(field);
  std::vector<Probe> dp = probes(ctx, dv, in.mc, k);
  mutate(ctx, dp);
  Tallies& dt = c.discrete;
  ++dt.usc.instances, ++dt.lsc.instances, ++dt.prop6.instances, ++dt.prop7.instances;
  for (const Probe& p : dp) judge(p, in.spacing, dt);
  if (const std::optional<std::string> why = exact_engine_unsupported(in.mc)) {
    ++c.refused;
    c.reason = *why;
    return;
  }
  // The junction rule's cost grows faster than linearly in the singular edges, so the
  // report keeps to the complexes it burns in seconds and counts the others as refused, with
  // the reason. tripod-s2.ma (222, under a second) runs since the sliver fix (NaN in the
  // double stage left a vertex unburned, failing Props 5.1, 5.2, 6 and 7 here); joint.ma
  // (402, about 5 s) since the kinks' rational brackets (0 uncertified) and the sources at
  // the burned ends of singular edges (without them "Prop 4 in a sheet" failed by 0.0054).
  if (in.mc.count(EdgeStratum::Singular) > kMaxSingularEdges) {
    ++c.refused;
    c.reason = "more than " + std::to_string(kMaxSingularEdges) +
               " singular edges (the junction rule is not yet fast enough on them for this report)";
    return;
  }
  ExactBurning eb(in.mc, engine_options(ctx));
  eb.add_border_ignition();
  eb.run();
  c.uncertified += eb.certification().uncertified;
  ExactValues ev(eb);
  std::vector<Probe> ep = probes(ctx, ev, in.mc, k);
  mutate(ctx, ep);
  Tallies& et = c.exact;
  ++et.usc.instances, ++et.lsc.instances, ++et.prop6.instances, ++et.prop7.instances;
  for (const Probe& p : ep) judge(p, 0.0, et);
  check_prop4_sheet(ctx, ep, et.prop4_sheet);
  check_prop4_curves(ctx, ev, in.mc, et.prop4_curve);
  check_definition10(in, ep, dv, et.def10);
}

const char* kProp51 = "Prop 5.1 (BT upper semicontinuous; a sequence reaches BT)";
const char* kProp52 = "Prop 5.2 (min CT lower semicontinuous; a sequence reaches it)";
const char* kProp6 = "Prop 6 (at x not on the border, two sectors' limits equal BT)";
const char* kProp7 = "Prop 7 (BT = inf exactly on the maximal closed subcomplex)";

std::vector<CheckRow> exact_rows(const Corpus3& corpus, const CorpusRun& c) {
  const std::string ref = "limits along x_n = x + 2^-n (c_t - x) into vertices and edge points, every sector";
  const std::string tol = "d_n = |x_n - x| (Prop 4 inside the sector; -> 0); the engine's certified enclosures";
  const std::string note = "exact engine; " + std::to_string(c.refused) + " instances refused" +
                           (c.refused ? " (" + c.reason + ")" : "") + "; uncertified decisions " +
                           std::to_string(c.uncertified);
  std::vector<CheckRow> rows = {
      tally_row(std::string(kProp51) + " on the exact BT", corpus.name, ref, tol, c.exact.usc, "length", note),
      tally_row(std::string(kProp52) + " on the exact BT", corpus.name, ref, tol, c.exact.lsc, "length", note),
      tally_row(std::string(kProp6) + " on the exact BT", corpus.name, ref, tol, c.exact.prop6, "count", note),
      tally_row(std::string(kProp7) + " on the exact BT", corpus.name, "maximal closed subcomplex peeled combinatorially",
                "exact", c.exact.prop7, "points", note),
      tally_row("Def. 10 on the exact BT (BT = inf over burning paths)", corpus.name,
                corpus.references.empty() || corpus.references == "none"
                    ? "the discrete baseline's value at every vertex (the time of one burning path): BT <= BT_h"
                    : "BT <= BT_h (the discrete baseline: one burning path's time) at every vertex; BT = the "
                      "independent value (" + corpus.references + ") where the instance has one",
                "the engine's certified enclosures; 1e-9 relative rounding of the doubles", c.exact.def10, "length",
                note)};
  CheckRow sheet = tally_row("Prop 4 in a sheet on the exact BT (|BT(x) - BT(y)| <= d, no allowance)", corpus.name,
                             "d: the straight length between two points of one sequence (a segment inside one triangle)",
                             "the engine's certified enclosures; rounding of d only", c.exact.prop4_sheet, "length", note);
  // A Prop 4 row with no point in instances the engine did burn: nothing of that kind there.
  const auto push_unless_empty = [&](CheckRow row, const auto& tally, const std::string& why) {
    if (tally.points == 0 && c.exact.usc.instances > 0) {
      row.verdict = Verdict::NotChecked;
      row.note = why + note;
    }
    rows.push_back(std::move(row));
  };
  push_unless_empty(sheet, c.exact.prop4_sheet, "no sheet in the instances the exact engine burns here (graphs only); ");
  CheckRow curves = tally_row("Prop 4 on singular curves on the exact BT (|BT(x) - BT(y)| <= arclength)", corpus.name,
                              "BT at 1/4, 1/2, 3/4 of every singular edge; d: their distance along the edge",
                              "the engine's certified enclosures; rounding of d only", c.exact.prop4_curve, "length", note);
  push_unless_empty(curves, c.exact.prop4_curve,
                    "no singular curve in the instances the exact engine burns today (it refuses singular edges); ");
  if (c.exact.usc.instances == 0)
    for (CheckRow& r : rows) {
      r.verdict = Verdict::NotChecked;
      r.note = "the exact engine refuses every instance of this corpus today: " + c.reason +
               "; these rows run as soon as it burns them (exact_engine_unsupported)";
    }
  return rows;
}

std::vector<CheckRow> discrete_rows(const Corpus3& corpus, const CorpusRun& c) {
  const std::string ref = "the same limits on the discrete baseline (BT_h at x, t-side samples along x_n)";
  const std::string tol = "d_n + h (h: the baseline's spacing; its paths are O(h) longer than the exact ones)";
  return {tally_row(std::string(kProp51) + " on the baseline", corpus.name, ref, tol, c.discrete.usc, "length",
                    "discrete baseline, allowance h"),
          tally_row(std::string(kProp6) + " on the baseline", corpus.name, ref, tol, c.discrete.prop6, "count",
                    "discrete baseline, allowance h")};
}

std::vector<CheckRow> check_exact_chapter4(const CheckContext& ctx) {
  std::vector<CheckRow> rows;
  for (const Corpus3& corpus : burning_corpora(ctx)) {
    if (corpus.instances.empty()) continue;
    CorpusRun c;
    for (const Instance3& in : corpus.instances) run_instance(ctx, in, c);
    for (CheckRow& r : exact_rows(corpus, c)) rows.push_back(std::move(r));
    for (CheckRow& r : discrete_rows(corpus, c)) rows.push_back(std::move(r));
  }
  return rows;
}

MutantList chapter4_mutants() {
  MutantList output;
  for (const MutantInfo& m : burning_mutants())
    if (m.name == "bt-bump" || m.name == "bt-dip" || m.name == "bt-infinite" || m.name == "closed-burns")
      output.push_back(m);
  for (const MutantInfo& m : engine_mutants()) output.push_back(m);
  return output;
}

GF_REGISTER_CHECK("exact-chapter4", check_exact_chapter4, chapter4_mutants());

}  // namespace
}  // namespace grassfire::checks
