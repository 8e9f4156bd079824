// Strata, sheets, sectors and links of hand-built medial complexes (ch. 4, docs/design.md 5).
#include <catch2/catch.hpp>

#include <cmath>

#include "complex3/complex_builder.h"
#include "complex3/medial_complex.h"
#include "complex3/synthetic_complexes.h"
#include "number/exact_sum.h"
#include "test_complex3_support.h"

using namespace grassfire;

using testing::built;

namespace {

std::uint32_t vertex_at(const MedialComplex& mc, long x, long y, long z) { return testing::vertex_at(mc, {x, y, z}); }

std::size_t count_sectors(const MedialComplex& mc, std::uint32_t v) {
  std::size_t n = 0;
  for (const LinkElement& el : mc.link_elements(v)) n += el.is_pole ? 0 : 1;
  return n;
}

}  // namespace

TEST_CASE("book of k pages: one singular spine, k sheets, k sectors on the spine", "[complex3]") {
  for (int k : {3, 4, 5, 7}) {
    BookOptions o;
    o.pages = k;
    o.cells_per_unit = 1;
    o.height = 2;
    const MedialComplex mc = built(book(o));
    CAPTURE(k);
    CHECK(mc.sheets().size() == static_cast<std::size_t>(k));
    CHECK(mc.count(EdgeStratum::Singular) == 2);  // the spine, two unit edges
    for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
      if (mc.edge(e).stratum == EdgeStratum::Singular) CHECK(mc.edge_triangles(e).size() == static_cast<std::size_t>(k));
    const std::uint32_t mid = vertex_at(mc, 0, 0, 1);
    CHECK(mc.vertex(mid).kind == VertexKind::SingularCurve);
    CHECK(count_sectors(mc, mid) == static_cast<std::size_t>(k));
    CHECK_FALSE(mc.is_border_point(mid));
    // The spine ends: a star of k pages, no cycle: border points igniting at f = R = 0.
    const std::uint32_t end = vertex_at(mc, 0, 0, 0);
    CHECK(mc.vertex(end).kind == VertexKind::SingularPoint);
    CHECK(mc.is_border_point(end));
    CHECK(mc.ignition_at_vertex(end) == 0.0);
    for (const Sheet& s : mc.sheets()) CHECK(s.planar);
  }
}

TEST_CASE("angular order around the spine follows the page angles", "[complex3]") {
  BookOptions o;
  o.pages = 5;
  o.cells_per_unit = 1;
  const MedialComplex mc = built(book(o));
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular) continue;
    std::vector<double> angles;
    for (std::uint32_t t : mc.edge_triangles(e)) {
      const auto& p = mc.vertex(third_vertex(mc.triangle(t), mc.edge(e).v)).approx;
      angles.push_back(std::atan2(p[1], p[0]));
    }
    // Seen from the upper end the order is counterclockwise: angles increase cyclically.
    int descents = 0;
    for (std::size_t i = 0; i < angles.size(); ++i) descents += angles[(i + 1) % angles.size()] < angles[i] ? 1 : 0;
    CHECK(descents == 1);
  }
}

TEST_CASE("board and fin: strata, sheets, the corner c and the junction N", "[complex3]") {
  const MedialComplex mc = built(board_fin({6, 1}));
  CHECK(mc.sheets().size() == 2);  // the board (slit along N) and the fin
  CHECK(mc.count(EdgeStratum::Singular) == 5);  // N from s = 1 to 6
  CHECK(mc.count(EdgeStratum::Dangling) == 0);
  const std::uint32_t c = vertex_at(mc, 1, 1, 0);
  // c: the board's fan is a loop at N and the fin's quarter a pendant arc: a cycle.
  CHECK(mc.vertex(c).kind == VertexKind::SingularPoint);
  CHECK_FALSE(mc.is_border_point(c));
  CHECK(count_sectors(mc, c) == 2);
  const std::uint32_t n3 = vertex_at(mc, 3, 3, 0);
  CHECK(mc.vertex(n3).kind == VertexKind::SingularCurve);
  CHECK(count_sectors(mc, n3) == 3);
  const std::uint32_t b0 = vertex_at(mc, 2, 0, 0);
  CHECK(mc.vertex(b0).kind == VertexKind::Border);
  CHECK(mc.ignition_at_vertex(b0) == 0.0);
  const std::uint32_t far = vertex_at(mc, -6, 3, 0);  // on a truncation border
  CHECK(mc.is_border_point(far));
  CHECK(std::isinf(mc.ignition_at_vertex(far)));
  CHECK(mc.vertex(vertex_at(mc, 0, 2, 0)).kind == VertexKind::Interior);
  for (const Sheet& s : mc.sheets()) CHECK(s.planar);
}

TEST_CASE("Y of three half-planes and a pinched double cone", "[complex3]") {
  const MedialComplex y = built(y_junction(1));
  CHECK(y.sheets().size() == 3);
  CHECK(y.count(VertexKind::SingularCurve) == 9);  // spine interior vertices z = 1, ..., 9
  const MedialComplex cone = built(pinched_double_cone(6));
  CHECK(cone.sheets().size() == 2);
  CHECK(cone.count(EdgeStratum::Singular) == 0);
  const std::uint32_t apex = vertex_at(cone, 0, 0, 0);
  CHECK(cone.vertex(apex).kind == VertexKind::SingularPoint);
  CHECK(count_sectors(cone, apex) == 2);
  for (const LinkElement& el : cone.link_elements(apex)) CHECK(cone.sectors()[el.id].closed);
  CHECK_FALSE(cone.is_border_point(apex));
  CHECK(cone.sheets()[0].planar == false);
}

TEST_CASE("closed surfaces: no border, every vertex interior", "[complex3]") {
  for (const RawComplex& raw : {tetrahedron_surface(), octahedron_surface()}) {
    const MedialComplex mc = built(raw);
    CHECK(mc.count(EdgeStratum::Border) == 0);
    CHECK(mc.count(VertexKind::Interior) == mc.vertex_count());
    CHECK(mc.sheets().size() == 1);
    CHECK_FALSE(mc.sheets()[0].planar);
  }
  const MedialComplex flap = built(tetrahedron_with_flap());
  CHECK(flap.count(EdgeStratum::Singular) == 1);
  CHECK(flap.sheets().size() == 2);
}

TEST_CASE("link rule: no cycle and at most one segment direction left", "[complex3]") {
  // Edge interiors: border burns at once, manifold after one arc, singular after k - 1.
  CHECK(MedialComplex::edge_link_burns(1, false, false, 0));
  CHECK_FALSE(MedialComplex::edge_link_burns(2, false, false, 0));
  CHECK(MedialComplex::edge_link_burns(2, false, false, 1));
  CHECK_FALSE(MedialComplex::edge_link_burns(4, false, false, 2));
  CHECK(MedialComplex::edge_link_burns(4, false, false, 3));
  CHECK(MedialComplex::edge_link_burns(4, false, false, 4));  // monotone (Lemma 2)
  CHECK(MedialComplex::edge_link_burns(4, true, false, 0));
  CHECK_FALSE(MedialComplex::edge_link_burns(0, false, false, 0));
  CHECK(MedialComplex::edge_link_burns(0, false, true, 0));
  // A three-segment junction burns like a 2D node: after two arrivals.
  ComplexBuilder b("tripod");
  const auto o = b.vertex({0, 0, 0});
  for (long i : {1, 2, 3}) b.segment(o, b.vertex({i, i * i, 0}));
  const MedialComplex mc = built(b.raw());
  CHECK(mc.vertex(o).kind == VertexKind::SingularPoint);
  CHECK(mc.count(VertexKind::SegmentEnd) == 3);
  CHECK_FALSE(mc.link_burns(o, {true, false, false}));
  CHECK(mc.link_burns(o, {true, false, true}));
  CHECK(mc.link_burns(o, {true, true, true}));
}

TEST_CASE("malformed raw complexes are rejected with the first violation", "[complex3]") {
  auto message = [](const RawComplex& raw) {
    try {
      MedialComplex mc(raw);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  ComplexBuilder b("hand");
  const auto p0 = b.vertex({0, 0, 0}), p1 = b.vertex({1, 0, 0}), p2 = b.vertex({0, 1, 0});
  b.triangle(p0, p1, p2);
  RawComplex ok = b.raw();
  CHECK(message(ok) == "accepted");
  RawComplex r = ok;
  r.triangles.push_back({0, 1, 7});
  CHECK_THAT(message(r), Catch::Contains("out of range"));
  r = ok;
  r.vertices.push_back({2, 2, 0});
  r.radius_squared.push_back(0);
  r.vertices.push_back({4, 4, 0});
  r.radius_squared.push_back(0);
  r.triangles.push_back({0, 3, 4});
  CHECK_THAT(message(r), Catch::Contains("degenerate"));
  r = ok;
  r.triangles.push_back({2, 1, 0});
  CHECK_THAT(message(r), Catch::Contains("are the same"));
  r = ok;
  r.vertices.push_back({1, 0, 0});
  r.radius_squared.push_back(0);
  CHECK_THAT(message(r), Catch::Contains("coincide"));
  r = ok;
  r.segments.push_back({0, 1});
  CHECK_THAT(message(r), Catch::Contains("also an edge"));
  r = ok;
  r.vertices.push_back({1, 1, 0});  // a second triangle folded onto the first
  r.radius_squared.push_back(0);
  r.triangles.push_back({0, 1, 3});
  CHECK_THAT(message(r), Catch::Contains("overlap"));
  r = ok;
  r.radius_squared[1] = -1;
  CHECK_THAT(message(r), Catch::Contains("R^2 < 0"));
  r = ok;
  r.border_rules.push_back({{0, 2}, IgnitionRule::Never, {}});
  CHECK(message(r) == "accepted");
  r.border_rules.push_back({{0, 9}, IgnitionRule::Never, {}});
  CHECK_THAT(message(r), Catch::Contains("not a border edge"));
  CHECK_THAT(message(RawComplex{}), Catch::Contains("empty"));
  // Embedding: crossing triangles, a segment through a triangle, overlapping edges.
  r = ok;  // three more points on the vertical line x = y = 1/4 and at (1, 1, 0)
  const mpq_class q = make_rational(1, 4);
  for (const ExactPoint3& p : {ExactPoint3{q, q, -1}, ExactPoint3{q, q, 1}, ExactPoint3{1, 1, 0}}) {
    r.vertices.push_back(p);
    r.radius_squared.push_back(0);
  }
  RawComplex crossing = r;  // a vertical triangle in the plane x = y, through the first one
  crossing.triangles.push_back({3, 4, 5});
  CHECK_THAT(message(crossing), Catch::Contains("triangle 0 and triangle 1 intersect"));
  RawComplex pierced = r;  // a segment through the first triangle
  pierced.segments.push_back({3, 4});
  CHECK_THAT(message(pierced), Catch::Contains("segment 0 intersect"));
  RawComplex coplanar = ok;  // a second triangle in the plane z = 0 overlapping the first
  coplanar.vertices.insert(coplanar.vertices.end(), {{q, q, 0}, {2, q, 0}, {q, 2, 0}});
  coplanar.radius_squared.insert(coplanar.radius_squared.end(), {0, 0, 0});
  coplanar.triangles.push_back({3, 4, 5});
  CHECK_THAT(message(coplanar), Catch::Contains("triangle 0 and triangle 1 intersect"));
  RawComplex apart = coplanar;  // the same, moved clear of the first: accepted
  for (std::size_t v = 3; v < 6; ++v) apart.vertices[v].x += 2;
  CHECK(message(apart) == "accepted");
  RawComplex folded = ok;  // a triangle sharing only vertex 0, along half of edge 0-1
  folded.vertices.push_back({make_rational(1, 2), 0, 0});
  folded.vertices.push_back({0, 0, 1});
  folded.radius_squared.insert(folded.radius_squared.end(), {0, 0});
  folded.triangles.push_back({0, 3, 4});
  CHECK_THAT(message(folded), Catch::Contains("intersect"));
}
