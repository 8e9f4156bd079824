// Medial curves (5.1.2): known answers on synthetic complexes, the axis' Betti numbers on
// every kind of complex, invariance under exact similarities, and validate() catching
// broken graphs.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "curves3/curve_distance.h"
#include "burn3/discrete/discrete_burning_field.h"
#include "curves3/medial_curves.h"
#include "medial3/convex/convex_polyhedron_axis.h"
#include "complex3/synthetic_complexes.h"
#include "complex3/synthetic_tubes.h"
#include "geometry3/vec3.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"
#include "support/union_find.h"
#include "test_complex3_support.h"

using namespace grassfire;
using testing::built;

namespace {

// A complex, its discrete burning at spacing h, and its medial curves.
struct CurvesRun {
  MedialComplex mc;
  DiscreteBurning d;
  std::unique_ptr<DiscreteBurningField> field;
  MedialCurves curves;
  CurvesRun(const RawComplex& raw, double h, const MedialCurveOptions& o = {}) : mc(built(raw)), d(burn_discrete(mc, {h})) {
    field = std::make_unique<DiscreteBurningField>(mc, d);
    curves = medial_curves(*field, o);
  }
};

using Segment = std::array<Vec3d, 2>;

double to_segment(const Vec3d& p, const Segment& s) {
  const Vec3d ab = v3::sub(s[1], s[0]);
  const double t = std::clamp(v3::dot(v3::sub(p, s[0]), ab) / v3::dot(ab, ab), 0.0, 1.0);
  return v3::dist(p, v3::lerp(s[0], s[1], t));
}

double to_segments(const Vec3d& p, const std::vector<Segment>& set) {
  double d = 1e300;
  for (const Segment& s : set) d = std::min(d, to_segment(p, s));
  return d;
}

// Largest distance from a curve node to the expected segments, and from points sampled
// on the expected segments (every h / 2) to the curve's nodes.
std::pair<double, double> hausdorff(const MedialCurves& c, const std::vector<Segment>& expected, double h) {
  double out = 0, in = 0;
  for (const CurveNode& n : c.nodes) out = std::max(out, to_segments(n.position, expected));
  for (const Segment& s : expected) {
    const int steps = static_cast<int>(std::ceil(v3::dist(s[0], s[1]) / (h / 2)));
    for (int i = 0; i <= steps; ++i) {
      const Vec3d p = v3::lerp(s[0], s[1], static_cast<double>(i) / steps);
      double best = 1e300;
      for (const CurveNode& n : c.nodes) best = std::min(best, v3::dist(p, n.position));
      in = std::max(in, best);
    }
  }
  return {out, in};
}

}  // namespace

TEST_CASE("medial curves of a box axis: the middle rectangle's medial axis and the corner segments", "[curves]") {
  const long a = 4, b = 3, c = 1;
  const double h = 0.2;
  const CurvesRun r(box_medial_axis(a, b, c, 2), h);
  r.curves.validate(r.mc);
  CHECK(r.curves.curve_betti.b0 == 1);
  CHECK(r.curves.curve_betti.b1 == 0);
  std::vector<Segment> expected = {{Vec3d{-(a - b) * 1.0, 0, 0}, Vec3d{(a - b) * 1.0, 0, 0}}};
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const Vec3d corner{sx * double(a - c), sy * double(b - c), 0};
      expected.push_back({Vec3d{sx * double(a - b), 0, 0}, corner});
      for (int sz : {-1, 1}) expected.push_back({corner, Vec3d{sx * double(a), sy * double(b), sz * double(c)}});
    }
  const auto [out, in] = hausdorff(r.curves, expected, h);
  CAPTURE(out, in, r.curves.nodes.size());
  CHECK(out <= 1.5 * h);  // every curve point near the expected skeleton
  CHECK(in <= 1.5 * h);   // and the whole skeleton found
}

TEST_CASE("medial curves of a tube and an annulus keep their cycle", "[curves]") {
  const TubeOptions t{12, 8, 2, 8};
  const double h = 0.25;
  const CurvesRun tube_run(tube(t), h);
  tube_run.curves.validate(tube_run.mc);
  CHECK(tube_run.curves.curve_betti.b1 == 1);
  double worst = 0;
  for (const CurveNode& n : tube_run.curves.nodes) worst = std::max(worst, std::abs(n.position[2] - t.height / 2.0));
  CHECK(worst <= h);  // the ring where the fronts from both rims meet
  // BT of the tube against its closed form at the graph's vertices.
  for (std::uint32_t v = 0; v < tube_run.mc.vertex_count(); ++v)
    CHECK(tube_run.d.vertex_bt[v] == Approx(tube_burning_time(t, tube_run.mc.vertex(v).approx[2])).margin(1e-9));

  const AnnulusOptions o{4, 2, 2};
  const CurvesRun ring(square_annulus(o), h);
  ring.curves.validate(ring.mc);
  CHECK(ring.curves.curve_betti.b1 == 1);
  std::vector<Segment> expected;
  const double m = (o.outer + o.inner) / 2.0;
  const Vec3d sq[4] = {{-m, -m, 0}, {m, -m, 0}, {m, m, 0}, {-m, m, 0}};
  for (int i = 0; i < 4; ++i) {
    expected.push_back({sq[i], sq[(i + 1) % 4]});
    expected.push_back({sq[i], v3::scale(sq[i], o.outer / m)});
  }
  const auto [out, in] = hausdorff(ring.curves, expected, h);
  CAPTURE(out, in);
  CHECK(out <= 1.5 * h);
  CHECK(in <= 1.5 * h);
}

TEST_CASE("medial curves of the board and fin: the junction beyond the kink", "[curves]") {
  const double h = 0.25, kink = 2 + std::sqrt(2.0);
  const CurvesRun r(board_fin({12, 1}), h);
  r.curves.validate(r.mc);
  // Away from the truncation (fire leaves the far end of N early, synthetic_complexes.h)
  // the curve is N from k on: the back side's fire dies there.
  for (const CurveNode& n : r.curves.nodes) {
    const Vec3d& p = n.position;
    if (std::max({std::abs(p[0]), p[1], p[2]}) > 8) continue;
    CAPTURE(p[0], p[1], p[2]);
    CHECK(std::abs(p[0] - p[1]) <= 1e-9);
    CHECK(std::abs(p[2]) <= 1e-9);
    CHECK(p[0] >= kink - 3 * h);
  }
  for (double s = kink + 3 * h; s <= 8; s += h / 2) {
    double best = 1e300;
    for (const CurveNode& n : r.curves.nodes) best = std::min(best, v3::dist(n.position, {s, s, 0}));
    CAPTURE(s);
    CHECK(best <= h);
  }
}

TEST_CASE("Y junction: the raw ends hold a cycle that bounds, the curves do not", "[curves]") {
  // Page 1 (width 2) dies on the spine for 2 < z < 8 and page 3 (width 4) quenches at
  // u = 1/2: spine and ridge enclose a strip of page 3 (medial_curves.h).
  const double h = 0.125;
  const CurvesRun r(y_junction(2), h);
  r.curves.validate(r.mc);
  CHECK(r.curves.curve_betti.b1 == 0);
  CHECK(r.curves.stats.walls_opened >= 1);
  const AxisRefinement k = AxisRefinement::build(*r.field);
  std::vector<bool> raw = raw_end_edges(k, {}, h);
  close_raw_ends(k, raw, 2, 3 * h);
  UnionFind uf(k.vertices.size());
  long edges = 0, cycles = 0;
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    if (!raw[e]) continue;
    ++edges;
    if (uf.find(k.edges[e].v[0]) == uf.find(k.edges[e].v[1])) ++cycles;
    uf.unite(k.edges[e].v[0], k.edges[e].v[1]);
  }
  CAPTURE(edges);
  CHECK(cycles >= 1);
  // The ridge of page 3 stays (the wall opened is elsewhere on the cycle or on the spine).
  const auto dir = rational_unit_direction(4 * M_PI / 3);
  for (double z : {4.5, 5.5}) {
    const Vec3d p{0.5 * dir[0].get_d(), 0.5 * dir[1].get_d(), z};
    double best = 1e300;
    for (const CurveNode& n : r.curves.nodes) best = std::min(best, v3::dist(n.position, p));
    CAPTURE(z);
    CHECK(best <= 2 * h);
  }
}

TEST_CASE("medial curves have the axis' b0 and b1 on every kind of complex", "[curves]") {
  struct Case {
    std::string name;
    RawComplex raw;
    double h;
  };
  std::vector<Case> cases = {{"book:4", book({4, {1, 2, 3, 2}, 0, 1}), 0.2},
                             {"double-cone", pinched_double_cone(6), 0.1},
                             {"board-cylinder", board_cylinder({12, 2, 3, 2.0, 6}), 0.3},
                             {"tetrahedron (closed, b2 = 1)", tetrahedron_surface(), 0.1},
                             {"tetrahedron-flap", tetrahedron_with_flap(), 0.1},
                             {"frame torus (b1 = 2, b2 = 1)", frame_torus(3, 1, 1), 0.25},
                             {"box .ma", read_ma(std::string(GF_PROJECT_DATA) + "/ma/box_5_3_2.ma"), 0.3},
                             {"cube (convex builder)",
                              convex_polyhedron_axis(convex_polyhedron_from_mesh(
                                                         read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/cube.off")))
                                  .complex,
                              0.1}};
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const CurvesRun r(c.raw, c.h);
    REQUIRE_NOTHROW(r.curves.validate(r.mc));
    CHECK(r.curves.curve_betti.b0 == r.curves.axis_betti.b0);
    CHECK(r.curves.curve_betti.b1 == r.curves.axis_betti.b1);
    CHECK(static_cast<long>(r.curves.stats.punctures) == r.curves.axis_betti.b2);
    CHECK(r.curves.stats.residual_triangles == 0);
  }
}

TEST_CASE("medial curves are invariant under exact similarities", "[curves]") {
  // Scaling by 2 (with h) and a quarter turn about z change no double computation's
  // outcome: the same graph, mapped.
  const RawComplex base = y_junction(1);
  RawComplex scaled = base, turned = base;
  for (ExactPoint3& p : scaled.vertices) p = {2 * p.x, 2 * p.y, 2 * p.z};
  for (mpq_class& r2 : scaled.radius_squared) r2 *= 4;
  for (ExactPoint3& p : turned.vertices) p = {-p.y, p.x, p.z};
  const double h = 0.25;
  const CurvesRun a(base, h), b(scaled, 2 * h), c(turned, h);
  REQUIRE(a.curves.nodes.size() == b.curves.nodes.size());
  REQUIRE(a.curves.edges.size() == b.curves.edges.size());
  REQUIRE(a.curves.nodes.size() == c.curves.nodes.size());
  REQUIRE(a.curves.edges.size() == c.curves.edges.size());
  for (std::size_t i = 0; i < a.curves.nodes.size(); ++i) {
    const Vec3d& p = a.curves.nodes[i].position;
    CHECK(v3::dist(v3::scale(p, 2), b.curves.nodes[i].position) <= 1e-12);
    CHECK(v3::dist(Vec3d{-p[1], p[0], p[2]}, c.curves.nodes[i].position) <= 1e-12);
  }
}

TEST_CASE("validate catches broken curve graphs", "[curves]") {
  const CurvesRun r(box_medial_axis(4, 3, 1, 1), 0.3);
  REQUIRE_NOTHROW(r.curves.validate(r.mc));
  REQUIRE(r.curves.edges.size() > 4);
  {  // a joining edge removed: two components
    MedialCurves m = r.curves;
    m.edges.erase(m.edges.begin() + static_cast<long>(m.edges.size() / 2));
    m.curve_betti.b0 += 1;
    CHECK_THROWS_WITH(m.validate(r.mc), Catch::Contains("b0 = 2"));
  }
  {  // an extra edge closing a cycle
    MedialCurves m = r.curves;
    CurveEdge e = m.edges.front();
    e.u = m.edges.front().u;
    e.v = m.edges.back().v;
    e.length = v3::dist(m.nodes[e.u].position, m.nodes[e.v].position);
    m.edges.push_back(e);
    m.curve_betti.b1 += 1;
    CHECK_THROWS(m.validate(r.mc));
  }
  {  // a node moved off the axis
    MedialCurves m = r.curves;
    m.nodes[m.edges[0].u].position[2] += 0.5;
    m.edges[0].length = v3::dist(m.nodes[m.edges[0].u].position, m.nodes[m.edges[0].v].position);
    CHECK_THROWS_WITH(m.validate(r.mc), Catch::Contains("leaves its cell"));
  }
  {  // a wrong length
    MedialCurves m = r.curves;
    m.edges[0].length *= 1.5;
    CHECK_THROWS_WITH(m.validate(r.mc), Catch::Contains("length"));
  }
  {  // not one-dimensional
    MedialCurves m = r.curves;
    m.stats.residual_triangles = 3;
    CHECK_THROWS_WITH(m.validate(r.mc), Catch::Contains("not 1-dimensional"));
  }
}

TEST_CASE("Hausdorff distance between curve graphs: zero to itself, the offset of a parallel copy", "[curves]") {
  const CurvesRun r(square_annulus({4, 2, 2}), 0.25);
  MedialCurves moved = r.curves;  // the annulus' curves lie in z = 0; lifted by 0.3
  for (CurveNode& n : moved.nodes) n.position[2] += 0.3;
  CHECK(curve_hausdorff(r.curves, r.curves, 0.05) <= 1e-12);
  CHECK(curve_hausdorff(r.curves, moved, 0.05) == Approx(0.3).margin(1e-12));
  // Against brute force on a shifted copy (x + 0.17): every sample's nearest segment.
  MedialCurves shifted = r.curves;
  for (CurveNode& n : shifted.nodes) n.position[0] += 0.17;
  double brute = 0;
  for (const CurveNode& n : r.curves.nodes) {
    double best = 1e300;
    for (const CurveEdge& e : shifted.edges) {
      const Segment s = {shifted.nodes[e.u].position, shifted.nodes[e.v].position};
      best = std::min(best, to_segment(n.position, s));
    }
    brute = std::max(brute, best);
  }
  CHECK(directed_curve_distance(r.curves, shifted, 1e9) == Approx(brute).margin(1e-12));  // nodes only
}
