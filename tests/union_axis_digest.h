// union_axis_digest.h -- a canonical text of everything union_of_balls_axis returns (every
// vertex's exact coordinates and R^2 with its exactness flag, nearest boundary vertex and
// singular simplex, the triangles and segments in order, the border rules, the boundary
// vertices, the singular simplices, the counts and Betti numbers, the error bounds), and
// the corpus it is taken on.
//
// tests/data/union_axis_digests.txt holds the FNV-1a hashes of these texts computed by the
// implementation before the fast path (main bad0ea7); test_union_balls_fast.cpp recomputes
// them with the current one, so "identical to today's axis" is checked vertex for vertex.
// Corpus: seeded random ball sets of the benchmark's density and of sparser and denser
// ones, coarse dyadic sets with many ties and nested balls, integer grids of equal balls
// (every cube of centres cospherical; tangent neighbours; spheres meeting in rational
// points; balls covering the cube centre exactly), a cospherical cube-plus-octahedron
// configuration, and data/balls/caffeine.cin. The header uses only what both
// implementations have, so the same file generates the reference.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "medial3/balls/union_of_balls_axis.h"
#include "io/mesh_io.h"

namespace grassfire::testing {

inline std::uint64_t union_fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

inline std::string union_hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

inline std::string union_axis_text(const UnionOfBallsAxis& a) {
  std::ostringstream os;
  const RawComplex& c = a.complex;
  for (std::size_t v = 0; v < c.vertices.size(); ++v) {
    const AxisVertexInfo& i = a.vertex_info[v];
    os << "v " << c.vertices[v].x << ' ' << c.vertices[v].y << ' ' << c.vertices[v].z << ' ' << c.radius_squared[v] << ' '
       << i.exact << ' ' << i.nearest << ' ' << i.simplex << '\n';
  }
  for (const auto& t : c.triangles) os << "t " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for (const auto& s : c.segments) os << "s " << s[0] << ' ' << s[1] << '\n';
  for (const BorderIgnition& r : c.border_rules)
    os << "r " << r.edge[0] << ' ' << r.edge[1] << ' ' << int(r.rule) << ' ' << r.point.x << ' ' << r.point.y << ' '
       << r.point.z << '\n';
  for (const BoundaryVertex& b : a.boundary) {
    os << "b " << b.balls[0] << ' ' << b.balls[1] << ' ' << b.balls[2] << ' ' << b.side << ' ' << b.rational;
    if (b.rational) os << ' ' << b.point.x << ' ' << b.point.y << ' ' << b.point.z;
    os << ' ' << b.s << '\n';
  }
  for (const PowerSimplex& s : a.singular)
    os << "k " << s.dim << ' ' << s.balls[0] << ' ' << s.balls[1] << ' ' << s.balls[2] << ' ' << s.power << '\n';
  os << "balls " << a.balls << " hidden " << a.hidden_balls << " dim " << a.triangulation_dimension << " alpha "
     << a.alpha_simplices[0] << ' ' << a.alpha_simplices[1] << ' ' << a.alpha_simplices[2] << ' ' << a.alpha_simplices[3]
     << " singular " << a.singular_simplices[0] << ' ' << a.singular_simplices[1] << ' ' << a.singular_simplices[2]
     << " polygons " << a.tet_polygons << " betti " << a.union_betti.b0 << ' ' << a.union_betti.b1 << ' '
     << a.union_betti.b2 << " errors " << union_hex(a.coordinate_error) << ' ' << union_hex(a.radius_squared_error) << ' '
     << union_hex(a.rule_point_error) << '\n';
  return os.str();
}

inline void union_add_ball(BallSet* s, const mpq_class& x, const mpq_class& y, const mpq_class& z, const mpq_class& r2) {
  s->centers.push_back({x, y, z});
  s->squared_radii.push_back(r2);
  s->approx_centers.push_back({x.get_d(), y.get_d(), z.get_d()});
  s->approx_radii.push_back(std::sqrt(r2.get_d()));
}

// Seeded random balls with dyadic coordinates in [0, side]^3 and radii in [r0, r0 + dr).
inline BallSet union_random_balls(std::size_t n, unsigned seed, double side, double r0, double dr) {
  std::mt19937 rng(seed);
  auto uniform = [&](double scale) { return scale * static_cast<double>(rng() % 4096) / 4096.0; };
  BallSet s;
  s.source = "random(" + std::to_string(n) + ", seed " + std::to_string(seed) + ", side " + std::to_string(side) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = uniform(side), y = uniform(side), z = uniform(side), r = r0 + uniform(dr);
    union_add_ball(&s, mpq_class(x), mpq_class(y), mpq_class(z), mpq_class(r) * mpq_class(r));
  }
  return s;
}

// Balls on an integer grid with equal squared radius r2.
inline BallSet union_grid_balls(int side, const mpq_class& r2) {
  BallSet s;
  s.source = "grid(" + std::to_string(side) + ", r2 " + r2.get_str() + ")";
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) union_add_ball(&s, x, y, z, r2);
  return s;
}

// Random dyadic balls on a coarse grid (many ties), plus balls contained in others.
inline BallSet union_coarse_balls(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  BallSet s;
  s.source = "coarse(" + std::to_string(n) + ", seed " + std::to_string(seed) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    const mpq_class x(rng() % 9, 2), y(rng() % 9, 2), z(rng() % 9, 2), r(2 + rng() % 3, 2);
    union_add_ball(&s, x, y, z, r * r);
    if (i % 5 == 0) union_add_ball(&s, x, y, z + mpq_class(1, 4), r * r / 4);
  }
  return s;
}

// Equal balls on the 8 corners of the cube [-1, 1]^3 (cospherical) and the 6 tips of an
// octahedron at distance 2 from the origin (cospherical too), plus, when c2 > 0, a central
// ball of squared radius c2.
inline BallSet union_cospherical_balls(const mpq_class& r2, const mpq_class& c2) {
  BallSet s;
  s.source = "cospherical(r2 " + r2.get_str() + ", centre " + c2.get_str() + ")";
  for (int x : {-1, 1})
    for (int y : {-1, 1})
      for (int z : {-1, 1}) union_add_ball(&s, x, y, z, r2);
  for (int k = 0; k < 3; ++k)
    for (int side : {-1, 1}) {
      mpq_class c[3] = {0, 0, 0};
      c[k] = side * 2;
      union_add_ball(&s, c[0], c[1], c[2], r2);
    }
  if (sgn(c2) > 0) union_add_ball(&s, 0, 0, 0, c2);
  return s;
}

inline std::vector<BallSet> union_digest_corpus(const std::string& data) {
  std::vector<BallSet> out;
  for (unsigned seed = 1; seed <= 6; ++seed) out.push_back(random_ball_set(40 + 30 * seed, seed));
  out.push_back(random_ball_set(400, 2024));
  for (unsigned seed = 1; seed <= 3; ++seed) out.push_back(union_random_balls(60, seed, 4.0, 0.8, 0.6));   // dense
  for (unsigned seed = 1; seed <= 3; ++seed) out.push_back(union_random_balls(80, seed, 12.0, 1.0, 1.0));  // sparse
  for (unsigned seed = 1; seed <= 6; ++seed) out.push_back(union_coarse_balls(30, seed));
  out.push_back(union_grid_balls(3, 1));
  out.push_back(union_grid_balls(3, mpq_class(1, 4)));
  out.push_back(union_grid_balls(2, 3));
  out.push_back(union_grid_balls(3, mpq_class(9, 16)));
  out.push_back(union_grid_balls(4, mpq_class(3, 4)));
  out.push_back(union_cospherical_balls(2, 0));
  out.push_back(union_cospherical_balls(mpq_class(3, 2), 1));
  out.push_back(union_cospherical_balls(3, 2));
  out.push_back(read_ball_list(data + "/balls/caffeine.cin"));
  return out;
}

}  // namespace grassfire::testing
