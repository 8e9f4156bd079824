// burn_outputs.cpp -- see burn_outputs.h.
#include "burn3/exact/burn_outputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "number/exact_sum.h"

namespace grassfire {

CertifiedValue certified_value(const Interval& i) {
  if (i.is_infinite()) return {std::numeric_limits<double>::infinity(), 0.0};
  return {i.mid(), i.radius()};
}

double decision_error(ExactBurning& eb) {
  const CertificationCounts& c = eb.certification();
  if (c.uncertified > 0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(c.negligible_ties) * 0x1p-64 * (1.0 + 0x1p-50);
}

VertexBurnValues vertex_values(ExactBurning& eb) {
  const MedialComplex& mc = eb.complex();
  const double extra = decision_error(eb);
  VertexBurnValues r;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const Interval bt = eb.vertex_burn_time(v);
    r.bt.push_back(certified_value(bt));
    r.et.push_back(bt.is_infinite() ? certified_value(bt) : certified_value(bt - sqrt(enclose(mc.vertex(v).radius_squared))));
    for (CertifiedValue* x : {&r.bt.back(), &r.et.back()})
      if (std::isfinite(x->value)) x->error += extra;
  }
  return r;
}

RefinedBurn refine(ExactBurning& eb, int n) {
  const MedialComplex& mc = eb.complex();
  if (n < 1) n = 1;
  RefinedBurn r;
  // Grid points keyed by (vertex, vertex, step): shared along edges, at vertices.
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> ids;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const auto& tv = mc.triangle(t).v;
    std::vector<std::uint32_t> grid;  // row i (0..n), column j (0..n-i)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) {
        const int k = n - i - j;  // weights (k, i, j) / n of tv[0], tv[1], tv[2]
        std::array<std::pair<std::uint32_t, int>, 3> w{{{tv[0], k}, {tv[1], i}, {tv[2], j}}};
        std::sort(w.begin(), w.end());
        std::array<std::uint64_t, 3> key{};
        int used = 0;
        for (const auto& [v, weight] : w)
          if (weight > 0) key[used++] = (static_cast<std::uint64_t>(v) << 20) | static_cast<std::uint64_t>(weight);
        auto [it, inserted] = ids.emplace(key, static_cast<std::uint32_t>(r.points.size()));
        if (inserted) {
          ExactPoint3 p{0, 0, 0};
          for (const auto& [v, weight] : w) {
            const mpq_class f(weight, n);
            p.x += f * mc.vertex(v).exact.x, p.y += f * mc.vertex(v).exact.y, p.z += f * mc.vertex(v).exact.z;
          }
          r.points.push_back(to_double(p));
          r.bt.push_back(certified_value(eb.burn_time(t, p)));
        }
        grid.push_back(it->second);
      }
    auto at = [&](int i, int j) { return grid[static_cast<std::size_t>(i * (n + 1) - i * (i - 1) / 2 + j)]; };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n - i; ++j) {
        r.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        r.source_triangle.push_back(t);
        if (j + 1 < n - i) {
          r.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
          r.source_triangle.push_back(t);
        }
      }
  }
  return r;
}

namespace {

Vec3d lerp(const Vec3d& a, const Vec3d& b, double s) {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

// The crossing of value t on the edge a-b (values fa < t <= fb or the reverse).
Vec3d crossing(const Vec3d& a, double fa, const Vec3d& b, double fb, double t) {
  if (!std::isfinite(fa)) return b;
  if (!std::isfinite(fb)) return a;
  return lerp(a, b, (t - fa) / (fb - fa));
}

}  // namespace

std::vector<std::vector<Segment3>> iso_lines(const RefinedBurn& r, const std::vector<double>& times) {
  std::vector<std::vector<Segment3>> out(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    for (const auto& tri : r.triangles) {
      std::vector<Vec3d> cut;
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
        const double fa = r.bt[a].value, fb = r.bt[b].value;
        if ((fa < t) != (fb < t)) cut.push_back(crossing(r.points[a], fa, r.points[b], fb, t));
      }
      if (cut.size() == 2) out[k].push_back({cut[0], cut[1]});
    }
  }
  return out;
}

std::vector<std::vector<Vec3d>> front_at(const RefinedBurn& r, double t) {
  std::vector<std::vector<Vec3d>> out;
  for (const auto& tri : r.triangles) {
    std::vector<Vec3d> poly;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
      const double fa = r.bt[a].value, fb = r.bt[b].value;
      if (fa <= t) poly.push_back(r.points[a]);
      if ((fa <= t) != (fb <= t)) poly.push_back(crossing(r.points[a], fa, r.points[b], fb, t));
    }
    if (poly.size() >= 3) out.push_back(std::move(poly));
  }
  return out;
}

const char* to_string(SweepEvent::Kind k) { return k == SweepEvent::Kind::VertexSource ? "vertex_source" : "vertex_burn"; }

std::vector<SweepEvent> event_log(ExactBurning& eb) {
  std::vector<SweepEvent> log = eb.propagation().events();
  Certifier& cert = eb.certifier();
  std::stable_sort(log.begin(), log.end(), [&](const SweepEvent& a, const SweepEvent& b) {
    const int c = a.time == b.time ? 0 : cert.compare_time_exprs(a.time, b.time, true);
    if (c == -1 || c == 1) return c == -1;
    if (c == kUndecided) {  // order by enclosure midpoints; the rank below breaks the rest
      const double ma = eb.propagation().store().times[a.time].value.mid();
      const double mb = eb.propagation().store().times[b.time].value.mid();
      if (ma != mb) return ma < mb;
    }
    return a.kind != b.kind ? a.kind < b.kind : a.id < b.id;
  });
  return log;
}

}  // namespace grassfire
