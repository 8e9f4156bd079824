// The medial axis of closed meshes with the solid's topology (mesh_axis.h): the solid's
// Betti numbers from the mesh, the exact locator against a definition-level parity test,
// the homotopy-preserving pruning, the homology, exact vertices, refinement and refusal.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>

#include "medial3/mesh/axis_pruning.h"
#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_checks.h"
#include "complex3/simplicial_homology.h"
#include "geometry3/synthetic_meshes.h"
#include "geometry3/exact_predicates3.h"
#include "complex3/medial_complex.h"
#include "io/mesh_io.h"
#include "number/exact_sum.h"

#include "test_mesh_axis_support.h"

using namespace grassfire;

using grassfire::testing::project_mesh;

namespace {

std::vector<Voxel> scattered_cubes(int count) {
  std::vector<Voxel> v;
  for (int i = 0; i < count; ++i) v.push_back({2 * (i % 5), 2 * ((i / 5) % 5), 2 * (i / 25)});
  return v;
}

// Definition-level parity: count the triangles crossed by the ray from p in direction d
// (exact rationals, every triangle tested), for p on no triangle; nullopt when the ray
// meets an edge or a vertex or runs in a triangle's plane (then another direction).
std::optional<int> ray_parity(const TriangleMesh3& m, const ExactPoint3& p, const ExactPoint3& d) {
  int crossings = 0;
  for (const auto& t : m.triangles) {
    const ExactPoint3 a = exact_point(m.vertices[t[0]]), b = exact_point(m.vertices[t[1]]), c = exact_point(m.vertices[t[2]]);
    const ExactPoint3 n = cross(b - a, c - a);
    const mpq_class den = dot(n, d);
    const mpq_class num = dot(n, a - p);
    if (sgn(den) == 0) {
      if (sgn(num) == 0) return std::nullopt;  // the ray lies in the plane: ambiguous
      continue;
    }
    const mpq_class s = num / den;
    if (sgn(s) <= 0) continue;  // s = 0: p in the plane but not on the triangle (checked first)
    const ExactPoint3 x = p + s * d;
    const int s0 = sgn(dot(n, cross(b - a, x - a))), s1 = sgn(dot(n, cross(c - b, x - b))), s2 = sgn(dot(n, cross(a - c, x - c)));
    if (s0 == 0 || s1 == 0 || s2 == 0) {
      if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return std::nullopt;
      continue;
    }
    if (s0 == s1 && s1 == s2) ++crossings;
  }
  return crossings % 2;
}

bool on_surface(const TriangleMesh3& m, const ExactPoint3& p) {
  for (const auto& t : m.triangles) {
    const ExactPoint3 a = exact_point(m.vertices[t[0]]), b = exact_point(m.vertices[t[1]]), c = exact_point(m.vertices[t[2]]);
    const ExactPoint3 n = cross(b - a, c - a);
    if (sgn(dot(n, p - a)) != 0) continue;
    const int s0 = sgn(dot(n, cross(b - a, p - a))), s1 = sgn(dot(n, cross(c - b, p - b))), s2 = sgn(dot(n, cross(a - c, p - c)));
    if (s0 >= 0 && s1 >= 0 && s2 >= 0) return true;
  }
  return false;
}

int reference_locate(const TriangleMesh3& m, const ExactPoint3& p) {
  if (on_surface(m, p)) return 0;
  const std::vector<ExactPoint3> directions = {{1, make_rational(1, 3), make_rational(1, 7)},
                                               {make_rational(2, 11), 1, make_rational(-3, 13)},
                                               {make_rational(-5, 17), make_rational(1, 19), 1}};
  for (const ExactPoint3& d : directions)
    if (const auto parity = ray_parity(m, p, d)) return *parity ? 1 : -1;
  FAIL("no generic ray direction");
  return 0;
}

void check_axis(const TriangleMesh3& mesh, const BettiNumbers& expected, const MeshAxisOptions& options = {}) {
  CAPTURE(mesh.source);
  const MeshAxis a = mesh_medial_axis(mesh, options);
  CHECK(a.solid.betti == expected);
  CHECK(a.axis_betti == expected);
  // The cellular check on the polygons agrees with simplicial homology of the triangles.
  CHECK(betti_numbers(a.complex) == expected);
  MedialComplex(a.complex).validate();  // embedded, distinct exact vertices, border rules
}

}  // namespace

TEST_CASE("solid locator: exact inside, boundary, outside against a definition-level parity", "[mesh_axis]") {
  const TriangleMesh3 meshes[] = {voxel_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, 1, "L block"),
                                  voxel_mesh(hollow_block_voxels(3), 1, "hollow cube"), project_mesh("tripod.off")};
  std::mt19937 rng(7);
  for (const TriangleMesh3& m : meshes) {
    CAPTURE(m.source);
    const SolidLocator locator(m);
    double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
    for (const auto& v : m.vertices)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 300; ++i) {
      // Points on a coarse rational grid hit faces, edges and vertices, and lie on the
      // lines of mesh edges (the degenerate rays of the +x direction), often.
      ExactPoint3 p;
      mpq_class* c[3] = {&p.x, &p.y, &p.z};
      for (int k = 0; k < 3; ++k) *c[k] = mpq_class(lo[k] - 0.5) + make_rational(static_cast<long>(rng() % 17), 16) * mpq_class(hi[k] - lo[k] + 1);
      if (i % 5 == 0) p = exact_point(m.vertices[rng() % m.vertices.size()]);
      const int got = locator.locate(p);
      CAPTURE(p.x.get_d(), p.y.get_d(), p.z.get_d());
      CHECK(got == reference_locate(m, p));
      ++counts[got + 1];
    }
    CHECK(counts[0] > 0);  // every outcome was exercised
    CHECK(counts[1] > 0);
    CHECK(counts[2] > 0);
  }
}

TEST_CASE("solid topology from the mesh: components, genus, cavities by nesting", "[mesh_axis]") {
  CHECK(solid_topology(torus_mesh(2, 0.5, 12, 8)).betti == BettiNumbers{1, 1, 0});
  CHECK(solid_topology(plate_with_holes(7, 3, {{1, 1}, {3, 1}, {5, 1}})).betti == BettiNumbers{1, 3, 0});
  CHECK(solid_topology(voxel_mesh(scattered_cubes(26))).betti == BettiNumbers{26, 0, 0});
  const SolidTopology hollow = solid_topology(voxel_mesh(hollow_block_voxels(3)));
  CHECK(hollow.betti == BettiNumbers{1, 0, 1});
  REQUIRE(hollow.shells.size() == 2);
  CHECK(hollow.shells[0].depth + hollow.shells[1].depth == 1);
  std::vector<Voxel> nested = hollow_block_voxels(5);  // a cube floating in the cavity of a hollow cube
  nested.push_back({2, 2, 2});
  CHECK(solid_topology(voxel_mesh(nested)).betti == BettiNumbers{2, 0, 1});
  // The even-odd rule needs no orientation: the inside-out mesh bounds the same solid.
  TriangleMesh3 flipped = torus_mesh(2, 0.5, 12, 8);
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  CHECK(solid_topology(flipped).betti == BettiNumbers{1, 1, 0});
  CHECK(solid_topology(project_mesh("double-torus-example.off")).betti == BettiNumbers{1, 2, 0});
}

TEST_CASE("mesh axes have the solid's Betti numbers", "[mesh_axis]") {
  check_axis(torus_mesh(2, 0.5, 24, 12), {1, 1, 0});
  check_axis(torus_mesh(2, 0.3, 16, 6), {1, 1, 0});  // thin: a 1-dimensional axis
  check_axis(plate_with_holes(5, 3, {{1, 1}, {3, 1}}), {1, 2, 0});
  check_axis(voxel_mesh(hollow_block_voxels(3), 1, "hollow cube"), {1, 0, 1});
  check_axis(voxel_mesh(scattered_cubes(26), 1, "26 cubes"), {26, 0, 0});
  check_axis(project_mesh("tripod.off"), {1, 0, 0});
  check_axis(project_mesh("cross.off"), {1, 0, 0});
  check_axis(project_mesh("double-torus-example.off"), {1, 2, 0});
}

TEST_CASE("mesh axis refines until the topology is right, or refuses", "[mesh_axis]") {
  const TriangleMesh3 joint = project_mesh("joint.off");  // genus 2, thin rings
  const MeshAxis a = mesh_medial_axis(joint);
  CHECK(a.axis_betti == BettiNumbers{1, 2, 0});
  REQUIRE(a.refinements() >= 1);
  CHECK(a.rounds.front().betti != a.solid.betti);  // the first sampling was too coarse
  CHECK(a.rounds.back().samples > a.rounds.front().samples);
  const nlohmann::json j = mesh_axis_json(a);
  CHECK(j["refinements"] == a.refinements());
  CHECK(j["solid_betti"] == nlohmann::json({1, 2, 0}));
  CHECK(j["axis_betti"] == nlohmann::json({1, 2, 0}));
  MeshAxisOptions none;
  none.max_refinements = 0;
  CHECK_THROWS_AS(mesh_medial_axis(joint, none), MeshAxisTopologyError);
  CHECK_THROWS_WITH(mesh_medial_axis(joint, none), Catch::Contains("joint.off") && Catch::Contains("Betti numbers") &&
                                                       Catch::Contains("the solid 1:2:0") && Catch::Contains("no axis"));
}

TEST_CASE("samples whose Voronoi cell lies inside (a narrow notch) do not leave voids", "[mesh_axis]") {
  // A square prism with a wedge-shaped notch of opening 0.4 : 3: at the notch's bottom
  // edge the other wall's samples cut sample cells off from the outside. Each such cell is
  // a 3-cell of the dual complex; collapsed through one face it leaves no void (before the
  // collapse was added the axis had b2 = the number of such samples).
  const TriangleMesh3 notch = prism_mesh({{1, 2}, {4, 2.2}, {4, 4}, {0, 4}, {0, 0}, {4, 0}, {4, 1.8}}, 1, "notch");
  MeshAxisOptions o;
  o.samples_per_edge = 4;
  const MeshAxis a = mesh_medial_axis(notch, o);
  CHECK(a.axis_betti == BettiNumbers{1, 0, 0});
  CHECK(a.rounds.back().interior_samples > 0);
  MedialComplex(a.complex).validate();
}

TEST_CASE("mesh axis vertices are exact circumcentres, merged exactly", "[mesh_axis]") {
  // The octahedron's six vertices are cospherical: one Delaunay cell, one vertex, the
  // centre, with R^2 = 4 exactly (the first round: no thickness refinement).
  MeshAxisOptions first;
  first.max_refinements = 0;
  const MeshAxis octa = mesh_medial_axis(project_mesh("octahedron.off"), first);
  REQUIRE(octa.complex.vertices.size() == 1);
  CHECK(octa.complex.vertices[0] == ExactPoint3{0, 0, 0});
  CHECK(octa.complex.radius_squared[0] == 4);
  // Every vertex is equidistant (exactly) from the four samples of its tetrahedron: R^2 is
  // its squared distance to the nearest sample, and no sample is nearer.
  const TriangleMesh3 torus = torus_mesh(2, 0.5, 16, 8);
  const MeshAxis a = mesh_medial_axis(torus);
  std::vector<ExactPoint3> samples;
  for (std::size_t i = 0; i < a.samples.lattice.size(); ++i) samples.push_back(exact_sample(a.samples, static_cast<std::uint32_t>(i)));
  for (std::size_t v = 0; v < a.complex.vertices.size(); v += 7) {
    mpq_class nearest = -1;
    for (const ExactPoint3& s : samples) {
      const mpq_class d = squared_distance(a.complex.vertices[v], s);
      if (nearest < 0 || d < nearest) nearest = d;
    }
    CHECK(nearest == a.complex.radius_squared[v]);
  }
  // Metamorphic: scaled by 2 and moved by a dyadic vector, the axis is the same complex
  // moved the same way (the lattice scales with the mesh).
  TriangleMesh3 moved = torus;
  for (auto& p : moved.vertices) p = {2 * p[0] + 0.25, 2 * p[1] - 3, 2 * p[2] + 0.5};
  const MeshAxis b = mesh_medial_axis(moved);
  REQUIRE(b.complex.vertices.size() == a.complex.vertices.size());
  CHECK(b.complex.triangles == a.complex.triangles);
  CHECK(b.complex.segments == a.complex.segments);
  for (std::size_t v = 0; v < a.complex.vertices.size(); ++v) {
    const ExactPoint3& p = a.complex.vertices[v];
    CHECK(b.complex.vertices[v] == ExactPoint3{2 * p.x + 0.25, 2 * p.y - 3, 2 * p.z + 0.5});
    CHECK(b.complex.radius_squared[v] == 4 * a.complex.radius_squared[v]);
  }
}

TEST_CASE("pruning by collapse keeps the homotopy type", "[mesh_axis]") {
  // A 3 x 3 grid of unit squares (vertex (i, j) = 4 i + j).
  auto grid = [](const std::vector<std::array<int, 2>>& squares) {
    PolygonalComplex c;
    c.vertex_count = 16;
    for (const auto& [i, j] : squares) {
      for (std::uint32_t v : {4 * i + j, 4 * (i + 1) + j, 4 * (i + 1) + j + 1, 4 * i + j + 1}) c.polygons.vertex.push_back(v);
      c.polygons.close();
    }
    return c;
  };
  auto betti = [](const PolygonalComplex& c, const PrunedComplex& p) {
    PolygonRings kept;
    for (std::size_t i = 0; i < c.polygons.size(); ++i)
      if (p.polygon_kept[i]) {
        kept.vertex.insert(kept.vertex.end(), c.polygons.ring(i), c.polygons.ring(i) + c.polygons.ring_size(i));
        kept.close();
      }
    std::vector<std::uint32_t> id(c.vertex_count, UINT32_MAX);
    std::uint32_t n = 0;
    for (std::size_t v = 0; v < c.vertex_count; ++v)
      if (p.vertex_kept[v]) id[v] = n++;
    for (auto& v : kept.vertex) v = id[v];
    std::vector<std::array<std::uint32_t, 2>> edges;
    for (const auto& e : p.bare_edges) edges.push_back({id[e[0]], id[e[1]]});
    return polygonal_betti_numbers(n, edges, kept);
  };
  const auto nothing = [](std::uint32_t) { return false; };
  const auto no_edge = [](const EdgeOrigin&) { return false; };
  std::vector<std::array<int, 2>> all, ring;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      all.push_back({i, j});
      if (i != 1 || j != 1) ring.push_back({i, j});
    }
  const PolygonalComplex disk = grid(all), annulus = grid(ring);
  const PrunedComplex d = prune_by_collapse(disk, nothing, no_edge);
  CHECK(betti(disk, d) == BettiNumbers{1, 0, 0});
  CHECK(std::count(d.polygon_kept.begin(), d.polygon_kept.end(), true) == 0);
  CHECK(std::count(d.vertex_kept.begin(), d.vertex_kept.end(), true) == 1);  // collapsed to a point
  const PrunedComplex r = prune_by_collapse(annulus, nothing, no_edge);
  CHECK(betti(annulus, r) == BettiNumbers{1, 1, 0});
  CHECK(std::count(r.polygon_kept.begin(), r.polygon_kept.end(), true) == 0);
  CHECK(r.bare_edges.size() >= 4);  // a cycle of edges is left
  // A closed surface (the boundary of a cube as six squares) has no free side.
  PolygonalComplex cube;
  cube.vertex_count = 8;
  for (const auto& f : std::vector<std::array<std::uint32_t, 4>>{{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}}) {
    cube.polygons.vertex.insert(cube.polygons.vertex.end(), f.begin(), f.end());
    cube.polygons.close();
  }
  const PrunedComplex c = prune_by_collapse(cube, nothing, no_edge);
  CHECK(betti(cube, c) == BettiNumbers{1, 0, 1});
  CHECK(std::count(c.polygon_kept.begin(), c.polygon_kept.end(), true) == 6);
  // Kept cells stay; random keep tests never change the Betti numbers.
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::array<int, 2>> squares;
    for (const auto& s : all)
      if (rng() % 3) squares.push_back(s);
    const PolygonalComplex g = grid(squares);
    const PrunedComplex keep_all = prune_by_collapse(g, [](std::uint32_t) { return true; }, [](const EdgeOrigin&) { return true; });
    const BettiNumbers before = betti(g, keep_all);
    CHECK(std::count(keep_all.polygon_kept.begin(), keep_all.polygon_kept.end(), true) == static_cast<long>(g.polygons.size()));
    const unsigned mask = rng();
    const PrunedComplex some = prune_by_collapse(g, [&](std::uint32_t p) { return (mask >> (p % 32)) & 1; }, no_edge);
    CHECK(betti(g, some) == before);
    for (std::size_t p = 0; p < g.polygons.size(); ++p)
      if ((mask >> (p % 32)) & 1) CHECK(some.polygon_kept[p]);
  }
}

TEST_CASE("homology: peeling free faces gives the plain reduction's Betti numbers", "[mesh_axis]") {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const std::uint32_t n = 6 + rng() % 10;
    std::vector<std::array<std::uint32_t, 2>> e;
    std::vector<std::array<std::uint32_t, 3>> t;
    std::vector<std::array<std::uint32_t, 4>> h;
    auto distinct = [&](std::size_t k) {
      std::vector<std::uint32_t> v;
      while (v.size() < k) {
        const std::uint32_t x = rng() % n;
        if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
      }
      return v;
    };
    for (int i = 0, m = static_cast<int>(rng() % 12); i < m; ++i) {
      const auto v = distinct(2);
      e.push_back({v[0], v[1]});
    }
    for (int i = 0, m = static_cast<int>(rng() % 25); i < m; ++i) {
      const auto v = distinct(3);
      t.push_back({v[0], v[1], v[2]});
    }
    for (int i = 0, m = static_cast<int>(rng() % 4); i < m; ++i) {
      const auto v = distinct(4);
      h.push_back({v[0], v[1], v[2], v[3]});
    }
    CAPTURE(trial);
    CHECK(betti_numbers(n, e, t, h) == betti_numbers_reference(n, e, t, h));
    // Quadrilaterals as cells equal their fan triangulations when no diagonal is an edge
    // of anything else (as in a polyhedral complex: a diagonal lies inside its face).
    PolygonRings quads;
    std::vector<std::array<std::uint32_t, 3>> fans;
    auto key = [](std::uint32_t a, std::uint32_t b) { return std::array<std::uint32_t, 2>{std::min(a, b), std::max(a, b)}; };
    std::set<std::array<std::uint32_t, 2>> sides, diagonals;
    for (const auto& x : e) sides.insert(key(x[0], x[1]));
    for (int i = 0, m = static_cast<int>(rng() % 10); i < m; ++i) {
      const auto v = distinct(4);
      const auto d = key(v[0], v[2]);
      bool ok = !sides.count(d) && !diagonals.count(d);
      for (int k = 0; k < 4; ++k) ok &= !diagonals.count(key(v[k], v[(k + 1) % 4]));
      if (!ok) continue;
      diagonals.insert(d);
      for (int k = 0; k < 4; ++k) sides.insert(key(v[k], v[(k + 1) % 4]));
      quads.vertex.insert(quads.vertex.end(), v.begin(), v.end());
      quads.close();
      fans.push_back({v[0], v[1], v[2]});
      fans.push_back({v[0], v[2], v[3]});
    }
    CHECK(polygonal_betti_numbers(n, e, quads) == betti_numbers_reference(n, e, fans, {}));
  }
  // A tetrahedron's boundary: b2 = 1; filled: b2 = 0.
  const std::vector<std::array<std::uint32_t, 3>> faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  CHECK(betti_numbers(4, {}, faces, {}) == BettiNumbers{1, 0, 1});
  CHECK(betti_numbers(4, {}, faces, {{0, 1, 2, 3}}) == BettiNumbers{1, 0, 0});
}

namespace {

std::array<double, 3> approx(const ExactPoint3& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }

double distance(const std::array<double, 3>& x, const std::array<double, 3>& y) {
  return std::sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
}

double distance_to_segment(const std::array<double, 3>& x, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  double ab2 = 0, t = 0;
  for (int k = 0; k < 3; ++k) ab2 += (b[k] - a[k]) * (b[k] - a[k]), t += (x[k] - a[k]) * (b[k] - a[k]);
  t = std::clamp(t / ab2, 0.0, 1.0);
  double d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += (x[k] - a[k] - t * (b[k] - a[k])) * (x[k] - a[k] - t * (b[k] - a[k]));
  return std::sqrt(d2);
}

// Whether some axis vertex lies past the middle of the arm from hub to end (closer to the
// end than half the arm's length) and within `radius` of the arm's centre line.
bool reaches_into_arm(const MeshAxis& a, const std::array<double, 3>& hub, const std::array<double, 3>& end, double radius) {
  const double length = distance(end, hub);
  for (const ExactPoint3& v : a.complex.vertices) {
    const std::array<double, 3> x = approx(v);
    if (distance(x, end) < length / 2 && distance_to_segment(x, hub, end) < radius) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("thin parts keep their axis: the tripod's arms and the cross's bars", "[mesh_axis]") {
  // At the default spacing (the mean edge, 0.31 on the tripod, 0.23 on the cross) the arms
  // (0.3 and 0.2 thick) are thinner than the separation threshold 2 h: before the
  // thickness rule every arm face was pruned and both axes were one vertex.
  const TriangleMesh3 tripod = project_mesh("tripod.off");
  const MeshAxis t = mesh_medial_axis(tripod);
  CHECK(t.axis_betti == BettiNumbers{1, 0, 0});
  CHECK(t.rounds.front().kept_polygons == 0);  // the coarse round lost the arms
  // The arms' ends: the centroids of the mesh vertices at each arm's tip (the arms run
  // towards -x, towards +x -y and towards +y from the hub, the centroid of the box
  // [-0.17, 0.14] x [-0.27, 0.04] between them).
  const std::array<double, 3> hub{-0.0165, -0.1166, 0.0059};
  auto tip = [&](auto at_tip) {
    std::array<double, 3> c{0, 0, 0};
    int n = 0;
    for (const auto& v : tripod.vertices)
      if (at_tip(v)) {
        for (int k = 0; k < 3; ++k) c[k] += v[k];
        ++n;
      }
    REQUIRE(n == 5);
    for (double& x : c) x /= n;
    return c;
  };
  const std::array<double, 3> ends[3] = {tip([](const auto& v) { return v[0] < -0.4; }),
                                         tip([](const auto& v) { return v[0] > 0.35; }),
                                         tip([](const auto& v) { return v[1] > 0.33; })};
  for (const auto& end : ends) CHECK(reaches_into_arm(t, hub, end, 0.15));
  // The cross: bars 0.2 x 0.2 along the x and y axes from -0.5 to 0.5; their centre lines
  // are the axes themselves.
  const MeshAxis c = mesh_medial_axis(project_mesh("cross.off"));
  CHECK(c.axis_betti == BettiNumbers{1, 0, 0});
  CHECK(c.complex.vertices.size() > 1);
  for (const std::array<double, 3>& end :
       {std::array<double, 3>{0.5, 0, 0}, {-0.5, 0, 0}, {0, 0.5, 0}, {0, -0.5, 0}})
    CHECK(reaches_into_arm(c, {0, 0, 0}, end, 0.1));
}

TEST_CASE("mesh axis skips a thickness round that would add few samples", "[mesh_axis]") {
  // joint: its thickness rounds add 147%, 25%, then 7.5% samples; the default skips the last.
  const TriangleMesh3 joint = project_mesh("joint.off");
  MeshAxisOptions every;
  every.min_thickness_growth = 0;
  const MeshAxis all = mesh_medial_axis(joint, every), skipped = mesh_medial_axis(joint);
  REQUIRE(skipped.rounds.size() < all.rounds.size());
  for (std::size_t r = 0; r < skipped.rounds.size(); ++r) CHECK(skipped.rounds[r].samples == all.rounds[r].samples);
  const double growth = static_cast<double>(all.rounds[skipped.rounds.size()].samples) / skipped.rounds.back().samples - 1;
  CHECK(growth < MeshAxisOptions{}.min_thickness_growth);
  CHECK(skipped.axis_betti == all.axis_betti);
  CHECK(skipped.axis_betti == skipped.solid.betti);
}

TEST_CASE("mesh axis sample limit: a round over it stops with a message naming --max-samples", "[mesh_axis]") {
  // A torus with a tube of triangular section far thinner than its edges: the first rounds
  // (216 and 792 samples) leave the axis in pieces, the third has its Betti numbers. A limit
  // at the first round's samples refuses with the rounds reached and the option; a limit at
  // the returned round's samples builds the same axis as the default.
  TriangleMesh3 torus = torus_mesh(2, 0.02, 24, 3);
  torus.source = "thin-torus";
  const MeshAxis a = mesh_medial_axis(torus);
  CHECK(a.axis_betti == BettiNumbers{1, 1, 0});
  REQUIRE(a.rounds.size() >= 2);
  REQUIRE(a.rounds.front().betti != a.solid.betti);
  MeshAxisOptions tight;
  tight.max_samples = a.rounds.front().samples;
  CHECK_THROWS_AS(mesh_medial_axis(torus, tight), MeshAxisTopologyError);
  CHECK_THROWS_WITH(mesh_medial_axis(torus, tight),
                    Catch::Contains("thin-torus") && Catch::Contains("over the limit of " + std::to_string(tight.max_samples)) &&
                        Catch::Contains("--max-samples") && Catch::Contains("Betti " + betti_text(a.rounds.front().betti)) &&
                        Catch::Contains("1:1:0") && Catch::Contains("no axis"));
  MeshAxisOptions enough;
  enough.max_samples = a.rounds[a.axis_round].samples;
  const MeshAxis b = mesh_medial_axis(torus, enough);
  CHECK(b.axis_betti == a.axis_betti);
  CHECK(b.rounds[b.axis_round].samples == a.rounds[a.axis_round].samples);
}
