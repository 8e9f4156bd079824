// test_burn3_exact_support.cpp -- see test_burn3_exact_support.h.
#include "test_burn3_exact_support.h"

#include <algorithm>
#include <cmath>

#include "burn3/discrete/discrete_burning.h"

namespace grassfire::testing {

RawComplex grid_sheet(int w, int h, int g, const std::vector<std::pair<int, int>>& holes, IgnitionRule rule) {
  ComplexBuilder b("grid sheet");
  auto vid = [&](int i, int j) { return b.vertex({mpq_class(i, g), mpq_class(j, g), 0}); };
  for (int i = 0; i < w * g; ++i)
    for (int j = 0; j < h * g; ++j) {
      if (std::find(holes.begin(), holes.end(), std::make_pair(i, j)) != holes.end()) continue;
      const auto a = vid(i, j), bb = vid(i + 1, j), c = vid(i + 1, j + 1), d = vid(i, j + 1);
      if ((i + j) % 2 == 0) {
        b.triangle(a, bb, c), b.triangle(a, c, d);
      } else {
        b.triangle(a, bb, d), b.triangle(bb, c, d);
      }
    }
  RawComplex raw = b.take();
  if (rule != IgnitionRule::Linear) {
    // Every border edge: an edge of exactly one triangle.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (const auto& t : raw.triangles)
      for (int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    for (const auto& [e, n] : count)
      if (n == 1) raw.border_rules.push_back({{e.first, e.second}, rule, {}});
  }
  return raw;
}

ExactPoint3 triangle_point(const MedialComplex& mc, std::uint32_t t, const mpq_class& a, const mpq_class& b) {
  const auto& v = mc.triangle(t).v;
  const ExactPoint3 &p = mc.vertex(v[0]).exact, &q = mc.vertex(v[1]).exact, &r = mc.vertex(v[2]).exact;
  const mpq_class c = 1 - a - b;
  return {a * p.x + b * q.x + c * r.x, a * p.y + b * q.y + c * r.y, a * p.z + b * q.z + c * r.z};
}

std::vector<ExactPoint3> sample_triangle(const MedialComplex& mc, std::uint32_t t, int count, std::mt19937& rng) {
  std::uniform_int_distribution<int> d(0, 64);
  std::vector<ExactPoint3> r;
  while (static_cast<int>(r.size()) < count) {
    const int a = d(rng), b = d(rng);
    if (a + b > 64) continue;
    r.push_back(triangle_point(mc, t, mpq_class(a, 64), mpq_class(b, 64)));
  }
  return r;
}

double baseline_gap(const MedialComplex& mc, const std::vector<Interval>& exact, double h,
                    const std::vector<PointSource>& sources) {
  DiscreteBurningOptions o;
  o.spacing = h;
  o.sources = sources;
  const DiscreteBurning d = burn_discrete(mc, o);
  double worst = 0.0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    CAPTURE(h, v);
    CHECK(d.vertex_bt[v] >= exact[v].lo - 1e-12);
    worst = std::max(worst, d.vertex_bt[v] - exact[v].lo);
  }
  return worst;
}

Vec3d to_vec(const ExactPoint3& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }

double distance3(const Vec3d& a, const Vec3d& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

BorderBurn::BorderBurn(const RawComplex& raw) : mc(built(raw)) {
  eb = std::make_unique<ExactBurning>(mc);
  eb->add_border_ignition();
  eb->run();
  points = junction_points(*eb);
}

// x -> s R x + t with R = the rotation by the Pythagorean angle (3/5, 4/5) about y, then
// by (5/13, 12/13) about z: rational, orthogonal.
ExactPoint3 motion(const ExactPoint3& p, const mpq_class& s, const ExactPoint3& t) {
  const mpq_class c1(3, 5), s1(4, 5), c2(5, 13), s2(12, 13);
  const ExactPoint3 a{c1 * p.x - s1 * p.z, p.y, s1 * p.x + c1 * p.z};
  const ExactPoint3 b{c2 * a.x - s2 * a.y, s2 * a.x + c2 * a.y, a.z};
  return {s * b.x + t.x, s * b.y + t.y, s * b.z + t.z};
}

RawComplex moved(RawComplex raw, const mpq_class& s, const ExactPoint3& t) {
  for (ExactPoint3& v : raw.vertices) v = motion(v, s, t);
  for (mpq_class& r2 : raw.radius_squared) r2 *= s * s;
  for (BorderIgnition& b : raw.border_rules) b.point = motion(b.point, s, t);
  raw.source += " moved";
  return raw;
}

// The same complex with vertices and triangles in a shuffled order (and each triangle's
// corners rotated).
RawComplex shuffled(RawComplex raw, std::mt19937& rng, std::vector<std::uint32_t>* new_triangle,
                    std::vector<std::uint32_t>* new_vertex) {
  std::vector<std::uint32_t> perm(raw.vertices.size());
  for (std::uint32_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  RawComplex r = raw;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    r.vertices[perm[i]] = raw.vertices[i];
    r.radius_squared[perm[i]] = raw.radius_squared[i];
  }
  std::vector<std::uint32_t> tperm(raw.triangles.size());
  for (std::uint32_t i = 0; i < tperm.size(); ++i) tperm[i] = i;
  std::shuffle(tperm.begin(), tperm.end(), rng);
  for (std::size_t i = 0; i < tperm.size(); ++i) {
    const auto& t = raw.triangles[i];
    const int k = static_cast<int>(i % 3);
    r.triangles[tperm[i]] = {perm[t[k]], perm[t[(k + 1) % 3]], perm[t[(k + 2) % 3]]};
  }
  for (auto& s : r.segments) s = {perm[s[0]], perm[s[1]]};
  for (auto& b : r.border_rules) b.edge = {perm[b.edge[0]], perm[b.edge[1]]};
  *new_triangle = tperm;
  if (new_vertex) *new_vertex = perm;
  return r;
}

}  // namespace grassfire::testing
