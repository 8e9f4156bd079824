// test_burn3_exact_support.cpp -- see test_burn3_exact_support.h.
#include "test_burn3_exact_support.h"

#include <algorithm>
#include <cmath>

#include "burn3/discrete_burning.h"

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

}  // namespace grassfire::testing
